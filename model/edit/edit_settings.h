#pragma once
// Edits of the solver settings and the saved camera. Each returns the
// previous value, so undo sets it back; refused values leave the scene as it was.
#include "model/result.h"
#include "model/scene.h"

#include <optional>

namespace regio::model {

// Ranges (checked in this order; the diagnostic points at the offending key,
// e.g. "/solver/hemicube"):
//   hemicube            even, 8..4096 (the side faces are N x N/2 pixels)
//   patchSize           finite, > 0 metres
//   elementsPerPatch    1..4096
//   adaptive.threshold  finite, in (0, 1] (a relative luminance difference)
//   adaptive.minEdge    finite, > 0 metres
//   maxIterations       >= 1
//   convergence         finite, in (0, 1) (a fraction of the emitted power)
Check checkSolverSettings(const SolverSettings& settings);
Result<SolverSettings> setSolverSettings(Scene& scene, const SolverSettings& settings);

// A camera needs finite vectors, a target away from the position, an up
// vector not along the view direction and a vertical field of view in
// (0, 180) degrees. The diagnostic points into "/camera".
Check checkCamera(const Camera& camera);
// std::nullopt clears the camera. Returns the previous camera (or nullopt).
Result<std::optional<Camera>> setCamera(Scene& scene, const std::optional<Camera>& camera);
Result<std::optional<Camera>> clearCamera(Scene& scene);

} // namespace regio::model
