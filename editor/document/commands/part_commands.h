#pragma once
// Undo commands on parts and faces: add, remove, duplicate, rename, move
// between objects, materials, transforms and the plane cut.
#include "editor/document/commands/change_value.h"
#include "model/edit/edit_parts.h"

#include <glm/mat4x4.hpp>

#include <optional>

namespace regio::editor {

class AddPart : public SceneCommand {
public:
    AddPart(SceneDocument* document, std::string objectId, model::Part part, int index = -1);
    void redo() override;
    void undo() override;

private:
    std::string m_objectId;
    model::Part m_part;
    int m_index;
    std::optional<model::RemovedPart> m_removed;
};

// Removes a part; its object stays even if empty (the editor removes an
// emptied object in the same macro).
class RemovePart : public SceneCommand {
public:
    RemovePart(SceneDocument* document, std::string partId);
    void redo() override;
    void undo() override;

private:
    std::string m_partId;
    std::optional<model::RemovedPart> m_removed;
};

class DuplicatePart : public SceneCommand {
public:
    DuplicatePart(SceneDocument* document, std::string partId);
    const std::string& copyId() const { return m_copyId; }
    void redo() override;
    void undo() override;

private:
    std::string m_partId;
    std::string m_copyId;
    std::optional<model::RemovedPart> m_removed;
};

class RenamePart : public SceneCommand {
public:
    RenamePart(SceneDocument* document, std::string partId, std::string newId);
    void redo() override;
    void undo() override;

private:
    std::string m_from, m_to;
};

class SetPartName : public ChangeValue<std::string> {
public:
    SetPartName(SceneDocument* document, std::string partId, std::string name);

protected:
    model::Result<std::string> set(model::Scene& scene, const std::string& target, const std::string& value) override;
};

// The part's default material (faces without their own use it).
class SetPartMaterial : public ChangeValue<std::string> {
public:
    SetPartMaterial(SceneDocument* document, std::string partId, std::string material);

protected:
    model::Result<std::string> set(model::Scene& scene, const std::string& target, const std::string& value) override;
};

// Moves a part to another object (or another place in its own).
class MovePart : public SceneCommand {
public:
    MovePart(SceneDocument* document, std::string partId, std::string objectId, int index = -1);
    void redo() override;
    void undo() override;

private:
    std::string m_partId;
    model::PartPlace m_target;
    model::PartPlace m_previous;
};

// Renames a face (and its entries in BSP orders).
class RenameFace : public SceneCommand {
public:
    RenameFace(SceneDocument* document, std::string faceId, std::string newId);
    void redo() override;
    void undo() override;

private:
    std::string m_from, m_to;
};

// A face's own material; empty = inherit the part's.
class SetFaceMaterial : public ChangeValue<std::string> {
public:
    SetFaceMaterial(SceneDocument* document, std::string faceId, std::string material);

protected:
    model::Result<std::string> set(model::Scene& scene, const std::string& target, const std::string& value) override;
};

// An affine transform of parts. Undo puts the exact previous numbers back.
// Steps of one gizmo drag (same non-zero serial) merge into one command.
class TransformParts : public SceneCommand {
public:
    // Transforms the parts as they are now.
    TransformParts(SceneDocument* document, std::vector<std::string> partIds, const glm::dmat4& transform,
                   const QString& text = {});
    // One step of a drag: `transform` is the whole transform since the drag
    // began, applied to the geometry the parts had then (no drift however
    // many steps merge).
    static TransformParts* dragStep(SceneDocument* document, const std::vector<model::PartGeometry>& start,
                                    const glm::dmat4& transform, int serial, const QString& text);

    int id() const override;
    bool mergeWith(const QUndoCommand* other) override;
    void redo() override;
    void undo() override;

private:
    TransformParts(SceneDocument* document, const QString& text);
    std::vector<std::string> m_partIds;
    glm::dmat4 m_transform{1.0};
    std::vector<model::PartGeometry> m_target; // the geometry to set (drag steps)
    std::vector<model::PartGeometry> m_before;
    std::vector<model::PartGeometry> m_after;
    int m_serial = 0;
    bool m_applied = false;
};

// Splits a part with a plane into two parts in the same object.
class SplitPart : public SceneCommand {
public:
    SplitPart(SceneDocument* document, std::string partId, const model::Plane& plane, std::string frontId,
              std::string backId, model::CutCaps caps = model::CutCaps::Close);
    const std::optional<model::PartSplit>& split() const { return m_split; }
    void redo() override;
    void undo() override;

private:
    std::string m_partId;
    model::Plane m_plane;
    std::string m_frontId, m_backId;
    model::CutCaps m_caps;
    std::optional<model::PartSplit> m_split;
};

} // namespace regio::editor
