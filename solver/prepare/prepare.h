#pragma once
// Scene preparation, the first steps of the pipeline (docs/architecture.md),
// in stages that the authoring tools (solver/authoring/) call too instead of
// copying them:
//
//   collectFaces      the input faces: properties, polygons on their planes
//   layOutRegions     the region boxes and the regional tree (§5.2)
//   prepareBspInput   both, and the face polygons clipped into the regions'
//                     cells (the Warnock variant, §3)
//   buildBsps         a BSP tree per region (§5.3)
//   prepareBsp        all of the above: everything but the mesh
//   prepareScene      and the strip triangulation into patches (§5.4) and
//                     elements (§5.5), cut into the pieces the painter paints
//
// The result is read-only input for the shooting loop.
#include "model/result.h"
#include "model/scene.h"
#include "solver/prepare/auto_regions.h"
#include "solver/prepare/face_polygon.h"
#include "solver/prepare/prepared_scene.h"
#include "solver/prepare/regional_tree.h"

#include <optional>
#include <string>
#include <vector>

namespace regio::solver {

// Authored: the scene's regions (a scene without regions is one region);
// None: one region holding everything, one classic BSP tree (the baseline);
// Auto: axis-aligned boxes split by a patch-count threshold (§3, last paragraph).
// The same enum as the scene file's solver.regions setting.
using model::RegionsMode;

struct PrepareOptions {
    RegionsMode regions = RegionsMode::Authored;
    // Auto mode: a box is split while it holds more (estimated) patches than this.
    int autoRegionPatchThreshold = kAutoRegionPatchThreshold;
    // Overrides of the scene's settings (solver/settings.h); empty = the scene's.
    std::optional<double> patchSize;
    std::optional<int> elementsPerPatch;
};

// The preparation a solve with these (resolved) settings runs: its regions
// mode, patch size and element/patch ratio.
PrepareOptions prepareOptionsFor(const model::SolverSettings& settings,
                                 int autoRegionPatchThreshold = kAutoRegionPatchThreshold);

// --- Stage 1: the input faces ------------------------------------------------

struct FaceSet {
    std::vector<InputFace> faces;       // every face of the file, scene order
    std::vector<Properties> properties; // same index as faces
    // The faces with area, projected onto their planes (so everything
    // downstream is exactly planar) and cleaned of repeated and straight-line
    // vertices; FacePolygon::face indexes `faces`.
    std::vector<FacePolygon> polygons;
    Box3 bounds; // of the polygons
};

// Refused (errors): a face without a known material, a non-convex face.
// Warned: a face without area, which is kept with area 0 and no polygon.
model::Result<FaceSet> collectFaces(const model::Scene& scene);

// --- Stage 2: the regions ------------------------------------------------------

struct RegionLayout {
    std::vector<Region> regions;                  // id and box (the rest comes with the BSP trees)
    std::vector<std::vector<std::string>> orders; // per region: the face ids ranked first as BSP roots
    RegionalTree tree;                            // §5.2
};

// The boxes of `mode` (authored, none: one box around everything, auto: see
// auto_regions.h, estimated with `patchSize`) and the regional tree over
// them. Refused when authored boxes overlap or interlock.
//
// BSP root order: in Authored mode each region uses its own bspOrder; in None
// and Auto modes the authored orders are concatenated (region order) and used
// as one priority list, so the author's sorting still helps.
model::Result<RegionLayout> layOutRegions(const model::Scene& scene, const FaceSet& faces, RegionsMode mode,
                                          double patchSize, int autoRegionPatchThreshold = kAutoRegionPatchThreshold);

// --- Stages 1 to 3: what the BSP build takes -----------------------------------

struct BspInput {
    FaceSet faces;
    RegionLayout layout;
    // Per region: the face polygons in its cell, clipped at the separating
    // planes (assignToCells).
    std::vector<std::vector<FacePolygon>> cells;
    double patchSize = 0.0; // the settings the scene is to be meshed with
    int elementsPerPatch = 0;
};

model::Result<BspInput> prepareBspInput(const model::Scene& scene, const PrepareOptions& options = {});

// --- Stage 4: the BSP trees ----------------------------------------------------

// One BSP tree per region (buildRegionBsp): the faces of the region's order
// first, in that order, then the unlisted ones in scene order. The result has
// faces, properties, regions, regional tree, nodes and fragments; no mesh.
PreparedScene buildBsps(BspInput input);

// Stages 1 to 4.
model::Result<PreparedScene> prepareBsp(const model::Scene& scene, const PrepareOptions& options = {});

// --- Everything ------------------------------------------------------------------

// Stages 1 to 4, the mesh (§5.4, §5.5, solver/prepare/meshing.h) and the
// pieces (solver/prepare/pieces.h). Never throws on bad input: problems come
// back as diagnostics whose pointers index the scene file; warnings (a face
// without area is skipped) come with the prepared scene.
model::Result<PreparedScene> prepareScene(const model::Scene& scene, const PrepareOptions& options = {});

} // namespace regio::solver
