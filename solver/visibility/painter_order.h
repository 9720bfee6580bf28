#pragma once
// Painter-order playback: the elements in the order the painter's hemicube
// paints them from a point (paper §5.6 and Appendix A), for the editor to
// replay step by step or as a colour ramp.
//
// The order comes from the same walk the solver's visibility calls
// (forEachNodeBackToFront in solver/visibility/traversal.h) with the same region culling
// (boxBehindPlane on the region's contents) and the same rule inside a node
// (forEachPaintRange in solver/visibility/visibility.h).
//
// The painter paints element PIECES (solver/prepare/pieces.h): an element cut by a
// separating or BSP plane is painted once per node holding a piece of it. A
// step is one element's consecutive pieces in one node, so an element cut by
// a plane appears in more than one step (in different nodes), each step naming
// the pieces it paints.
#include "solver/prepare/prepared_scene.h"

#include <vector>

namespace regio::solver {

struct PaintStep {
    int element = -1;
    int node = -1;
    int region = -1;
    bool receives = false; // faces the eye; otherwise painted as a blocker ("no receiver")
    int firstPiece = -1;   // the piece triangles painted: [firstPiece, firstPiece + pieceCount)
    int pieceCount = 0;
};

struct PainterOrder {
    std::vector<int> regions;       // regions walked, back to front
    std::vector<int> culledRegions; // regions skipped whole (behind the shooter plane), in walk order
    std::vector<int> nodes;         // BSP nodes, back to front
    std::vector<PaintStep> steps;   // element pieces, back to front: later ones paint over earlier ones
};

// From a point with no plane: nothing is culled (a point picked in the viewport).
PainterOrder painterOrder(const PreparedScene& scene, const Vec3& eye);
// From a shooter sitting on `shooterPlane` at `eye`: regions whose contents
// lie behind the plane are culled, as in the solver.
PainterOrder painterOrder(const PreparedScene& scene, const Vec3& eye, const Plane& shooterPlane);
// From a patch, exactly as the solver shoots it: the hemicube at the patch
// centroid on its face's plane.
PainterOrder painterOrderFromPatch(const PreparedScene& scene, int patch);

} // namespace regio::solver
