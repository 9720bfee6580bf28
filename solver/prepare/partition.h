#pragma once
// The partition rule of preparation, written once. Every walk that takes a
// face polygon across a plane decides the same way: the regional clipping
// (regional_tree.cpp, §5.2), automatic regions (auto_regions.cpp, §3), the
// BSP build (bsp_tree.cpp, §5.3), the suggested-order simulation
// (authoring/bsp_suggest.cpp) and the element pieces (pieces.cpp). So the
// pieces of an element go exactly where its face went, and a suggested order
// builds exactly the tree that was predicted.
#include "solver/prepare/face_polygon.h"
#include "solver/prepare/prepared_scene.h"

#include <span>
#include <vector>

namespace regio::solver {

// The sliver rule: a side of a split polygon is kept only if something of
// area is left once repeated and straight-line vertices are removed (a split
// within eps of a vertex leaves a sliver of no area). Cleans `loop` in place.
bool keepSplitSide(std::vector<Vec3>& loop, double eps = model::kDistanceEpsilon);

// The kept sides of a polygon split by a plane (empty = dropped as a sliver).
struct PlaneSplit {
    std::vector<Vec3> front;
    std::vector<Vec3> back;
};

// Splits `loop`, which spans `plane`, and applies the sliver rule to each side.
PlaneSplit splitAcross(const std::vector<Vec3>& loop, const Plane& plane, double eps = model::kDistanceEpsilon);

// Where a polygon goes at a separating plane (axis-aligned, §5.2): Front or
// Back, or Spanning, and then `split` holds its kept sides. A polygon lying on
// the plane goes to the side its normal faces (a wall belongs to the room it
// bounds), so this never answers On.
model::Side routeAtSeparatingPlane(const std::vector<Vec3>& loop, int axis, double position, PlaneSplit& split);

// Pushes polygons across a separating plane, clipping those that span it.
void partitionAtSeparatingPlane(std::vector<FacePolygon> polygons, int axis, double position,
                                std::vector<FacePolygon>& back, std::vector<FacePolygon>& front);

// The root of a BSP (sub)tree: the polygon of lowest rank (rank[face]); ties
// go to the earlier polygon.
size_t lowestRank(const std::vector<FacePolygon>& polygons, std::span<const int> rank);

// A subset of polygons partitioned by its root (§5.3): everything coplanar
// with the root's plane (either orientation) stays at the node, the rest goes
// front or back, split (with the sliver rule) where it spans the plane.
struct BspPartition {
    std::vector<FacePolygon> on; // in subset order, the root among them
    std::vector<FacePolygon> front;
    std::vector<FacePolygon> back;
    int splits = 0; // polygons that spanned the plane
};
BspPartition partitionAtRoot(std::vector<FacePolygon> polygons, size_t root, const Plane& plane,
                             double eps = model::kDistanceEpsilon);

} // namespace regio::solver
