#pragma once
// A convex piece of an input face on its way through preparation: clipped by
// separating planes (§5.2) and split by BSP planes (§5.3) before it becomes a
// fragment. `face` indexes PreparedScene::faces / properties.
#include "model/geometry/geometry.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace regio::solver {

struct FacePolygon {
    std::vector<model::Vec3> loop; // convex, counter-clockwise seen from the face normal
    int face = -1;
};

// Removes repeated vertices and vertices on a straight line between their
// neighbours (within eps), which plane splits leave behind. Such points would
// otherwise become zero-area triangles downstream. The result may have fewer
// than three vertices when the loop was degenerate.
inline std::vector<model::Vec3> cleanConvexLoop(const std::vector<model::Vec3>& loop,
                                                double eps = model::kDistanceEpsilon)
{
    std::vector<model::Vec3> out;
    out.reserve(loop.size());
    for (const model::Vec3& p : loop)
        if (out.empty() || glm::length(p - out.back()) > eps)
            out.push_back(p);
    while (out.size() > 1 && glm::length(out.front() - out.back()) <= eps)
        out.pop_back();
    // Drop straight corners until none is left (each removal can expose another).
    bool removed = true;
    while (removed && out.size() >= 3) {
        removed = false;
        for (size_t i = 0; i < out.size() && out.size() >= 3; ++i) {
            const model::Vec3& a = out[(i + out.size() - 1) % out.size()];
            const model::Vec3& b = out[i];
            const model::Vec3& c = out[(i + 1) % out.size()];
            double base = glm::length(c - a);
            // Distance of b from the line a-c.
            double off = base > 0.0 ? glm::length(glm::cross(b - a, c - a)) / base : glm::length(b - a);
            if (off <= eps) {
                out.erase(out.begin() + std::ptrdiff_t(i));
                removed = true;
                --i;
            }
        }
    }
    if (out.size() < 3)
        out.clear();
    return out;
}

// Keeps the part of a convex polygon where dot(m, x - a) >= 0, exactly: no
// tolerance, so the parts kept on either side of a line meet on it.
inline std::vector<model::Vec3> clipConvex(const std::vector<model::Vec3>& polygon, const model::Vec3& a,
                                           const model::Vec3& m)
{
    std::vector<model::Vec3> out;
    const size_t n = polygon.size();
    for (size_t i = 0; i < n; ++i) {
        const model::Vec3& p = polygon[i];
        const model::Vec3& q = polygon[(i + 1) % n];
        const double dp = glm::dot(m, p - a);
        const double dq = glm::dot(m, q - a);
        if (dp >= 0.0)
            out.push_back(p);
        if ((dp >= 0.0) != (dq >= 0.0))
            out.push_back(p + (q - p) * (dp / (dp - dq)));
    }
    return out;
}

// Inside a convex polygon, counter-clockwise around `normal`, or on its
// outline within eps (a point in the polygon's plane).
inline bool insideConvex(const std::vector<model::Vec3>& polygon, const model::Vec3& normal, const model::Vec3& x,
                         double eps = model::kDistanceEpsilon)
{
    const size_t n = polygon.size();
    for (size_t k = 0; k < n; ++k) {
        const model::Vec3& a = polygon[k];
        const model::Vec3 edge = polygon[(k + 1) % n] - a;
        const double length = glm::length(edge);
        if (length > 0.0 && glm::dot(glm::cross(normal, edge), x - a) / length < -eps)
            return false;
    }
    return true;
}

// The stretch [t0, t1] of the segment origin + t direction, 0 <= t <= length
// (direction of unit length), that lies inside a convex polygon,
// counter-clockwise around `normal`; t1 <= t0 when none does. A segment
// running along an edge counts as inside.
inline std::pair<double, double> segmentInsideConvex(const std::vector<model::Vec3>& polygon, const model::Vec3& normal,
                                                     const model::Vec3& origin, const model::Vec3& direction,
                                                     double length)
{
    double t0 = 0.0, t1 = length;
    const size_t n = polygon.size();
    for (size_t i = 0; i < n && t0 < t1; ++i) {
        const model::Vec3& a = polygon[i];
        const model::Vec3 inward = glm::cross(normal, polygon[(i + 1) % n] - a);
        const double at = glm::dot(inward, origin - a), rate = glm::dot(inward, direction);
        if (std::abs(rate) < 1e-15) {
            if (at < 0.0)
                t1 = t0;
        } else if (rate > 0.0) {
            t0 = std::max(t0, -at / rate);
        } else {
            t1 = std::min(t1, -at / rate);
        }
    }
    return {t0, t1};
}

// The distance from a point to the segment ab.
inline double pointSegmentDistance(const model::Vec3& p, const model::Vec3& a, const model::Vec3& b)
{
    const model::Vec3 ab = b - a;
    const double length2 = glm::dot(ab, ab);
    const double t = length2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + ab * t));
}

} // namespace regio::solver
