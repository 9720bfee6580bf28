#pragma once
// What the user has selected: a list of ids of one kind. Viewport picking,
// the scene tree, the diagnostics dock and the properties dock all read and
// write this one value through SceneDocument.
#include "model/scene.h"

#include <string>
#include <vector>

namespace regio::editor {

enum class SelectionKind { None, Object, Part, Face, Material, Region };

struct Selection {
    SelectionKind kind = SelectionKind::None;
    std::vector<std::string> ids;

    static Selection of(SelectionKind kind, std::vector<std::string> ids);
    static Selection single(SelectionKind kind, const std::string& id);

    bool empty() const { return ids.empty(); }
    bool contains(const std::string& id) const;
    // Adds the id if absent, removes it if present (Ctrl+click). A different
    // kind replaces the selection.
    Selection toggled(SelectionKind kind, const std::string& id) const;
    // The selection without the ids that no longer exist in the scene.
    Selection prunedTo(const model::Scene& scene) const;

    bool operator==(const Selection&) const = default;
};

// Whether an id of the given kind exists in the scene.
bool selectionIdExists(const model::Scene& scene, SelectionKind kind, const std::string& id);

// The parts a selection covers: an object's parts, the parts themselves, or
// the parts owning the selected faces (each once, in scene order).
std::vector<std::string> selectedPartIds(const model::Scene& scene, const Selection& selection);
// The faces a selection covers (every face of selected objects and parts).
std::vector<std::string> selectedFaceIds(const model::Scene& scene, const Selection& selection);

} // namespace regio::editor
