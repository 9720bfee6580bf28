#pragma once
// Resizing a region by dragging one of its face handles in the viewport. A
// SetRegionBox whose steps merge only within one drag (the same serial), so
// every drag is one undo step of its own even when the same box is dragged
// twice in a row, and never merges with a numeric edit in the properties dock.
#include "editor/document/commands/region_commands.h"

namespace regio::editor {

class ResizeRegionByHandle : public SetRegionBox {
public:
    ResizeRegionByHandle(SceneDocument* document, std::string regionId, const model::Vec3& min, const model::Vec3& max,
                         int dragSerial);
    bool mergeWith(const QUndoCommand* other) override;
    int dragSerial() const { return m_serial; }

private:
    int m_serial;
};

} // namespace regio::editor
