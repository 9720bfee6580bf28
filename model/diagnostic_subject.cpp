#include "model/diagnostic_subject.h"

#include "model/io/json_pointer.h"
#include "model/io/printable.h"

#include <array>
#include <string_view>
#include <utility>
#include <vector>

namespace regio::model {

namespace {

constexpr std::array<std::pair<std::string_view, std::string_view>, 5> kCollections{{
    {"materials", "material"},
    {"objects", "object"},
    {"parts", "part"},
    {"faces", "face"},
    {"regions", "region"},
}};

} // namespace

std::optional<DiagnosticSubject> subjectOf(const Diagnostic& diagnostic)
{
    if (diagnostic.idPath.empty() || diagnostic.pointer.empty())
        return std::nullopt;
    // The kinds of the "/collection/index" pairs of the pointer, outside in,
    // each with its id in idPath: the innermost one whose id is known (a face
    // whose id is not a string is reported as its part).
    const std::vector<std::string> tokens = pointerTokens(diagnostic.pointer);
    std::vector<std::string_view> kinds;
    for (std::size_t i = 0; i + 1 < tokens.size(); ++i) {
        const std::string& index = tokens[i + 1];
        if (index.empty() || index.find_first_not_of("0123456789") != std::string::npos)
            continue;
        for (const auto& [collection, singular] : kCollections)
            if (tokens[i] == collection)
                kinds.push_back(singular);
    }
    if (kinds.size() < diagnostic.idPath.size())
        return std::nullopt;
    return DiagnosticSubject{std::string(kinds[diagnostic.idPath.size() - 1]), diagnostic.idPath.back()};
}

std::string describeSubject(const Diagnostic& diagnostic)
{
    const std::optional<DiagnosticSubject> subject = subjectOf(diagnostic);
    if (!subject)
        return {};
    return subject->kind + " \"" + printable(subject->id) + "\"";
}

} // namespace regio::model
