#include "output/report.h"

#include "model/io/file_io.h"

namespace regio::output {

using solver::FaceResult;
using solver::Hemicube;
using solver::PreparedScene;
using solver::Region;
using solver::SolverStats;

nlohmann::json rgbJson(const Rgb& c) { return nlohmann::json::array({c.r, c.g, c.b}); }

nlohmann::json solveReport(const std::string& sceneName, const Solver& solver, std::optional<double> totalSeconds)
{
    using nlohmann::json;
    const SolverStats stats = solver.stats();
    const model::SolverSettings& settings = solver.settings();
    const PreparedScene& prepared = solver.prepared();

    json report;
    report["scene"] = sceneName;
    report["visibility"] = model::visibilityName(settings.visibility);
    report["regions"] = model::regionsModeName(settings.regions);
    report["hemicube"] = Hemicube(settings.hemicube).resolution();
    // The lights' shots render a finer one (solver/shooting/shooting.h).
    report["lightHemicube"] = solver.shooting().lightHemicubeResolution();
    report["patchSize"] = settings.patchSize;
    report["elementsPerPatch"] = settings.elementsPerPatch;
    report["maxIterations"] = settings.maxIterations;
    report["convergence"] = settings.convergence;
    report["iterations"] = stats.iterations;
    // Shots that rendered a hemicube (the others reused the kept form factors
    // of an earlier shot of the same patch) and the threads that rendered them.
    report["renderedShots"] = stats.renderedShots;
    report["threads"] = solver.shooting().threads();
    report["stop"] = stopReasonName(stats.stop);
    report["unshotRatio"] = stats.unshotRatio;
    report["patches"] = stats.patches;
    report["elements"] = stats.elements; // final count, after adaptive subdivision (§5.7)
    report["adaptive"] = {{"enabled", settings.adaptive.enabled},
                          {"threshold", settings.adaptive.threshold},
                          {"minEdge", settings.adaptive.minEdge},
                          {"anchoring", settings.adaptive.anchoring},
                          {"rounds", stats.adaptiveRounds},
                          {"contactElements", stats.contactElements},
                          {"penumbraElements", stats.penumbraElements}};
    // Element pieces painted per BSP node (solver/prepare/pieces.h) and any that found
    // no node (should be none).
    report["pieces"] = prepared.stats.pieces;
    report["lostPieces"] = prepared.stats.lostPieces;
    report["seconds"] = {
        {"preprocess", stats.preprocessSeconds},
        {"shoot", stats.shootSeconds},
        {"adaptive", stats.adaptiveSeconds},
        {"total", totalSeconds.value_or(stats.preprocessSeconds + stats.shootSeconds + stats.adaptiveSeconds)}};
    report["energy"] = {{"emitted", rgbJson(stats.energy.emitted)},
                        {"absorbed", rgbJson(stats.energy.absorbed)},
                        {"unshot", rgbJson(stats.energy.unshot)},
                        {"escaped", rgbJson(stats.energy.escaped)}};
    report["ambient"] = rgbJson(stats.ambient);

    json regions = json::array();
    for (const Region& r : prepared.regions)
        regions.push_back({{"id", r.id},
                           {"inputFaces", r.stats.inputFaces},
                           {"fragments", r.stats.fragments},
                           {"splits", r.stats.splits},
                           {"depth", r.stats.depth},
                           {"nodes", r.stats.nodes}});
    report["bsp"] = {{"regions", static_cast<int>(prepared.regions.size())},
                     {"inputFaces", prepared.stats.inputFaces},
                     {"regionPieces", prepared.stats.regionPieces},
                     {"fragments", prepared.stats.fragments},
                     {"splits", prepared.stats.splits},
                     {"maxDepth", prepared.stats.maxDepth},
                     {"perRegion", std::move(regions)}};

    json faces = json::array();
    for (const FaceResult& f : solver.faceResults())
        faces.push_back({{"id", f.id}, {"area", f.area}, {"radiosity", rgbJson(f.radiosity)}});
    report["faces"] = std::move(faces);
    return report;
}

model::Check writeReport(const std::string& path, const nlohmann::json& report)
{
    return model::writeFileAtomically(path, report.dump(2) + "\n");
}

} // namespace regio::output
