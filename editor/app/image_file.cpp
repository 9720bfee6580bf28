#include "editor/app/image_file.h"

#include "editor/document/qt_conversions.h"
#include "model/io/file_io.h"

#include <QBuffer>
#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QImageWriter>

namespace regio::editor {

std::optional<QString> writeImageFile(const QString& path, const QImage& image)
{
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    QImageWriter writer(&buffer, QFileInfo(path).suffix().toLower().toLatin1());
    if (!writer.write(image))
        return QCoreApplication::translate("regio::editor::ImageFile", "cannot write %1: %2")
            .arg(QDir::toNativeSeparators(path), writer.errorString());
    const model::Check written =
        model::writeFileAtomically(toStd(path), std::string_view(bytes.constData(), size_t(bytes.size())));
    if (!written)
        return toQString(written.error().message);
    return std::nullopt;
}

} // namespace regio::editor
