// regio-solve: the headless batch companion of the Regio editor. main() only
// dispatches to the subcommands declared in commands.h.
#include "cli/commands.h"

#include "model/io/scene_json.h"

#include <cstring>
#include <iostream>
#include <string>

namespace {

const char* const kUsage =
    "Usage: regio-solve COMMAND [ARGUMENTS...]\n"
    "\n"
    "Batch tools for Regio radiosity scenes (no display needed).\n"
    "\n"
    "Commands:\n"
    "  check SCENE.json...   check scene files and print every problem found\n"
    "  solve SCENE.json ...  compute the radiosity solution of scenes, one or a\n"
    "                        batch into a directory (--out-dir)\n"
    "  sweep SCENE.json ...  write (and solve) the variants of a parameter study\n"
    "  summary DIR           the table of a batch from the reports in DIR\n"
    "  import MODEL OUT.json import a model file (OBJ, glTF, FBX, ...) as a scene\n"
    "\n"
    "Options:\n"
    "  -h, --help            show this help\n"
    "  --version             show the version and the scene format it reads\n"
    "\n"
    "'regio-solve COMMAND --help' describes a command's options.\n"
    "Exit status: 0 success, 1 the scene has errors, 2 usage error or unreadable file.\n";

} // namespace

namespace {

int dispatch(int argc, char** argv);

} // namespace

// What escapes a command (memory exhausted past the estimate that let a
// solve start, a fault of the solver's own) ends it with a message and
// status 2, never with std::terminate's abort and a core file.
int main(int argc, char** argv)
{
    try {
        return dispatch(argc, argv);
    } catch (const std::bad_alloc&) {
        std::cerr << "regio-solve: out of memory (try a larger patch size or a lower hemicube resolution)\n";
    } catch (const std::exception& e) {
        std::cerr << "regio-solve: " << e.what() << "\n";
    }
    return regio::cli::kExitFailure;
}

namespace {

int dispatch(int argc, char** argv)
{
    using namespace regio::cli;
    if (argc < 2) {
        std::cerr << kUsage;
        return kExitFailure;
    }
    const std::string command = argv[1];
    if (command == "-h" || command == "--help" || command == "help") {
        std::cout << kUsage;
        return kExitOk;
    }
    if (command == "--version") {
        std::cout << "regio-solve " << REGIO_VERSION << " (scene format " << regio::model::kSceneFormatTag
                  << " version " << regio::model::kSceneFormatVersion << ")\n";
        return kExitOk;
    }
    if (command == "check")
        return runCheck(argc - 1, argv + 1);
    if (command == "solve")
        return runSolve(argc - 1, argv + 1);
    if (command == "sweep")
        return runSweep(argc - 1, argv + 1);
    if (command == "summary")
        return runSummary(argc - 1, argv + 1);
    if (command == "import")
        return runImport(argc - 1, argv + 1);
    std::cerr << "regio-solve: unknown command '" << command << "'\n"
              << "Try 'regio-solve --help'.\n";
    return kExitFailure;
}

} // namespace
