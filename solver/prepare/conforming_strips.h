#pragma once
// One conforming patch mesh for a face made of several convex pieces (the
// parts of a face that no solid covers, solver/prepare/covered_parts.h).
//
// Each piece is strip-triangulated on its own (§5.4), so two pieces that meet
// along a line divide it differently: a corner of one lies in the middle of
// an edge of the other (a T-vertex). Adaptive subdivision finds neighbours,
// anchors and grades through shared vertices (§5.7), and the smooth output
// averages over the elements around a vertex (§6), so a face's mesh must meet
// vertex to vertex. Here the corners of the pieces are welded, and every
// patch edge on a piece's outline takes the corners of the neighbouring
// pieces that lie on it: a triangle with such points on one edge is fanned
// from its opposite corner, one with points on several edges from its
// centroid. Every line between two pieces stays a line of patch edges: some
// are the shadow lines the pieces were cut along
// (solver/prepare/shadow_lines.h), where the radiosity bends.
#include "solver/prepare/strip_triangulation.h"

#include <vector>

namespace regio::solver {

// `pieces` are convex, counter-clockwise around the unit `normal`, without
// repeated or collinear corners, and do not overlap. The result covers them
// all and is conforming; a single piece gives exactly stripTriangulate's mesh.
StripMesh stripTriangulatePieces(const std::vector<std::vector<model::Vec3>>& pieces, const model::Vec3& normal,
                                 double patchSize);

} // namespace regio::solver
