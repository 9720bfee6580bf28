#pragma once
// The command line of `regio-solve solve`, parsed once for the one-scene
// path (solve_command.cpp) and the batch into a directory (batch.cpp).
#include "output/export.h"
#include "solver/solver.h"

#include <optional>
#include <string>
#include <vector>

namespace regio::cli {

// What the batch writes per scene besides its report (--format).
enum class BatchFormat { Glb, Gltf, Ply, Obj, Png };

// The file extension of a format, with the dot (".glb").
const char* extensionOf(BatchFormat format);

enum class ProgressStyle { Text, Json };

struct SolveOptions {
    solver::SolverOptions solver;
    bool iterationsGiven = false;
    bool convergenceGiven = false;
    std::optional<std::string> reportPath;
    output::OutputRequest output;
    bool flat = false;
    bool quiet = false;
    std::vector<std::string> files;

    // The batch: one report and the requested outputs per scene in outDir.
    std::optional<std::string> outDir;
    std::vector<BatchFormat> formats;
    int jobs = 0;            // 0 = one per core, or cores / --threads
    bool cacheGiven = false; // --cache-mb
    bool force = false;
    ProgressStyle progress = ProgressStyle::Text;
    // The options that change a solution or its files, as given, in order:
    // a scene solved before with the same bytes and these is not solved again.
    std::vector<std::string> resultArguments;
};

extern const char* const kSolveUsage;

// Parses `argv` (argv[0] == "solve"); returns an exit code when the command
// must stop here (--help, or a usage error already printed).
std::optional<int> parseSolveOptions(int argc, char** argv, SolveOptions& options);

// Prints "regio-solve solve: MESSAGE" and the hint; returns kExitFailure.
int solveUsageError(const std::string& message);

} // namespace regio::cli
