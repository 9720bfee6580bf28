#include "editor/document/commands/bsp_order_commands.h"

#include "editor/document/qt_conversions.h"

#include <QCoreApplication>

namespace regio::editor {

SetBspOrder::SetBspOrder(SceneDocument* document, std::string regionId, std::vector<std::string> order)
    : ChangeValue(
          document,
          QCoreApplication::translate("regio::editor::Commands", "Set BSP order of %1").arg(toQString(regionId)),
          Change::Regions, regionId, order)
{
}

model::Result<std::vector<std::string>> SetBspOrder::set(model::Scene& scene, const std::string& target,
                                                         const std::vector<std::string>& value)
{
    return model::setBspOrder(scene, target, value);
}

InsertBspEntry::InsertBspEntry(SceneDocument* document, std::string regionId, std::string faceId, int index)
    : SceneCommand(document, QCoreApplication::translate("regio::editor::Commands", "Add %1 to the BSP order of %2")
                                 .arg(toQString(faceId), toQString(regionId)))
    , m_regionId(std::move(regionId))
    , m_faceId(std::move(faceId))
    , m_index(index)
{
}

void InsertBspEntry::redo()
{
    auto index = model::insertBspEntry(scene(), m_regionId, m_faceId, m_usedIndex >= 0 ? m_usedIndex : m_index);
    if (!index)
        return fail(index.error());
    m_usedIndex = *index;
    notify(Change::Regions);
}

void InsertBspEntry::undo()
{
    if (auto r = model::removeBspEntry(scene(), m_regionId, m_usedIndex); !r)
        return fail(r.error());
    notify(Change::Regions);
}

RemoveBspEntry::RemoveBspEntry(SceneDocument* document, std::string regionId, int index)
    : SceneCommand(document,
                   QCoreApplication::translate("regio::editor::Commands", "Remove entry %1 from the BSP order of %2")
                       .arg(index + 1)
                       .arg(toQString(regionId)))
    , m_regionId(std::move(regionId))
    , m_index(index)
{
}

void RemoveBspEntry::redo()
{
    auto removed = model::removeBspEntry(scene(), m_regionId, m_index);
    if (!removed)
        return fail(removed.error());
    m_removed = std::move(*removed);
    notify(Change::Regions);
}

void RemoveBspEntry::undo()
{
    if (auto r = model::insertBspEntry(scene(), m_regionId, m_removed.faceId, m_removed.index); !r)
        return fail(r.error());
    notify(Change::Regions);
}

MoveBspEntry::MoveBspEntry(SceneDocument* document, std::string regionId, int from, int to)
    : SceneCommand(document, QCoreApplication::translate("regio::editor::Commands", "Move BSP entry %1 of %2 to %3")
                                 .arg(from + 1)
                                 .arg(toQString(regionId))
                                 .arg(to + 1))
    , m_regionId(std::move(regionId))
    , m_from(from)
    , m_to(to)
{
}

void MoveBspEntry::redo()
{
    if (auto r = model::moveBspEntry(scene(), m_regionId, m_from, m_to); !r)
        return fail(r.error());
    notify(Change::Regions);
}

void MoveBspEntry::undo()
{
    if (auto r = model::moveBspEntry(scene(), m_regionId, m_to, m_from); !r)
        return fail(r.error());
    notify(Change::Regions);
}

} // namespace regio::editor
