#pragma once
// `regio-solve solve --out-dir DIR SCENES...`: many scenes solved
// unattended, up to --jobs at once, each into DIR/NAME.report.json and the
// outputs --format asks for, skipping the scenes DIR already holds solved
// with the same bytes and options, and stopping cleanly on Ctrl-C or SIGTERM.
#include "cli/solve_options.h"

namespace regio::cli {

int runBatch(const SolveOptions& options);

} // namespace regio::cli
