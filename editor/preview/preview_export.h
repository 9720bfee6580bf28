#pragma once
// Exports of the preview: the lit model as the viewport
// shows it (smooth vertex radiosity, the same display settings), and a
// self-contained scene for batch machines with the regio-solve command that
// solves it at final quality with the preview's display settings.
#include "editor/preview/preview_display.h"
#include "model/scene.h"

#include <QString>
#include <QStringList>

#include <optional>

namespace regio::editor {

// glTF (.gltf/.glb), PLY or OBJ by the extension (output::writeLitModel).
std::optional<QString> writePreviewModel(const QString& path, const PreviewFrame& frame, const PreviewDisplay& display);

// The scene as it is, with the final preset's settings (what a batch machine
// should run); the file is self-contained like every scene file.
model::Scene batchScene(const model::Scene& scene);
std::optional<QString> writeBatchScene(const QString& path, const model::Scene& scene);
// The regio-solve arguments that solve `scenePath` and write the report, a
// lit model and a picture next to it with the preview's display settings.
QStringList batchArguments(const QString& scenePath, const PreviewDisplay& display);
QString batchCommand(const QString& scenePath, const PreviewDisplay& display);

} // namespace regio::editor
