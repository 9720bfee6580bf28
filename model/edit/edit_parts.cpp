#include "model/edit/edit_parts.h"

#include "model/edit/edit_support.h"
#include "model/geometry/transform.h"

#include <algorithm>
#include <unordered_map>
#include <unordered_set>

namespace regio::model {

using edit::locatePart;
using edit::objectIndex;

namespace {

std::vector<std::string> faceIdsOf(const Part& part)
{
    std::vector<std::string> ids;
    for (const Face& face : part.faces)
        ids.push_back(face.id);
    return ids;
}

Check checkIndex(int index, int count, const std::string& what)
{
    if (index < -1 || index > count)
        return makeError(what + " position " + std::to_string(index) + " is out of range (0.." + std::to_string(count) +
                         ")");
    return success();
}

} // namespace

// --- Parts -----------------------------------------------------------------

Result<int> addPart(Scene& scene, const std::string& objectId, Part part, int index)
{
    int o = objectIndex(scene, objectId);
    if (o < 0)
        return edit::unknown("object", objectId);
    auto& parts = scene.objects[size_t(o)].parts;
    if (Check check = checkIndex(index, int(parts.size()), "part"); !check)
        return check.error();
    if (index == -1)
        index = int(parts.size());
    std::unordered_set<std::string> taken;
    if (Check check = edit::checkNewPart(scene, part, partPointer(o, index), taken); !check)
        return check.error();
    parts.insert(parts.begin() + index, std::move(part));
    return index;
}

Result<RemovedPart> removePart(Scene& scene, const std::string& partId)
{
    auto at = locatePart(scene, partId);
    if (!at.valid())
        return edit::unknown("part", partId);
    Object& object = scene.objects[size_t(at.object)];
    RemovedPart removed{object.id, at.part, std::move(object.parts[size_t(at.part)]), {}};
    object.parts.erase(object.parts.begin() + at.part);
    removed.bspOrders = removeFacesFromBspOrders(scene, faceIdsOf(removed.part));
    return removed;
}

Result<Unit> restorePart(Scene& scene, const RemovedPart& removed)
{
    int o = objectIndex(scene, removed.objectId);
    if (o < 0)
        return edit::unknown("object", removed.objectId);
    auto& parts = scene.objects[size_t(o)].parts;
    if (removed.index < 0 || removed.index > int(parts.size()))
        return makeError("part position " + std::to_string(removed.index) + " is out of range");
    std::unordered_set<std::string> taken;
    if (Check check = edit::checkNewPart(scene, removed.part, partPointer(o, removed.index), taken); !check)
        return check.error();
    parts.insert(parts.begin() + removed.index, removed.part);
    restoreBspOrders(scene, removed.bspOrders);
    return Unit{};
}

Result<std::string> duplicatePart(Scene& scene, const std::string& partId)
{
    auto at = locatePart(scene, partId);
    if (!at.valid())
        return edit::unknown("part", partId);
    auto& parts = scene.objects[size_t(at.object)].parts;
    Part copy = parts[size_t(at.part)];
    edit::IdAllocator ids(scene);
    copy.id = ids.fresh(partId);
    for (Face& face : copy.faces)
        face.id = ids.freshRenamed(face.id, partId, copy.id);
    std::string id = copy.id;
    parts.insert(parts.begin() + at.part + 1, std::move(copy));
    return id;
}

Result<Unit> renamePart(Scene& scene, const std::string& partId, const std::string& newId)
{
    Part* part = scene.findPart(partId);
    if (!part)
        return edit::unknown("part", partId);
    if (newId == partId)
        return Unit{};
    if (Check check = edit::checkNewId(scene, newId, "part"); !check)
        return check.error();
    part->id = newId;
    return Unit{};
}

Result<std::string> setPartName(Scene& scene, const std::string& partId, std::string name)
{
    Part* part = scene.findPart(partId);
    if (!part)
        return edit::unknown("part", partId);
    std::swap(part->name, name);
    return name;
}

Result<std::string> setPartMaterial(Scene& scene, const std::string& partId, std::string material)
{
    auto at = locatePart(scene, partId);
    if (!at.valid())
        return edit::unknown("part", partId);
    if (Check check = edit::checkMaterialReference(scene, material, partPointer(at.object, at.part) + "/material");
        !check)
        return check.error();
    std::swap(scene.objects[size_t(at.object)].parts[size_t(at.part)].material, material);
    return material;
}

Result<PartPlace> movePart(Scene& scene, const std::string& partId, const std::string& objectId, int index)
{
    auto at = locatePart(scene, partId);
    if (!at.valid())
        return edit::unknown("part", partId);
    int target = objectIndex(scene, objectId);
    if (target < 0)
        return edit::unknown("object", objectId);
    int countAfterTaking = int(scene.objects[size_t(target)].parts.size()) - (target == at.object);
    if (Check check = checkIndex(index, countAfterTaking, "part"); !check)
        return check.error();
    if (index == -1)
        index = countAfterTaking;
    auto& from = scene.objects[size_t(at.object)].parts;
    PartPlace previous{scene.objects[size_t(at.object)].id, at.part};
    Part part = std::move(from[size_t(at.part)]);
    from.erase(from.begin() + at.part);
    auto& to = scene.objects[size_t(target)].parts;
    to.insert(to.begin() + index, std::move(part));
    return previous;
}

// --- Faces -------------------------------------------------------------------

Result<Unit> renameFace(Scene& scene, const std::string& faceId, const std::string& newId)
{
    auto at = scene.locateFace(faceId);
    if (!at.valid())
        return edit::unknown("face", faceId);
    if (newId == faceId)
        return Unit{};
    if (Check check = edit::checkNewId(scene, newId, "face"); !check)
        return check.error();
    scene.objects[size_t(at.object)].parts[size_t(at.part)].faces[size_t(at.face)].id = newId;
    renameFaceInBspOrders(scene, faceId, newId);
    return Unit{};
}

Result<std::string> setFaceMaterial(Scene& scene, const std::string& faceId, std::string material)
{
    auto at = scene.locateFace(faceId);
    if (!at.valid())
        return edit::unknown("face", faceId);
    if (Check check =
            edit::checkMaterialReference(scene, material, facePointer(at.object, at.part, at.face) + "/material");
        !check)
        return check.error();
    std::swap(scene.objects[size_t(at.object)].parts[size_t(at.part)].faces[size_t(at.face)].material, material);
    return material;
}

// --- Geometry ----------------------------------------------------------------

PartGeometry geometryOf(const Part& part) { return {part.id, part.vertices, part.faces}; }

Result<PartGeometry> transformPart(Scene& scene, const std::string& partId, const glm::dmat4& m)
{
    auto previous = transformParts(scene, {partId}, m);
    if (!previous)
        return previous.error();
    return std::move(previous->front());
}

Result<std::vector<PartGeometry>> transformParts(Scene& scene, const std::vector<std::string>& partIds,
                                                 const glm::dmat4& m)
{
    if (Check check = checkAffineTransform(m); !check)
        return check.error();
    std::vector<Part*> parts;
    std::unordered_set<std::string> seen;
    for (const std::string& id : partIds) {
        Part* part = scene.findPart(id);
        if (!part)
            return edit::unknown("part", id);
        if (!seen.insert(id).second)
            return makeError("part \"" + id + "\" is listed twice");
        parts.push_back(part);
    }
    std::vector<PartGeometry> previous;
    for (Part* part : parts) {
        previous.push_back(geometryOf(*part));
        transformVertices(part->vertices, part->faces, m);
    }
    return previous;
}

Result<PartGeometry> setPartGeometry(Scene& scene, PartGeometry geometry)
{
    std::vector<PartGeometry> one;
    one.push_back(std::move(geometry));
    auto previous = setPartGeometries(scene, std::move(one));
    if (!previous)
        return previous.error();
    return std::move(previous->front());
}

Result<std::vector<PartGeometry>> setPartGeometries(Scene& scene, std::vector<PartGeometry> geometries)
{
    std::vector<edit::PartLocation> places;
    std::unordered_set<std::string> released; // the current face ids of the parts replaced
    for (const PartGeometry& g : geometries) {
        auto at = locatePart(scene, g.partId);
        if (!at.valid())
            return edit::unknown("part", g.partId);
        for (const auto& other : places)
            if (other.object == at.object && other.part == at.part)
                return makeError("part \"" + g.partId + "\" is listed twice");
        places.push_back(at);
        for (const Face& face : scene.objects[size_t(at.object)].parts[size_t(at.part)].faces)
            released.insert(face.id);
    }
    std::unordered_set<std::string> taken;
    for (size_t i = 0; i < geometries.size(); ++i) {
        const PartGeometry& g = geometries[i];
        std::string pointer = partPointer(places[i].object, places[i].part);
        for (size_t f = 0; f < g.faces.size(); ++f) {
            if (Check check = edit::checkNewId(scene, g.faces[f].id, "face", taken, released); !check)
                return withPointer(check.error(), pointer + "/faces/" + std::to_string(f) + "/id");
            taken.insert(g.faces[f].id);
        }
        if (Check check = edit::checkPartGeometry(scene, g.vertices, g.faces, pointer); !check)
            return check.error();
    }
    for (const std::string& id : released)
        if (!taken.count(id))
            if (const Region* region = regionOrderingFace(scene, id))
                return makeError("face \"" + id + "\" would disappear but the BSP order of region \"" + region->id +
                                 "\" names it; take it out of the order first");
    std::vector<PartGeometry> previous;
    for (size_t i = 0; i < geometries.size(); ++i) {
        Part& part = scene.objects[size_t(places[i].object)].parts[size_t(places[i].part)];
        previous.push_back({part.id, std::move(part.vertices), std::move(part.faces)});
        part.vertices = std::move(geometries[i].vertices);
        part.faces = std::move(geometries[i].faces);
    }
    return previous;
}

// --- The plane cut in the scene ---------------------------------------------

Result<PartSplit> splitPartInScene(Scene& scene, const std::string& partId, const Plane& plane,
                                   const std::string& frontId, const std::string& backId, CutCaps caps)
{
    auto at = locatePart(scene, partId);
    if (!at.valid())
        return edit::unknown("part", partId);
    Object& object = scene.objects[size_t(at.object)];
    const Part& source = object.parts[size_t(at.part)];
    auto cut = splitPart(source, plane, frontId, backId, caps);
    if (!cut)
        return cut.error();

    std::unordered_set<std::string> released{source.id};
    for (const Face& face : source.faces)
        released.insert(face.id);
    std::unordered_set<std::string> taken;
    std::string pointer = partPointer(at.object, at.part);
    if (Check check = edit::checkNewPart(scene, cut->front, pointer, taken, released); !check)
        return check.error();
    if (Check check = edit::checkNewPart(scene, cut->back, partPointer(at.object, at.part + 1), taken, released);
        !check)
        return check.error();

    PartSplit split;
    split.original = {object.id, at.part, source, {}};
    split.frontId = frontId;
    split.backId = backId;
    split.pieces = cut->pieces;
    split.frontCaps = cut->frontCaps;
    split.backCaps = cut->backCaps;

    // BSP orders: each cut face is replaced by its pieces where it stood.
    std::unordered_map<std::string, const std::vector<std::string>*> piecesOf;
    for (const auto& p : cut->pieces)
        piecesOf[p.sourceId] = &p.pieceIds;
    for (Region& region : scene.regions) {
        if (std::none_of(region.bspOrder.begin(), region.bspOrder.end(),
                         [&](const std::string& id) { return piecesOf.count(id) > 0; }))
            continue;
        split.original.bspOrders.push_back({region.id, region.bspOrder});
        std::vector<std::string> order;
        for (const std::string& id : region.bspOrder) {
            auto it = piecesOf.find(id);
            if (it == piecesOf.end())
                order.push_back(id);
            else
                order.insert(order.end(), it->second->begin(), it->second->end());
        }
        region.bspOrder = std::move(order);
    }
    object.parts[size_t(at.part)] = std::move(cut->front);
    object.parts.insert(object.parts.begin() + at.part + 1, std::move(cut->back));
    return split;
}

Result<Unit> unsplitPart(Scene& scene, const PartSplit& split)
{
    int o = objectIndex(scene, split.original.objectId);
    if (o < 0)
        return edit::unknown("object", split.original.objectId);
    auto& parts = scene.objects[size_t(o)].parts;
    int index = split.original.index;
    if (index < 0 || index + 1 >= int(parts.size()) || parts[size_t(index)].id != split.frontId ||
        parts[size_t(index) + 1].id != split.backId)
        return makeError("the halves \"" + split.frontId + "\" and \"" + split.backId +
                         "\" are no longer where the cut left them");
    std::unordered_set<std::string> released;
    for (int k = index; k <= index + 1; ++k) {
        released.insert(parts[size_t(k)].id);
        for (const Face& face : parts[size_t(k)].faces)
            released.insert(face.id);
    }
    std::unordered_set<std::string> taken;
    if (Check check = edit::checkNewPart(scene, split.original.part, partPointer(o, index), taken, released); !check)
        return check.error();
    parts.erase(parts.begin() + index, parts.begin() + index + 2);
    parts.insert(parts.begin() + index, split.original.part);
    restoreBspOrders(scene, split.original.bspOrders);
    return Unit{};
}

} // namespace regio::model
