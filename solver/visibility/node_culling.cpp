#include "solver/visibility/node_culling.h"

#include "solver/visibility/hemicube_raster.h"
#include "solver/visibility/traversal.h"

namespace regio::solver {

std::vector<Box3> nodePieceBounds(const PreparedScene& scene)
{
    std::vector<Box3> bounds(scene.nodes.size());
    for (size_t n = 0; n < scene.nodes.size(); ++n) {
        const BspNode& node = scene.nodes[n];
        for (int i = node.firstPiece; i < node.firstPiece + node.pieceCount; ++i)
            for (int v : scene.pieces[static_cast<size_t>(i)].vertices)
                bounds[n].extend(scene.pieceVertices[static_cast<size_t>(v)]);
    }
    return bounds;
}

bool piecesBehindShooter(const Box3& box, const Plane& shooterPlane)
{
    // Half the near plane's distance leaves room for the rounding of the
    // rasteriser's own transform (about 1e-15 m at these distances).
    return !box.empty && boxBehindPlane(box, shooterPlane, 0.5 * kNearPlane);
}

} // namespace regio::solver
