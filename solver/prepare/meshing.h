#pragma once
// Patches and elements (paper §5.4, §5.5): every input face of a prepared
// scene (its whole polygon, not its BSP fragments: see prepared_scene.h),
// less what solids standing on it cover (solver/prepare/covered_parts.h), is
// strip-triangulated into triangle patches, one conforming mesh per face
// (solver/prepare/conforming_strips.h), and every patch is split into
// elements by the element/patch ratio.
//
// The split is a k x k grid in barycentric coordinates: k^2 triangles, all
// similar to the patch (so no element is thinner than its patch). k = 1 keeps
// the patch as its only element and k = 2 is the classic midpoint subdivision
// into 4. elementsPerPatch values that are not squares take the nearest square
// (k = round(sqrt(n)): 2 -> 1, 3 -> 4, 5..6 -> 4, 7..12 -> 9, ...); the ratio is
// a mesh density, not an exact count, and similar triangles are worth more
// than hitting 3 or 5 exactly.
#include "solver/prepare/prepared_scene.h"

namespace regio::solver {

// k of the k x k split for an element/patch ratio (at least 1).
int elementGridDivisions(int elementsPerPatch);

// Fills scene.vertices, patches, elements, InputFace::firstPatch/patchCount
// and InputFace::elements from InputFace::polygon, with scene.patchSize and
// scene.elementsPerPatch. Vertices are shared between the patches and
// elements of one face (the mesh of a face is conforming). Element::node and
// Patch::node are set later, by buildPieces (solver/prepare/pieces.h).
void meshFaces(PreparedScene& scene);

} // namespace regio::solver
