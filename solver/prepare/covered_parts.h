#pragma once
// The parts of an input face that no solid covers.
//
// Where a solid stands on a face (a block on the floor, a box on a box), the
// face and the solid's face touch back to back, coplanar and facing
// opposite ways. No light reaches the covered part and none leaves it. Meshed
// with the rest, it makes elements that straddle the contact line: half lit,
// half dark, their value the average, and the smooth shading carries it to
// the contact line, while shooters whose centre lies under the solid waste
// their power on its inside. So the covered part is not meshed: the face's
// patches and elements cover its uncovered convex pieces only (§5.4 strips
// each one), and no element straddles a contact line.
#include "solver/prepare/prepared_scene.h"

#include <vector>

namespace regio::solver {

// For every input face, the faces of solids that lie on it back to back
// (coplanar, facing the other way) and whose bounds meet its own: the faces
// that may cover part of it, ascending.
std::vector<std::vector<size_t>> coversOfFaces(const PreparedScene& scene);

// For every input face of `scene` (faces and properties filled, parallel):
// the convex pieces of its polygon that the coplanar, opposite-facing faces
// of solids leave uncovered, counter-clockwise around the face's normal. A
// face nothing covers keeps its polygon as its one piece (bit-identical); a
// face covered whole has none. Where solids stand on a face, its pieces are
// also cut along their shadow lines (solver/prepare/shadow_lines.h), whose
// corners are added to `shadowCorners` when it is given.
std::vector<std::vector<std::vector<Vec3>>> uncoveredPieces(const PreparedScene& scene,
                                                            std::vector<Vec3>* shadowCorners = nullptr);

// The other side of it: for every input face, the convex pieces of its
// polygon that solids cover (none where nothing stands on it), disjoint,
// counter-clockwise around the face's normal. The solver never meshes them;
// a model export fills them in, so that a floor under a block is whole.
std::vector<std::vector<std::vector<Vec3>>> coveredPieces(const PreparedScene& scene);

} // namespace regio::solver
