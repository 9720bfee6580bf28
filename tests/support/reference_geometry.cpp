#include "support/reference_geometry.h"

#include "model/geometry/geometry.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace regio::test::reference {

// SplitMix64 (Steele, Lea and Flood 2014): a good hash of an index, so that
// every sample's jitter is fixed by where it is, not by the order of work.
std::uint64_t mix64(std::uint64_t x)
{
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
}

double unitInterval(std::uint64_t hash) { return static_cast<double>(hash >> 11) * 0x1.0p-53; }

double maxComponent(const Rgb& c) { return std::max(c.x, std::max(c.y, c.z)); }

// Sutherland-Hodgman against one half-space: keeps the part of the convex
// polygon `in` where dot(m, p) >= c.
void clipKeep(std::span<const Vec3> in, const Vec3& m, double c, std::vector<Vec3>& out)
{
    out.clear();
    const std::size_t count = in.size();
    for (std::size_t k = 0; k < count; ++k) {
        const Vec3& p = in[k];
        const Vec3& q = in[(k + 1) % count];
        const double dp = glm::dot(m, p) - c;
        const double dq = glm::dot(m, q) - c;
        if (dp >= 0.0)
            out.push_back(p);
        if ((dp > 0.0 && dq < 0.0) || (dp < 0.0 && dq > 0.0))
            out.push_back(p + (q - p) * (dp / (dp - dq)));
    }
}

// Lambert's contour formula over `polygon` clipped to the front of the
// tangent plane at x (see the header); `clipped` is scratch.
double contourFormFactor(const Vec3& x, const Vec3& n, std::span<const Vec3> polygon, std::vector<Vec3>& clipped)
{
    clipKeep(polygon, n, glm::dot(n, x), clipped);
    const std::size_t count = clipped.size();
    if (count < 3)
        return 0.0;
    double sum = 0.0;
    for (std::size_t k = 0; k < count; ++k) {
        const Vec3 a = clipped[k] - x;
        const Vec3 b = clipped[(k + 1) % count] - x;
        const Vec3 c = glm::cross(a, b);
        const double length = glm::length(c);
        // An edge in line with the point (or through it) subtends no area.
        if (length <= 1e-14 * glm::length(a) * glm::length(b) || length == 0.0)
            continue;
        const double gamma = std::atan2(length, glm::dot(a, b));
        sum += gamma * glm::dot(n, c) / length;
    }
    // The sign only says which way round the corners run.
    return std::abs(sum) / (2.0 * kPi);
}

bool insideConvex(std::span<const Vec3> polygon, const Vec3& n, const Vec3& p)
{
    const std::size_t count = polygon.size();
    for (std::size_t k = 0; k < count; ++k) {
        const Vec3& a = polygon[k];
        const Vec3& b = polygon[(k + 1) % count];
        if (glm::dot(glm::cross(n, b - a), p - a) < 0.0)
            return false;
    }
    return true;
}

Vec3 vertexMean(std::span<const Vec3> polygon)
{
    Vec3 sum(0.0);
    for (const Vec3& p : polygon)
        sum += p;
    return sum / static_cast<double>(polygon.size());
}

// An in-plane frame: u along the longest edge (so that a rectangle's grid
// follows its sides), v = n x u.
void planeFrame(std::span<const Vec3> polygon, const Vec3& n, Vec3& u, Vec3& v)
{
    Vec3 longest(0.0);
    for (std::size_t k = 0; k < polygon.size(); ++k) {
        const Vec3 e = polygon[(k + 1) % polygon.size()] - polygon[k];
        if (glm::dot(e, e) > glm::dot(longest, longest))
            longest = e;
    }
    u = glm::normalize(longest - n * glm::dot(n, longest));
    v = glm::cross(n, u);
}

