#include "editor/app/preferences.h"

#include <QSettings>

#include <algorithm>

namespace regio::editor {

Preferences Preferences::load(QSettings& settings)
{
    Preferences p;
    settings.beginGroup(QStringLiteral("preferences"));
    p.language = settings.value(QStringLiteral("language"), p.language).toString();
    p.autosaveMinutes =
        std::clamp(settings.value(QStringLiteral("autosaveMinutes"), p.autosaveMinutes).toInt(), 0, 120);
    const double grid = settings.value(QStringLiteral("gridStep"), p.gridStep).toDouble();
    p.gridStep = grid > 0.0 && grid <= 100.0 ? grid : 0.1;
    p.snapToGrid = settings.value(QStringLiteral("snapToGrid"), p.snapToGrid).toBool();
    const double angle = settings.value(QStringLiteral("angleSnapDegrees"), p.angleSnapDegrees).toDouble();
    p.angleSnapDegrees = angle > 0.0 && angle <= 90.0 ? angle : 15.0;
    settings.endGroup();
    return p;
}

void Preferences::save(QSettings& settings) const
{
    settings.beginGroup(QStringLiteral("preferences"));
    settings.setValue(QStringLiteral("language"), language);
    settings.setValue(QStringLiteral("autosaveMinutes"), autosaveMinutes);
    settings.setValue(QStringLiteral("gridStep"), gridStep);
    settings.setValue(QStringLiteral("snapToGrid"), snapToGrid);
    settings.setValue(QStringLiteral("angleSnapDegrees"), angleSnapDegrees);
    settings.endGroup();
}

} // namespace regio::editor
