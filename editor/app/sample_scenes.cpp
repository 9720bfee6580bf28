#include "editor/app/sample_scenes.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>

namespace regio::editor {

QString sampleScenesFolder(const QString& applicationDir)
{
    const QString installed = QDir::cleanPath(applicationDir + QStringLiteral("/../share/regio/scenes"));
    if (QFileInfo(installed).isDir())
        return installed;
    return QStringLiteral(REGIO_SAMPLE_SCENES);
}

QString sampleScenesFolder() { return sampleScenesFolder(QCoreApplication::applicationDirPath()); }

QString userGuideFile(const QString& applicationDir)
{
    const QString installed = QDir::cleanPath(applicationDir + QStringLiteral("/../share/doc/regio-solve/guide.md"));
    if (QFileInfo(installed).isFile())
        return installed;
    return QStringLiteral(REGIO_DOCS "/guide.md");
}

QString userGuideFile() { return userGuideFile(QCoreApplication::applicationDirPath()); }

} // namespace regio::editor
