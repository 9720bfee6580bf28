#include "output/software_render.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace regio::output {

namespace {

constexpr double kPi = 3.14159265358979323846;

struct View {
    glm::dvec3 eye{0.0};
    glm::dvec3 right{1.0, 0.0, 0.0};
    glm::dvec3 up{0.0, 1.0, 0.0};
    glm::dvec3 forward{0.0, 0.0, -1.0};
    double tanHalf = 1.0; // tan(fovY / 2)
    double aspect = 1.0;  // width / height
    double width = 1.0;
    double height = 1.0;

    // Camera space: x right, y up, z = distance along the view direction.
    glm::dvec3 toCamera(const glm::dvec3& p) const
    {
        const glm::dvec3 d = p - eye;
        return {glm::dot(d, right), glm::dot(d, up), glm::dot(d, forward)};
    }
    // Camera space (z > 0) to image pixels.
    glm::dvec2 toImage(const glm::dvec3& c) const
    {
        const double nx = c.x / (c.z * tanHalf * aspect);
        const double ny = c.y / (c.z * tanHalf);
        return {(nx + 1.0) * 0.5 * width, (1.0 - ny) * 0.5 * height};
    }
};

std::optional<View> makeView(const model::Camera& camera, int width, int height)
{
    if (!checkCamera(camera) || width <= 0 || height <= 0)
        return std::nullopt;
    View v;
    v.eye = camera.position;
    v.forward = glm::normalize(camera.target - camera.position);
    v.right = glm::normalize(glm::cross(v.forward, camera.up));
    v.up = glm::cross(v.right, v.forward);
    v.tanHalf = std::tan(camera.fovY * kPi / 360.0);
    v.width = width;
    v.height = height;
    v.aspect = static_cast<double>(width) / static_cast<double>(height);
    return v;
}

struct ClipVertex {
    glm::dvec3 camera; // camera-space position
    glm::vec3 colour;  // linear display colour
};

struct ScreenVertex {
    double x = 0.0, y = 0.0;
    double invZ = 0.0;
    glm::vec3 colourOverZ{0.0f};
};

// Sutherland-Hodgman against z >= near; a triangle becomes at most a quad.
int clipNear(const std::array<ClipVertex, 3>& in, double nearPlane, std::array<ClipVertex, 4>& out)
{
    int n = 0;
    for (int i = 0; i < 3; ++i) {
        const ClipVertex& a = in[static_cast<size_t>(i)];
        const ClipVertex& b = in[static_cast<size_t>((i + 1) % 3)];
        const bool aIn = a.camera.z >= nearPlane;
        const bool bIn = b.camera.z >= nearPlane;
        if (aIn)
            out[static_cast<size_t>(n++)] = a;
        if (aIn != bIn) {
            const double t = (nearPlane - a.camera.z) / (b.camera.z - a.camera.z);
            ClipVertex c;
            c.camera = a.camera + (b.camera - a.camera) * t;
            c.camera.z = nearPlane;
            c.colour = a.colour + (b.colour - a.colour) * static_cast<float>(t);
            out[static_cast<size_t>(n++)] = c;
        }
    }
    return n;
}

double edge(const ScreenVertex& a, const ScreenVertex& b, double px, double py)
{
    return (b.x - a.x) * (py - a.y) - (b.y - a.y) * (px - a.x);
}

// Top-left rule for a triangle whose interior has positive edge functions,
// in y-down image coordinates: an edge owns its pixels when it is a left edge
// (going up the image) or a horizontal top edge (going right).
bool topLeft(const ScreenVertex& a, const ScreenVertex& b)
{
    const double dx = b.x - a.x;
    const double dy = b.y - a.y;
    return dy < 0.0 || (dy == 0.0 && dx > 0.0);
}

struct Target {
    int width = 0;
    int height = 0;
    std::vector<glm::vec3> colour; // linear
    std::vector<float> invDepth;   // 1 / z; 0 = nothing drawn
};

void rasterise(Target& target, ScreenVertex v0, ScreenVertex v1, ScreenVertex v2)
{
    double area = edge(v0, v1, v2.x, v2.y);
    if (!(std::abs(area) > 1e-12))
        return;
    if (area < 0.0) {
        std::swap(v1, v2);
        area = -area;
    }
    const double minX = std::min({v0.x, v1.x, v2.x});
    const double maxX = std::max({v0.x, v1.x, v2.x});
    const double minY = std::min({v0.y, v1.y, v2.y});
    const double maxY = std::max({v0.y, v1.y, v2.y});
    const int x0 = static_cast<int>(std::max(0.0, std::ceil(minX - 0.5)));
    const int x1 = static_cast<int>(std::min(static_cast<double>(target.width - 1), std::floor(maxX - 0.5)));
    const int y0 = static_cast<int>(std::max(0.0, std::ceil(minY - 0.5)));
    const int y1 = static_cast<int>(std::min(static_cast<double>(target.height - 1), std::floor(maxY - 0.5)));
    if (x0 > x1 || y0 > y1)
        return;
    const bool own0 = topLeft(v1, v2);
    const bool own1 = topLeft(v2, v0);
    const bool own2 = topLeft(v0, v1);
    const double inv = 1.0 / area;
    for (int y = y0; y <= y1; ++y) {
        const double py = y + 0.5;
        for (int x = x0; x <= x1; ++x) {
            const double px = x + 0.5;
            const double w0 = edge(v1, v2, px, py);
            const double w1 = edge(v2, v0, px, py);
            const double w2 = edge(v0, v1, px, py);
            if (w0 < 0.0 || w1 < 0.0 || w2 < 0.0)
                continue;
            if ((w0 == 0.0 && !own0) || (w1 == 0.0 && !own1) || (w2 == 0.0 && !own2))
                continue;
            const double l0 = w0 * inv, l1 = w1 * inv, l2 = w2 * inv;
            const double invZ = l0 * v0.invZ + l1 * v1.invZ + l2 * v2.invZ;
            const size_t i = static_cast<size_t>(y) * static_cast<size_t>(target.width) + static_cast<size_t>(x);
            if (!(static_cast<float>(invZ) > target.invDepth[i]))
                continue;
            target.invDepth[i] = static_cast<float>(invZ);
            // Perspective-correct: colour/z is affine in the image, so is 1/z.
            const glm::vec3 c = (v0.colourOverZ * static_cast<float>(l0) + v1.colourOverZ * static_cast<float>(l1) +
                                 v2.colourOverZ * static_cast<float>(l2)) /
                                static_cast<float>(invZ);
            target.colour[i] = glm::max(c, glm::vec3(0.0f));
        }
    }
}

} // namespace

