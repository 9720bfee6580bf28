#pragma once
// Scene preparation, the first four steps of the pipeline (docs/architecture.md):
// regional tree (§5.2), face assignment to the region cells with clipping
// (Warnock variant, §3), regional BSP trees (§5.3), strip triangulation into
// patches (§5.4) and elements (§5.5). The result is read-only input for the
// shooting loop.
#include "model/diagnostic.h"
#include "model/scene.h"
#include "solver/prepare/prepared_scene.h"

#include <optional>

namespace regio::solver {

// Authored: the scene's regions (a scene without regions is one region);
// None: one region holding everything, one classic BSP tree (the baseline);
// Auto: axis-aligned boxes split by a patch-count threshold (§3, last paragraph).
// The same enum as the scene file's solver.regions setting.
using model::RegionsMode;

struct PrepareOptions {
    RegionsMode regions = RegionsMode::Authored;
    // Auto mode: a box is split while it holds more (estimated) patches than this.
    int autoRegionPatchThreshold = 256;
    // Empty = the scene's solver settings.
    std::optional<double> patchSize;
    std::optional<int> elementsPerPatch;
};

struct PrepareResult {
    std::optional<PreparedScene> scene; // empty when an error made preparation impossible
    model::Diagnostics diagnostics;     // errors (then no scene) and warnings
};

// Never throws on bad input: problems come back as diagnostics whose pointers
// index the scene file (regions that no axis-aligned plane separates, unknown
// materials, non-convex faces; zero-area faces are a warning and are skipped).
//
// BSP root order: in Authored mode each region uses its own bspOrder; in None
// and Auto modes the authored orders are concatenated (region order) and used
// as one priority list, so the author's sorting still helps. Unlisted faces
// follow in scene order.
PrepareResult prepareScene(const model::Scene& scene, const PrepareOptions& options = {});

} // namespace regio::solver
