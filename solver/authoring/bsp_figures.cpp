#include "solver/authoring/bsp_figures.h"

#include <chrono>

namespace regio::solver {

BspFigures figuresOf(const RegionStats& stats)
{
    return {stats.inputFaces, stats.fragments, stats.splits, stats.depth, stats.nodes};
}

int SceneBspFigures::regionIndex(const std::string& id) const
{
    for (size_t i = 0; i < regions.size(); ++i)
        if (regions[i].id == id)
            return int(i);
    return -1;
}

SceneBspFigures bspFiguresOf(const PreparedScene& prepared, RegionsMode mode)
{
    SceneBspFigures out;
    out.mode = mode;
    out.inputFaces = prepared.stats.inputFaces;
    out.regionPieces = prepared.stats.regionPieces;
    out.fragments = prepared.stats.fragments;
    out.splits = prepared.stats.splits;
    out.maxDepth = prepared.stats.maxDepth;
    for (const Region& region : prepared.regions) {
        out.regions.push_back({region.id, region.box, figuresOf(region.stats)});
        out.nodes += region.stats.nodes;
    }
    return out;
}

model::Result<SceneBspFigures> computeBspFigures(const model::Scene& scene, const BspFiguresOptions& options)
{
    PrepareOptions prepare;
    prepare.regions = options.regions;
    prepare.autoRegionPatchThreshold = options.autoRegionPatchThreshold;
    model::Result<PreparedScene> prepared = prepareBsp(scene, prepare);
    if (!prepared)
        return model::Result<SceneBspFigures>::failureOf(prepared);
    model::Diagnostics warnings = prepared.takeDiagnostics();
    return {bspFiguresOf(*prepared, options.regions), std::move(warnings)};
}

BspComparison compareWithSingleBsp(const model::Scene& scene)
{
    const auto start = std::chrono::steady_clock::now();
    BspComparison out;
    model::Result<SceneBspFigures> authored = computeBspFigures(scene, {RegionsMode::Authored});
    out.diagnostics = authored.takeDiagnostics();
    if (authored)
        out.authored = std::move(*authored);
    if (model::Result<SceneBspFigures> baseline = computeBspFigures(scene, {RegionsMode::None}))
        out.baseline = std::move(*baseline);
    out.milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return out;
}

} // namespace regio::solver
