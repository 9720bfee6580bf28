#pragma once
// `regio-solve solve --out-dir DIR SCENES...`: many scenes solved
// unattended, up to --jobs at once, each into DIR/NAME.report.json and the
// outputs --format asks for, skipping the scenes DIR already holds solved
// with the same bytes and options, and stopping cleanly on Ctrl-C or SIGTERM.
#include "cli/solve_options.h"

#include <string>

namespace regio::cli {

int runBatch(const SolveOptions& options);

// What a scene's files in the directory are named after: its file's name
// without .json ("rooms/hall.json" -> "hall").
std::string sceneNameOf(const std::string& file);

} // namespace regio::cli
