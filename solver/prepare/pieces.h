#pragma once
// Element pieces: how the elements of a face-wide mesh (solver/prepare/meshing.h) are
// painted by the BSP order (§5.6, Appendix A).
//
// The painter needs every polygon it paints to lie in one BSP node's cell, on
// that node's plane. Elements are meshed over the whole input face, so an
// element may cross a separating plane (§5.2) or a BSP plane that split its
// face (§5.3). Each element is therefore pushed down the regional tree and
// its region's BSP tree exactly the way its face was: the face's polygon goes
// along and takes, at every node, the same decision the builders took for it
// (same classification, same epsilon, same sliver rule), and the element is
// cut only where the face was cut. It stops at the node whose plane holds its
// face. The convex pieces are fan-triangulated into Piece triangles.
//
// Crack-free cuts: a cut point is computed from the edge ordered by vertex
// index (lower index first) and shared through a map keyed by (edge, plane).
// The two pieces on both sides of a cut, and the neighbouring element sharing
// the cut edge, get the very same vertex, so the hemicube rasteriser's
// consistent pixel-centre rule leaves no gap and counts no pixel twice.
//
// Faces that meet along a line (a wall on the floor, a block's side on the
// outline the floor's mesh leaves around it) divide that line at their own
// points. Every piece edge also takes the outline corners of other faces'
// meshes lying on it, so the two sides meet vertex to vertex there too and
// no pixel falls between them into what lies behind (the covered part under
// a block is not meshed: nothing would stop it there).
//
// Following the face's decisions means no piece can end in an empty subtree;
// were it to happen anyway (a piece whose face was lost to rounding), it is
// counted in PrepareStats::lostPieces / lostPieceArea, never dropped silently.
#include "solver/prepare/prepared_scene.h"

#include <span>
#include <vector>

namespace regio::solver {

// (Re)builds scene.pieceVertices, scene.pieces, the piece ranges of the
// nodes, Element::node, Patch::node and the piece statistics, from the
// elements, the input face polygons and the trees. Called by prepareScene and
// again after adaptive subdivision changed the elements.
//
// `elementLoops`, when given, holds per element either nothing (paint its
// triangle) or its boundary loop: its corners and, in order between them, the
// vertices of finer neighbours lying on its edges (the T-vertices adaptive
// subdivision leaves, §5.7). Such an element is painted around its centroid
// through those vertices, so the rasteriser meets its neighbours vertex to
// vertex and no pixel falls through the crack a T-junction would open.
void buildPieces(PreparedScene& scene, std::span<const std::vector<int>> elementLoops = {});

} // namespace regio::solver
