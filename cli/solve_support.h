#pragma once
// What the one-scene solve (solve_command.cpp) and the batch (batch.cpp)
// share: report entries, the outputs of a solution, a warning.
#include "cli/solve_options.h"

#include "model/result.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace regio::cli {

struct SceneInput;

// "<stdin>" for "-", else the name as given.
std::string displayName(const std::string& name);

// The report entry of a scene that was not solved: its status ("invalid",
// "unreadable") and its error diagnostics.
nlohmann::json unsolvedEntry(const SceneInput& input, const model::Diagnostics& diagnostics, const char* status);

// Standard output ("-"), or a file written atomically: a half-written report
// never replaces a previous one. Prints the error and returns false.
bool writeReportTo(const std::string& path, const nlohmann::json& report);

// The lit model and the picture of each request (smooth vertex radiosity
// unless --flat, §6), from one lit mesh; the first error, naming its file.
model::Check writeSolutionOutputs(const SolveOptions& options, const std::vector<output::OutputRequest>& requests,
                                  const model::Scene& scene, const solver::Solver& s);

// --threshold, --min-edge and --anchoring tune a subdivision that a scene
// with adaptive.enabled = false (or --adaptive off) never does: the warning
// that says so, if any.
std::optional<std::string> idleAdaptiveOptionsWarning(const std::string& name, const SolveOptions& options,
                                                      const model::SolverSettings& settings);

} // namespace regio::cli
