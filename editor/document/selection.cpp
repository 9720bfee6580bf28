#include "editor/document/selection.h"

#include <algorithm>
#include <unordered_set>

namespace regio::editor {

Selection Selection::of(SelectionKind kind, std::vector<std::string> ids)
{
    if (ids.empty())
        return {};
    return Selection{kind, std::move(ids)};
}

Selection Selection::single(SelectionKind kind, const std::string& id) { return of(kind, {id}); }

bool Selection::contains(const std::string& id) const { return std::find(ids.begin(), ids.end(), id) != ids.end(); }

Selection Selection::toggled(SelectionKind newKind, const std::string& id) const
{
    if (newKind != kind || empty())
        return single(newKind, id);
    Selection out = *this;
    auto it = std::find(out.ids.begin(), out.ids.end(), id);
    if (it != out.ids.end())
        out.ids.erase(it);
    else
        out.ids.push_back(id);
    return of(kind, std::move(out.ids));
}

bool selectionIdExists(const model::Scene& scene, SelectionKind kind, const std::string& id)
{
    switch (kind) {
    case SelectionKind::None: return false;
    case SelectionKind::Object: return scene.findObject(id) != nullptr;
    case SelectionKind::Part: return scene.findPart(id) != nullptr;
    case SelectionKind::Face: return scene.locateFace(id).valid();
    case SelectionKind::Material: return scene.findMaterial(id) != nullptr;
    case SelectionKind::Region: return scene.findRegion(id) != nullptr;
    }
    return false;
}

Selection Selection::prunedTo(const model::Scene& scene) const
{
    std::vector<std::string> kept;
    for (const std::string& id : ids)
        if (selectionIdExists(scene, kind, id))
            kept.push_back(id);
    return of(kind, std::move(kept));
}

std::vector<std::string> selectedPartIds(const model::Scene& scene, const Selection& selection)
{
    std::unordered_set<std::string> wanted(selection.ids.begin(), selection.ids.end());
    std::vector<std::string> out;
    for (const model::Object& object : scene.objects) {
        for (const model::Part& part : object.parts) {
            bool take = false;
            switch (selection.kind) {
            case SelectionKind::Object: take = wanted.count(object.id) > 0; break;
            case SelectionKind::Part: take = wanted.count(part.id) > 0; break;
            case SelectionKind::Face:
                take = std::any_of(part.faces.begin(), part.faces.end(),
                                   [&](const model::Face& f) { return wanted.count(f.id) > 0; });
                break;
            default: break;
            }
            if (take)
                out.push_back(part.id);
        }
    }
    return out;
}

std::vector<std::string> selectedFaceIds(const model::Scene& scene, const Selection& selection)
{
    std::unordered_set<std::string> wanted(selection.ids.begin(), selection.ids.end());
    std::vector<std::string> out;
    for (const model::Object& object : scene.objects) {
        const bool wholeObject = selection.kind == SelectionKind::Object && wanted.count(object.id);
        for (const model::Part& part : object.parts) {
            const bool wholePart = wholeObject || (selection.kind == SelectionKind::Part && wanted.count(part.id));
            for (const model::Face& face : part.faces)
                if (wholePart || (selection.kind == SelectionKind::Face && wanted.count(face.id)))
                    out.push_back(face.id);
        }
    }
    return out;
}

} // namespace regio::editor
