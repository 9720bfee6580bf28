#pragma once
// Assimp in a process of its own. Debian's Assimp aborts on some broken
// files (failed assertions), reads others for ever, and writes into freed
// memory on a few (docs/reliability.md): in the editor any of these would
// take the open scene with it. readModelFileIsolated forks, reads the model
// in the child (readModelFile) and hands the triangles back through a pipe;
// a child that crashes or takes too long fails the import, nothing else.
#include "importer/assimp_reader.h"

#include <string>

namespace regio::importer {

// How long a model may take to read before the child is stopped.
inline constexpr int kReadTimeoutSeconds = 600;

// `inChild`, for tests: called in the child before it reads (to stand for
// a reader that hangs or crashes).
model::Result<ReadModel> readModelFileIsolated(const std::string& path, const ReadOptions& options = {},
                                               int timeoutSeconds = kReadTimeoutSeconds, void (*inChild)() = nullptr);

} // namespace regio::importer
