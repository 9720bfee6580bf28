#pragma once
// Base of every undo command: the only code allowed to change a document's
// scene. A command performs its model edit in redo(); if the model refuses
// the edit the command reports why and marks itself obsolete, so the undo
// stack drops it and the scene stays as it was.
#include "editor/document/scene_document.h"
#include "model/result.h"

#include <QUndoCommand>

namespace regio::editor {

class SceneCommand : public QUndoCommand {
public:
    SceneDocument* document() const { return m_document; }

protected:
    SceneCommand(SceneDocument* document, const QString& text, QUndoCommand* parent = nullptr);

    model::Scene& scene() { return m_document->mutableScene(); }
    const model::Scene& scene() const { return m_document->scene(); }
    void notify(Change changes) { m_document->notify(changes); }

    // Reports a refused edit. In redo() of a command not yet on the stack it
    // makes the command obsolete; later (undo/redo of a stored command) it
    // means the scene was changed behind the stack's back, and is reported.
    void fail(const model::Diagnostic& error);

    // True when `other` may be merged into this command: same merge id and
    // not itself a refused edit.
    bool canMerge(const QUndoCommand* other) const;

private:
    SceneDocument* m_document;
};

} // namespace regio::editor
