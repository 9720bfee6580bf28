// `regio-solve check`: reports the format and validation diagnostics of scene
// files, for people (a summary per file) and for scripts (the exit code).
#include "cli/commands.h"
#include "cli/scene_input.h"

#include <algorithm>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

namespace regio::cli {

namespace {

const char* const kCheckUsage =
    "Usage: regio-solve check [--quiet] SCENE.json...\n"
    "\n"
    "Checks scene files: JSON syntax, the scene format, and the scene's\n"
    "validation rules (ids, references, geometry, regions). Every problem is\n"
    "printed as\n"
    "  FILE: /json/pointer: error|warning: message\n"
    "  FILE:LINE:COLUMN: error: message          (syntax errors)\n"
    "followed by a summary line per file. '-' reads standard input.\n"
    "\n"
    "Options:\n"
    "  -q, --quiet   print the diagnostics only, no summary lines\n"
    "  -h, --help    show this help\n"
    "\n"
    "Exit status: 0 every file is clean or has warnings only, 1 some file has\n"
    "errors, 2 some file could not be read or the command line is wrong.\n";

std::string counted(std::size_t count, const char* singular)
{
    return std::to_string(count) + " " + singular + (count == 1 ? "" : "s");
}

std::string summaryOf(const SceneInput& input)
{
    const auto errors = static_cast<std::size_t>(
        std::count_if(input.diagnostics.begin(), input.diagnostics.end(), [](const auto& d) { return d.isError(); }));
    const std::size_t warnings = input.diagnostics.size() - errors;
    const std::string file = input.name == "-" ? "<stdin>" : input.name;
    if (input.unreadable)
        return file + ": not checked (unreadable)";
    if (errors > 0)
        return file + ": " + counted(errors, "error") + ", " + counted(warnings, "warning");

    std::size_t parts = 0;
    std::size_t faces = 0;
    for (const model::Object& object : input.scene->objects) {
        parts += object.parts.size();
        for (const model::Part& part : object.parts)
            faces += part.faces.size();
    }
    std::string summary = file + ": ok";
    if (warnings > 0)
        summary += " with " + counted(warnings, "warning");
    summary += " (" + counted(input.scene->materials.size(), "material") + ", " +
               counted(input.scene->objects.size(), "object") + ", " + counted(parts, "part") + ", " +
               counted(faces, "face") + ", " + counted(input.scene->regions.size(), "region") + ")";
    return summary;
}

} // namespace

int runCheck(int argc, char** argv)
{
    bool quiet = false;
    std::vector<std::string> files;
    bool optionsEnded = false;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (optionsEnded || arg == "-" || arg.empty() || arg[0] != '-') {
            files.push_back(arg);
        } else if (arg == "--") {
            optionsEnded = true;
        } else if (arg == "-q" || arg == "--quiet") {
            quiet = true;
        } else if (arg == "-h" || arg == "--help") {
            std::cout << kCheckUsage;
            return kExitOk;
        } else {
            std::cerr << "regio-solve check: unknown option '" << arg << "'\n"
                      << "Try 'regio-solve check --help'.\n";
            return kExitFailure;
        }
    }
    if (files.empty()) {
        std::cerr << "regio-solve check: no scene file given\n"
                  << "Usage: regio-solve check [--quiet] SCENE.json...\n";
        return kExitFailure;
    }
    if (std::count(files.begin(), files.end(), "-") > 1) {
        std::cerr << "regio-solve check: standard input ('-') can be read only once\n";
        return kExitFailure;
    }

    int exitCode = kExitOk;
    for (const std::string& file : files) {
        const SceneInput input = readSceneInput(file);
        printDiagnostics(std::cout, input);
        if (!quiet)
            std::cout << summaryOf(input) << '\n';
        std::cout.flush();
        exitCode = std::max(exitCode, exitCodeOf(input));
    }
    return exitCode;
}

} // namespace regio::cli
