#include "model/edit/edit_objects.h"

#include "model/edit/edit_support.h"

#include <algorithm>
#include <unordered_map>
#include <unordered_set>

namespace regio::model {

using edit::objectIndex;

Result<int> insertObject(Scene& scene, Object object, int index)
{
    int count = int(scene.objects.size());
    if (index < -1 || index > count)
        return makeError("object position " + std::to_string(index) + " is out of range (0.." + std::to_string(count) +
                         ")");
    if (index == -1)
        index = count;
    std::unordered_set<std::string> taken;
    if (Check check = edit::checkNewId(scene, object.id, "object"); !check)
        return withPointer(check.error(), objectPointer(index) + "/id");
    taken.insert(object.id);
    for (size_t p = 0; p < object.parts.size(); ++p)
        if (Check check = edit::checkNewPart(scene, object.parts[p], partPointer(index, int(p)), taken); !check)
            return check.error();
    scene.objects.insert(scene.objects.begin() + index, std::move(object));
    return index;
}

Result<int> addObject(Scene& scene, Object object) { return insertObject(scene, std::move(object), -1); }

Result<RemovedObject> removeObject(Scene& scene, const std::string& objectId)
{
    int o = objectIndex(scene, objectId);
    if (o < 0)
        return edit::unknown("object", objectId);
    RemovedObject removed{std::move(scene.objects[size_t(o)]), o, {}};
    scene.objects.erase(scene.objects.begin() + o);
    std::vector<std::string> faceIds;
    for (const Part& part : removed.object.parts)
        for (const Face& face : part.faces)
            faceIds.push_back(face.id);
    removed.bspOrders = removeFacesFromBspOrders(scene, faceIds);
    return removed;
}

Result<Unit> restoreObject(Scene& scene, const RemovedObject& removed)
{
    auto inserted = insertObject(scene, removed.object, removed.index);
    if (!inserted)
        return inserted.error();
    restoreBspOrders(scene, removed.bspOrders);
    return Unit{};
}

Result<Unit> renameObject(Scene& scene, const std::string& objectId, const std::string& newId)
{
    Object* object = scene.findObject(objectId);
    if (!object)
        return edit::unknown("object", objectId);
    if (newId == objectId)
        return Unit{};
    if (Check check = edit::checkNewId(scene, newId, "object"); !check)
        return check.error();
    object->id = newId;
    return Unit{};
}

Result<std::string> setObjectName(Scene& scene, const std::string& objectId, std::string name)
{
    Object* object = scene.findObject(objectId);
    if (!object)
        return edit::unknown("object", objectId);
    std::swap(object->name, name);
    return name;
}

Object withFreshIds(const Scene& scene, const Object& object)
{
    edit::IdAllocator ids(scene);
    Object copy = object;
    copy.id = ids.fresh(object.id);
    for (Part& part : copy.parts) {
        std::string oldPartId = part.id;
        part.id = ids.freshRenamed(part.id, object.id, copy.id);
        for (Face& face : part.faces) {
            std::string renamed = edit::replacePrefix(face.id, oldPartId, part.id);
            if (renamed == face.id)
                renamed = edit::replacePrefix(face.id, object.id, copy.id);
            face.id = ids.fresh(renamed);
        }
    }
    return copy;
}

Result<std::string> duplicateObject(Scene& scene, const std::string& objectId)
{
    int o = objectIndex(scene, objectId);
    if (o < 0)
        return edit::unknown("object", objectId);
    Object copy = withFreshIds(scene, scene.objects[size_t(o)]);
    std::string id = copy.id;
    scene.objects.insert(scene.objects.begin() + o + 1, std::move(copy));
    return id;
}

ObjectLayout objectLayout(const Scene& scene)
{
    ObjectLayout layout;
    for (const Object& object : scene.objects) {
        ObjectLayout::Entry entry{object.id, object.name, {}};
        for (const Part& part : object.parts)
            entry.parts.push_back(part.id);
        layout.objects.push_back(std::move(entry));
    }
    return layout;
}

Result<ObjectLayout> restoreObjectLayout(Scene& scene, const ObjectLayout& layout)
{
    std::unordered_set<std::string> objectIds;
    std::unordered_set<std::string> partIds;
    size_t partCount = 0;
    for (const Object& object : scene.objects)
        partCount += object.parts.size();
    for (const auto& entry : layout.objects) {
        if (entry.id.empty())
            return makeError("the object id must not be empty");
        if (!objectIds.insert(entry.id).second)
            return makeError("the object id \"" + entry.id + "\" appears twice");
        if (!scene.findObject(entry.id) && scene.idInUse(entry.id))
            return makeError("the id \"" + entry.id + "\" is already in use by something else");
        for (const std::string& partId : entry.parts) {
            if (!scene.findPart(partId))
                return edit::unknown("part", partId);
            if (!partIds.insert(partId).second)
                return makeError("part \"" + partId + "\" appears twice in the grouping");
        }
    }
    if (partIds.size() != partCount)
        return makeError("a grouping must place every part of the scene");

    ObjectLayout previous = objectLayout(scene);
    std::unordered_map<std::string, Part> parts;
    for (Object& object : scene.objects)
        for (Part& part : object.parts)
            parts.emplace(part.id, std::move(part));
    std::vector<Object> objects;
    for (const auto& entry : layout.objects) {
        Object object{entry.id, entry.name, {}};
        for (const std::string& partId : entry.parts)
            object.parts.push_back(std::move(parts.at(partId)));
        objects.push_back(std::move(object));
    }
    scene.objects = std::move(objects);
    return previous;
}

Result<ObjectLayout> groupParts(Scene& scene, const std::vector<std::string>& partIds, const std::string& objectId,
                                const std::string& name)
{
    if (partIds.empty())
        return makeError("grouping needs at least one part");
    std::unordered_set<std::string> grouped;
    int first = int(scene.objects.size());
    for (const std::string& partId : partIds) {
        auto at = edit::locatePart(scene, partId);
        if (!at.valid())
            return edit::unknown("part", partId);
        if (!grouped.insert(partId).second)
            return makeError("part \"" + partId + "\" is listed twice");
        first = std::min(first, at.object);
    }
    // Objects that give up all their parts disappear and free their ids.
    std::unordered_set<std::string> released;
    for (const Object& object : scene.objects)
        if (!object.parts.empty() && std::all_of(object.parts.begin(), object.parts.end(),
                                                 [&](const Part& p) { return grouped.count(p.id) > 0; }))
            released.insert(object.id);
    if (Check check = edit::checkNewId(scene, objectId, "object", {}, released); !check)
        return check.error();

    ObjectLayout layout;
    for (int o = 0; o < int(scene.objects.size()); ++o) {
        const Object& object = scene.objects[size_t(o)];
        if (o == first)
            layout.objects.push_back({objectId, name, partIds});
        ObjectLayout::Entry entry{object.id, object.name, {}};
        for (const Part& part : object.parts)
            if (!grouped.count(part.id))
                entry.parts.push_back(part.id);
        if (!released.count(object.id))
            layout.objects.push_back(std::move(entry));
    }
    return restoreObjectLayout(scene, layout);
}

Result<ObjectLayout> groupObjects(Scene& scene, const std::vector<std::string>& objectIds, const std::string& objectId,
                                  const std::string& name)
{
    std::vector<std::string> partIds;
    std::unordered_set<std::string> seen;
    for (const std::string& id : objectIds) {
        const Object* object = scene.findObject(id);
        if (!object)
            return edit::unknown("object", id);
        if (!seen.insert(id).second)
            return makeError("object \"" + id + "\" is listed twice");
        for (const Part& part : object->parts)
            partIds.push_back(part.id);
    }
    return groupParts(scene, partIds, objectId, name);
}

Result<ObjectLayout> ungroupObject(Scene& scene, const std::string& objectId)
{
    int o = objectIndex(scene, objectId);
    if (o < 0)
        return edit::unknown("object", objectId);
    const Object& object = scene.objects[size_t(o)];
    if (object.parts.size() < 2)
        return makeError("object \"" + objectId + "\" has only " + std::to_string(object.parts.size()) +
                         " part; nothing to ungroup");
    ObjectLayout layout = objectLayout(scene);
    std::vector<ObjectLayout::Entry> split;
    edit::IdAllocator ids(scene);
    for (size_t p = 0; p < object.parts.size(); ++p) {
        const Part& part = object.parts[p];
        if (p == 0) {
            split.push_back({object.id, object.name, {part.id}});
            continue;
        }
        std::string suffix = edit::replacePrefix(part.id, object.id, "");
        if (!suffix.empty() && suffix.front() == '.')
            suffix.erase(0, 1);
        split.push_back({ids.fresh(object.id + "-" + suffix), part.name, {part.id}});
    }
    layout.objects.erase(layout.objects.begin() + o);
    layout.objects.insert(layout.objects.begin() + o, split.begin(), split.end());
    return restoreObjectLayout(scene, layout);
}

Result<std::vector<PartGeometry>> transformObject(Scene& scene, const std::string& objectId, const glm::dmat4& m)
{
    const Object* object = scene.findObject(objectId);
    if (!object)
        return edit::unknown("object", objectId);
    std::vector<std::string> partIds;
    for (const Part& part : object->parts)
        partIds.push_back(part.id);
    return transformParts(scene, partIds, m);
}

} // namespace regio::model
