#pragma once
// Viewport layers of the BSP views (viewport_layers.h): a region's fragments
// with the edges the regional tree and the BSP splits made (§5.2, §5.3), a BSP
// node's plane clipped to its region box, and the painter-order playback
// (§5.6, Appendix A) as a colour ramp over the element triangles.
#include "editor/viewport/viewport_layers.h"
#include "model/scene.h"
#include "solver/prepare/prepared_scene.h"
#include "solver/visibility/painter_order.h"

#include <glm/vec4.hpp>

namespace regio::editor {

// What made a fragment edge.
enum class FragmentEdgeKind { Boundary, RegionCut, BspSplit };

// `scene` must be the scene `prepared` was built from: a fragment edge is a
// boundary edge when it lies on its input face's outline, a region cut when
// it lies on a separating plane of the regional tree, else a BSP split.
FragmentEdgeKind classifyFragmentEdge(const model::Scene& scene, const solver::PreparedScene& prepared, int fragment,
                                      const model::Vec3& a, const model::Vec3& b);

struct FragmentEdgeCounts {
    int boundary = 0, regionCuts = 0, bspSplits = 0;
};

// Outlines of every fragment of `region` (-1: all regions); split edges
// orange, region cuts cyan, face outlines grey. Drawn over the surfaces.
ViewportLayer buildFragmentLayer(const model::Scene& scene, const solver::PreparedScene& prepared, int region,
                                 FragmentEdgeCounts* counts = nullptr);

// The node's plane as a translucent polygon clipped to its region's box, and
// the node's own fragments outlined.
ViewportLayer buildNodePlaneLayer(const solver::PreparedScene& prepared, int node);

// The plane of `plane` clipped to `box` (empty when they do not meet); CCW
// seen from the plane normal.
std::vector<model::Vec3> planeInBox(const model::Plane& plane, const model::Box3& box);

// The colour of paint step `index` of `count`: a blue-green-red ramp for
// receivers, a grey ramp for blockers (elements seen from behind).
glm::vec4 paintStepColour(int index, int count, bool receives);

// The elements of the first `steps` paint steps, each in its ramp colour,
// hiding the scene's surfaces; the element of the last step drawn is
// outlined and the eye marked in a second, undepth-tested layer.
ViewportLayer buildPainterLayer(const solver::PreparedScene& prepared, const solver::PainterOrder& order, int steps);
ViewportLayer buildPainterMarkerLayer(const solver::PreparedScene& prepared, const solver::PainterOrder& order,
                                      int steps, const model::Vec3& eye);

} // namespace regio::editor
