#include "solver/authoring/bsp_figures.h"

#include <chrono>

namespace regio::solver {

namespace {

// A strip width far beyond any room: every fragment becomes one strip, i.e. a
// handful of triangles, and one element per patch. The BSP trees come before
// meshing and do not read these settings.
constexpr double kCoarsestPatchSize = 1.0e9;

} // namespace

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

PrepareOptions bspStageOptions(const BspFiguresOptions& options)
{
    PrepareOptions prepare;
    prepare.regions = options.regions;
    prepare.autoRegionPatchThreshold = options.autoRegionPatchThreshold;
    if (options.regions != RegionsMode::Auto)
        prepare.patchSize = kCoarsestPatchSize;
    prepare.elementsPerPatch = 1;
    return prepare;
}

BspFiguresResult computeBspFigures(const model::Scene& scene, const BspFiguresOptions& options)
{
    BspFiguresResult result;
    PrepareResult prepared = prepareScene(scene, bspStageOptions(options));
    result.diagnostics = std::move(prepared.diagnostics);
    if (prepared.scene)
        result.figures = bspFiguresOf(*prepared.scene, options.regions);
    return result;
}

BspComparison compareWithSingleBsp(const model::Scene& scene)
{
    const auto start = std::chrono::steady_clock::now();
    BspComparison out;
    BspFiguresResult authored = computeBspFigures(scene, {RegionsMode::Authored});
    out.authored = std::move(authored.figures);
    out.diagnostics = std::move(authored.diagnostics);
    out.baseline = computeBspFigures(scene, {RegionsMode::None}).figures;
    out.milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return out;
}

} // namespace regio::solver
