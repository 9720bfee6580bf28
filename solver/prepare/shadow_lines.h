#pragma once
// Where the shadows of a solid standing on a face begin: the lines of the
// discontinuity mesh (Heckbert 1992; Lischinski, Tampieri and Greenberg
// 1992) that run from the solid's foot corners.
//
// A block on a floor casts the shadow of each of its edges that rises from
// the floor. Seen from a floor point beside such a corner, a light vertex
// disappears behind the edge exactly where the point crosses the plane
// through the edge and that vertex (an edge-vertex event): on the floor, a
// line through the corner. Between the lines of the light's extreme
// vertices lies the edge's penumbra; on one side of it the umbra, on the
// other full light. The radiosity bends sharply across these lines and is
// darkest right at the corner, so an element that straddles one averages
// light into the umbra, and the smooth output carries a lit vertex into it
// (+200 % on the Cornell box's floor in front of a block's corner).
//
// Here the line of every light vertex is found at every foot corner (lines
// within 2 degrees of one another counted once), from the corner as far as
// the edge's own shadow from that vertex reaches; the pieces of the face are
// cut along them (solver/prepare/covered_parts.h), so elements lie on either
// side, and the corner itself is listed in PreparedScene::shadowCorners,
// where the smooth output gives every element its own value. Lines farther
// out (the shadows of the solid's top edges) are not drawn.
#include "solver/prepare/prepared_scene.h"

#include <span>
#include <utility>
#include <vector>

namespace regio::solver {

// How far the lines go (covered_parts.cpp applies them). Widths are shares
// of the scene's patch size.
struct ShadowLineLimits {
    // A solid narrower than this (a table leg, a shelf board) draws no lines:
    // its umbra at the foot is narrower than the elements there, and the
    // lines would only cut the face into slivers.
    double solidMinWidth = 0.25;
    // No cut leaves a piece narrower than this on one side, or a corner
    // sharper than cutMinAngle (degrees).
    double cutMinWidth = 0.1;
    double cutMinAngle = 15.0;
    // At most this many lines a face, those of the brightest lights.
    size_t maxLines = 32;
};

// A segment on a face's plane, from a foot corner along a shadow boundary.
struct ShadowLine {
    Vec3 origin;    // the solid's corner on the face
    Vec3 direction; // unit, in the face's plane, away from the light
    double length = 0.0;
    double weight = 0.0; // how much direct light its light sends to the corner (to rank lines)
};

// The shadow lines on face `face` of the solids whose faces `covers` stand on
// it (coplanar, back to back: solver/prepare/covered_parts.h), for the faces
// `lights` (lightFaces). Solids whose footprint is narrower than
// `minWidth` (twice its area over its perimeter) draw none. Past `maxLines`,
// the lines of the lights that send the most direct light to their corner
// are kept.
// Twice the area over the perimeter: the width of a square or a long strip
// (what solidMinWidth is compared with).
double footprintWidth(const std::vector<Vec3>& polygon);

// The faces of the part that face `face` belongs to, [first, last): a run in
// scene order that starts faceInPart places before it.
std::pair<size_t, size_t> facesOfPart(const PreparedScene& scene, size_t face);

// How much direct light the light face `light` sends to a point x with
// normal n, as if nothing stood between: luminance of the emission x the
// light's area x the two cosines over pi d^2 from its centroid. Only to rank
// lights at a point.
double directLight(const PreparedScene& scene, size_t light, const Vec3& x, const Vec3& n);

// The faces of the scene that emit (with a polygon): the lights.
std::vector<size_t> lightFaces(const PreparedScene& scene);

std::vector<ShadowLine> footShadowLines(const PreparedScene& scene, size_t face, std::span<const size_t> covers,
                                        std::span<const size_t> lights, double minWidth, size_t maxLines);

// Cuts the convex pieces along the line wherever its segment passes through a
// piece's inside (the cut runs across that whole piece, which keeps pieces
// convex). A cut that would leave a piece thinner than `minWidth` (metres)
// on one side, or a corner sharper than `minAngle` (degrees), is not made:
// the patches of such a piece would be slivers.
void cutAlong(std::vector<std::vector<Vec3>>& pieces, const ShadowLine& line, const Vec3& normal, double minWidth,
              double minAngle);

} // namespace regio::solver
