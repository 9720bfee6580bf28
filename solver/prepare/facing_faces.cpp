#include "solver/prepare/facing_faces.h"

#include "model/geometry/geometry.h"
#include "solver/prepare/face_polygon.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace regio::solver {

namespace {

// Closest points of two segments (Ericson, Real-Time Collision Detection §5.1.9).
double segmentDistance(const Vec3& p1, const Vec3& q1, const Vec3& p2, const Vec3& q2)
{
    const Vec3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
    const double a = glm::dot(d1, d1), e = glm::dot(d2, d2), f = glm::dot(d2, r);
    if (a <= 0.0 || e <= 0.0)
        return a <= 0.0 ? pointSegmentDistance(p1, p2, q2) : pointSegmentDistance(p2, p1, q1);
    const double b = glm::dot(d1, d2), c = glm::dot(d1, r);
    const double denominator = a * e - b * b;
    double s = denominator > 0.0 ? std::clamp((b * f - c * e) / denominator, 0.0, 1.0) : 0.0;
    double t = (b * s + f) / e;
    if (t < 0.0) {
        t = 0.0;
        s = std::clamp(-c / a, 0.0, 1.0);
    } else if (t > 1.0) {
        t = 1.0;
        s = std::clamp((b - c) / a, 0.0, 1.0);
    }
    return glm::length((p1 + d1 * s) - (p2 + d2 * t));
}

// Distance from a point to a convex polygon: to its plane where the point
// projects inside it, else to its nearest edge.
double pointPolygonDistance(const Vec3& p, std::span<const Vec3> polygon, const Vec3& normal)
{
    const size_t n = polygon.size();
    bool inside = true;
    double sign = 0.0;
    for (size_t i = 0; i < n && inside; ++i) {
        const double side = glm::dot(glm::cross(polygon[(i + 1) % n] - polygon[i], p - polygon[i]), normal);
        if (side != 0.0) {
            if (sign == 0.0)
                sign = side;
            else if ((side > 0.0) != (sign > 0.0))
                inside = false;
        }
    }
    if (inside)
        return std::abs(glm::dot(p - polygon[0], normal));
    double best = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < n; ++i)
        best = std::min(best, pointSegmentDistance(p, polygon[i], polygon[(i + 1) % n]));
    return best;
}

} // namespace

double polygonGap(std::span<const Vec3> a, std::span<const Vec3> b)
{
    const Vec3 na = model::polygonNormal(a), nb = model::polygonNormal(b);
    double gap = std::numeric_limits<double>::infinity();
    for (const Vec3& p : a)
        gap = std::min(gap, pointPolygonDistance(p, b, nb));
    for (const Vec3& p : b)
        gap = std::min(gap, pointPolygonDistance(p, a, na));
    // Edges that cross with no corner near the other polygon (two boards
    // laid crosswise, one above the other).
    for (size_t i = 0; i < a.size(); ++i)
        for (size_t j = 0; j < b.size(); ++j)
            gap = std::min(gap, segmentDistance(a[i], a[(i + 1) % a.size()], b[j], b[(j + 1) % b.size()]));
    return gap;
}

std::vector<std::vector<int>> closeFacingFaces(const PreparedScene& scene, double largestGap)
{
    const size_t count = scene.faces.size();
    std::vector<std::vector<int>> close(count);
    if (largestGap <= 0.0)
        return close;
    // Normals within 60 degrees of opposite.
    constexpr double kFacingCosine = -0.5;
    // A gap below this share of the largest is a contact, not a gap.
    constexpr double kContactShare = 0.01;

    std::vector<model::Box3> boxes(count); // grown by the largest gap
    std::vector<Vec3> centroids(count);
    std::vector<size_t> order;
    for (size_t f = 0; f < count; ++f) {
        const std::vector<Vec3>& polygon = scene.faces[f].polygon;
        if (polygon.size() < 3 || scene.faces[f].area <= 0.0)
            continue;
        for (const Vec3& p : polygon) {
            boxes[f].extend(p - Vec3(largestGap));
            boxes[f].extend(p + Vec3(largestGap));
        }
        centroids[f] = model::polygonCentroid(polygon);
        order.push_back(f);
    }
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return boxes[a].min.x < boxes[b].min.x; });

    const auto inFront = [&](size_t of, size_t plane) {
        return scene.properties[plane].plane.signedDistance(centroids[of]) > 0.0;
    };
    for (size_t i = 0; i < order.size(); ++i) {
        const size_t f = order[i];
        for (size_t j = i + 1; j < order.size() && boxes[order[j]].min.x <= boxes[f].max.x; ++j) {
            const size_t g = order[j];
            if (!boxes[f].overlapsInterior(boxes[g], 0.0))
                continue;
            if (glm::dot(scene.properties[f].plane.normal, scene.properties[g].plane.normal) > kFacingCosine)
                continue;
            if (!inFront(f, g) || !inFront(g, f))
                continue;
            const double gap = polygonGap(scene.faces[f].polygon, scene.faces[g].polygon);
            if (gap > kContactShare * largestGap && gap < largestGap) {
                close[f].push_back(int(g));
                close[g].push_back(int(f));
            }
        }
    }
    for (std::vector<int>& faces : close)
        std::sort(faces.begin(), faces.end());
    return close;
}

} // namespace regio::solver
