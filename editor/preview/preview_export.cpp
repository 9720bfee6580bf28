#include "editor/preview/preview_export.h"

#include "editor/preview/solver_presets.h"
#include "model/io/scene_json.h"
#include "output/export.h"

#include <QCoreApplication>
#include <QFileInfo>

namespace regio::editor {

std::optional<QString> writePreviewModel(const QString& path, const PreviewFrame& frame, const PreviewDisplay& display)
{
    if (!frame.lit || frame.lit->empty())
        return QCoreApplication::translate("regio::editor::PreviewExport", "there is no solution to export");
    if (!output::modelFormatForPath(path.toStdString()))
        return QCoreApplication::translate("regio::editor::PreviewExport",
                                           "%1: unknown model format (use .gltf, .glb, .ply or .obj)")
            .arg(path);
    const output::PreparedColours colours = output::prepareColours(*frame.lit, displaySettings(display, frame));
    if (model::Check written = output::writeLitModel(path.toStdString(), *frame.lit, colours.colours); !written)
        return QString::fromStdString(written.error().message);
    return std::nullopt;
}

model::Scene batchScene(const model::Scene& scene)
{
    model::Scene out = scene;
    out.solver = applyPreset(scene.solver, SolverPreset::Final);
    return out;
}

std::optional<QString> writeBatchScene(const QString& path, const model::Scene& scene)
{
    if (model::Check saved = model::saveSceneFile(batchScene(scene), path.toStdString()); !saved)
        return QString::fromStdString(saved.error().message);
    return std::nullopt;
}

namespace {

QString quoted(const QString& arg)
{
    static const QString safe = QStringLiteral("-_./=:+,%@");
    bool plain = !arg.isEmpty();
    for (QChar c : arg)
        plain = plain && (c.isLetterOrNumber() || safe.contains(c));
    if (plain)
        return arg;
    QString out = arg;
    out.replace(QLatin1Char('\''), QStringLiteral("'\\''"));
    return QLatin1Char('\'') + out + QLatin1Char('\'');
}

} // namespace

QStringList batchArguments(const QString& scenePath, const PreviewDisplay& display)
{
    const QFileInfo info(scenePath);
    const QString base = info.path() + QLatin1Char('/') + info.completeBaseName();
    QStringList args{QStringLiteral("solve"),      scenePath,
                     QStringLiteral("--report"),   base + QStringLiteral(".report.json"),
                     QStringLiteral("--out"),      base + QStringLiteral(".glb"),
                     QStringLiteral("--image"),    base + QStringLiteral(".png"),
                     QStringLiteral("--exposure"), QString::number(display.exposure),
                     QStringLiteral("--gamma"),    QString::number(display.gamma)};
    if (display.falseColour)
        args << QStringLiteral("--false-colour")
             << (display.falseColourScale == output::FalseColourScale::Linear ? QStringLiteral("linear")
                                                                              : QStringLiteral("log"));
    return args;
}

QString batchCommand(const QString& scenePath, const PreviewDisplay& display)
{
    QStringList parts{QStringLiteral("regio-solve")};
    for (const QString& a : batchArguments(scenePath, display))
        parts << quoted(a);
    return parts.join(QLatin1Char(' '));
}

} // namespace regio::editor
