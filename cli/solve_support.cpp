// What the one-scene solve and the batch share (solve_support.h).
#include "cli/solve_support.h"

#include "cli/scene_input.h"

#include "model/io/printable.h"
#include "output/exact_direct.h"
#include "output/report.h"
#include "output/vertex_radiosity.h"

#include <iostream>

namespace regio::cli {

std::string displayName(const std::string& name) { return name == "-" ? "<stdin>" : name; }

nlohmann::json unsolvedEntry(const SceneInput& input, const model::Diagnostics& diagnostics, const char* status)
{
    nlohmann::json entry;
    entry["scene"] = input.name;
    entry["status"] = status;
    nlohmann::json errors = nlohmann::json::array();
    for (const model::Diagnostic& d : diagnostics)
        if (d.isError())
            errors.push_back(formatDiagnostic(displayName(input.name), d));
    entry["errors"] = std::move(errors);
    return entry;
}

// Standard output ("-"), or a file written atomically: a half-written report
// never replaces a previous one.
bool writeReportTo(const std::string& path, const nlohmann::json& report)
{
    if (path == "-") {
        std::cout << report.dump(2) << "\n" << std::flush;
        return true;
    }
    if (model::Check written = output::writeReport(path, report); !written) {
        std::cerr << "regio-solve solve: " << model::printable(written.error().message) << "\n";
        return false;
    }
    return true;
}

// The lit model and the picture: smooth vertex radiosity (§6)
// unless --flat; display values only ever touch the copies written out.
model::Check writeSolutionOutputs(const SolveOptions& options, const std::vector<output::OutputRequest>& requests,
                                  const model::Scene& scene, const solver::Solver& s)
{
    if (requests.empty())
        return model::success();
    const solver::SolutionSnapshot snapshot = s.snapshot();
    const output::LitMesh mesh =
        output::litMeshForOutput(s.prepared(), snapshot.radiosity, !options.flat,
                                 output::directShare(s.prepared(), s.shooting().unshotRadiosity()));
    for (output::OutputRequest request : requests) {
        request.camera = scene.camera;
        if (request.includeAmbient)
            request.display.toneMap.ambient = glm::vec3(snapshot.stats.ambient);
        if (model::Check written = output::writeOutputs(mesh, request); !written)
            return written;
    }
    return model::success();
}

// --threshold, --min-edge and --anchoring tune a subdivision that a scene
// with adaptive.enabled = false (or --adaptive off) never does: say so
// rather than let the user believe they had an effect.
std::optional<std::string> idleAdaptiveOptionsWarning(const std::string& name, const SolveOptions& options,
                                                      const model::SolverSettings& settings)
{
    if (settings.adaptive.enabled)
        return std::nullopt;
    std::string given;
    int count = 0;
    for (const auto& [set, option] : {std::pair{options.solver.adaptiveThreshold.has_value(), "--threshold"},
                                      std::pair{options.solver.adaptiveMinEdge.has_value(), "--min-edge"},
                                      std::pair{options.solver.adaptiveAnchoring.has_value(), "--anchoring"}})
        if (set) {
            given += (given.empty() ? "" : ", ") + std::string(option);
            ++count;
        }
    if (count == 0)
        return std::nullopt;
    return name + ": warning: " + given + (count == 1 ? " has" : " have") + " no effect: adaptive subdivision is off" +
           (options.solver.adaptive ? "" : " in the scene (--adaptive on turns it on)");
}

} // namespace regio::cli
