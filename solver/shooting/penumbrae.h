#pragma once
// Where a solid standing on a face casts its penumbra from a light: the band
// between the shadow that every point of the light makes (the umbra) and the
// shadow that any point makes. For a convex solid and a convex light the
// shadows from the light's vertices bound both: the umbra is their
// intersection, the penumbra's outer edge their convex hull (beside an
// upright edge of the solid the band reaches into a wedge between two
// vertices' shadows that neither covers; elementsInPenumbra, below, takes
// only what reaches into a vertex's shadow and so leaves the wedge out,
// which changes nothing measurable: docs/accuracy.md). Across
// the band the direct light rises from nothing to full within centimetres
// and bends at both edges; a straight line between two vertices an element
// apart cuts across the bend and carries light into the umbra, or shade into
// the light. On the Cornell box, with elements of a third of a patch, that
// leaves 15 points on the floor and the blocks more than 5 % brighter than
// the reference (docs/accuracy.md); the §5.7 criterion only sees it once the
// light has been shot onto the coarse mesh, and then splits on values that
// already averaged the bend in.
//
// So the elements in the band are split before the first shot, as the
// contact lines' are (solver/shooting/contact_lines.h), and as a
// discontinuity mesh would place them (Heckbert 1992; Lischinski, Tampieri
// and Greenberg 1992) without tracing its lines: the shadows are convex
// polygons here, and an element is in the band when some of its corners or
// its centroid lie inside the shadow of one light vertex and some outside
// that of another.
//
// Only the solids that draw shadow lines count (at least
// ShadowLineLimits::solidMinWidth patches wide), only lights that face the
// solid and lie wholly above its top (else the shadow is unbounded), and per
// solid only the lights that send it at least `PenumbraLimits::dimmestShare`
// of what its brightest light sends: a dim light's bend is a small share of
// the light there.
#include "model/geometry/geometry.h"
#include "solver/prepare/prepared_scene.h"
#include "solver/shooting/adaptive_subdivision.h"

#include <vector>

namespace regio::solver {

struct PenumbraLimits {
    // A solid's lights that send its footprint's centre less than this share
    // of the direct light its brightest light sends draw no band.
    double dimmestShare = 0.25;
};

// The shadows one solid casts on one face from one light, one per light
// vertex: the convex hull of the solid's footprint and the solid's vertices
// projected from that light vertex onto the face's plane, counter-clockwise
// around the face's normal.
struct Penumbra {
    int face = -1;
    double weight = 0.0; // the direct light its light sends to the footprint's centre (to rank them)
    std::vector<std::vector<Vec3>> shadows;
    model::Box3 bounds; // of the shadows
};

// Every solid's penumbrae on the faces it stands on, brightest first.
std::vector<Penumbra> penumbrae(const PreparedScene& scene, const PenumbraLimits& limits = PenumbraLimits{});

// The active elements of the penumbra's face that reach into the band (see
// the top of the file). Ascending.
std::vector<int> elementsInPenumbra(const AdaptiveMesh& mesh, const Penumbra& penumbra);

} // namespace regio::solver
