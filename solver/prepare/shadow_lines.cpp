#include "solver/prepare/shadow_lines.h"

#include "solver/prepare/face_polygon.h"
#include "solver/shooting/energy_balance.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

namespace regio::solver {

namespace {

using Polygon = std::vector<Vec3>;

constexpr double kSameDirection = 0.9994; // cos 2 degrees

// The ends of the solid's edges that rise from its corner `corner` on the
// face: the neighbours of that corner in the part's other faces, above the
// face's plane.
std::vector<Vec3> risingEdgeEnds(const PreparedScene& scene, size_t cover, const Vec3& corner, const Plane& plane)
{
    std::vector<Vec3> ends;
    const auto [first, last] = facesOfPart(scene, cover);
    for (size_t h = first; h < last; ++h) {
        if (h == cover)
            continue;
        const Polygon& loop = scene.faces[h].polygon;
        for (size_t i = 0; i < loop.size(); ++i) {
            if (glm::length(loop[i] - corner) > model::kDistanceEpsilon)
                continue;
            for (const Vec3& q : {loop[(i + loop.size() - 1) % loop.size()], loop[(i + 1) % loop.size()]}) {
                if (plane.signedDistance(q) <= model::kDistanceEpsilon)
                    continue;
                const bool known = std::any_of(ends.begin(), ends.end(), [&](const Vec3& e) {
                    return glm::length(e - q) <= model::kDistanceEpsilon;
                });
                if (!known)
                    ends.push_back(q);
            }
        }
    }
    return ends;
}

// The line on the plane where the plane through the edge corner-top and the
// light vertex meets it, from the corner away from the light, as far as the
// edge's shadow from that vertex reaches. No line when the three are in one
// line.
bool edgeVertexLine(const Plane& plane, const Vec3& corner, const Vec3& top, const Vec3& light, double farthest,
                    ShadowLine& line)
{
    Vec3 d = glm::cross(glm::cross(top - corner, light - corner), plane.normal);
    const double length = glm::length(d);
    if (length < 1e-12)
        return false;
    d /= length;
    if (glm::dot(d, corner - light) < 0.0)
        d = -d;
    line.origin = corner;
    line.direction = d;
    // Where the ray from the light over the top of the edge meets the plane.
    const double hLight = plane.signedDistance(light), hTop = plane.signedDistance(top);
    line.length = farthest;
    if (hLight > hTop * (1.0 + 1e-9)) {
        const Vec3 end = light + (top - light) * (hLight / (hLight - hTop));
        line.length = std::min(farthest, glm::length(end - corner));
    }
    return line.length > model::kDistanceEpsilon;
}

// The smallest inner angle of a convex polygon, in degrees.
double smallestAngle(const Polygon& polygon)
{
    double smallest = 180.0;
    const size_t n = polygon.size();
    for (size_t i = 0; i < n; ++i) {
        const Vec3 a = glm::normalize(polygon[(i + n - 1) % n] - polygon[i]);
        const Vec3 b = glm::normalize(polygon[(i + 1) % n] - polygon[i]);
        smallest = std::min(smallest, glm::degrees(std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0))));
    }
    return smallest;
}

} // namespace

std::pair<size_t, size_t> facesOfPart(const PreparedScene& scene, size_t face)
{
    const InputFace& of = scene.faces[face];
    const size_t first = face - size_t(of.faceInPart);
    size_t last = first;
    while (last < scene.faces.size() && scene.faces[last].object == of.object && scene.faces[last].part == of.part)
        ++last;
    return {first, last};
}

double directLight(const PreparedScene& scene, size_t light, const Vec3& x, const Vec3& n)
{
    const Vec3 d = model::polygonCentroid(scene.faces[light].polygon) - x;
    const double d2 = glm::dot(d, d);
    if (d2 <= 0.0)
        return 0.0;
    const double cosHere = glm::dot(n, d) / std::sqrt(d2);
    const double cosThere = -glm::dot(scene.properties[light].plane.normal, d) / std::sqrt(d2);
    return std::max(0.0, cosHere) * std::max(0.0, cosThere) * luminance(scene.properties[light].emission) *
           scene.faces[light].area / (std::numbers::pi * d2);
}

double footprintWidth(const std::vector<Vec3>& polygon)
{
    double perimeter = 0.0;
    for (size_t i = 0; i < polygon.size(); ++i)
        perimeter += glm::length(polygon[(i + 1) % polygon.size()] - polygon[i]);
    return perimeter > 0.0 ? 2.0 * model::polygonArea(polygon) / perimeter : 0.0;
}

