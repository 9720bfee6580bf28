#pragma once
// Where a face hangs just in front of another (a lamp's top 2 cm under a
// ceiling), the other face is cut along its outline. Inside the outline the
// two faces light each other across the gap: the ceiling over a lamp takes
// the lamp's emission and then the light that bounces between the two until
// it is absorbed; a few centimetres outside, only what leaks through the
// slit. The radiosity falls across the outline nearly as steeply as at a
// contact line, and an element that straddles it holds a mean of both
// sides, which the smooth output spreads over the element's width: a ring
// of cells 10-20 cm wide, too bright outside the outline and too dark
// inside, on the furnished room's ceiling around each lamp (docs/accuracy.md).
// With the outline among the pieces' edges (solver/prepare/covered_parts.h)
// the elements lie on one side or the other, as a discontinuity mesh would
// place them (Heckbert 1992; Lischinski, Tampieri and Greenberg 1992), and
// the refinement splits those along it before the first shot
// (solver/shooting/adaptive_refinement.h): the cut alone left 25 cm
// elements on either side, and the ring as it was. Over a panel that does
// not glow the gap is dark, and the light falls across the outline from
// outside: the same cut and split (left whole, the ceiling showed a dark
// ring 15 cm wide around each of the two-light room's panels, 12-25 % too
// dark). With the cut, a ceiling patch lies over the panel or beside it,
// and only those over it shoot from several points
// (solver/shooting/shooter_points.h).
#include "solver/prepare/prepared_scene.h"

#include <vector>

namespace regio::solver {

// The largest gap, in patch sizes, across which a face cuts the face it
// hangs in front of. Farther away the fall-off across the outline is as
// wide as the gap, and the elements resolve it.
inline constexpr double kNearOutlineGapPatches = 0.1;

// For every face, the outlines of the faces that hang in front of it within
// kNearOutlineGapPatches patch sizes, parallel to it within 5 degrees and
// facing it, dropped onto its plane, where they cross it. A face narrower
// than ShadowLineLimits::solidMinWidth patches draws none (a board's edge would only cut slivers, as a narrow solid
// draws no shadow lines), and a face with more than eight faces in front of
// it takes none at all: the lines run across the whole face and would cut
// it into slivers.
std::vector<std::vector<std::vector<Vec3>>> nearOutlines(const PreparedScene& scene);

// Cuts `pieces` (the convex pieces of every face, as meshFaces meshes them)
// along the edges of the face's nearOutlines where they cross a piece, with
// the limits of the shadow lines (ShadowLineLimits: no sliver, no sharp
// corner).
void cutAlongNearOutlines(const PreparedScene& scene, std::vector<std::vector<std::vector<Vec3>>>& pieces);

// The point, in the plane the outlines were dropped onto, lies on one of
// their edges (within model::kDistanceEpsilon).
bool liesOnOutline(const std::vector<std::vector<Vec3>>& outlines, const Vec3& point);

} // namespace regio::solver
