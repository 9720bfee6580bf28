#pragma once
// A software picture of a lit model: for reports and batch
// machines, no GL needed. Perspective projection from a model::Camera,
// clipping at a near plane, a z-buffer, and Gouraud shading: the per-vertex
// display colours are interpolated (perspective-correct, in linear light) and
// encoded per pixel. Supersampling (s x s samples per pixel, box filter in
// linear light) smooths the edges.
//
// Image coordinates: x to the right, y down, pixel (x, y) covers
// [x, x+1) x [y, y+1) and is sampled at its centre. Coverage follows a
// top-left rule, so two triangles sharing an edge never both own a pixel.
// The back of a surface shows `backFace` (black by default: in a radiosity
// solution a surface's back emits nothing) and still hides what is behind it.
#include "model/scene.h"
#include "output/lit_mesh.h"
#include "output/tone_map.h"

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace regio::output {

struct Image {
    int width = 0;
    int height = 0;
    std::vector<uint8_t> rgb; // 3 bytes per pixel, rows top to bottom

    Image() = default;
    Image(int w, int h)
        : width(w)
        , height(h)
        , rgb(static_cast<size_t>(w) * static_cast<size_t>(h) * 3, 0)
    {
    }
    std::array<uint8_t, 3> pixel(int x, int y) const
    {
        const size_t i = (static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)) * 3;
        return {rgb[i], rgb[i + 1], rgb[i + 2]};
    }
    void setPixel(int x, int y, const std::array<uint8_t, 3>& c)
    {
        const size_t i = (static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)) * 3;
        rgb[i] = c[0];
        rgb[i + 1] = c[1];
        rgb[i + 2] = c[2];
    }
};

struct RenderOptions {
    int width = 1024;
    int height = 768;
    int supersample = 2;                       // samples per pixel along each axis (1 = none)
    glm::vec3 background{0.12f, 0.12f, 0.14f}; // display-encoded
    glm::vec3 backFace{0.0f};                  // linear display colour of surfaces seen from behind
    double nearPlane = 1e-3;                   // metres in front of the eye
};

// Why a camera cannot take a picture (eye on the target, up along the view,
// field of view outside (0, 180) degrees), or nothing.
model::Check checkCamera(const model::Camera& camera);

// A camera that shows the whole of `bounds`: looking at the centre from the
// front-right and slightly above, for models without a scene camera.
model::Camera frameCamera(const LitBounds& bounds, double fovY = 45.0, double aspect = 4.0 / 3.0);

// Where a world point lands: image x, y (pixel units, as described above) and
// its distance in front of the eye along the view direction; empty when it is
// not in front of the near plane. The projection renderImage uses.
std::optional<glm::dvec3> projectToImage(const model::Camera& camera, int width, int height, const glm::dvec3& point,
                                         double nearPlane = 1e-3);

// Renders the mesh with per-vertex colours (colours.linear, encoded with
// colours.encoding). A camera that checkCamera() refuses gives an image of
// the background only.
Image renderImage(const LitMesh& mesh, const DisplayColours& colours, const model::Camera& camera,
                  const RenderOptions& options = {});

} // namespace regio::output
