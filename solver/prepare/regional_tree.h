#pragma once
// The regional tree (paper §5.2): axis-aligned planes that separate the region
// boxes, found on sorted "limit lists" of the boxes' projections per axis, and
// the assignment of face polygons to the cells of that tree (a polygon that
// crosses a separating plane is clipped into pieces, the Warnock variant, §3).
#include "solver/prepare/face_polygon.h"
#include "solver/prepare/prepared_scene.h"

#include <span>
#include <vector>

namespace regio::solver {

struct RegionalTree {
    std::vector<RegionalNode> nodes;
    int root = -1; // -1 when there are no boxes
};

struct RegionalTreeBuild {
    RegionalTree tree;
    // When not empty, the boxes of these regions (indices) overlap or interlock
    // so that no axis-aligned plane splits them into two non-empty groups; the
    // tree is then unusable.
    std::vector<int> inseparable;
    bool ok() const { return inseparable.empty(); }
};

// Boxes are indexed by region; boxes may touch (within eps) but not overlap.
// At every level the most balanced split over the three axes is taken (ties:
// the wider gap, then the lower axis), so the tree stays shallow.
RegionalTreeBuild buildRegionalTree(std::span<const Box3> boxes, double eps = model::kDistanceEpsilon);

// Pushes every polygon down the tree into the leaf cells, clipping at the
// separating planes. A polygon lying on a separating plane goes to the side
// its normal faces (a wall belongs to the room it bounds). Returns one list
// per region (`regionCount` lists); pieces keep their face index.
std::vector<std::vector<FacePolygon>> assignToCells(const RegionalTree& tree, std::vector<FacePolygon> polygons,
                                                    int regionCount);

// The plane coordinate[axis] = position with its normal along +axis, so that
// "front" is the side of the greater coordinate, as in RegionalNode.
Plane separatingPlane(int axis, double position);

} // namespace regio::solver
