#pragma once
// Small exact-enough geometry on planar polygons, shared by validation, the
// plane cut, the primitives and the solver's BSP splitting.
#include "model/types.h"

#include <span>
#include <vector>

namespace regio::model {

// Tolerances in metres. Scenes are authored in metres at room scale: 1e-6 m is
// far below any modelling precision and far above double rounding.
inline constexpr double kDistanceEpsilon = 1e-6;
inline constexpr double kAreaEpsilon = 1e-12;

struct Plane {
    Vec3 normal{0.0, 0.0, 1.0}; // unit length
    double d = 0.0;             // plane: dot(normal, p) + d = 0

    double signedDistance(const Vec3& p) const;
    static Plane fromPointNormal(const Vec3& point, const Vec3& normal);
};

struct Box3 {
    Vec3 min{0.0};
    Vec3 max{0.0};
    bool empty = true;

    void extend(const Vec3& p);
    void extend(const Box3& other);
    Vec3 center() const { return (min + max) * 0.5; }
    Vec3 size() const { return max - min; }
    // Interiors intersect (touching faces do not count).
    bool overlapsInterior(const Box3& other, double eps = kDistanceEpsilon) const;
    bool contains(const Vec3& p, double eps = kDistanceEpsilon) const;
};

enum class Side { Front, Back, On, Spanning };

// Newell's method: robust for any planar (and nearly planar) loop. Its length
// is twice the polygon's area.
Vec3 newellNormal(std::span<const Vec3> loop);
double polygonArea(std::span<const Vec3> loop);
Vec3 polygonCentroid(std::span<const Vec3> loop);
// Turns a loop of indices into `positions` so that it starts at its least
// corner (by x, then y, then z), keeping its order: where a loop has no
// given start (a face merged from triangles), the geometry chooses it.
void startAtLeastCorner(std::vector<int>& loop, std::span<const Vec3> positions);
// Unit normal; zero vector for a degenerate polygon.
Vec3 polygonNormal(std::span<const Vec3> loop);
Plane polygonPlane(std::span<const Vec3> loop);
// Largest distance of a vertex from the best-fit (Newell) plane.
double planarityDeviation(std::span<const Vec3> loop);
// True if every corner turns the same way around `normal` (collinear corners
// allowed), i.e. the loop is convex and counter-clockwise seen from `normal`.
bool isConvex(std::span<const Vec3> loop, const Vec3& normal, double eps = kDistanceEpsilon);
// Shortest edge length of the loop.
double shortestEdge(std::span<const Vec3> loop);

Side classifyPolygon(std::span<const Vec3> loop, const Plane& plane, double eps = kDistanceEpsilon);
// Splits a convex polygon by a plane (Sutherland-Hodgman on one plane). Either
// output may come back empty. Vertices within eps of the plane go to both sides.
void splitPolygon(std::span<const Vec3> loop, const Plane& plane, std::vector<Vec3>& front, std::vector<Vec3>& back,
                  double eps = kDistanceEpsilon);

// Gathers a face loop's positions from its part's vertices (indices assumed valid).
std::vector<Vec3> loopPositions(std::span<const Vec3> vertices, std::span<const int> loop);

} // namespace regio::model
