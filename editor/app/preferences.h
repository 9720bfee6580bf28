#pragma once
// User preferences kept in QSettings, read once at start and written by the
// Preferences dialog.
#include <QString>

class QSettings;

namespace regio::editor {

struct Preferences {
    QString language;        // "" = follow the system locale; else "en", "cs", ...
    int autosaveMinutes = 2; // 0 = no autosave
    double gridStep = 0.1;   // metres
    bool snapToGrid = true;
    double angleSnapDegrees = 15.0;

    static Preferences load(QSettings& settings);
    void save(QSettings& settings) const;
    bool operator==(const Preferences&) const = default;
};

} // namespace regio::editor
