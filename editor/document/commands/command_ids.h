#pragma once
// Merge ids of every command that merges with its successor (QUndoCommand::id).
// One enum for the whole editor so two families can never collide. A command
// merges only with the same id and the same target (see each mergeWith).
namespace regio::editor {

enum CommandId : int {
    TransformPartsId = 1,
    SetMaterialReflectanceId,
    SetMaterialEmissionId,
    SetMaterialNameId,
    SetRegionBoxId,
    SetRegionNameId,
    SetSolverSettingsId,
    SetObjectNameId,
    SetPartNameId,
};

} // namespace regio::editor
