#pragma once
// What a diagnostic is about, for people: the innermost element its JSON
// pointer enters (a material, object, part, face or region) and that
// element's id, so that a message reads 'face "box.body.top"' beside
// '/objects/0/parts/0/faces/2' and still names the right face after the file
// was edited.
#include "model/diagnostic.h"

#include <optional>
#include <string>

namespace regio::model {

struct DiagnosticSubject {
    std::string kind; // "material", "object", "part", "face" or "region"
    std::string id;
};

// Empty for a diagnostic about the whole document, or one without ids.
std::optional<DiagnosticSubject> subjectOf(const Diagnostic& diagnostic);

// 'face "box.body.top"', the id escaped as printable() does; empty when
// there is no subject.
std::string describeSubject(const Diagnostic& diagnostic);

} // namespace regio::model
