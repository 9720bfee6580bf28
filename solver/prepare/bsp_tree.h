#pragma once
// Regional BSP trees (paper §5.3), built by the classic algorithm (Foley et
// al.): the root of every (sub)tree is the polygon of highest priority still
// in the subset; everything coplanar with it (either orientation) joins its
// node; the rest goes to the front or back subtree, split when it spans the
// plane. No balancing heuristic: the author's BSP order is the heuristic.
#include "solver/prepare/face_polygon.h"
#include "solver/prepare/prepared_scene.h"

#include <span>
#include <vector>

namespace regio::solver {

// Builds the BSP tree of one region from its polygons, appending its nodes,
// fragments and fragment points to `scene` (nodes in pre-order, each node's
// fragments contiguous, those facing along the node plane first) and setting
// scene.regions[region].bspRoot, .stats and .bounds.
//
// `rank[face]` orders the root choice: lowest rank first (ties: the earlier
// polygon in the list). Node planes come from scene.properties, so every
// fragment of one face is tested against exactly the same plane.
void buildRegionBsp(PreparedScene& scene, int region, std::vector<FacePolygon> polygons, std::span<const int> rank,
                    double eps = model::kDistanceEpsilon);

} // namespace regio::solver
