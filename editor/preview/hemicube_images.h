#pragma once
// The five faces of a patch's hemicube item buffer as pictures, for the
// hemicube view of a chosen patch: every element in its own colour,
// the sky black, back faces (blockers that receive nothing) dark grey.
// Built on the preview's worker thread; Qt-free so it can be.
#include "solver/visibility/hemicube_view.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace regio::editor {

struct HemicubeFaceImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint32_t> argb; // row-major, top row first (QImage::Format_ARGB32)
    std::vector<int> element;        // per pixel: element, -1 sky, -2 back face
};

struct HemicubeImages {
    int patch = -1;
    int resolution = 0;
    std::string faceId;                     // the input face the patch belongs to
    std::array<HemicubeFaceImage, 5> faces; // top, +x, -x, +y, -y (solver::HemicubeFace order)
    int elementsSeen = 0;
    double escaped = 0.0; // form factor to the sky
    double blocked = 0.0; // form factor to back faces
};

// A colour per element that neighbours rarely share (hashed hue).
std::uint32_t elementColour(int element);

HemicubeImages hemicubeImages(const solver::HemicubeView& view, const solver::PreparedScene& scene);

} // namespace regio::editor
