#include "solver/settings.h"

#include <cmath>

namespace regio::solver {

model::SolverSettings resolveSettings(const model::SolverSettings& scene, const SettingsOverrides& overrides)
{
    model::SolverSettings s = scene;
    s.hemicube = overrides.hemicube.value_or(s.hemicube);
    s.maxIterations = overrides.maxIterations.value_or(s.maxIterations);
    s.convergence = overrides.convergence.value_or(s.convergence);
    s.patchSize = overrides.patchSize.value_or(s.patchSize);
    s.elementsPerPatch = overrides.elementsPerPatch.value_or(s.elementsPerPatch);
    s.visibility = overrides.visibility.value_or(s.visibility);
    s.regions = overrides.regions.value_or(s.regions);
    s.adaptive.enabled = overrides.adaptive.value_or(s.adaptive.enabled);
    s.adaptive.threshold = overrides.adaptiveThreshold.value_or(s.adaptive.threshold);
    s.adaptive.minEdge = overrides.adaptiveMinEdge.value_or(s.adaptive.minEdge);
    s.adaptive.anchoring = overrides.adaptiveAnchoring.value_or(s.adaptive.anchoring);
    return s;
}

model::Check checkRunnable(const model::SolverSettings& s)
{
    if (s.adaptive.enabled && !(std::isfinite(s.adaptive.minEdge) && s.adaptive.minEdge > 0.0))
        return model::makeError("the adaptive minEdge must be a positive length", "/solver/adaptive/minEdge");
    if (s.adaptive.enabled && !(std::isfinite(s.adaptive.threshold) && s.adaptive.threshold >= 0.0))
        return model::makeError("the adaptive threshold must be a non-negative number", "/solver/adaptive/threshold");
    if (s.hemicube < 2)
        return model::makeError("the hemicube resolution must be at least 2", "/solver/hemicube");
    return checkMeshSettings(s);
}

model::Check checkMeshSettings(const model::SolverSettings& s)
{
    if (!(s.patchSize > 0.0) || !std::isfinite(s.patchSize))
        return model::makeError("the patch size must be a positive length", "/solver/patchSize");
    if (s.elementsPerPatch < 1)
        return model::makeError("the element/patch ratio must be at least 1", "/solver/elementsPerPatch");
    return model::success();
}

} // namespace regio::solver
