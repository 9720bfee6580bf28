#pragma once
// Adding another scene's materials and objects (an imported model into the
// open scene) as one command: one undo step, and one change notification
// for the views however many objects come in.
#include "editor/document/commands/scene_command.h"
#include "model/edit/merge_scene.h"

namespace regio::editor {

class AddSceneItems : public SceneCommand {
public:
    // `items` as model::itemsToMerge makes them ready for the scene.
    AddSceneItems(SceneDocument* document, const QString& text, model::MergeItems items);
    void redo() override;
    void undo() override;

private:
    // Takes out the first `objects` objects and `materials` materials of
    // the items again, last first.
    void takeOut(std::size_t objects, std::size_t materials);

    model::MergeItems m_items;
};

} // namespace regio::editor
