#pragma once
// The subcommands of `regio-solve`. main() dispatches on the first argument;
// each command receives argv starting at its own name (argv[0] == "check"),
// parses the rest itself and returns the process exit code.
namespace regio::cli {

// Exit codes shared by every command, so scripts can tell "the scene has
// errors" from "the command could not run at all".
inline constexpr int kExitOk = 0;      // clean, or warnings only
inline constexpr int kExitErrors = 1;  // at least one error diagnostic
inline constexpr int kExitFailure = 2; // usage error or unreadable file

// `regio-solve check [--quiet] SCENE.json...`: format and validation
// diagnostics of every file.
int runCheck(int argc, char** argv);

// `regio-solve solve ...`: the batch radiosity solve (solve_command.cpp).
int runSolve(int argc, char** argv);

// `regio-solve sweep SCENE --set PATH=VALUES... --out-dir DIR`: variant
// scenes of a parameter study, solved with --solve (sweep_command.cpp).
int runSweep(int argc, char** argv);

// `regio-solve summary DIR [SCENES...]`: a batch's table from its reports
// (summary_command.cpp).
int runSummary(int argc, char** argv);

// `regio-solve import MODEL OUT.json ...`: a model file into a scene (import_command.cpp).
int runImport(int argc, char** argv);

} // namespace regio::cli