model::Check checkCamera(const model::Camera& camera)
{
    if (!(camera.fovY > 0.0 && camera.fovY < 180.0))
        return model::makeError("the camera's field of view must be between 0 and 180 degrees");
    const glm::dvec3 forward = camera.target - camera.position;
    if (!(glm::length(forward) > 1e-12))
        return model::makeError("the camera's position and target coincide");
    if (!(glm::length(glm::cross(glm::normalize(forward), camera.up)) > 1e-9))
        return model::makeError("the camera's up direction is parallel to its view direction");
    return model::success();
}

model::Camera frameCamera(const LitBounds& bounds, double fovY, double aspect)
{
    model::Camera camera;
    camera.fovY = fovY;
    if (bounds.empty)
        return camera;
    const glm::dvec3 lo(bounds.min), hi(bounds.max);
    const glm::dvec3 centre = 0.5 * (lo + hi);
    const double radius = std::max(0.5 * glm::length(hi - lo), 1e-3);
    // Fit the bounding sphere into the narrower of the two fields of view.
    const double halfY = fovY * kPi / 360.0;
    const double halfX = std::atan(std::tan(halfY) * std::max(aspect, 1e-3));
    const double distance = radius / std::sin(std::min(halfX, halfY));
    const glm::dvec3 direction = glm::normalize(glm::dvec3(0.4, 0.35, -1.0));
    camera.position = centre + direction * distance;
    camera.target = centre;
    camera.up = {0.0, 1.0, 0.0};
    return camera;
}

