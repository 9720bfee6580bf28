#include "solver/visibility/painter_order.h"

#include "solver/visibility/closed_back_faces.h"
#include "solver/visibility/hemicube_raster.h"
#include "solver/visibility/node_culling.h"
#include "solver/visibility/traversal.h"
#include "solver/visibility/visibility.h"

namespace regio::solver {

namespace {

PainterOrder walk(const PreparedScene& scene, const Vec3& eye, const Plane* shooterPlane)
{
    PainterOrder out;
    // As the solver paints: from a shooter on the empty side of every closed
    // part, without their back faces (closed_back_faces.h); from a point with
    // no plane, all.
    const bool solidBacks = !shooterPlane || !closedBackFacesHidden(closedParts(scene), eye, shooterPlane->normal);
    // And without the nodes whose pieces all lie behind the shooter
    // (node_culling.h); they stay in `nodes`, the walk's order.
    const std::vector<Box3> nodeBounds = shooterPlane ? nodePieceBounds(scene) : std::vector<Box3>{};
    forEachNodeBackToFront(
        scene, eye,
        [&](int region) {
            if (shooterPlane && boxBehindPlane(scene.regions[size_t(region)].bounds, *shooterPlane)) {
                out.culledRegions.push_back(region);
                return false;
            }
            out.regions.push_back(region);
            return true;
        },
        [&](int nodeIndex, bool eyeInFront) {
            out.nodes.push_back(nodeIndex);
            if (shooterPlane && piecesBehindShooter(nodeBounds[size_t(nodeIndex)], *shooterPlane))
                return;
            const BspNode& node = scene.nodes[size_t(nodeIndex)];
            forEachPaintRange(node, eyeInFront, solidBacks, [&](int begin, int end, bool receives) {
                for (int i = begin; i < end; ++i) {
                    const int element = scene.pieces[size_t(i)].element;
                    PaintStep* last = out.steps.empty() ? nullptr : &out.steps.back();
                    if (last && last->element == element && last->node == nodeIndex && last->receives == receives &&
                        last->firstPiece + last->pieceCount == i)
                        ++last->pieceCount;
                    else
                        out.steps.push_back({element, nodeIndex, node.region, receives, i, 1});
                }
            });
        });
    return out;
}

} // namespace

PainterOrder painterOrder(const PreparedScene& scene, const Vec3& eye) { return walk(scene, eye, nullptr); }

PainterOrder painterOrder(const PreparedScene& scene, const Vec3& eye, const Plane& shooterPlane)
{
    return walk(scene, eye, &shooterPlane);
}

PainterOrder painterOrderFromPatch(const PreparedScene& scene, int patch)
{
    const ShooterFrame frame = shooterFrameOfPatch(scene, patch);
    return painterOrder(scene, frame.origin, Plane::fromPointNormal(frame.origin, frame.n));
}

} // namespace regio::solver
