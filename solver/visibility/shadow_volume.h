#pragma once
// What a face standing just in front of the eye hides (§5.6: the painter
// paints every piece in front of the shooter; this leaves out those that
// cannot win a pixel). A ceiling patch over a lamp hung 2 cm below it sees
// the room only through the slit between the two: from its points the
// lamp's top covers all of the lower hemisphere but a band a few degrees
// high at the horizon, and the floor, the furniture and most of the walls
// lie behind it. The painter would paint all of those and then the lamp's
// top over them.
//
// The shadow volume of a convex polygon seen from the eye is the set of
// points whose ray from the eye passes through the polygon's interior before
// it reaches them. A piece inside it cannot win a pixel: the ray through a
// pixel centre that meets the piece meets the polygon first, and the
// polygon's pieces, nearer to the eye, are painted after it (back to front)
// or win the depth test; where a solid rests on the polygon and it is not
// meshed, the solid's faces towards the eye stand in front of it. Points
// count as inside only with margins far wider than the rasteriser's
// snapping and the pieces' own rounding (through the polygon 1e-5 m inside
// its edges and 1e-5 radians from them, 1e-6 m behind its plane), so a
// pixel centre that a hidden piece would cover lies well inside the
// polygon's own pixels.
#include "model/geometry/geometry.h"

#include <span>
#include <vector>

namespace regio::solver {

using model::Box3;
using model::Plane;
using model::Vec3;

// A face standing in front of the eye, which may hide much of the scene:
// its convex polygon and the unit normal of its front. Empty: none.
struct Occluder {
    std::span<const Vec3> polygon;
    Vec3 front{0.0};
};

class ShadowVolume {
public:
    // Hides nothing.
    ShadowVolume() = default;
    // The shadow volume of the occluder's convex polygon (either winding),
    // whose front faces along its unit normal `front`, from `eye`, when the
    // eye lies in front of it by more than 1e-6 m (so that the painter
    // paints it as a receiver, never as a back face it may leave out) and
    // every corner of it lies in front of the shooter's plane by as much;
    // otherwise, or for fewer than three corners, it hides nothing.
    ShadowVolume(const Vec3& eye, const Occluder& occluder, const Plane& shooterPlane);

    bool empty() const { return m_edges.empty(); }
    // True when the point lies inside the volume, margins included.
    bool hides(const Vec3& p) const;
    // True when every point of the box does (a convex volume: its corners).
    bool hides(const Box3& box) const;

private:
    Vec3 m_eye{0.0};
    Plane m_plane;             // the occluder's, its normal towards the eye
    std::vector<Vec3> m_edges; // unit normals of the planes through the eye and each edge, inward
};

} // namespace regio::solver
