#include "editor/document/commands/import_command.h"

#include "model/edit/edit_materials.h"
#include "model/edit/edit_objects.h"

namespace regio::editor {

AddSceneItems::AddSceneItems(SceneDocument* document, const QString& text, model::MergeItems items)
    : SceneCommand(document, text)
    , m_items(std::move(items))
{
}

void AddSceneItems::redo()
{
    for (std::size_t m = 0; m < m_items.materials.size(); ++m)
        if (auto r = model::addMaterial(scene(), m_items.materials[m]); !r) {
            takeOut(0, m);
            return fail(r.error());
        }
    for (std::size_t o = 0; o < m_items.objects.size(); ++o)
        if (auto r = model::addObject(scene(), m_items.objects[o]); !r) {
            takeOut(o, m_items.materials.size());
            return fail(r.error());
        }
    notify(Change::Materials | Change::Objects);
}

void AddSceneItems::undo()
{
    takeOut(m_items.objects.size(), m_items.materials.size());
    notify(Change::Materials | Change::Objects | Change::Regions);
}

void AddSceneItems::takeOut(std::size_t objects, std::size_t materials)
{
    for (std::size_t o = objects; o-- > 0;)
        if (auto r = model::removeObject(scene(), m_items.objects[o].id); !r)
            return fail(r.error());
    for (std::size_t m = materials; m-- > 0;)
        if (auto r = model::removeMaterial(scene(), m_items.materials[m].id); !r)
            return fail(r.error());
}

} // namespace regio::editor
