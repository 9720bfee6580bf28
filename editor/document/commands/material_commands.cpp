#include "editor/document/commands/material_commands.h"

#include "editor/document/commands/command_ids.h"
#include "editor/document/qt_conversions.h"

#include <QCoreApplication>

namespace regio::editor {

AddMaterial::AddMaterial(SceneDocument* document, model::Material material, int index)
    : SceneCommand(
          document,
          QCoreApplication::translate("regio::editor::Commands", "Add material %1").arg(toQString(material.id)))
    , m_material(std::move(material))
    , m_index(index)
{
}

void AddMaterial::redo()
{
    auto index = model::addMaterial(scene(), m_material, m_usedIndex >= 0 ? m_usedIndex : m_index);
    if (!index)
        return fail(index.error());
    m_usedIndex = *index;
    notify(Change::Materials);
}

void AddMaterial::undo()
{
    if (auto r = model::removeMaterial(scene(), m_material.id); !r)
        return fail(r.error());
    notify(Change::Materials);
}

RemoveMaterial::RemoveMaterial(SceneDocument* document, std::string materialId)
    : SceneCommand(
          document,
          QCoreApplication::translate("regio::editor::Commands", "Delete material %1").arg(toQString(materialId)))
    , m_materialId(std::move(materialId))
{
}

void RemoveMaterial::redo()
{
    auto removed = model::removeMaterial(scene(), m_materialId);
    if (!removed)
        return fail(removed.error());
    m_removed = std::move(*removed);
    notify(Change::Materials);
}

void RemoveMaterial::undo()
{
    if (auto r = model::addMaterial(scene(), m_removed->material, m_removed->index); !r)
        return fail(r.error());
    notify(Change::Materials);
}

RenameMaterial::RenameMaterial(SceneDocument* document, std::string materialId, std::string newId)
    : SceneCommand(document, QCoreApplication::translate("regio::editor::Commands", "Rename %1 to %2")
                                 .arg(toQString(materialId), toQString(newId)))
    , m_from(std::move(materialId))
    , m_to(std::move(newId))
{
}

void RenameMaterial::redo()
{
    if (auto r = model::renameMaterial(scene(), m_from, m_to); !r)
        return fail(r.error());
    notify(Change::Materials | Change::Objects); // part and face references follow
}

void RenameMaterial::undo()
{
    if (auto r = model::renameMaterial(scene(), m_to, m_from); !r)
        return fail(r.error());
    notify(Change::Materials | Change::Objects);
}

SetMaterialName::SetMaterialName(SceneDocument* document, std::string materialId, std::string name)
    : ChangeValue(document,
                  QCoreApplication::translate("regio::editor::Commands", "Name %1 \"%2\"")
                      .arg(toQString(materialId), toQString(name)),
                  Change::Materials, materialId, name, SetMaterialNameId)
{
}

model::Result<std::string> SetMaterialName::set(model::Scene& scene, const std::string& target,
                                                const std::string& value)
{
    return model::setMaterialName(scene, target, value);
}

SetMaterialReflectance::SetMaterialReflectance(SceneDocument* document, std::string materialId,
                                               const model::Rgb& reflectance)
    : ChangeValue(
          document,
          QCoreApplication::translate("regio::editor::Commands", "Reflectance of %1").arg(toQString(materialId)),
          Change::Materials, materialId, reflectance, SetMaterialReflectanceId)
{
}

model::Result<model::Rgb> SetMaterialReflectance::set(model::Scene& scene, const std::string& target,
                                                      const model::Rgb& value)
{
    return model::setMaterialReflectance(scene, target, value);
}

SetMaterialEmission::SetMaterialEmission(SceneDocument* document, std::string materialId, const model::Rgb& emission)
    : ChangeValue(document,
                  QCoreApplication::translate("regio::editor::Commands", "Emission of %1").arg(toQString(materialId)),
                  Change::Materials, materialId, emission, SetMaterialEmissionId)
{
}

model::Result<model::Rgb> SetMaterialEmission::set(model::Scene& scene, const std::string& target,
                                                   const model::Rgb& value)
{
    return model::setMaterialEmission(scene, target, value);
}

} // namespace regio::editor
