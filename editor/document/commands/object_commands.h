#pragma once
// Undo commands on whole objects and on how parts are grouped into objects.
#include "editor/document/commands/change_value.h"
#include "model/edit/edit_objects.h"

#include <functional>
#include <optional>

namespace regio::editor {

// Adds an object (a new primitive, a pasted copy). Its ids must be fresh:
// pass it through model::withFreshIds first.
class AddObject : public SceneCommand {
public:
    AddObject(SceneDocument* document, model::Object object, int index = -1);
    const std::string& objectId() const { return m_object.id; }
    void redo() override;
    void undo() override;

private:
    model::Object m_object;
    int m_index;
    std::optional<model::RemovedObject> m_removed;
};

class RemoveObject : public SceneCommand {
public:
    RemoveObject(SceneDocument* document, std::string objectId);
    void redo() override;
    void undo() override;

private:
    std::string m_objectId;
    std::optional<model::RemovedObject> m_removed;
};

// A copy with fresh ids right after the original.
class DuplicateObject : public SceneCommand {
public:
    DuplicateObject(SceneDocument* document, std::string objectId);
    // The copy's id, once pushed.
    const std::string& copyId() const { return m_copyId; }
    void redo() override;
    void undo() override;

private:
    std::string m_objectId;
    std::string m_copyId;
    std::optional<model::RemovedObject> m_removed;
};

// Changes an object's id.
class RenameObject : public SceneCommand {
public:
    RenameObject(SceneDocument* document, std::string objectId, std::string newId);
    void redo() override;
    void undo() override;

private:
    std::string m_from, m_to;
};

// Changes an object's display name.
class SetObjectName : public ChangeValue<std::string> {
public:
    SetObjectName(SceneDocument* document, std::string objectId, std::string name);

protected:
    model::Result<std::string> set(model::Scene& scene, const std::string& target, const std::string& value) override;
};

// Any regrouping of parts into objects: group, ungroup, moving parts to
// another object. The first redo runs the model edit; undo and later redos
// restore the layouts before and after it.
class ChangeObjectLayout : public SceneCommand {
public:
    using Edit = std::function<model::Result<model::ObjectLayout>(model::Scene&)>;
    ChangeObjectLayout(SceneDocument* document, const QString& text, Edit edit);
    void redo() override;
    void undo() override;

    static ChangeObjectLayout* groupParts(SceneDocument* document, std::vector<std::string> partIds,
                                          std::string objectId);
    static ChangeObjectLayout* groupObjects(SceneDocument* document, std::vector<std::string> objectIds,
                                            std::string objectId);
    static ChangeObjectLayout* ungroup(SceneDocument* document, std::string objectId);
    // Moves parts into an existing object, or (target empty) gives each its
    // own new object. Objects left without parts disappear.
    static ChangeObjectLayout* moveParts(SceneDocument* document, std::vector<std::string> partIds,
                                         std::string targetObjectId);

private:
    Edit m_edit;
    std::optional<model::ObjectLayout> m_before;
    std::optional<model::ObjectLayout> m_after;
};

// The layout a move of parts produces (see ChangeObjectLayout::moveParts).
model::Result<model::ObjectLayout> layoutWithPartsMoved(const model::Scene& scene,
                                                        const std::vector<std::string>& partIds,
                                                        const std::string& targetObjectId);

} // namespace regio::editor
