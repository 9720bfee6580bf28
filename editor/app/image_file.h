#pragma once
// Pictures the editor writes (screenshots, viewport exports): encoded by Qt
// in the format the file name asks for, and written like every file Regio
// writes, atomically (model/io/file_io.h).
#include <QImage>
#include <QString>

#include <optional>

namespace regio::editor {

// Nothing on success, otherwise why not (naming the file).
std::optional<QString> writeImageFile(const QString& path, const QImage& image);

} // namespace regio::editor
