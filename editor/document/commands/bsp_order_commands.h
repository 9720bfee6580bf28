#pragma once
// Undo commands on a region's BSP root-patch order (paper §5.3): the list of
// faces whose planes split the region's BSP tree first.
#include "editor/document/commands/change_value.h"
#include "model/edit/edit_regions.h"

namespace regio::editor {

// Replaces the whole order (sorting, pasting an order).
class SetBspOrder : public ChangeValue<std::vector<std::string>> {
public:
    SetBspOrder(SceneDocument* document, std::string regionId, std::vector<std::string> order);

protected:
    model::Result<std::vector<std::string>> set(model::Scene& scene, const std::string& target,
                                                const std::vector<std::string>& value) override;
};

class InsertBspEntry : public SceneCommand {
public:
    InsertBspEntry(SceneDocument* document, std::string regionId, std::string faceId, int index = -1);
    void redo() override;
    void undo() override;

private:
    std::string m_regionId, m_faceId;
    int m_index;
    int m_usedIndex = -1;
};

class RemoveBspEntry : public SceneCommand {
public:
    RemoveBspEntry(SceneDocument* document, std::string regionId, int index);
    void redo() override;
    void undo() override;

private:
    std::string m_regionId;
    int m_index;
    model::BspEntry m_removed;
};

class MoveBspEntry : public SceneCommand {
public:
    MoveBspEntry(SceneDocument* document, std::string regionId, int from, int to);
    void redo() override;
    void undo() override;

private:
    std::string m_regionId;
    int m_from, m_to;
};

} // namespace regio::editor
