#include "editor/document/commands/scene_command.h"

namespace regio::editor {

SceneCommand::SceneCommand(SceneDocument* document, const QString& text, QUndoCommand* parent)
    : QUndoCommand(text, parent)
    , m_document(document)
{
}

void SceneCommand::fail(const model::Diagnostic& error)
{
    setObsolete(true);
    m_document->reportFailure(error);
}

bool SceneCommand::canMerge(const QUndoCommand* other) const
{
    return other->id() == id() && id() != -1 && !other->isObsolete() && !isObsolete();
}

} // namespace regio::editor
