#pragma once
// How each scene of a batch ended, and the table and counts that sum a
// batch up: printed at the end of 'regio-solve solve --out-dir' and by
// 'regio-solve summary' from the reports a batch left in its directory.
#include "cli/commands.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace regio::cli {

enum class Outcome { NotStarted, Solved, Skipped, Failed, Interrupted };

// "not started", "solved", "skipped", "failed", "interrupted".
const char* outcomeName(Outcome outcome);

struct SceneJob {
    std::string file; // as given
    std::string name; // the file's name without .json: DIR/NAME.report.json
    Outcome outcome = Outcome::NotStarted;
    int exitCode = kExitOk;
    nlohmann::json report; // what DIR/NAME.report.json holds (or held, when skipped)
    std::string error;     // the first error, for the summary
};

// A row per scene (status, iterations, unshot, elements, seconds), the
// error under a failed one, and a line of counts ("in S s" when given).
void printSummary(std::ostream& out, const std::vector<SceneJob>& jobs, std::optional<double> seconds);

// {"scenes": N, "solved": n, "failed": n, ...}: the counts by outcome.
nlohmann::json summaryCounts(const std::vector<SceneJob>& jobs);

} // namespace regio::cli
