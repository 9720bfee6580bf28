#pragma once
// Polygon geometry of the pointwise reference (pointwise_reference.h): clipping,
// Lambert's contour formula, in-plane frames, grids and stratified points,
// hashes for fixed jitter and a parallel loop. Nothing of the solver.
#include "model/types.h"

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <thread>
#include <vector>

namespace regio::test::reference {

using model::Rgb;
using model::Vec3;

inline constexpr double kPi = 3.14159265358979323846;
// Metres. Far below the size of any patch and far above double rounding at
// room scale: a point this close to a plane counts as on it.
inline constexpr double kPlaneTolerance = 1e-9;
// A point this far outside an occluder's edge still hits it, so that a ray
// through the shared edge of two faces of a solid cannot slip between them.
inline constexpr double kEdgeTolerance = 1e-9;

// SplitMix64 (Steele, Lea and Flood 2014): a good hash of an index, so that
// every sample's jitter is fixed by where it is, not by the order of work.
std::uint64_t mix64(std::uint64_t x);

// A hash mapped to [0, 1) (its top 53 bits).
double unitInterval(std::uint64_t hash);

// The largest channel.
double maxComponent(const Rgb& c);

// Sutherland-Hodgman against one half-space: keeps the part of the convex
// polygon `in` where dot(m, p) >= c.
void clipKeep(std::span<const Vec3> in, const Vec3& m, double c, std::vector<Vec3>& out);

// Lambert's contour formula over `polygon` clipped to the front of the
// tangent plane at x (see the header); `clipped` is scratch.
double contourFormFactor(const Vec3& x, const Vec3& n, std::span<const Vec3> polygon, std::vector<Vec3>& clipped);

// Whether p (on the polygon's plane) lies inside the convex polygon, counter-
// clockwise around n.
bool insideConvex(std::span<const Vec3> polygon, const Vec3& n, const Vec3& p);

// The mean of the corners.
Vec3 vertexMean(std::span<const Vec3> polygon);

// An in-plane frame: u along the longest edge (so that a rectangle's grid
// follows its sides), v = n x u.
void planeFrame(std::span<const Vec3> polygon, const Vec3& n, Vec3& u, Vec3& v);

// The polygon's extent along an axis.
void extent(std::span<const Vec3> polygon, const Vec3& axis, double& lo, double& hi);

// The convex polygon cut by a grid of nu x nv cells along u and v (its
// extent divided evenly); empty cells are left out. `cellIndex`, if given,
// receives i * nv + j of every cell kept.
std::vector<std::vector<Vec3>> splitGrid(std::span<const Vec3> polygon, const Vec3& u, const Vec3& v, int nu, int nv,
                                         std::vector<int>* cellIndex = nullptr);

// perSide x perSide points, one in each cell of a grid over the polygon's
// extent, those outside the polygon left out (uniform by area, and
// stratified); the centroid when none falls inside (a sliver). Without a
// seed the points are the cell centres: the midpoint rule, exact for form
// factors that change linearly across the polygon. With one, each point is
// jittered inside its cell, so that ray ends over many patches do not line up.
void stratifiedPoints(std::span<const Vec3> polygon, const Vec3& n, const Vec3& u, const Vec3& v, int perSide,
                      std::optional<std::uint64_t> seed, std::vector<Vec3>& out);

// Runs body(i, scratch) for i in [0, count) on `threads` threads, each with
// scratch of its own; indices are handed out one by one, so uneven work
// spreads evenly. Every result depends on i only.
template <class Scratch, class Body>
void parallelFor(std::size_t count, int threads, const Body& body)
{
    std::size_t workers =
        threads > 0 ? static_cast<std::size_t>(threads) : std::max<std::size_t>(1, std::thread::hardware_concurrency());
    workers = std::max<std::size_t>(1, std::min(workers, count));
    std::atomic<std::size_t> next{0};
    const auto work = [&] {
        Scratch scratch;
        for (std::size_t i = next.fetch_add(1); i < count; i = next.fetch_add(1))
            body(i, scratch);
    };
    std::vector<std::thread> pool;
    for (std::size_t t = 1; t < workers; ++t)
        pool.emplace_back(work);
    work();
    for (std::thread& t : pool)
        t.join();
}

} // namespace regio::test::reference
