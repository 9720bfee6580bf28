#pragma once
// Reading scene files for the commands of regio-solve: the file (or standard
// input), its format diagnostics and, once it parses, validateScene's.
#include "model/diagnostic.h"
#include "model/scene.h"

#include <iosfwd>
#include <optional>
#include <string>

namespace regio::cli {

struct SceneInput {
    std::string name;                  // as given on the command line; "-" reads standard input
    std::optional<model::Scene> scene; // set when the format is readable (it may still have errors)
    model::Diagnostics diagnostics;    // format diagnostics, then validation diagnostics
    bool unreadable = false;           // the file could not be read at all
};

// Reads, parses and validates one scene file. Never throws.
SceneInput readSceneInput(const std::string& name);

// The same for text already read (named `name` in diagnostics).
SceneInput sceneInputFromText(const std::string& name, const std::string& text);

// kExitFailure if unreadable, kExitErrors if any error, else kExitOk.
int exitCodeOf(const SceneInput& input);

// "file: /pointer: error: message", or "file:line:column: ..." for syntax
// errors. Control characters and invalid UTF-8 from the input are escaped.
std::string formatDiagnostic(const std::string& file, const model::Diagnostic& diagnostic);

// Prints every diagnostic of `input`, one per line.
void printDiagnostics(std::ostream& out, const SceneInput& input);

} // namespace regio::cli
