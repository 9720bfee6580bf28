#include "editor/document/commands/region_commands.h"

#include "editor/document/commands/command_ids.h"
#include "editor/document/qt_conversions.h"

#include <QCoreApplication>

namespace regio::editor {

AddRegion::AddRegion(SceneDocument* document, model::Region region, int index)
    : SceneCommand(document,
                   QCoreApplication::translate("regio::editor::Commands", "Add region %1").arg(toQString(region.id)))
    , m_region(std::move(region))
    , m_index(index)
{
}

void AddRegion::redo()
{
    auto index = model::addRegion(scene(), m_region, m_usedIndex >= 0 ? m_usedIndex : m_index);
    if (!index)
        return fail(index.error());
    m_usedIndex = *index;
    notify(Change::Regions);
}

void AddRegion::undo()
{
    if (auto r = model::removeRegion(scene(), m_region.id); !r)
        return fail(r.error());
    notify(Change::Regions);
}

RemoveRegion::RemoveRegion(SceneDocument* document, std::string regionId)
    : SceneCommand(document,
                   QCoreApplication::translate("regio::editor::Commands", "Delete region %1").arg(toQString(regionId)))
    , m_regionId(std::move(regionId))
{
}

void RemoveRegion::redo()
{
    auto removed = model::removeRegion(scene(), m_regionId);
    if (!removed)
        return fail(removed.error());
    m_removed = std::move(*removed);
    notify(Change::Regions);
}

void RemoveRegion::undo()
{
    if (auto r = model::addRegion(scene(), m_removed->region, m_removed->index); !r)
        return fail(r.error());
    notify(Change::Regions);
}

RenameRegion::RenameRegion(SceneDocument* document, std::string regionId, std::string newId)
    : SceneCommand(document, QCoreApplication::translate("regio::editor::Commands", "Rename %1 to %2")
                                 .arg(toQString(regionId), toQString(newId)))
    , m_from(std::move(regionId))
    , m_to(std::move(newId))
{
}

void RenameRegion::redo()
{
    if (auto r = model::renameRegion(scene(), m_from, m_to); !r)
        return fail(r.error());
    notify(Change::Regions);
}

void RenameRegion::undo()
{
    if (auto r = model::renameRegion(scene(), m_to, m_from); !r)
        return fail(r.error());
    notify(Change::Regions);
}

SetRegionName::SetRegionName(SceneDocument* document, std::string regionId, std::string name)
    : ChangeValue(document,
                  QCoreApplication::translate("regio::editor::Commands", "Name %1 \"%2\"")
                      .arg(toQString(regionId), toQString(name)),
                  Change::Regions, regionId, name, SetRegionNameId)
{
}

model::Result<std::string> SetRegionName::set(model::Scene& scene, const std::string& target, const std::string& value)
{
    return model::setRegionName(scene, target, value);
}

SetRegionBox::SetRegionBox(SceneDocument* document, std::string regionId, const model::Vec3& min,
                           const model::Vec3& max)
    : ChangeValue(document,
                  QCoreApplication::translate("regio::editor::Commands", "Resize region %1").arg(toQString(regionId)),
                  Change::Regions, regionId, model::RegionBox{min, max}, SetRegionBoxId)
{
}

model::Result<model::RegionBox> SetRegionBox::set(model::Scene& scene, const std::string& target,
                                                  const model::RegionBox& value)
{
    return model::setRegionBox(scene, target, value.min, value.max);
}

} // namespace regio::editor
