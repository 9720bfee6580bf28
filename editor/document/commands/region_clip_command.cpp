#include "editor/document/commands/region_clip_command.h"

#include "editor/document/qt_conversions.h"

#include <QCoreApplication>

namespace regio::editor {

ClipPartToRegions::ClipPartToRegions(SceneDocument* document, std::string partId)
    : SceneCommand(document,
                   QCoreApplication::translate("regio::editor::Commands", "Clip %1 to regions").arg(toQString(partId)))
    , m_partId(std::move(partId))
{
}

void ClipPartToRegions::redo()
{
    // The clip is recomputed on every redo: it is deterministic on the scene
    // it started from, which undo restored exactly.
    auto clip = model::clipPartToRegions(scene(), m_partId);
    if (!clip)
        return fail(clip.error());
    m_clip = std::move(*clip);
    // Pieces and BSP orders changed.
    notify(Change::Objects | Change::Regions);
}

void ClipPartToRegions::undo()
{
    if (!m_clip)
        return;
    if (auto r = model::unclipPart(scene(), *m_clip); !r)
        return fail(r.error());
    notify(Change::Objects | Change::Regions);
}

} // namespace regio::editor
