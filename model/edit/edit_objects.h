#pragma once
// Edits of whole objects and of how parts are grouped into objects (the
// "whole" of the whole-part model). Each validates first and leaves the scene
// unchanged when it refuses; each returns what its inverse needs:
//   insertObject(o, i) / addObject(o) -> index <-> removeObject(o.id)
//   removeObject(id) -> r                    <-> restoreObject(r)
//   renameObject(a, b)                       <-> renameObject(b, a)
//   setObjectName returns the previous name
//   duplicateObject(id) -> newId             <-> removeObject(newId)
//   groupParts / groupObjects / ungroupObject -> previous layout
//                                            <-> restoreObjectLayout(previous)
//   transformObject -> previous geometries   <-> setPartGeometries(previous)
// Part moves between objects are in edit_parts.h (movePart).
#include "model/edit/edit_parts.h"
#include "model/edit/edit_regions.h"
#include "model/result.h"
#include "model/scene.h"

#include <glm/mat4x4.hpp>

#include <string>
#include <vector>

namespace regio::model {

// Inserts at `index` (-1 = append); returns the index. The object, part and
// face ids must be fresh and distinct, loops valid, materials known.
Result<int> insertObject(Scene& scene, Object object, int index);
Result<int> addObject(Scene& scene, Object object);

struct RemovedObject {
    Object object;
    int index = -1;
    BspOrderSnapshots bspOrders; // orders as they were before its faces left them
    bool operator==(const RemovedObject&) const = default;
};
// Its faces also leave every BSP order.
Result<RemovedObject> removeObject(Scene& scene, const std::string& objectId);
Result<Unit> restoreObject(Scene& scene, const RemovedObject& removed);

// Only the object's id changes: nothing refers to objects, and part and face
// ids are independent strings even when they were derived from it.
Result<Unit> renameObject(Scene& scene, const std::string& objectId, const std::string& newId);
Result<std::string> setObjectName(Scene& scene, const std::string& objectId, std::string name);

// A copy of `object` whose object, part and face ids are all fresh in `scene`:
// "box1" -> "box1-2", its part "box1.body" -> "box1-2.body", face
// "box1.body.px" -> "box1-2.body.px" (ids not derived from the parent's only
// get a "-N" suffix). Also makes a new primitive's ids safe to add.
Object withFreshIds(const Scene& scene, const Object& object);
// Inserts such a copy right after the original; returns the copy's id.
Result<std::string> duplicateObject(Scene& scene, const std::string& objectId);

// Which parts each object holds, in order: the undo record of regrouping.
struct ObjectLayout {
    struct Entry {
        std::string id;
        std::string name;
        std::vector<std::string> parts;
        bool operator==(const Entry&) const = default;
    };
    std::vector<Entry> objects;
    bool operator==(const ObjectLayout&) const = default;
};
ObjectLayout objectLayout(const Scene& scene);
// Rebuilds the objects from `layout`, moving the existing parts (their content
// untouched). Every part of the scene must appear exactly once. Returns the
// layout it replaced.
Result<ObjectLayout> restoreObjectLayout(Scene& scene, const ObjectLayout& layout);

// Moves the listed parts (from any objects, in the order given) into a new
// object `objectId` placed where the first contributing object was. Objects
// left without parts are removed. Returns the previous layout.
Result<ObjectLayout> groupParts(Scene& scene, const std::vector<std::string>& partIds, const std::string& objectId,
                                const std::string& name = {});
// The same with every part of the listed objects.
Result<ObjectLayout> groupObjects(Scene& scene, const std::vector<std::string>& objectIds, const std::string& objectId,
                                  const std::string& name = {});
// One object per part, in part order, where the object was. The first keeps
// the object's id and name; the others get "<object>-<part id without the
// object prefix>" ("table.legs" of "table" -> "table-legs") made unique, and
// the part's name. Refused for an object with fewer than two parts.
Result<ObjectLayout> ungroupObject(Scene& scene, const std::string& objectId);

// Transforms every part of the object (see transformPart).
Result<std::vector<PartGeometry>> transformObject(Scene& scene, const std::string& objectId, const glm::dmat4& m);

} // namespace regio::model
