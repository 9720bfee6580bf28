#pragma once
// The scene file: JSON with "format": "regio-scene" and an integer "version".
// Reading reports every problem as a diagnostic with a JSON pointer (and line
// and column for syntax errors); writing is deterministic so that
// save -> load -> save is byte-identical.
#include "model/diagnostic.h"
#include "model/result.h"
#include "model/scene.h"

#include <optional>
#include <string>
#include <string_view>

namespace regio::model {

inline constexpr const char* kSceneFormatTag = "regio-scene";
inline constexpr int kSceneFormatVersion = 1;

// Parses scene JSON text: the scene with the format's warnings, or every
// problem found. Never throws, whatever the input.
Result<Scene> parseScene(std::string_view text);
// The canonical text of a scene (2-space indent, trailing newline).
std::string serializeScene(const Scene& scene);

// Reads a file (model/io/file_io.h) and parses it; an unreadable file is one
// error diagnostic.
Result<Scene> loadSceneFile(const std::string& path);
// Writes atomically (model/io/file_io.h), after checking that the text reads
// back as the same scene. On failure the previous file is untouched and the
// error says why.
Check saveSceneFile(const Scene& scene, const std::string& path);

} // namespace regio::model
