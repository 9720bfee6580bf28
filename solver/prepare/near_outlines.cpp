#include "solver/prepare/near_outlines.h"

#include "solver/prepare/face_polygon.h"
#include "solver/prepare/facing_faces.h"
#include "solver/prepare/shadow_lines.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace regio::solver {

namespace {

constexpr double kParallelCosine = -0.996; // normals within 5 degrees of opposite

// A face with more faces hanging in front of it is left as it is.
constexpr size_t kMostOutlines = 8;

// How long a stretch of the segment ab lies inside the convex polygon
// (normal `normal`).
double lengthInside(const std::vector<Vec3>& polygon, const Vec3& normal, const Vec3& a, const Vec3& b)
{
    const double length = glm::length(b - a);
    if (length <= 0.0)
        return 0.0;
    const auto [t0, t1] = segmentInsideConvex(polygon, normal, a, (b - a) / length, length);
    return std::max(0.0, t1 - t0);
}

} // namespace

std::vector<std::vector<std::vector<Vec3>>> nearOutlines(const PreparedScene& scene)
{
    const std::vector<std::vector<int>> near = closeFacingFaces(scene, kNearOutlineGapPatches * scene.patchSize);
    const double minWidth = ShadowLineLimits{}.solidMinWidth * scene.patchSize;
    std::vector<std::vector<std::vector<Vec3>>> outlines(near.size());
    for (size_t f = 0; f < near.size(); ++f) {
        const Plane& plane = scene.properties[f].plane;
        for (int g : near[f]) {
            const std::vector<Vec3>& polygon = scene.faces[size_t(g)].polygon;
            // Whether or not one of the two emits into the gap: over a panel
            // that does not, the ceiling is dark inside the outline and lit
            // a few centimetres outside it, and an element across the
            // outline drew a dark ring 15 cm wide around the panel
            // (docs/accuracy.md, "A dark gap's rim").
            if (glm::dot(plane.normal, scene.properties[size_t(g)].plane.normal) > kParallelCosine ||
                footprintWidth(polygon) < minWidth)
                continue;
            std::vector<Vec3> dropped;
            for (const Vec3& p : polygon)
                dropped.push_back(p - plane.normal * plane.signedDistance(p));
            // Only an outline that crosses the face (a ceiling's outline,
            // dropped onto the lamp under it, lies all around it).
            bool crosses = false;
            for (size_t i = 0; i < dropped.size() && !crosses; ++i)
                crosses = lengthInside(scene.faces[f].polygon, plane.normal, dropped[i],
                                       dropped[(i + 1) % dropped.size()]) > model::kDistanceEpsilon;
            if (crosses)
                outlines[f].push_back(std::move(dropped));
        }
        if (outlines[f].size() > kMostOutlines)
            outlines[f].clear();
    }
    return outlines;
}

void cutAlongNearOutlines(const PreparedScene& scene, std::vector<std::vector<std::vector<Vec3>>>& pieces)
{
    const ShadowLineLimits limits;
    const double minWidth = limits.cutMinWidth * scene.patchSize;
    const std::vector<std::vector<std::vector<Vec3>>> outlines = nearOutlines(scene);
    for (size_t f = 0; f < outlines.size(); ++f) {
        if (pieces[f].empty())
            continue;
        for (const std::vector<Vec3>& outline : outlines[f]) {
            for (size_t i = 0; i < outline.size(); ++i) {
                const Vec3 &a = outline[i], &b = outline[(i + 1) % outline.size()];
                ShadowLine line;
                line.length = glm::length(b - a);
                if (line.length <= minWidth)
                    continue;
                line.origin = a;
                line.direction = (b - a) / line.length;
                cutAlong(pieces[f], line, scene.properties[f].plane.normal, minWidth, limits.cutMinAngle);
            }
        }
    }
}

bool liesOnOutline(const std::vector<std::vector<Vec3>>& outlines, const Vec3& point)
{
    for (const std::vector<Vec3>& outline : outlines)
        for (size_t i = 0; i < outline.size(); ++i)
            if (pointSegmentDistance(point, outline[i], outline[(i + 1) % outline.size()]) <= model::kDistanceEpsilon)
                return true;
    return false;
}

} // namespace regio::solver
