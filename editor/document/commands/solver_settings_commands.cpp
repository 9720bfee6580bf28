#include "editor/document/commands/solver_settings_commands.h"

#include "editor/document/commands/command_ids.h"

#include <QCoreApplication>

namespace regio::editor {

SetSolverSettings::SetSolverSettings(SceneDocument* document, const model::SolverSettings& settings)
    : ChangeValue(document, QCoreApplication::translate("regio::editor::Commands", "Change solver settings"),
                  Change::Settings, std::string(), settings, SetSolverSettingsId)
{
}

model::Result<model::SolverSettings> SetSolverSettings::set(model::Scene& scene, const std::string&,
                                                            const model::SolverSettings& value)
{
    return model::setSolverSettings(scene, value);
}

SetSceneCamera::SetSceneCamera(SceneDocument* document, const std::optional<model::Camera>& camera)
    : ChangeValue(document,
                  camera ? QCoreApplication::translate("regio::editor::Commands", "Store the view as the scene camera")
                         : QCoreApplication::translate("regio::editor::Commands", "Clear the scene camera"),
                  Change::Camera, std::string(), camera)
{
}

model::Result<std::optional<model::Camera>> SetSceneCamera::set(model::Scene& scene, const std::string&,
                                                                const std::optional<model::Camera>& value)
{
    return model::setCamera(scene, value);
}

} // namespace regio::editor
