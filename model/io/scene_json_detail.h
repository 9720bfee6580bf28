#pragma once
// Internals of the scene file shared by scene_json*.cpp and scene_file.cpp:
// not part of the model's public API (include model/io/scene_json.h instead).
#include "model/diagnostic.h"
#include "model/io/json_pointer.h"
#include "model/scene.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace regio::model::detail {

// Limits that keep hostile input harmless, checked by a linear scan before
// the parser runs. A scene nests 7 levels deep (root, objects, object, parts,
// part, vertices, vertex); recursion over the parsed tree stays far from the
// stack limit below 64. No double needs more than a few dozen characters
// (strtod on a gigabyte of digits is slow and pointless). The parser keeps
// the text of a whole token (and of the white space before it) and copies it
// into its error message several times: a gigabyte-long string took minutes
// and 8 GB. Every parsed value costs about 16 bytes plus containers, so the
// value count bounds memory (a million-face scene has about 16 million).
inline constexpr int kMaxNestingDepth = 64;
inline constexpr std::size_t kMaxNumberLength = 1000;
inline constexpr std::size_t kMaxStringLength = std::size_t{1} << 20;
inline constexpr std::size_t kMaxWhitespaceRun = std::size_t{1} << 20;
inline constexpr std::size_t kMaxValueCount = std::size_t{64} << 20;

struct JsonText {
    std::optional<nlohmann::json> document; // empty on a syntax error
    Diagnostics diagnostics;                // syntax errors, duplicate keys
};

// Parses JSON text without exceptions: a syntax error becomes a diagnostic with
// its line and column (and the JSON pointer of the value being read, when the
// parser got that far). Duplicate object keys are errors: keeping either value
// would silently lose the other.
JsonText parseJsonText(std::string_view text);

// 1-based line and column (in UTF-8 code points) of a byte offset.
void setTextPosition(std::string_view text, std::size_t offset, Diagnostic& diagnostic);

// The value of an integer, or of a float with an integral value that a double
// holds exactly (JSON Schema counts 3.0 as an integer); empty otherwise.
std::optional<std::int64_t> asInteger(const nlohmann::json& value);

// Reads a current-version scene document into `scene`; every problem is
// appended to `diagnostics`. `scene` is complete only if no error was added.
void readSceneDocument(const nlohmann::json& document, Scene& scene, Diagnostics& diagnostics);

// The canonical ordered document of a scene (key order of the file format).
nlohmann::ordered_json sceneToJson(const Scene& scene);

// Shortest text that reads back as the same double, for messages.
std::string formatNumber(double value);

} // namespace regio::model::detail
