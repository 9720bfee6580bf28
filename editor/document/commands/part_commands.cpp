#include "editor/document/commands/part_commands.h"

#include "editor/document/commands/command_ids.h"
#include "editor/document/qt_conversions.h"
#include "model/geometry/transform.h"

#include <QCoreApplication>

namespace regio::editor {

// --- AddPart -----------------------------------------------------------------

AddPart::AddPart(SceneDocument* document, std::string objectId, model::Part part, int index)
    : SceneCommand(document, QCoreApplication::translate("regio::editor::Commands", "Add %1").arg(toQString(part.id)))
    , m_objectId(std::move(objectId))
    , m_part(std::move(part))
    , m_index(index)
{
}

void AddPart::redo()
{
    if (m_removed) {
        if (auto r = model::restorePart(scene(), *m_removed); !r)
            return fail(r.error());
    } else if (auto r = model::addPart(scene(), m_objectId, m_part, m_index); !r) {
        return fail(r.error());
    }
    notify(Change::Objects);
}

void AddPart::undo()
{
    auto removed = model::removePart(scene(), m_part.id);
    if (!removed)
        return fail(removed.error());
    m_removed = std::move(*removed);
    notify(Change::Objects | Change::Regions);
}

// --- RemovePart ----------------------------------------------------------------

RemovePart::RemovePart(SceneDocument* document, std::string partId)
    : SceneCommand(document, QCoreApplication::translate("regio::editor::Commands", "Delete %1").arg(toQString(partId)))
    , m_partId(std::move(partId))
{
}

void RemovePart::redo()
{
    auto removed = model::removePart(scene(), m_partId);
    if (!removed)
        return fail(removed.error());
    m_removed = std::move(*removed);
    notify(Change::Objects | Change::Regions);
}

void RemovePart::undo()
{
    if (auto r = model::restorePart(scene(), *m_removed); !r)
        return fail(r.error());
    notify(Change::Objects | Change::Regions);
}

// --- DuplicatePart -------------------------------------------------------------

DuplicatePart::DuplicatePart(SceneDocument* document, std::string partId)
    : SceneCommand(document,
                   QCoreApplication::translate("regio::editor::Commands", "Duplicate %1").arg(toQString(partId)))
    , m_partId(std::move(partId))
{
}

void DuplicatePart::redo()
{
    if (m_removed) {
        if (auto r = model::restorePart(scene(), *m_removed); !r)
            return fail(r.error());
    } else {
        auto copy = model::duplicatePart(scene(), m_partId);
        if (!copy)
            return fail(copy.error());
        m_copyId = *copy;
    }
    notify(Change::Objects);
}

void DuplicatePart::undo()
{
    auto removed = model::removePart(scene(), m_copyId);
    if (!removed)
        return fail(removed.error());
    m_removed = std::move(*removed);
    notify(Change::Objects);
}

// --- RenamePart ------------------------------------------------------------------

RenamePart::RenamePart(SceneDocument* document, std::string partId, std::string newId)
    : SceneCommand(document, QCoreApplication::translate("regio::editor::Commands", "Rename %1 to %2")
                                 .arg(toQString(partId), toQString(newId)))
    , m_from(std::move(partId))
    , m_to(std::move(newId))
{
}

void RenamePart::redo()
{
    if (auto r = model::renamePart(scene(), m_from, m_to); !r)
        return fail(r.error());
    notify(Change::Objects);
}

void RenamePart::undo()
{
    if (auto r = model::renamePart(scene(), m_to, m_from); !r)
        return fail(r.error());
    notify(Change::Objects);
}

// --- names and materials ---------------------------------------------------------

SetPartName::SetPartName(SceneDocument* document, std::string partId, std::string name)
    : ChangeValue(document,
                  QCoreApplication::translate("regio::editor::Commands", "Name %1 \"%2\"")
                      .arg(toQString(partId), toQString(name)),
                  Change::Objects, partId, name, SetPartNameId)
{
}

model::Result<std::string> SetPartName::set(model::Scene& scene, const std::string& target, const std::string& value)
{
    return model::setPartName(scene, target, value);
}

SetPartMaterial::SetPartMaterial(SceneDocument* document, std::string partId, std::string material)
    : ChangeValue(document,
                  QCoreApplication::translate("regio::editor::Commands", "Material of %1: %2")
                      .arg(toQString(partId), toQString(material)),
                  Change::Objects, partId, material)
{
}

model::Result<std::string> SetPartMaterial::set(model::Scene& scene, const std::string& target,
                                                const std::string& value)
{
    return model::setPartMaterial(scene, target, value);
}

SetFaceMaterial::SetFaceMaterial(SceneDocument* document, std::string faceId, std::string material)
    : ChangeValue(document,
                  material.empty()
                      ? QCoreApplication::translate("regio::editor::Commands", "Material of %1: the part's")
                            .arg(toQString(faceId))
                      : QCoreApplication::translate("regio::editor::Commands", "Material of %1: %2")
                            .arg(toQString(faceId), toQString(material)),
                  Change::Objects, faceId, material)
{
}

model::Result<std::string> SetFaceMaterial::set(model::Scene& scene, const std::string& target,
                                                const std::string& value)
{
    return model::setFaceMaterial(scene, target, value);
}

// --- MovePart ----------------------------------------------------------------------

MovePart::MovePart(SceneDocument* document, std::string partId, std::string objectId, int index)
    : SceneCommand(document, QCoreApplication::translate("regio::editor::Commands", "Move %1 to %2")
                                 .arg(toQString(partId), toQString(objectId)))
    , m_partId(std::move(partId))
    , m_target{std::move(objectId), index}
{
}

void MovePart::redo()
{
    auto previous = model::movePart(scene(), m_partId, m_target.objectId, m_target.index);
    if (!previous)
        return fail(previous.error());
    m_previous = std::move(*previous);
    notify(Change::Objects);
}

void MovePart::undo()
{
    if (auto r = model::movePart(scene(), m_partId, m_previous.objectId, m_previous.index); !r)
        return fail(r.error());
    notify(Change::Objects);
}

// --- RenameFace ----------------------------------------------------------------------

RenameFace::RenameFace(SceneDocument* document, std::string faceId, std::string newId)
    : SceneCommand(document, QCoreApplication::translate("regio::editor::Commands", "Rename %1 to %2")
                                 .arg(toQString(faceId), toQString(newId)))
    , m_from(std::move(faceId))
    , m_to(std::move(newId))
{
}

void RenameFace::redo()
{
    if (auto r = model::renameFace(scene(), m_from, m_to); !r)
        return fail(r.error());
    notify(Change::Objects | Change::Regions);
}

void RenameFace::undo()
{
    if (auto r = model::renameFace(scene(), m_to, m_from); !r)
        return fail(r.error());
    notify(Change::Objects | Change::Regions);
}

// --- TransformParts ------------------------------------------------------------------

TransformParts::TransformParts(SceneDocument* document, const QString& text)
    : SceneCommand(document, text)
{
}

TransformParts::TransformParts(SceneDocument* document, std::vector<std::string> partIds, const glm::dmat4& transform,
                               const QString& text)
    : SceneCommand(document, text.isEmpty()
                                 ? QCoreApplication::translate("regio::editor::Commands", "Transform %n part(s)",
                                                               nullptr, int(partIds.size()))
                                 : text)
    , m_partIds(std::move(partIds))
    , m_transform(transform)
{
}

TransformParts* TransformParts::dragStep(SceneDocument* document, const std::vector<model::PartGeometry>& start,
                                         const glm::dmat4& transform, int serial, const QString& text)
{
    auto* command = new TransformParts(document, text);
    command->m_serial = serial;
    command->m_transform = transform;
    command->m_target = start;
    for (model::PartGeometry& geometry : command->m_target) {
        command->m_partIds.push_back(geometry.partId);
        model::transformVertices(geometry.vertices, geometry.faces, transform);
    }
    return command;
}

int TransformParts::id() const { return m_serial > 0 ? TransformPartsId : -1; }

bool TransformParts::mergeWith(const QUndoCommand* other)
{
    if (!canMerge(other))
        return false;
    const auto* next = dynamic_cast<const TransformParts*>(other);
    if (!next || next->m_serial != m_serial || next->m_partIds != m_partIds)
        return false;
    m_transform = next->m_transform;
    m_after = next->m_after;
    if (m_after == m_before)
        setObsolete(true); // dragged back to where it started
    return true;
}

void TransformParts::redo()
{
    if (m_applied) {
        if (auto r = model::setPartGeometries(scene(), m_after); !r)
            return fail(r.error());
    } else {
        if (model::Check affine = model::checkAffineTransform(m_transform); !affine)
            return fail(affine.error());
        auto before = m_target.empty() ? model::transformParts(scene(), m_partIds, m_transform)
                                       : model::setPartGeometries(scene(), m_target);
        if (!before)
            return fail(before.error());
        m_before = std::move(*before);
        for (const std::string& id : m_partIds)
            m_after.push_back(model::geometryOf(*scene().findPart(id)));
        m_target.clear();
        m_applied = true;
    }
    notify(Change::Geometry);
}

void TransformParts::undo()
{
    if (auto r = model::setPartGeometries(scene(), m_before); !r)
        return fail(r.error());
    notify(Change::Geometry);
}

// --- SplitPart ------------------------------------------------------------------------

SplitPart::SplitPart(SceneDocument* document, std::string partId, const model::Plane& plane, std::string frontId,
                     std::string backId, model::CutCaps caps)
    : SceneCommand(document, QCoreApplication::translate("regio::editor::Commands", "Split %1").arg(toQString(partId)))
    , m_partId(std::move(partId))
    , m_plane(plane)
    , m_frontId(std::move(frontId))
    , m_backId(std::move(backId))
    , m_caps(caps)
{
}

void SplitPart::redo()
{
    // The cut is deterministic: redoing it gives the same parts and ids.
    auto split = model::splitPartInScene(scene(), m_partId, m_plane, m_frontId, m_backId, m_caps);
    if (!split)
        return fail(split.error());
    m_split = std::move(*split);
    notify(Change::Objects | Change::Regions);
}

void SplitPart::undo()
{
    if (auto r = model::unsplitPart(scene(), *m_split); !r)
        return fail(r.error());
    notify(Change::Objects | Change::Regions);
}

} // namespace regio::editor
