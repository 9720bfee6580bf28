#pragma once
// BSP nodes whose pieces all lie behind the shooter's plane (§5.6: the
// regional culling, one level down). A region is culled whole when its
// contents lie behind the plane; inside the regions that remain, the nodes
// of faces below a shooter (the floor and the room's lower parts, seen from
// a lamp's top 2 cm under the ceiling) still hand every piece to the
// rasteriser, which transforms its corners only to find them behind the
// plane. A node whose pieces' bounding box lies behind it is left out of the
// paint order instead: every piece of it would have been dropped by the
// rasteriser's outcodes (below the base plane), so no pixel changes.
#include "solver/prepare/prepared_scene.h"

#include <vector>

namespace regio::solver {

// The bounding box of each node's own pieces (empty for a node with none).
std::vector<Box3> nodePieceBounds(const PreparedScene& scene);

// True when every point of `box` lies behind `shooterPlane` by more than
// rounding, so that the rasteriser would find each corner below its base
// plane (kNearPlane).
bool piecesBehindShooter(const Box3& box, const Plane& shooterPlane);

} // namespace regio::solver
