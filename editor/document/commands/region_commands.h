#pragma once
// Undo commands on regions: the axis-aligned boxes of paper §5.2.
#include "editor/document/commands/change_value.h"
#include "model/edit/edit_regions.h"

#include <optional>

namespace regio::editor {

class AddRegion : public SceneCommand {
public:
    AddRegion(SceneDocument* document, model::Region region, int index = -1);
    void redo() override;
    void undo() override;

private:
    model::Region m_region;
    int m_index;
    int m_usedIndex = -1;
};

class RemoveRegion : public SceneCommand {
public:
    RemoveRegion(SceneDocument* document, std::string regionId);
    void redo() override;
    void undo() override;

private:
    std::string m_regionId;
    std::optional<model::RemovedRegion> m_removed;
};

class RenameRegion : public SceneCommand {
public:
    RenameRegion(SceneDocument* document, std::string regionId, std::string newId);
    void redo() override;
    void undo() override;

private:
    std::string m_from, m_to;
};

class SetRegionName : public ChangeValue<std::string> {
public:
    SetRegionName(SceneDocument* document, std::string regionId, std::string name);

protected:
    model::Result<std::string> set(model::Scene& scene, const std::string& target, const std::string& value) override;
};

// Resizing a box by dragging or scrubbing merges into one step.
class SetRegionBox : public ChangeValue<model::RegionBox> {
public:
    SetRegionBox(SceneDocument* document, std::string regionId, const model::Vec3& min, const model::Vec3& max);

protected:
    model::Result<model::RegionBox> set(model::Scene& scene, const std::string& target,
                                        const model::RegionBox& value) override;
};

} // namespace regio::editor
