#pragma once
// Where a solid stands on a face (a block on the floor, a box on a box), the
// face and the solid's sides meet along its foot: a contact line. Right
// beside it the radiosity falls steeply on both faces (the corner sees
// itself, little of the light), and an element that touches it is coarse:
// on the Cornell box, with elements of a patch's size along the blocks'
// feet, the points within 2 cm of the line read 14.8 % off at the 99th
// percentile against 6.7 % over all points (docs/accuracy.md). The §5.7
// criterion splits them only where a neighbour differs, and the foot's
// elements have no neighbour across the line: what the line hides, the
// criterion cannot see.
//
// So these elements are split before the first shot, as a discontinuity
// mesh would place its first lines (Heckbert 1992): the elements of a face
// with a corner on the solid's side, and those of the side with a corner on
// the face. Only solids at least
// ShadowLineLimits::solidMinWidth patches wide count, as for the shadow
// lines of their feet: a table leg or a shelf board would only add slivers.
// The walls of a room meeting its floor are no contact line (the room is not
// a solid standing on anything): the corner's fall-off is gentle there.
#include "solver/shooting/adaptive_subdivision.h"

#include <vector>

namespace regio::solver {

// For every face of the scene, the faces that meet it along a contact line:
// for a face f that a solid's face g covers (solver/prepare/covered_parts.h),
// the other faces of g's part, and f for each of them; none for a face that
// solids cover whole (it has no mesh). Ascending.
std::vector<std::vector<int>> contactFaces(const PreparedScene& scene);

// The active elements of `mesh` with a corner on a contact face's polygon
// (in its plane and inside it, within model::kDistanceEpsilon): on the line
// where the two meet. `contacts` is contactFaces() of the scene the mesh
// grew from. Ascending.
std::vector<int> elementsOnContactLines(const AdaptiveMesh& mesh, const std::vector<std::vector<int>>& contacts);

// The active elements of `mesh` with a corner on an edge of one of their
// face's near outlines (solver/prepare/near_outlines.h: a lamp hanging 2 cm
// under the ceiling, whose outline the ceiling is cut along). The light that
// bounces in the gap falls off across the outline within a few gap widths,
// inside and out, as steeply as at a contact line, and the criterion sees
// it no better: the elements on both sides are split before the first shot
// too. `outlines` is nearOutlines() of the scene the mesh grew from.
// Ascending.
std::vector<int> elementsOnNearOutlines(const AdaptiveMesh& mesh,
                                        const std::vector<std::vector<std::vector<Vec3>>>& outlines);

} // namespace regio::solver
