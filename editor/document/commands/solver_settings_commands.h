#pragma once
// Undo commands on the solver settings and the scene's stored camera.
#include "editor/document/commands/change_value.h"
#include "model/edit/edit_settings.h"

#include <optional>

namespace regio::editor {

// Replaces the settings; consecutive edits (spin boxes scrubbed) merge.
class SetSolverSettings : public ChangeValue<model::SolverSettings> {
public:
    SetSolverSettings(SceneDocument* document, const model::SolverSettings& settings);

protected:
    model::Result<model::SolverSettings> set(model::Scene& scene, const std::string& target,
                                             const model::SolverSettings& value) override;
};

// Stores the view as the scene's camera (or clears it with nullopt).
class SetSceneCamera : public ChangeValue<std::optional<model::Camera>> {
public:
    SetSceneCamera(SceneDocument* document, const std::optional<model::Camera>& camera);

protected:
    model::Result<std::optional<model::Camera>> set(model::Scene& scene, const std::string& target,
                                                    const std::optional<model::Camera>& value) override;
};

} // namespace regio::editor
