#pragma once
// Where the editor finds its sample scenes (File > Open Example, Help >
// Examples) and its user guide: beside an
// installed editor in ../share/regio/scenes (as `cmake --install` and the
// Debian package put them), else in the source tree it was built from.
#include <QString>

namespace regio::editor {

// The folder for an editor whose executable is in `applicationDir`.
QString sampleScenesFolder(const QString& applicationDir);

// The same for the running editor (QCoreApplication::applicationDirPath()).
QString sampleScenesFolder();

// The user guide (Help > User Guide): docs/guide.md as installed with the
// other documents in ../share/doc/regio-solve, else the source tree's.
QString userGuideFile(const QString& applicationDir);
QString userGuideFile();

} // namespace regio::editor
