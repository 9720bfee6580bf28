#include "editor/preview/solver_presets.h"

#include "solver/prepare/prepare.h"

#include <QCoreApplication>
#include <QStringList>
#include <QtCore/qcoreapplication.h>

#include <chrono>

namespace regio::editor {

namespace {

class SolverPresets {
    Q_DECLARE_TR_FUNCTIONS(SolverPresets)
};

} // namespace

model::SolverSettings applyPreset(model::SolverSettings s, SolverPreset preset)
{
    switch (preset) {
    case SolverPreset::Draft:
        s.hemicube = 100;
        s.patchSize = 1.0;
        s.elementsPerPatch = 4;
        s.adaptive.enabled = false;
        s.adaptive.threshold = 0.1;
        s.adaptive.minEdge = 0.05;
        s.maxIterations = 200;
        s.convergence = 0.01;
        break;
    case SolverPreset::Normal: {
        const model::SolverSettings d;
        s.hemicube = d.hemicube;
        s.patchSize = d.patchSize;
        s.elementsPerPatch = d.elementsPerPatch;
        s.adaptive.enabled = d.adaptive.enabled;
        s.adaptive.threshold = d.adaptive.threshold;
        s.adaptive.minEdge = d.adaptive.minEdge;
        s.maxIterations = d.maxIterations;
        s.convergence = d.convergence;
        break;
    }
    case SolverPreset::Final:
        s.hemicube = 300;
        s.patchSize = 0.25;
        s.elementsPerPatch = 9;
        s.adaptive.enabled = true;
        s.adaptive.threshold = 0.02;
        s.adaptive.minEdge = 0.01;
        s.maxIterations = 5000;
        s.convergence = 0.0001;
        break;
    }
    return s;
}

std::optional<SolverPreset> presetOf(const model::SolverSettings& settings)
{
    for (SolverPreset p : {SolverPreset::Draft, SolverPreset::Normal, SolverPreset::Final})
        if (applyPreset(settings, p) == settings)
            return p;
    return std::nullopt;
}

QString presetName(SolverPreset preset)
{
    switch (preset) {
    case SolverPreset::Draft: return SolverPresets::tr("Draft");
    case SolverPreset::Normal: return SolverPresets::tr("Normal");
    case SolverPreset::Final: return SolverPresets::tr("Final");
    }
    return {};
}

DryRun dryRun(const model::Scene& scene)
{
    DryRun out;
    const auto start = std::chrono::steady_clock::now();
    // What Solver::create would run with (solver/settings.h), and the same preparation.
    out.settings = solver::resolveSettings(scene.solver);
    model::Result<solver::PreparedScene> prepared =
        solver::prepareScene(scene, solver::prepareOptionsFor(out.settings));
    out.diagnostics = prepared.diagnostics();
    if (prepared) {
        out.ok = true;
        out.stats = prepared->stats;
        out.regions = int(prepared->regions.size());
    }
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

QString describeDryRun(const DryRun& run)
{
    const model::SolverSettings& s = run.settings;
    QStringList lines;
    lines << SolverPresets::tr("Hemicube: %1 x %1 (sides %1 x %2)").arg(s.hemicube).arg(s.hemicube / 2);
    lines << SolverPresets::tr("Patch size: %1 m, %2 elements per patch").arg(s.patchSize).arg(s.elementsPerPatch);
    lines << SolverPresets::tr("Stops after %1 iterations or below %2 % unshot")
                 .arg(s.maxIterations)
                 .arg(100.0 * s.convergence);
    lines << SolverPresets::tr("Visibility: %1; regions: %2")
                 .arg(QString::fromLatin1(model::visibilityName(s.visibility)),
                      QString::fromLatin1(model::regionsModeName(s.regions)));
    if (s.adaptive.enabled)
        lines << SolverPresets::tr("Adaptive subdivision: threshold %1, shortest edge %2 m, anchoring %3")
                     .arg(s.adaptive.threshold)
                     .arg(s.adaptive.minEdge)
                     .arg(s.adaptive.anchoring ? SolverPresets::tr("on") : SolverPresets::tr("off"));
    else
        lines << SolverPresets::tr("Adaptive subdivision: off");
    if (run.ok) {
        lines << SolverPresets::tr("Regions: %1; BSP fragments: %2 (%3 splits, depth %4)")
                     .arg(run.regions)
                     .arg(run.stats.fragments)
                     .arg(run.stats.splits)
                     .arg(run.stats.maxDepth);
        lines << SolverPresets::tr("Patches: %1; elements: %2 (before adaptive subdivision)")
                     .arg(run.stats.patches)
                     .arg(run.stats.elements);
        lines << SolverPresets::tr("Prepared in %1 s").arg(run.seconds, 0, 'f', 2);
    } else {
        lines << SolverPresets::tr("The scene cannot be prepared:");
    }
    for (const model::Diagnostic& d : run.diagnostics)
        lines << (d.severity == model::Severity::Error ? SolverPresets::tr("error: %1")
                                                       : SolverPresets::tr("warning: %1"))
                     .arg(QString::fromStdString(d.message));
    return lines.join(QLatin1Char('\n'));
}

} // namespace regio::editor
