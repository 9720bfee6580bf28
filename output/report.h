#pragma once
// The JSON report of a solve (`regio-solve solve --report`): what was solved
// with which settings, how long it took, where the energy went (watts per
// channel: W/m^2 x m^2), what the scene preparation made of the regions, and
// the area-weighted mean radiosity of every input face, keyed by its file id.
#include "model/result.h"
#include "solver/solver.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace regio::output {

using model::Rgb;
using solver::Solver;

// One scene's report. `totalSeconds` is the caller's wall time from reading
// the file to the end of the solve; empty = preprocess + shoot.
nlohmann::json solveReport(const std::string& sceneName, const Solver& solver,
                           std::optional<double> totalSeconds = std::nullopt);

nlohmann::json rgbJson(const Rgb& c);

// Writes a report (one object, or an array of them) as indented JSON,
// atomically (model/io/file_io.h).
model::Check writeReport(const std::string& path, const nlohmann::json& report);

} // namespace regio::output
