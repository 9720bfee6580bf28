// Authoring: the edits themselves, as undo commands and macros.
#include "editor/objects/authoring.h"

#include "editor/document/commands/material_commands.h"
#include "editor/document/commands/object_commands.h"
#include "editor/document/commands/part_commands.h"
#include "editor/document/commands/region_commands.h"
#include "editor/document/commands/solver_settings_commands.h"
#include "editor/document/qt_conversions.h"
#include "editor/document/scene_document.h"
#include "editor/viewport/scene_mesh.h"
#include "editor/viewport/viewport.h"
#include "model/edit/edit_support.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <unordered_set>

namespace regio::editor {

namespace {

// True if the plane has part vertices strictly on both sides of it.
bool planeCrosses(const model::Part& part, const model::Plane& plane)
{
    bool front = false, back = false;
    for (const model::Vec3& v : part.vertices) {
        const double d = plane.signedDistance(v);
        front = front || d > model::kDistanceEpsilon;
        back = back || d < -model::kDistanceEpsilon;
    }
    return front && back;
}

double snapped(double value, double step) { return step > 0.0 ? std::round(value / step) * step : value; }

} // namespace

bool Authoring::pushMacro(const QString& text, const std::function<bool()>& body)
{
    m_document->beginMacro(text);
    const bool ok = body();
    const bool kept = m_document->endMacro();
    return ok && kept;
}

model::Box3 Authoring::selectionBounds() const
{
    return boundsOfFaces(m_document->scene(), selectedFaceIds(m_document->scene(), m_document->selection()));
}

PrimitiveParams Authoring::defaultPrimitive(PrimitiveKind kind) const
{
    const model::Scene& scene = m_document->scene();
    PrimitiveParams p;
    p.kind = kind;
    p.id = scene.uniqueId(primitiveBaseId(kind));
    if (!scene.materials.empty())
        p.material = scene.materials.front().id;
    const double step = m_viewport->snap().step;
    const model::Vec3 target = m_viewport->camera().target();
    p.base = {snapped(target.x, step), 0.0, snapped(target.z, step)};
    switch (kind) {
    case PrimitiveKind::Box: p.size = {0.5, 0.5, 0.5}; break;
    case PrimitiveKind::Room: p.size = {4.0, 2.5, 4.0}; break;
    case PrimitiveKind::Prism: p.size = {0.5, 1.0, 0.5}; break;
    case PrimitiveKind::Wedge: p.size = {1.0, 0.5, 1.0}; break;
    case PrimitiveKind::Stairs: p.size = {1.0, 1.0, 1.5}; break;
    }
    return p;
}

bool Authoring::createPrimitive(const PrimitiveParams& params)
{
    auto object = buildPrimitive(params);
    if (!object) {
        emit m_document->editFailed(toQString(object.error().message));
        return false;
    }
    model::Object fresh = model::withFreshIds(m_document->scene(), *object);
    const std::string id = fresh.id;
    if (!m_document->push(new AddObject(m_document, std::move(fresh))))
        return false;
    m_document->setSelection(Selection::single(SelectionKind::Object, id));
    return true;
}

bool Authoring::createMaterial()
{
    model::Material material;
    material.id = m_document->scene().uniqueId("material");
    material.reflectance = {0.5, 0.5, 0.5};
    const std::string id = material.id;
    if (!m_document->push(new AddMaterial(m_document, std::move(material))))
        return false;
    m_document->setSelection(Selection::single(SelectionKind::Material, id));
    return true;
}

bool Authoring::duplicateSelection()
{
    const Selection s = m_document->selection();
    if (s.empty() || (s.kind != SelectionKind::Object && s.kind != SelectionKind::Part))
        return false;
    std::vector<std::string> copies;
    const bool ok = pushMacro(tr("Duplicate"), [&] {
        for (const std::string& id : s.ids) {
            if (s.kind == SelectionKind::Object) {
                auto* command = new DuplicateObject(m_document, id);
                if (!m_document->push(command))
                    return false;
                copies.push_back(command->copyId());
            } else {
                auto* command = new DuplicatePart(m_document, id);
                if (!m_document->push(command))
                    return false;
                copies.push_back(command->copyId());
            }
        }
        return true;
    });
    if (ok)
        m_document->setSelection(Selection::of(s.kind, copies));
    return ok;
}

bool Authoring::deleteSelection()
{
    const Selection s = m_document->selection();
    if (s.empty())
        return false;
    const model::Scene& scene = m_document->scene();
    switch (s.kind) {
    case SelectionKind::Object:
        return pushMacro(tr("Delete %n object(s)", nullptr, int(s.ids.size())), [&] {
            for (const std::string& id : s.ids)
                if (!m_document->push(new RemoveObject(m_document, id)))
                    return false;
            return true;
        });
    case SelectionKind::Part: {
        // Objects left without parts go too: an empty whole means nothing.
        std::unordered_set<std::string> removed(s.ids.begin(), s.ids.end());
        std::vector<std::string> emptied;
        for (const model::Object& object : scene.objects) {
            bool all = !object.parts.empty();
            for (const model::Part& part : object.parts)
                all = all && removed.count(part.id);
            if (all)
                emptied.push_back(object.id);
        }
        return pushMacro(tr("Delete %n part(s)", nullptr, int(s.ids.size())), [&] {
            for (const std::string& id : s.ids)
                if (!m_document->push(new RemovePart(m_document, id)))
                    return false;
            for (const std::string& id : emptied)
                if (!m_document->push(new RemoveObject(m_document, id)))
                    return false;
            return true;
        });
    }
    case SelectionKind::Material:
        return pushMacro(tr("Delete %n material(s)", nullptr, int(s.ids.size())), [&] {
            for (const std::string& id : s.ids)
                if (!m_document->push(new RemoveMaterial(m_document, id)))
                    return false;
            return true;
        });
    case SelectionKind::Region:
        return pushMacro(tr("Delete %n region(s)", nullptr, int(s.ids.size())), [&] {
            for (const std::string& id : s.ids)
                if (!m_document->push(new RemoveRegion(m_document, id)))
                    return false;
            return true;
        });
    default:
        // Faces are boundaries of their solid: deleting one would open it.
        emit m_document->editFailed(tr("faces cannot be deleted on their own; split or delete the part"));
        return false;
    }
}

bool Authoring::renameElement(SelectionKind kind, const std::string& id, const std::string& newId,
                              const std::string& newName)
{
    const model::Scene& scene = m_document->scene();
    std::string oldName;
    switch (kind) {
    case SelectionKind::Object: oldName = scene.findObject(id) ? scene.findObject(id)->name : ""; break;
    case SelectionKind::Part: oldName = scene.findPart(id) ? scene.findPart(id)->name : ""; break;
    case SelectionKind::Material: oldName = scene.findMaterial(id) ? scene.findMaterial(id)->name : ""; break;
    case SelectionKind::Region: oldName = scene.findRegion(id) ? scene.findRegion(id)->name : ""; break;
    default: break;
    }
    const bool idChanges = newId != id;
    const bool nameChanges = newName != oldName && kind != SelectionKind::Face;
    if (!idChanges && !nameChanges)
        return false;
    const bool ok = pushMacro(tr("Rename %1").arg(toQString(id)), [&] {
        if (nameChanges) {
            SceneCommand* command = nullptr;
            switch (kind) {
            case SelectionKind::Object: command = new SetObjectName(m_document, id, newName); break;
            case SelectionKind::Part: command = new SetPartName(m_document, id, newName); break;
            case SelectionKind::Material: command = new SetMaterialName(m_document, id, newName); break;
            case SelectionKind::Region: command = new SetRegionName(m_document, id, newName); break;
            default: break;
            }
            if (command && !m_document->push(command))
                return false;
        }
        if (idChanges) {
            SceneCommand* command = nullptr;
            switch (kind) {
            case SelectionKind::Object: command = new RenameObject(m_document, id, newId); break;
            case SelectionKind::Part: command = new RenamePart(m_document, id, newId); break;
            case SelectionKind::Face: command = new RenameFace(m_document, id, newId); break;
            case SelectionKind::Material: command = new RenameMaterial(m_document, id, newId); break;
            case SelectionKind::Region: command = new RenameRegion(m_document, id, newId); break;
            default: break;
            }
            if (!command || !m_document->push(command))
                return false;
        }
        return true;
    });
    if (ok && idChanges)
        m_document->setSelection(Selection::single(kind, newId));
    return ok;
}

bool Authoring::groupSelection()
{
    const Selection s = m_document->selection();
    const std::string objectId = m_document->scene().uniqueId("group");
    bool ok = false;
    if (s.kind == SelectionKind::Part && !s.empty())
        ok = m_document->push(ChangeObjectLayout::groupParts(m_document, s.ids, objectId));
    else if (s.kind == SelectionKind::Object && s.ids.size() >= 2)
        ok = m_document->push(ChangeObjectLayout::groupObjects(m_document, s.ids, objectId));
    if (ok)
        m_document->setSelection(Selection::single(SelectionKind::Object, objectId));
    return ok;
}

bool Authoring::ungroupSelection()
{
    const Selection s = m_document->selection();
    if (s.kind != SelectionKind::Object || s.empty())
        return false;
    std::vector<std::string> targets;
    for (const std::string& id : s.ids)
        if (const model::Object* o = m_document->scene().findObject(id); o && o->parts.size() >= 2)
            targets.push_back(id);
    if (targets.empty())
        return false;
    return pushMacro(tr("Ungroup"), [&] {
        for (const std::string& id : targets)
            if (!m_document->push(ChangeObjectLayout::ungroup(m_document, id)))
                return false;
        return true;
    });
}

bool Authoring::splitSelection(const model::Plane& plane)
{
    const model::Scene& scene = m_document->scene();
    const Selection s = m_document->selection();
    std::vector<std::string> parts;
    for (const std::string& id : selectedPartIds(scene, s))
        if (planeCrosses(*scene.findPart(id), plane))
            parts.push_back(id);
    if (parts.empty()) {
        emit m_document->editFailed(tr("the plane does not cross any selected part"));
        return false;
    }
    // The front half keeps the part's id (and so its faces' ids and their
    // places in BSP orders); the back half gets a fresh one.
    model::edit::IdAllocator ids(scene);
    std::vector<std::pair<std::string, std::string>> halves;
    for (const std::string& id : parts)
        halves.emplace_back(id, ids.fresh(id));
    std::vector<std::string> created;
    const bool ok = pushMacro(tr("Split %n part(s)", nullptr, int(parts.size())), [&] {
        for (const auto& [front, back] : halves) {
            if (!m_document->push(new SplitPart(m_document, front, plane, front, back)))
                return false;
            created.push_back(front);
            created.push_back(back);
        }
        return true;
    });
    if (ok)
        m_document->setSelection(Selection::of(SelectionKind::Part, created));
    return ok;
}

bool Authoring::splitSelectionAlong(int axis)
{
    const model::Box3 box = selectionBounds();
    if (box.empty || axis < 0 || axis > 2)
        return false;
    model::Vec3 normal(0.0);
    normal[axis] = 1.0;
    return splitSelection(model::Plane::fromPointNormal(box.center(), normal));
}

bool Authoring::assignMaterial(const std::string& materialId)
{
    const model::Scene& scene = m_document->scene();
    const Selection s = m_document->selection();
    if (s.empty())
        return false;
    if (s.kind == SelectionKind::Face) {
        return pushMacro(tr("Assign %1").arg(toQString(materialId)), [&] {
            for (const std::string& id : s.ids)
                if (!m_document->push(new SetFaceMaterial(m_document, id, materialId)))
                    return false;
            return true;
        });
    }
    const std::vector<std::string> parts = selectedPartIds(scene, s);
    if (parts.empty())
        return false;
    // A whole part takes the material everywhere: faces drop their own.
    return pushMacro(tr("Assign %1").arg(toQString(materialId)), [&] {
        for (const std::string& id : parts) {
            const model::Part* part = m_document->scene().findPart(id);
            std::vector<std::string> overridden;
            for (const model::Face& face : part->faces)
                if (!face.material.empty())
                    overridden.push_back(face.id);
            if (part->material != materialId && !m_document->push(new SetPartMaterial(m_document, id, materialId)))
                return false;
            for (const std::string& face : overridden)
                if (!m_document->push(new SetFaceMaterial(m_document, face, {})))
                    return false;
        }
        return true;
    });
}

bool Authoring::transformSelection(const glm::dmat4& transform, const QString& text)
{
    const std::vector<std::string> parts = selectedPartIds(m_document->scene(), m_document->selection());
    if (parts.empty() || m_document->selection().kind == SelectionKind::Face)
        return false;
    return m_document->push(new TransformParts(m_document, parts, transform, text));
}

void Authoring::onTransformDragged(const std::vector<std::string>& partIds, const glm::dmat4& transform, int serial)
{
    if (serial != m_dragSerial || m_dragStart.empty()) {
        // A new drag: remember the geometry it starts from.
        m_dragSerial = serial;
        m_dragStart.clear();
        for (const std::string& id : partIds)
            if (const model::Part* part = m_document->scene().findPart(id))
                m_dragStart.push_back(model::geometryOf(*part));
    }
    if (m_dragStart.empty())
        return;
    const QString text = tr("Transform %n part(s)", nullptr, int(m_dragStart.size()));
    m_document->push(TransformParts::dragStep(m_document, m_dragStart, transform, serial, text));
}

bool Authoring::moveParts(const std::vector<std::string>& partIds, const std::string& targetObjectId)
{
    if (partIds.empty())
        return false;
    const bool ok = m_document->push(ChangeObjectLayout::moveParts(m_document, partIds, targetObjectId));
    if (ok)
        m_document->setSelection(Selection::of(SelectionKind::Part, partIds));
    return ok;
}

bool Authoring::storeViewAsSceneCamera()
{
    return m_document->push(new SetSceneCamera(m_document, m_viewport->camera().toSceneCamera()));
}

} // namespace regio::editor
