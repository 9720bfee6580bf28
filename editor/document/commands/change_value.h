#pragma once
// One value of one scene element set through a model edit that returns the
// previous value: names, materials of parts and faces, material colours,
// region boxes, solver settings. Subclasses only say which edit to call.
// Consecutive changes of the same value of the same element merge (a spin box
// scrubbed, a colour dragged) when the subclass gives a merge id.
#include "editor/document/commands/scene_command.h"

#include <string>
#include <typeinfo>

namespace regio::editor {

template <typename Value>
class ChangeValue : public SceneCommand {
public:
    int id() const override { return m_mergeId; }
    const std::string& target() const { return m_target; }
    const Value& newValue() const { return m_newValue; }
    const Value& oldValue() const { return m_oldValue; }

    void redo() override { apply(m_newValue, true); }
    void undo() override { apply(m_oldValue, false); }

    bool mergeWith(const QUndoCommand* other) override
    {
        if (!canMerge(other) || typeid(*other) != typeid(*this))
            return false;
        const auto* next = static_cast<const ChangeValue*>(other);
        if (next->m_target != m_target)
            return false;
        m_newValue = next->m_newValue;
        // Scrubbed back to where it started: nothing left to undo.
        if (m_newValue == m_oldValue)
            setObsolete(true);
        return true;
    }

protected:
    ChangeValue(SceneDocument* document, const QString& text, Change changes, std::string target, Value value,
                int mergeId = -1)
        : SceneCommand(document, text)
        , m_changes(changes)
        , m_target(std::move(target))
        , m_newValue(std::move(value))
        , m_mergeId(mergeId)
    {
    }

    // Sets the value through the model; returns the previous value.
    virtual model::Result<Value> set(model::Scene& scene, const std::string& target, const Value& value) = 0;

private:
    void apply(const Value& value, bool forward)
    {
        model::Result<Value> previous = set(scene(), m_target, value);
        if (!previous) {
            fail(previous.error());
            return;
        }
        if (forward && !m_applied) {
            m_oldValue = std::move(*previous);
            m_applied = true;
        }
        notify(m_changes);
    }

    Change m_changes;
    std::string m_target;
    Value m_newValue;
    Value m_oldValue{};
    int m_mergeId;
    bool m_applied = false;
};

} // namespace regio::editor