std::optional<glm::dvec3> projectToImage(const model::Camera& camera, int width, int height, const glm::dvec3& point,
                                         double nearPlane)
{
    const auto view = makeView(camera, width, height);
    if (!view)
        return std::nullopt;
    const glm::dvec3 c = view->toCamera(point);
    if (c.z < nearPlane)
        return std::nullopt;
    const glm::dvec2 p = view->toImage(c);
    return glm::dvec3(p.x, p.y, c.z);
}

Image renderImage(const LitMesh& mesh, const DisplayColours& colours, const model::Camera& camera,
                  const RenderOptions& options)
{
    const int width = std::max(options.width, 1);
    const int height = std::max(options.height, 1);
    const int s = std::clamp(options.supersample, 1, 8);
    Target target;
    target.width = width * s;
    target.height = height * s;
    const size_t samples = static_cast<size_t>(target.width) * static_cast<size_t>(target.height);
    const glm::vec3 background = colours.encoding.decode(options.background);
    target.colour.assign(samples, background);
    target.invDepth.assign(samples, 0.0f);

    const auto view = makeView(camera, target.width, target.height);
    const bool usable = view && checkLitMesh(mesh) && colours.linear.size() == mesh.vertexCount();
    if (usable) {
        const double nearPlane = std::max(options.nearPlane, 1e-9);
        for (size_t t = 0; t < mesh.triangleCount(); ++t) {
            const std::array<uint32_t, 3> idx{mesh.indices[3 * t], mesh.indices[3 * t + 1], mesh.indices[3 * t + 2]};
            const glm::dvec3 p0(mesh.positions[idx[0]]), p1(mesh.positions[idx[1]]), p2(mesh.positions[idx[2]]);
            const glm::dvec3 n = glm::cross(p1 - p0, p2 - p0);
            const double facing = glm::dot(n, view->eye - p0);
            if (facing == 0.0)
                continue; // seen edge-on (or degenerate): covers nothing
            const bool front = facing > 0.0;
            std::array<ClipVertex, 3> in;
            for (size_t k = 0; k < 3; ++k) {
                in[k].camera = view->toCamera(glm::dvec3(mesh.positions[idx[k]]));
                in[k].colour = front ? colours.linear[idx[k]] : options.backFace;
            }
            std::array<ClipVertex, 4> clipped;
            const int count = clipNear(in, nearPlane, clipped);
            if (count < 3)
                continue;
            std::array<ScreenVertex, 4> screen;
            for (int k = 0; k < count; ++k) {
                const ClipVertex& c = clipped[static_cast<size_t>(k)];
                const glm::dvec2 p = view->toImage(c.camera);
                ScreenVertex& sv = screen[static_cast<size_t>(k)];
                sv.x = p.x;
                sv.y = p.y;
                sv.invZ = 1.0 / c.camera.z;
                sv.colourOverZ = c.colour * static_cast<float>(sv.invZ);
            }
            for (int k = 1; k + 1 < count; ++k)
                rasterise(target, screen[0], screen[static_cast<size_t>(k)], screen[static_cast<size_t>(k + 1)]);
        }
    }

    // Box filter in linear light, then encode.
    Image image(width, height);
    const float weight = 1.0f / static_cast<float>(s * s);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            glm::vec3 sum(0.0f);
            for (int sy = 0; sy < s; ++sy) {
                const size_t row = static_cast<size_t>(y * s + sy) * static_cast<size_t>(target.width);
                for (int sx = 0; sx < s; ++sx)
                    sum += target.colour[row + static_cast<size_t>(x * s + sx)];
            }
            image.setPixel(x, y, toBytes(colours.encoding.encode(sum * weight)));
        }
    }
    return image;
}

} // namespace regio::output
