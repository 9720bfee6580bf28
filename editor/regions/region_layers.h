#pragma once
// What region authoring draws in the viewport, as overlay layers
// (viewport_layers.h): translucent region boxes, the scene's faces coloured by
// the region that holds them, the separating planes of the solver's regional
// tree (paper §5.2, Figure 3) and the resize handles of a selected box. Pure
// functions of the scene, so tests check them without a window.
#include "editor/viewport/viewport_layers.h"
#include "model/geometry/geometry.h"
#include "model/scene.h"
#include "solver/prepare/regional_tree.h"

#include <glm/vec4.hpp>

#include <span>
#include <string>
#include <vector>

namespace regio::editor {

// Layer names, so other features can ask the viewport whether they are shown.
inline constexpr const char* kRegionBoxesLayer = "regions.boxes";
inline constexpr const char* kRegionColoursLayer = "regions.colours";
inline constexpr const char* kSeparatingPlanesLayer = "regions.planes";
inline constexpr const char* kRegionHandlesLayer = "regions.handles";
inline constexpr const char* kRegionDraftLayer = "regions.draft";
inline constexpr const char* kRegionProposalLayer = "regions.proposal";

// One colour per region index (well apart in hue), and the grey of faces
// outside every region.
glm::vec4 regionColour(int index, float alpha = 1.0f);
glm::vec4 outsideRegionsColour();

model::Box3 boxOf(const model::Region& region);
// Everything a region tool works in: the geometry and every region box.
model::Box3 sceneExtent(const model::Scene& scene);

// The region (index into scene.regions) holding the largest area of the
// polygon, or -1 when no box holds any (validation's rule, kMinFaceArea).
int regionHoldingPolygon(const model::Scene& scene, std::span<const model::Vec3> loop);

// Translucent boxes with outlines; the selected ones brighter.
ViewportLayer buildRegionBoxesLayer(const model::Scene& scene, const std::vector<std::string>& selected);
// Boxes of regions that are not (yet) in the scene: a proposal's, drawn
// dashed in their own colours on top of the scene.
ViewportLayer buildProposalLayer(const std::vector<model::Region>& regions);
// Every face with its region's colour (grey outside all), lit by a fixed
// light so shapes stay readable. Computed once per scene change; the layer is
// then rebuilt from it when the view moves (back faces are left out as the
// viewport leaves them out of its own surfaces).
struct ColouredFace {
    std::vector<model::Vec3> loop;
    model::Vec3 normal{0.0};
    glm::vec4 colour{1.0f};
};
std::vector<ColouredFace> colourFacesByRegion(const model::Scene& scene);
// Where the faces are seen from, for leaving out the back faces.
struct Viewer {
    model::Vec3 eye{0.0};
    model::Vec3 forward{0.0, 0.0, -1.0};
    bool orthographic = false;
};
// Replaces the scene's own surfaces; with a viewer, faces seen from behind are left out.
ViewportLayer buildPartsByRegionLayer(const std::vector<ColouredFace>& faces, const Viewer* viewer = nullptr);
ViewportLayer buildPartsByRegionLayer(const model::Scene& scene);

// An inner node of the regional tree as the solver builds it from the
// scene's region boxes: the plane coordinate[axis] = position and the cell
// it splits (the scene extent cut by the planes above it).
struct SeparatingPlane {
    int node = -1;
    int axis = 0;
    double position = 0.0;
    model::Box3 cell;
};
struct RegionalTreeView {
    solver::RegionalTree tree;
    std::vector<SeparatingPlane> planes; // in node order
    bool ok = false;                     // false: no regions, or they cannot be separated
};
// buildRegionalTree (§5.2) on the region boxes, exactly as prepareScene
// calls it, with the cells of its inner nodes.
RegionalTreeView regionalTreeOf(const model::Scene& scene);
// Each separating plane as a translucent quad across its cell, coloured by
// axis; the plane of `highlightedNode` (a tree node index) stands out.
ViewportLayer buildSeparatingPlanesLayer(const RegionalTreeView& view, int highlightedNode = -1);

// The six face handles of a box: index 2*axis (min side) or 2*axis+1 (max side).
model::Vec3 handlePosition(const model::Box3& box, int handle);
// Small squares facing the handle's axis, `size` metres wide; `active` brighter.
ViewportLayer buildHandlesLayer(const model::Box3& box, double size, int active);

} // namespace regio::editor
