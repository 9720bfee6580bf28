#include "model/edit/edit_settings.h"

#include "model/edit/edit_support.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace regio::model {

namespace {

Check settingError(const std::string& key, const std::string& expected)
{
    return makeError(key + " must be " + expected, "/solver/" + key);
}

} // namespace

Check checkSolverSettings(const SolverSettings& s)
{
    if (s.hemicube < 8 || s.hemicube > 4096 || s.hemicube % 2 != 0)
        return settingError("hemicube", "an even resolution from 8 to 4096, not " + std::to_string(s.hemicube));
    if (!std::isfinite(s.patchSize) || s.patchSize <= 0.0)
        return settingError("patchSize", "a positive length in metres");
    if (s.elementsPerPatch < 1 || s.elementsPerPatch > 4096)
        return settingError("elementsPerPatch", "from 1 to 4096, not " + std::to_string(s.elementsPerPatch));
    if (!std::isfinite(s.adaptive.threshold) || s.adaptive.threshold <= 0.0 || s.adaptive.threshold > 1.0)
        return settingError("adaptive/threshold", "a relative difference in (0, 1]");
    if (!std::isfinite(s.adaptive.minEdge) || s.adaptive.minEdge <= 0.0)
        return settingError("adaptive/minEdge", "a positive length in metres");
    if (s.maxIterations < 1)
        return settingError("maxIterations", "at least 1, not " + std::to_string(s.maxIterations));
    if (!std::isfinite(s.convergence) || s.convergence <= 0.0 || s.convergence >= 1.0)
        return settingError("convergence", "a fraction of the emitted power in (0, 1)");
    return success();
}

Result<SolverSettings> setSolverSettings(Scene& scene, const SolverSettings& settings)
{
    if (Check check = checkSolverSettings(settings); !check)
        return check.error();
    SolverSettings previous = scene.solver;
    scene.solver = settings;
    return previous;
}

Check checkCamera(const Camera& camera)
{
    if (!edit::isFinite(camera.position) || !edit::isFinite(camera.target) || !edit::isFinite(camera.up) ||
        !std::isfinite(camera.fovY))
        return makeError("the camera needs finite numbers", "/camera");
    Vec3 view = camera.target - camera.position;
    if (glm::length(view) < 1e-9)
        return makeError("the camera target must differ from its position", "/camera/target");
    if (glm::length(camera.up) < 1e-9 ||
        glm::length(glm::cross(glm::normalize(view), glm::normalize(camera.up))) < 1e-6)
        return makeError("the camera's up vector must not point along the view direction", "/camera/up");
    if (camera.fovY <= 0.0 || camera.fovY >= 180.0)
        return makeError("the camera's field of view must lie in (0, 180) degrees", "/camera/fovY");
    return success();
}

Result<std::optional<Camera>> setCamera(Scene& scene, const std::optional<Camera>& camera)
{
    if (camera)
        if (Check check = checkCamera(*camera); !check)
            return check.error();
    std::optional<Camera> previous = scene.camera;
    scene.camera = camera;
    return previous;
}

Result<std::optional<Camera>> clearCamera(Scene& scene) { return setCamera(scene, std::nullopt); }

} // namespace regio::model
