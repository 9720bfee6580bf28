#pragma once
// When a render may leave out the back faces of closed parts.
//
// A ray from the eye that reaches a closed surface from its material side (a
// back face) has crossed that surface before, from its empty side, through
// a face that faces the eye; that face is nearer, so the painter paints it
// later (§5.6, Appendix A) and the z-buffer keeps it. So from an eye on the
// empty side of every closed part (outside each solid, inside each room
// built as one closed shell facing inwards) the closed parts' back faces
// are painted only to be painted over, and a render may skip them: about a
// fifth of the pieces of a furnished room, the far sides of its furniture.
// They are still needed from an eye on the material side of a closed part:
// inside a solid, on the face of one that stands on the shooter's face (a
// wall patch whose centre lies behind a shelf that touches the wall: there
// the whole shelf shows its back and blocks the view), or outside a room's
// shell.
//
// Which side: the generalised winding number of the part's surface at a
// point a hair in front of the eye along the shooter's normal (so that a
// shooter on a part's own face, or on a room's wall, counts as outside that
// solid and inside that room), 1 inside a closed surface whose normals point
// out and -1 inside one whose normals point in, 0 outside either.
#include "solver/prepare/prepared_scene.h"

#include <array>
#include <vector>

namespace regio::solver {

// A part whose faces close a volume (Properties::solid), as triangles wound
// counter-clockwise seen from their front.
struct ClosedPart {
    Box3 bounds;
    bool inward = false; // normals point into the volume (a room seen from inside)
    std::vector<std::array<Vec3, 3>> triangles;
};

std::vector<ClosedPart> closedParts(const PreparedScene& scene);

// Sum of the signed solid angles of `part`'s triangles seen from `point`,
// over 4 pi: 1 or -1 inside (see the top of the file), 0 outside.
double windingNumber(const ClosedPart& part, const Vec3& point);

// True when every closed part's back faces are hidden from a shooter at
// `eye` with unit normal `normal` (see the top of the file).
bool closedBackFacesHidden(const std::vector<ClosedPart>& parts, const Vec3& eye, const Vec3& normal);

} // namespace regio::solver
