#pragma once
// The scene file: JSON with "format": "regio-scene" and an integer "version".
// Reading reports every problem as a diagnostic with a JSON pointer (and line
// and column for syntax errors); writing is deterministic so that
// save -> load -> save is byte-identical.
#include "model/diagnostic.h"
#include "model/scene.h"

#include <optional>
#include <string>
#include <string_view>

namespace regio::model {

inline constexpr const char* kSceneFormatTag = "regio-scene";
inline constexpr int kSceneFormatVersion = 1;

struct SceneReadResult {
    std::optional<Scene> scene; // empty when the file could not be read as a scene
    Diagnostics diagnostics;    // format problems (errors and warnings)
};

// Parses scene JSON text. Never throws, whatever the input.
SceneReadResult parseScene(std::string_view text);
// The canonical text of a scene (2-space indent, trailing newline).
std::string serializeScene(const Scene& scene);

// Reads a file and parses it; an unreadable file is one error diagnostic.
SceneReadResult loadSceneFile(const std::string& path);
// Writes atomically: a temporary file beside the target, flushed, then renamed
// over it. On failure the previous file is untouched and the error says why.
std::optional<Diagnostic> saveSceneFile(const Scene& scene, const std::string& path);

} // namespace regio::model
