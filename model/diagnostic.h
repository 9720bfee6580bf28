#pragma once
// Validation and edit results are reported as diagnostics instead of exceptions:
// the editor lists them, the CLI prints them as `file: pointer: message`.
#include <string>
#include <vector>

namespace regio::model {

enum class Severity { Warning, Error };

struct Diagnostic {
    Severity severity = Severity::Error;
    std::string message;
    // JSON pointer into the scene file ("/objects/0/parts/1/faces/2"); empty
    // for the document as a whole. Positions in the model equal positions in the
    // file, so the same pointer serves the editor and the CLI.
    std::string pointer;
    // Ids from the outside in (object, part, face), so the editor can select
    // the offending element even after reordering.
    std::vector<std::string> idPath;
    // 1-based text position, for syntax errors only (0 = unknown).
    int line = 0;
    int column = 0;

    bool isError() const { return severity == Severity::Error; }
};

using Diagnostics = std::vector<Diagnostic>;

inline bool hasErrors(const Diagnostics& diagnostics)
{
    for (const Diagnostic& d : diagnostics)
        if (d.isError())
            return true;
    return false;
}

inline Diagnostic makeError(std::string message, std::string pointer = {}, std::vector<std::string> idPath = {})
{
    return Diagnostic{Severity::Error, std::move(message), std::move(pointer), std::move(idPath)};
}

inline Diagnostic makeWarning(std::string message, std::string pointer = {}, std::vector<std::string> idPath = {})
{
    return Diagnostic{Severity::Warning, std::move(message), std::move(pointer), std::move(idPath)};
}

// The same diagnostic about another place of the file (a check written for
// one value, reported where that value sits).
inline Diagnostic withPointer(Diagnostic diagnostic, std::string pointer)
{
    diagnostic.pointer = std::move(pointer);
    return diagnostic;
}

} // namespace regio::model
