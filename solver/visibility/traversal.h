#pragma once
// Back-to-front walk of the regional tree and the regional BSP trees from an
// eye point (paper Appendix A), the order the painter's hemicube paints in:
// later nodes overwrite earlier ones, so no depth is stored.
//
// Regional tree: the far side of each separating plane first, then the near
// side. Region BSP tree: the far side of the node plane, then the node's own
// elements, then the near side. Unlike Appendix A, a node whose plane faces
// away from the eye is NOT skipped: its elements still block light (surfaces
// are opaque from both sides; skipping them lets light through the inside of
// open or touching solids: the floor under the Cornell blocks read 22 % too
// bright); only the order of its subtrees flips. (What the painter may
// leave out, where that changes no pixel, it decides itself:
// node_culling.h, closed_back_faces.h.)
// Whether an element receives is the painter's business: `eyeInFront` tells
// it which of the node's two orientation groups faces the eye (BspNode's
// forward* counts).
//
// An eye exactly on a plane (within kDistanceEpsilon) may take either order:
// everything on that plane is seen edge-on and covers no hemicube pixel.
#include "solver/prepare/prepared_scene.h"

#include <vector>

namespace regio::solver {

// True if the whole box lies on or behind the plane: nothing in it can be
// seen from a hemicube sitting on that plane (regional culling, §5.6).
inline bool boxBehindPlane(const Box3& box, const Plane& plane, double eps = model::kDistanceEpsilon)
{
    if (box.empty)
        return true;
    // The box corner farthest along the normal decides.
    Vec3 corner{plane.normal.x >= 0 ? box.max.x : box.min.x, plane.normal.y >= 0 ? box.max.y : box.min.y,
                plane.normal.z >= 0 ? box.max.z : box.min.z};
    return plane.signedDistance(corner) <= eps;
}

namespace detail {

template <typename NodeVisitor>
void walkBsp(const std::vector<BspNode>& nodes, int index, const Vec3& eye, NodeVisitor& visitNode)
{
    // Recursion depth is the tree depth; region trees stay shallow because
    // regions keep them small (that is the point of the paper).
    while (index >= 0) {
        const BspNode& node = nodes[size_t(index)];
        const bool eyeInFront = node.plane.signedDistance(eye) > 0.0;
        const int farSide = eyeInFront ? node.back : node.front;
        const int nearSide = eyeInFront ? node.front : node.back;
        if (farSide >= 0)
            walkBsp(nodes, farSide, eye, visitNode);
        visitNode(index, eyeInFront);
        index = nearSide; // tail position: loop instead of recursing
    }
}

template <typename RegionPredicate, typename NodeVisitor>
void walkRegional(const PreparedScene& scene, int index, const Vec3& eye, RegionPredicate& acceptRegion,
                  NodeVisitor& visitNode)
{
    while (index >= 0) {
        const RegionalNode& node = scene.regionalNodes[size_t(index)];
        if (node.isLeaf()) {
            const Region& region = scene.regions[size_t(node.region)];
            if (region.bspRoot >= 0 && acceptRegion(node.region))
                walkBsp(scene.nodes, region.bspRoot, eye, visitNode);
            return;
        }
        const bool eyeInFront = eye[node.axis] > node.position;
        walkRegional(scene, eyeInFront ? node.back : node.front, eye, acceptRegion, visitNode);
        index = eyeInFront ? node.front : node.back;
    }
}

} // namespace detail

// Calls acceptRegion(int region) -> bool once per non-empty region in
// back-to-front order (false skips the region), and visitNode(int node,
// bool eyeInFront) for every BSP node of the accepted regions, back to front.
template <typename RegionPredicate, typename NodeVisitor>
void forEachNodeBackToFront(const PreparedScene& scene, const Vec3& eye, RegionPredicate&& acceptRegion,
                            NodeVisitor&& visitNode)
{
    detail::walkRegional(scene, scene.regionalRoot, eye, acceptRegion, visitNode);
}

// The same order as a list of node indices. With `cullPlane` (the shooter's
// plane), regions whose bounds lie entirely behind it are left out.
inline void backToFrontNodes(const PreparedScene& scene, const Vec3& eye, const Plane* cullPlane,
                             std::vector<int>& order)
{
    order.clear();
    forEachNodeBackToFront(
        scene, eye,
        [&](int region) { return !cullPlane || !boxBehindPlane(scene.regions[size_t(region)].bounds, *cullPlane); },
        [&](int node, bool) { order.push_back(node); });
}

} // namespace regio::solver
