#include "editor/regions/region_drag_command.h"

namespace regio::editor {

ResizeRegionByHandle::ResizeRegionByHandle(SceneDocument* document, std::string regionId, const model::Vec3& min,
                                           const model::Vec3& max, int dragSerial)
    : SetRegionBox(document, std::move(regionId), min, max)
    , m_serial(dragSerial)
{
}

bool ResizeRegionByHandle::mergeWith(const QUndoCommand* other)
{
    const auto* next = dynamic_cast<const ResizeRegionByHandle*>(other);
    if (!next || next->m_serial != m_serial)
        return false;
    return SetRegionBox::mergeWith(other);
}

} // namespace regio::editor