std::vector<size_t> lightFaces(const PreparedScene& scene)
{
    std::vector<size_t> lights;
    for (size_t e = 0; e < scene.faces.size(); ++e)
        if (scene.properties[e].emits() && scene.faces[e].polygon.size() >= 3)
            lights.push_back(e);
    return lights;
}

std::vector<ShadowLine> footShadowLines(const PreparedScene& scene, size_t face, std::span<const size_t> covers,
                                        std::span<const size_t> lights, double minWidth, size_t maxLines)
{
    std::vector<ShadowLine> lines;
    const Plane& plane = scene.properties[face].plane;
    const Polygon& polygon = scene.faces[face].polygon;
    if (polygon.size() < 3)
        return lines;
    double farthest = 0.0;
    for (const Vec3& p : polygon)
        for (const Vec3& q : polygon)
            farthest = std::max(farthest, glm::length(p - q));

    for (size_t cover : covers) {
        const Polygon& footprint = scene.faces[cover].polygon;
        if (footprintWidth(footprint) < minWidth)
            continue;
        const Vec3& footprintNormal = scene.properties[cover].plane.normal;
        for (const Vec3& corner : footprint) {
            const size_t cornerBegin = lines.size();
            for (const Vec3& top : risingEdgeEnds(scene, cover, corner, plane)) {
                for (size_t e : lights) {
                    for (const Vec3& light : scene.faces[e].polygon) {
                        // A light vertex behind the face, or a corner behind the light, casts nothing.
                        ShadowLine line;
                        if (plane.signedDistance(light) <= model::kDistanceEpsilon ||
                            glm::dot(scene.properties[e].plane.normal, corner - light) <= 0.0 ||
                            !edgeVertexLine(plane, corner, top, light, farthest, line))
                            continue;
                        // Only lines into what the solid leaves uncovered, on the face.
                        const Vec3 probe = corner + line.direction * (10.0 * model::kDistanceEpsilon);
                        if (insideConvex(footprint, footprintNormal, probe) ||
                            !insideConvex(polygon, plane.normal, probe))
                            continue;
                        const bool known = std::any_of(
                            lines.begin() + std::ptrdiff_t(cornerBegin), lines.end(), [&](const ShadowLine& other) {
                                return glm::dot(other.direction, line.direction) > kSameDirection;
                            });
                        if (!known) {
                            line.weight = directLight(scene, e, corner, plane.normal);
                            lines.push_back(line);
                        }
                    }
                }
            }
        }
    }
    // Past the budget, the lines of the lights that matter most at their
    // corner, in the order found.
    if (lines.size() > maxLines) {
        std::vector<size_t> order(lines.size());
        std::iota(order.begin(), order.end(), size_t(0));
        std::stable_sort(order.begin(), order.end(),
                         [&](size_t a, size_t b) { return lines[a].weight > lines[b].weight; });
        order.resize(maxLines);
        std::sort(order.begin(), order.end());
        std::vector<ShadowLine> kept;
        for (size_t i : order)
            kept.push_back(lines[i]);
        lines = std::move(kept);
    }
    return lines;
}

void cutAlong(std::vector<std::vector<Vec3>>& pieces, const ShadowLine& line, const Vec3& normal, double minWidth,
              double minAngle)
{
    const Vec3 across = glm::normalize(glm::cross(normal, line.direction));
    std::vector<Polygon> out;
    out.reserve(pieces.size() + 1);
    for (Polygon& piece : pieces) {
        // Both sides at least minWidth wide...
        double below = 0.0, above = 0.0;
        for (const Vec3& p : piece) {
            const double s = glm::dot(across, p - line.origin);
            below = std::min(below, s);
            above = std::max(above, s);
        }
        // ... and the segment through the inside for at least minWidth.
        const auto [t0, t1] = segmentInsideConvex(piece, normal, line.origin, line.direction, line.length);
        if (above < minWidth || -below < minWidth || t1 - t0 < minWidth) {
            out.push_back(std::move(piece));
            continue;
        }
        Polygon left = cleanConvexLoop(clipConvex(piece, line.origin, across));
        Polygon right = cleanConvexLoop(clipConvex(piece, line.origin, -across));
        if (left.size() < 3 || right.size() < 3 || smallestAngle(left) < minAngle || smallestAngle(right) < minAngle) {
            out.push_back(std::move(piece));
            continue;
        }
        out.push_back(std::move(left));
        out.push_back(std::move(right));
    }
    pieces = std::move(out);
}

} // namespace regio::solver
