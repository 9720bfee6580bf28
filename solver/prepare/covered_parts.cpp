#include "solver/prepare/covered_parts.h"

#include "solver/prepare/face_polygon.h"

#include <glm/geometric.hpp>

#include <array>
#include <cmath>
#include <map>

namespace regio::solver {

namespace {

using Polygon = std::vector<Vec3>;

// Areas below this (m^2) are rounding: slivers along a contact line.
constexpr double kNegligibleArea = model::kDistanceEpsilon * model::kDistanceEpsilon;

// Keeps the part of a convex polygon where dot(m, x - a) >= 0.
Polygon clipKeep(const Polygon& polygon, const Vec3& a, const Vec3& m)
{
    Polygon out;
    const size_t n = polygon.size();
    for (size_t i = 0; i < n; ++i) {
        const Vec3& p = polygon[i];
        const Vec3& q = polygon[(i + 1) % n];
        const double dp = glm::dot(m, p - a);
        const double dq = glm::dot(m, q - a);
        if (dp >= 0.0)
            out.push_back(p);
        if ((dp >= 0.0) != (dq >= 0.0))
            out.push_back(p + (q - p) * (dp / (dp - dq)));
    }
    return out;
}

double polygonArea(const Polygon& polygon, const Vec3& normal)
{
    Vec3 sum(0.0);
    for (size_t i = 0; i < polygon.size(); ++i)
        sum += glm::cross(polygon[i], polygon[(i + 1) % polygon.size()]);
    return 0.5 * std::abs(glm::dot(sum, normal));
}

// polygon - cover, as convex pieces: outside each edge of the cover in turn,
// the rest going on to the next edge; what is inside every edge is covered.
// Pieces thinner than the distance tolerance are dropped.
void subtract(const Polygon& polygon, const Polygon& cover, const Vec3& coverNormal, const Vec3& normal,
              std::vector<Polygon>& out)
{
    Polygon rest = polygon;
    const size_t n = cover.size();
    for (size_t k = 0; k < n && rest.size() >= 3; ++k) {
        const Vec3& a = cover[k];
        const Vec3 inward = glm::normalize(glm::cross(coverNormal, cover[(k + 1) % n] - a));
        Polygon outside = cleanConvexLoop(clipKeep(rest, a, -inward));
        if (outside.size() >= 3 && polygonArea(outside, normal) > kNegligibleArea)
            out.push_back(std::move(outside));
        rest = clipKeep(rest, a, inward);
    }
}

// Bounding boxes apart by more than the tolerance: nothing in common.
bool boxesApart(const Polygon& a, const Polygon& b)
{
    for (int axis = 0; axis < 3; ++axis) {
        double a0 = a[0][axis], a1 = a0, b0 = b[0][axis], b1 = b0;
        for (const Vec3& p : a) {
            a0 = std::min(a0, p[axis]);
            a1 = std::max(a1, p[axis]);
        }
        for (const Vec3& p : b) {
            b0 = std::min(b0, p[axis]);
            b1 = std::max(b1, p[axis]);
        }
        if (a1 < b0 - model::kDistanceEpsilon || b1 < a0 - model::kDistanceEpsilon)
            return true;
    }
    return false;
}

// The area of polygon and cover in common.
double commonArea(const Polygon& polygon, const Polygon& cover, const Vec3& coverNormal, const Vec3& normal)
{
    Polygon common = polygon;
    const size_t n = cover.size();
    for (size_t k = 0; k < n && common.size() >= 3; ++k) {
        const Vec3& a = cover[k];
        common = clipKeep(common, a, glm::normalize(glm::cross(coverNormal, cover[(k + 1) % n] - a)));
    }
    return common.size() >= 3 ? polygonArea(common, normal) : 0.0;
}

// A plane and its opposite share a key: the normal and offset rounded, then
// turned so that the first non-zero component of the normal is positive
// (rounding first, so that a normal a rounding away from an axis cannot turn
// one copy and not the other).
using PlaneKey = std::array<long long, 4>;
PlaneKey keyOf(const Plane& plane, bool& flipped)
{
    PlaneKey key{std::llround(plane.normal.x * 1e6), std::llround(plane.normal.y * 1e6),
                 std::llround(plane.normal.z * 1e6), std::llround(plane.d * 1e6)};
    flipped = key[0] < 0 || (key[0] == 0 && (key[1] < 0 || (key[1] == 0 && key[2] < 0)));
    if (flipped)
        for (long long& k : key)
            k = -k;
    return key;
}

} // namespace

std::vector<std::vector<std::vector<Vec3>>> uncoveredPieces(const PreparedScene& scene)
{
    const size_t count = scene.faces.size();
    std::vector<std::vector<Polygon>> pieces(count);
    // Faces by plane, each side apart: solids' faces are the covers.
    std::map<PlaneKey, std::array<std::vector<size_t>, 2>> byPlane;
    std::vector<PlaneKey> keys(count);
    std::vector<char> flippedOf(count, 0);
    for (size_t f = 0; f < count; ++f) {
        bool flipped = false;
        keys[f] = keyOf(scene.properties[f].plane, flipped);
        flippedOf[f] = flipped;
        if (scene.faces[f].polygon.size() >= 3)
            byPlane[keys[f]][flipped ? 1 : 0].push_back(f);
    }
    for (size_t f = 0; f < count; ++f) {
        const Polygon& polygon = scene.faces[f].polygon;
        if (polygon.size() < 3)
            continue;
        pieces[f].push_back(polygon);
        const auto it = byPlane.find(keys[f]);
        if (it == byPlane.end())
            continue;
        const Vec3& normal = scene.properties[f].plane.normal;
        for (size_t g : it->second[flippedOf[f] ? 0 : 1]) {
            const Polygon& cover = scene.faces[g].polygon;
            const Vec3& coverNormal = scene.properties[g].plane.normal;
            if (!scene.properties[g].solid || boxesApart(polygon, cover))
                continue;
            std::vector<Polygon> next;
            for (Polygon& piece : pieces[f]) {
                // Pieces it does not cover stay as they are, to the bit.
                if (commonArea(piece, cover, coverNormal, normal) <= kNegligibleArea)
                    next.push_back(std::move(piece));
                else
                    subtract(piece, cover, coverNormal, normal, next);
            }
            pieces[f] = std::move(next);
        }
    }
    return pieces;
}

} // namespace regio::solver
