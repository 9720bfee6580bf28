#pragma once
// Where the editor finds its sample scenes (File > Open Example): beside an
// installed editor in ../share/regio/scenes (as `cmake --install` and the
// Debian package put them), else in the source tree it was built from.
#include <QString>

namespace regio::editor {

// The folder for an editor whose executable is in `applicationDir`.
QString sampleScenesFolder(const QString& applicationDir);

// The same for the running editor (QCoreApplication::applicationDirPath()).
QString sampleScenesFolder();

} // namespace regio::editor
