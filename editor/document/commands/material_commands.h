#pragma once
// Undo commands on materials: the list and each material's values.
#include "editor/document/commands/change_value.h"
#include "model/edit/edit_materials.h"

#include <optional>

namespace regio::editor {

class AddMaterial : public SceneCommand {
public:
    AddMaterial(SceneDocument* document, model::Material material, int index = -1);
    void redo() override;
    void undo() override;

private:
    model::Material m_material;
    int m_index;
    int m_usedIndex = -1;
};

// Refused while any part or face uses the material.
class RemoveMaterial : public SceneCommand {
public:
    RemoveMaterial(SceneDocument* document, std::string materialId);
    void redo() override;
    void undo() override;

private:
    std::string m_materialId;
    std::optional<model::RemovedMaterial> m_removed;
};

// Changes a material's id and every reference to it.
class RenameMaterial : public SceneCommand {
public:
    RenameMaterial(SceneDocument* document, std::string materialId, std::string newId);
    void redo() override;
    void undo() override;

private:
    std::string m_from, m_to;
};

class SetMaterialName : public ChangeValue<std::string> {
public:
    SetMaterialName(SceneDocument* document, std::string materialId, std::string name);

protected:
    model::Result<std::string> set(model::Scene& scene, const std::string& target, const std::string& value) override;
};

class SetMaterialReflectance : public ChangeValue<model::Rgb> {
public:
    SetMaterialReflectance(SceneDocument* document, std::string materialId, const model::Rgb& reflectance);

protected:
    model::Result<model::Rgb> set(model::Scene& scene, const std::string& target, const model::Rgb& value) override;
};

class SetMaterialEmission : public ChangeValue<model::Rgb> {
public:
    SetMaterialEmission(SceneDocument* document, std::string materialId, const model::Rgb& emission);

protected:
    model::Result<model::Rgb> set(model::Scene& scene, const std::string& target, const model::Rgb& value) override;
};

} // namespace regio::editor
