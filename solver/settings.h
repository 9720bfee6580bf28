#pragma once
// The settings a solve runs with. A scene file carries its own
// (model::SolverSettings, the `solver` block); the command line and the
// editor may override some of them. resolveSettings is the one place where
// the two meet: the Solver, regio-solve and the editor's dry run all call it,
// so they can never disagree about what a solve will do.
#include "model/result.h"
#include "model/scene.h"

#include <optional>

namespace regio::solver {

// Overrides of a scene's solver settings; empty = the scene's value.
struct SettingsOverrides {
    std::optional<int> hemicube;
    std::optional<int> maxIterations;
    std::optional<double> convergence;
    std::optional<double> patchSize;
    std::optional<int> elementsPerPatch;
    std::optional<model::Visibility> visibility;
    std::optional<model::RegionsMode> regions;
    // Adaptive subdivision (§5.7).
    std::optional<bool> adaptive;
    std::optional<double> adaptiveThreshold;
    std::optional<double> adaptiveMinEdge;
    std::optional<bool> adaptiveAnchoring;
};

// The scene's settings with the overrides applied.
model::SolverSettings resolveSettings(const model::SolverSettings& scene, const SettingsOverrides& overrides = {});

// What meshing needs (§5.4, §5.5): a positive patch size and an
// element/patch ratio of at least 1.
model::Check checkMeshSettings(const model::SolverSettings& settings);

// What the solver itself needs of resolved settings to run at all (the file
// format and the command line have stricter ranges of their own): a hemicube
// of at least 2, a positive patch size, an element/patch ratio of at least 1
// and, with adaptive subdivision on, a finite threshold >= 0 and a positive
// minimum edge. The diagnostic points at the setting in the scene file.
model::Check checkRunnable(const model::SolverSettings& settings);

} // namespace regio::solver
