#include "cli/scene_input.h"

#include "cli/commands.h"

#include "model/diagnostic_subject.h"
#include "model/io/file_io.h"
#include "model/io/printable.h"
#include "model/io/scene_json.h"
#include "model/validation/validation.h"

#include <iterator>
#include <ostream>

namespace regio::cli {

SceneInput readSceneInput(const std::string& name)
{
    SceneInput input;
    input.name = name;
    // Read apart from parsing (not model::loadSceneFile) to tell an
    // unreadable file (exit 2) from a broken one (exit 1).
    model::Result<std::string> text = name == "-" ? model::readStandardInput() : model::readFile(name);
    if (!text) {
        input.unreadable = true;
        input.diagnostics = text.takeDiagnostics();
        return input;
    }
    return sceneInputFromText(name, *text);
}

SceneInput sceneInputFromText(const std::string& name, const std::string& text)
{
    SceneInput input;
    input.name = name;
    model::Result<model::Scene> read = model::parseScene(text);
    input.diagnostics = read.takeDiagnostics();
    if (read) {
        input.scene = std::move(*read);
        model::Diagnostics validation = model::validateScene(*input.scene);
        input.diagnostics.insert(input.diagnostics.end(), std::make_move_iterator(validation.begin()),
                                 std::make_move_iterator(validation.end()));
    }
    return input;
}

int exitCodeOf(const SceneInput& input)
{
    if (input.unreadable)
        return kExitFailure;
    return model::hasErrors(input.diagnostics) ? kExitErrors : kExitOk;
}

std::string formatDiagnostic(const std::string& file, const model::Diagnostic& diagnostic)
{
    std::string out = model::printable(file);
    if (diagnostic.line > 0)
        out += ":" + std::to_string(diagnostic.line) + ":" + std::to_string(diagnostic.column);
    if (!diagnostic.pointer.empty())
        out += ": " + model::printable(diagnostic.pointer);
    if (const std::string subject = model::describeSubject(diagnostic); !subject.empty())
        out += " (" + subject + ")";
    out += diagnostic.isError() ? ": error: " : ": warning: ";
    out += model::printable(diagnostic.message);
    return out;
}

void printDiagnostics(std::ostream& out, const SceneInput& input)
{
    const std::string file = input.name == "-" ? "<stdin>" : input.name;
    for (const model::Diagnostic& diagnostic : input.diagnostics)
        out << formatDiagnostic(file, diagnostic) << '\n';
}

} // namespace regio::cli