void extent(std::span<const Vec3> polygon, const Vec3& axis, double& lo, double& hi)
{
    lo = hi = glm::dot(axis, polygon[0]);
    for (const Vec3& p : polygon) {
        lo = std::min(lo, glm::dot(axis, p));
        hi = std::max(hi, glm::dot(axis, p));
    }
}

// The convex polygon cut by a grid of nu x nv cells along u and v (its
// extent divided evenly); empty cells are left out. `cellIndex`, if given,
// receives i * nv + j of every cell kept.
std::vector<std::vector<Vec3>> splitGrid(std::span<const Vec3> polygon, const Vec3& u, const Vec3& v, int nu, int nv,
                                         std::vector<int>* cellIndex)
{
    double s0 = 0.0, s1 = 0.0, t0 = 0.0, t1 = 0.0;
    extent(polygon, u, s0, s1);
    extent(polygon, v, t0, t1);
    const double ds = (s1 - s0) / nu, dt = (t1 - t0) / nv;
    std::vector<std::vector<Vec3>> cells;
    std::vector<Vec3> column, a, b;
    for (int i = 0; i < nu; ++i) {
        // The outermost cuts are left out: rounding must not shave the polygon.
        a.assign(polygon.begin(), polygon.end());
        if (i > 0) {
            clipKeep(a, u, s0 + ds * i, b);
            a.swap(b);
        }
        if (i + 1 < nu) {
            clipKeep(a, -u, -(s0 + ds * (i + 1)), b);
            a.swap(b);
        }
        column = a;
        for (int j = 0; j < nv; ++j) {
            a = column;
            if (j > 0) {
                clipKeep(a, v, t0 + dt * j, b);
                a.swap(b);
            }
            if (j + 1 < nv) {
                clipKeep(a, -v, -(t0 + dt * (j + 1)), b);
                a.swap(b);
            }
            if (a.size() >= 3 && model::polygonArea(a) > 1e-9 * ds * dt) {
                cells.push_back(a);
                if (cellIndex != nullptr)
                    cellIndex->push_back(i * nv + j);
            }
        }
    }
    return cells;
}

// perSide x perSide points, one in each cell of a grid over the polygon's
// extent, those outside the polygon left out (uniform by area, and
// stratified); the centroid when none falls inside (a sliver). Without a
// seed the points are the cell centres: the midpoint rule, exact for form
// factors that change linearly across the polygon. With one, each point is
// jittered inside its cell, so that ray ends over many patches do not line up.
void stratifiedPoints(std::span<const Vec3> polygon, const Vec3& n, const Vec3& u, const Vec3& v, int perSide,
                      std::optional<std::uint64_t> seed, std::vector<Vec3>& out)
{
    out.clear();
    double s0 = 0.0, s1 = 0.0, t0 = 0.0, t1 = 0.0;
    extent(polygon, u, s0, s1);
    extent(polygon, v, t0, t1);
    const double ds = (s1 - s0) / perSide, dt = (t1 - t0) / perSide;
    // The point's height above the plane, so the points lie on it.
    const double height = glm::dot(n, polygon[0]);
    for (int i = 0; i < perSide; ++i) {
        for (int j = 0; j < perSide; ++j) {
            double js = 0.5, jt = 0.5;
            if (seed) {
                // Within the middle 80 % of the cell: never on a cell line, where
                // a shadow edge aligned with the grid would make it a coin toss.
                const std::uint64_t h = mix64(*seed ^ mix64(static_cast<std::uint64_t>(i * perSide + j)));
                js = 0.1 + 0.8 * unitInterval(h);
                jt = 0.1 + 0.8 * unitInterval(mix64(h));
            }
            const double s = s0 + ds * (i + js);
            const double t = t0 + dt * (j + jt);
            const Vec3 p = u * s + v * t + n * height;
            if (insideConvex(polygon, n, p))
                out.push_back(p);
        }
    }
    if (out.empty())
        out.push_back(model::polygonCentroid(polygon));
}

} // namespace regio::test::reference
