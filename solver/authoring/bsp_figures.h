#pragma once
// BSP figures: what the author's regions and root orders cost (paper §3, §5.3:
// "BSP sorting can produce extremely large number of divided patches").
// Input faces, fragments, splits and tree depth, per region and for the scene,
// for the authored regions and for the single-BSP baseline.
//
// The numbers are never recomputed here: they are read from a PreparedScene
// built by the solver's own preparation (its stages up to the BSP trees), so
// the editor's figures are the solver's (and the `bsp` figures of
// `regio-solve solve --report`, which reads the same PrepareStats).
#include "model/diagnostic.h"
#include "model/result.h"
#include "model/scene.h"
#include "solver/prepare/prepare.h"
#include "solver/prepare/prepared_scene.h"

#include <optional>
#include <string>
#include <vector>

namespace regio::solver {

// The cost of one BSP tree (one region), or of all of them summed.
struct BspFigures {
    int inputFaces = 0; // polygons that entered the BSP build (face pieces after regional clipping)
    int fragments = 0;  // after BSP splitting
    int splits = 0;     // polygons cut in two by a BSP plane
    int depth = 0;      // nodes on the longest root-to-leaf path
    int nodes = 0;

    bool operator==(const BspFigures&) const = default;
};

BspFigures figuresOf(const RegionStats& stats);

struct RegionBspFigures {
    std::string id; // authored region id, "auto-<n>", or "scene" for the single tree
    Box3 box;
    BspFigures figures;
};

struct SceneBspFigures {
    RegionsMode mode = RegionsMode::Authored;
    int inputFaces = 0;   // faces of the scene with area (PrepareStats::inputFaces)
    int regionPieces = 0; // polygons after clipping at the separating planes
    int fragments = 0;    // all regions
    int splits = 0;       // all regions
    int maxDepth = 0;     // deepest region tree
    int nodes = 0;        // all regions
    std::vector<RegionBspFigures> regions;

    // Index into `regions` of the region with this id, or -1.
    int regionIndex(const std::string& id) const;
};

// Reads the figures of a prepared scene; `mode` is only recorded.
SceneBspFigures bspFiguresOf(const PreparedScene& prepared, RegionsMode mode);

struct BspFiguresOptions {
    RegionsMode regions = RegionsMode::Authored;
    int autoRegionPatchThreshold = kAutoRegionPatchThreshold;
};

// Prepares the scene up to its BSP trees (prepareBsp: no mesh, which the
// figures do not depend on) and reads its figures. Auto mode estimates its
// boxes' patches with the scene's patch size.
model::Result<SceneBspFigures> computeBspFigures(const model::Scene& scene, const BspFiguresOptions& options = {});

// The author's regions beside the single-BSP baseline (RegionsMode::None),
// what the BSP order editor shows after each change.
struct BspComparison {
    std::optional<SceneBspFigures> authored;
    std::optional<SceneBspFigures> baseline;
    model::Diagnostics diagnostics; // of the authored preparation (the baseline cannot fail where it succeeds)
    double milliseconds = 0.0;      // wall time of both preparations
};
BspComparison compareWithSingleBsp(const model::Scene& scene);

} // namespace regio::solver
