#pragma once
// Solver presets of the solver dock and the dry run.
//   draft:  interactive previews on the sample scenes while editing
//   normal: the file format's defaults
//   final:  what a batch machine should run ("Export for batch")
// A preset sets resolution, meshing, subdivision and stopping; it keeps the
// scene's visibility method, regions mode and anchoring choice.
#include "model/scene.h"
#include "solver/solver.h"

#include <QString>

#include <optional>

namespace regio::editor {

enum class SolverPreset { Draft, Normal, Final };

model::SolverSettings applyPreset(model::SolverSettings settings, SolverPreset preset);
// The preset the settings equal, if any.
std::optional<SolverPreset> presetOf(const model::SolverSettings& settings);
QString presetName(SolverPreset preset);

// What a solve of the scene would run with, without shooting: effective
// settings, regions, fragments, patches and elements (solver::prepareScene).
struct DryRun {
    bool ok = false;
    model::SolverSettings settings;
    solver::PrepareStats stats;
    int regions = 0;
    model::Diagnostics diagnostics;
    double seconds = 0.0;
};
DryRun dryRun(const model::Scene& scene);
QString describeDryRun(const DryRun& run);

} // namespace regio::editor
