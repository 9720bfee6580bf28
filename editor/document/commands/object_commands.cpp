#include "editor/document/commands/object_commands.h"

#include "editor/document/commands/command_ids.h"
#include "editor/document/qt_conversions.h"
#include "model/edit/edit_support.h"

#include <QCoreApplication>

#include <algorithm>
#include <unordered_set>

namespace regio::editor {

// --- AddObject ---------------------------------------------------------------

AddObject::AddObject(SceneDocument* document, model::Object object, int index)
    : SceneCommand(document, QCoreApplication::translate("regio::editor::Commands", "Add %1").arg(toQString(object.id)))
    , m_object(std::move(object))
    , m_index(index)
{
}

void AddObject::redo()
{
    if (m_removed) {
        if (auto r = model::restoreObject(scene(), *m_removed); !r)
            return fail(r.error());
    } else if (auto r = model::insertObject(scene(), m_object, m_index); !r) {
        return fail(r.error());
    }
    notify(Change::Objects);
}

void AddObject::undo()
{
    auto removed = model::removeObject(scene(), m_object.id);
    if (!removed)
        return fail(removed.error());
    m_removed = std::move(*removed);
    notify(Change::Objects | Change::Regions);
}

// --- RemoveObject ------------------------------------------------------------

RemoveObject::RemoveObject(SceneDocument* document, std::string objectId)
    : SceneCommand(document,
                   QCoreApplication::translate("regio::editor::Commands", "Delete %1").arg(toQString(objectId)))
    , m_objectId(std::move(objectId))
{
}

void RemoveObject::redo()
{
    auto removed = model::removeObject(scene(), m_objectId);
    if (!removed)
        return fail(removed.error());
    m_removed = std::move(*removed);
    notify(Change::Objects | Change::Regions); // its faces left the BSP orders
}

void RemoveObject::undo()
{
    if (auto r = model::restoreObject(scene(), *m_removed); !r)
        return fail(r.error());
    notify(Change::Objects | Change::Regions);
}

// --- DuplicateObject ---------------------------------------------------------

DuplicateObject::DuplicateObject(SceneDocument* document, std::string objectId)
    : SceneCommand(document,
                   QCoreApplication::translate("regio::editor::Commands", "Duplicate %1").arg(toQString(objectId)))
    , m_objectId(std::move(objectId))
{
}

void DuplicateObject::redo()
{
    if (m_removed) {
        if (auto r = model::restoreObject(scene(), *m_removed); !r)
            return fail(r.error());
    } else {
        auto copy = model::duplicateObject(scene(), m_objectId);
        if (!copy)
            return fail(copy.error());
        m_copyId = *copy;
    }
    notify(Change::Objects);
}

void DuplicateObject::undo()
{
    auto removed = model::removeObject(scene(), m_copyId);
    if (!removed)
        return fail(removed.error());
    m_removed = std::move(*removed);
    notify(Change::Objects);
}

// --- RenameObject ------------------------------------------------------------

RenameObject::RenameObject(SceneDocument* document, std::string objectId, std::string newId)
    : SceneCommand(document, QCoreApplication::translate("regio::editor::Commands", "Rename %1 to %2")
                                 .arg(toQString(objectId), toQString(newId)))
    , m_from(std::move(objectId))
    , m_to(std::move(newId))
{
}

void RenameObject::redo()
{
    if (auto r = model::renameObject(scene(), m_from, m_to); !r)
        return fail(r.error());
    notify(Change::Objects);
}

void RenameObject::undo()
{
    if (auto r = model::renameObject(scene(), m_to, m_from); !r)
        return fail(r.error());
    notify(Change::Objects);
}

// --- SetObjectName -----------------------------------------------------------

SetObjectName::SetObjectName(SceneDocument* document, std::string objectId, std::string name)
    : ChangeValue(document,
                  QCoreApplication::translate("regio::editor::Commands", "Name %1 \"%2\"")
                      .arg(toQString(objectId), toQString(name)),
                  Change::Objects, objectId, name, SetObjectNameId)
{
}

model::Result<std::string> SetObjectName::set(model::Scene& scene, const std::string& target, const std::string& value)
{
    return model::setObjectName(scene, target, value);
}

// --- ChangeObjectLayout ------------------------------------------------------

ChangeObjectLayout::ChangeObjectLayout(SceneDocument* document, const QString& text, Edit edit)
    : SceneCommand(document, text)
    , m_edit(std::move(edit))
{
}

void ChangeObjectLayout::redo()
{
    if (m_after) {
        if (auto r = model::restoreObjectLayout(scene(), *m_after); !r)
            return fail(r.error());
    } else {
        auto before = m_edit(scene());
        if (!before)
            return fail(before.error());
        m_before = std::move(*before);
        m_after = model::objectLayout(scene());
    }
    notify(Change::Objects);
}

void ChangeObjectLayout::undo()
{
    if (auto r = model::restoreObjectLayout(scene(), *m_before); !r)
        return fail(r.error());
    notify(Change::Objects);
}

ChangeObjectLayout* ChangeObjectLayout::groupParts(SceneDocument* document, std::vector<std::string> partIds,
                                                   std::string objectId)
{
    const QString text =
        QCoreApplication::translate("regio::editor::Commands", "Group %n part(s)", nullptr, int(partIds.size()));
    return new ChangeObjectLayout(document, text, [partIds, objectId](model::Scene& scene) {
        return model::groupParts(scene, partIds, objectId);
    });
}

ChangeObjectLayout* ChangeObjectLayout::groupObjects(SceneDocument* document, std::vector<std::string> objectIds,
                                                     std::string objectId)
{
    const QString text =
        QCoreApplication::translate("regio::editor::Commands", "Group objects into %1").arg(toQString(objectId));
    return new ChangeObjectLayout(document, text, [objectIds, objectId](model::Scene& scene) {
        return model::groupObjects(scene, objectIds, objectId);
    });
}

ChangeObjectLayout* ChangeObjectLayout::ungroup(SceneDocument* document, std::string objectId)
{
    const QString text = QCoreApplication::translate("regio::editor::Commands", "Ungroup %1").arg(toQString(objectId));
    return new ChangeObjectLayout(document, text,
                                  [objectId](model::Scene& scene) { return model::ungroupObject(scene, objectId); });
}

ChangeObjectLayout* ChangeObjectLayout::moveParts(SceneDocument* document, std::vector<std::string> partIds,
                                                  std::string targetObjectId)
{
    const QString text =
        targetObjectId.empty()
            ? QCoreApplication::translate("regio::editor::Commands", "Make parts separate objects")
            : QCoreApplication::translate("regio::editor::Commands", "Move parts to %1").arg(toQString(targetObjectId));
    return new ChangeObjectLayout(document, text, [partIds, targetObjectId](model::Scene& scene) {
        auto layout = layoutWithPartsMoved(scene, partIds, targetObjectId);
        if (!layout)
            return model::Result<model::ObjectLayout>(layout.error());
        return model::restoreObjectLayout(scene, *layout);
    });
}

model::Result<model::ObjectLayout> layoutWithPartsMoved(const model::Scene& scene,
                                                        const std::vector<std::string>& partIds,
                                                        const std::string& targetObjectId)
{
    if (partIds.empty())
        return model::makeError("no parts to move");
    std::unordered_set<std::string> moving;
    for (const std::string& id : partIds) {
        if (!scene.findPart(id))
            return model::edit::unknown("part", id);
        if (!moving.insert(id).second)
            return model::makeError("part \"" + id + "\" is listed twice");
    }
    if (!targetObjectId.empty() && !scene.findObject(targetObjectId))
        return model::edit::unknown("object", targetObjectId);

    model::ObjectLayout layout = model::objectLayout(scene);
    for (auto& entry : layout.objects)
        std::erase_if(entry.parts, [&](const std::string& p) { return moving.count(p) > 0; });
    if (targetObjectId.empty()) {
        // Each part becomes an object named after it, where its object was.
        model::edit::IdAllocator ids(scene);
        std::vector<model::ObjectLayout::Entry> entries;
        for (const model::Object& object : scene.objects) {
            auto entry = std::find_if(layout.objects.begin(), layout.objects.end(),
                                      [&](const auto& e) { return e.id == object.id; });
            if (!entry->parts.empty())
                entries.push_back(*entry);
            for (const model::Part& part : object.parts) {
                if (!moving.count(part.id))
                    continue;
                // The ungroup rule: "table.legs" of "table" -> "table-legs".
                const std::string prefix = object.id + ".";
                const std::string rest = part.id.starts_with(prefix) ? part.id.substr(prefix.size()) : part.id;
                std::string id = ids.fresh(object.id + "-" + rest);
                entries.push_back({std::move(id), part.name, {part.id}});
            }
        }
        layout.objects = std::move(entries);
    } else {
        for (auto& entry : layout.objects)
            if (entry.id == targetObjectId)
                entry.parts.insert(entry.parts.end(), partIds.begin(), partIds.end());
        std::erase_if(layout.objects, [](const auto& e) { return e.parts.empty(); });
    }
    return layout;
}

} // namespace regio::editor
