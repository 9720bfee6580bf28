#pragma once
// Edits of parts and faces. Each validates first and leaves the scene
// unchanged when it refuses; each returns what its inverse needs, so an undo
// command is a pair of calls:
//   addPart(o, p, i)             <-> removePart(p.id) -> RemovedPart
//   removePart(id) -> r          <-> restorePart(r)
//   duplicatePart(id) -> newId   <-> removePart(newId)
//   renamePart / renameFace(a,b) <-> the same with (b, a)
//   setPartName/Material, setFaceMaterial return the previous value
//   movePart(id, o, i) -> place  <-> movePart(id, place.objectId, place.index)
//   transformPart(s) -> previous <-> setPartGeometry / setPartGeometries(previous)
//   splitPartInScene -> split    <-> unsplitPart(split)
// Removing or cutting faces keeps the regions' BSP orders consistent (removed
// faces leave the orders, cut faces are replaced by their pieces in place);
// the records carry the previous orders.
#include "model/edit/edit_regions.h"
#include "model/geometry/plane_cut.h"
#include "model/result.h"
#include "model/scene.h"

#include <glm/mat4x4.hpp>

#include <string>
#include <vector>

namespace regio::model {

// --- Parts -----------------------------------------------------------------

// Inserts into object `objectId` at `index` (-1 = append); returns the index.
// Part and face ids must be fresh, loops valid, materials known.
Result<int> addPart(Scene& scene, const std::string& objectId, Part part, int index = -1);

struct RemovedPart {
    std::string objectId;
    int index = -1;
    Part part;
    BspOrderSnapshots bspOrders; // orders as they were before its faces left them
    bool operator==(const RemovedPart&) const = default;
};
// The object may be left without parts; removing the object is the caller's
// choice (the editor does both in one macro).
Result<RemovedPart> removePart(Scene& scene, const std::string& partId);
Result<Unit> restorePart(Scene& scene, const RemovedPart& removed);

// A copy with fresh ids ("box1.body" -> "box1.body-2", its faces prefixed the
// same way) right after the original; returns the new part's id.
Result<std::string> duplicatePart(Scene& scene, const std::string& partId);

// Only the part's id changes (face ids keep their text; nothing refers to parts).
Result<Unit> renamePart(Scene& scene, const std::string& partId, const std::string& newId);
Result<std::string> setPartName(Scene& scene, const std::string& partId, std::string name);
// `material` must exist (or be empty: no default material). Returns the previous one.
Result<std::string> setPartMaterial(Scene& scene, const std::string& partId, std::string material);

struct PartPlace {
    std::string objectId;
    int index = -1;
    bool operator==(const PartPlace&) const = default;
};
// Moves a part to object `objectId` at `index` of that object's parts as they
// are after taking the part out (-1 = append); the same object reorders.
// Returns where the part was. A source object left empty stays.
Result<PartPlace> movePart(Scene& scene, const std::string& partId, const std::string& objectId, int index = -1);

// --- Faces -------------------------------------------------------------------

// Renames a face and every BSP order entry naming it.
Result<Unit> renameFace(Scene& scene, const std::string& faceId, const std::string& newId);
// `material` empty = inherit the part's. Returns the previous value.
Result<std::string> setFaceMaterial(Scene& scene, const std::string& faceId, std::string material);

// --- Geometry ----------------------------------------------------------------

struct PartGeometry {
    std::string partId;
    std::vector<Vec3> vertices;
    std::vector<Face> faces;
    bool operator==(const PartGeometry&) const = default;
};
PartGeometry geometryOf(const Part& part);

// Applies an affine transform (move, rotate, scale, shear, mirror) to the
// part's vertices; a mirror reverses the loops so normals stay outward. The
// previous geometry comes back, so undo restores the exact numbers instead of
// applying an inverse matrix with its rounding.
Result<PartGeometry> transformPart(Scene& scene, const std::string& partId, const glm::dmat4& m);
// All or nothing; the ids must name distinct parts.
Result<std::vector<PartGeometry>> transformParts(Scene& scene, const std::vector<std::string>& partIds,
                                                 const glm::dmat4& m);

// Replaces a part's vertices and faces; returns the previous ones. Face ids
// must be fresh or the part's own; refused if a face named by a BSP order
// would disappear.
Result<PartGeometry> setPartGeometry(Scene& scene, PartGeometry geometry);
// All or nothing, for undoing transformParts / transformObject.
Result<std::vector<PartGeometry>> setPartGeometries(Scene& scene, std::vector<PartGeometry> geometries);

// --- The plane cut in the scene ---------------------------------------------

struct PartSplit {
    RemovedPart original; // where it was, what it was, the BSP orders before
    std::string frontId;
    std::string backId;
    std::vector<PlaneCut::FacePieces> pieces; // source face -> piece ids
    std::vector<std::string> frontCaps;
    std::vector<std::string> backCaps;
    bool operator==(const PartSplit&) const = default;
};
// Replaces the part by its two halves (front at its index, back right after)
// in the same object (see splitPart for ids and caps). The new ids may reuse
// the original part's ids, which it gives up. BSP orders naming a cut face
// name its pieces instead, at the same position.
Result<PartSplit> splitPartInScene(Scene& scene, const std::string& partId, const Plane& plane,
                                   const std::string& frontId, const std::string& backId,
                                   CutCaps caps = CutCaps::Close);
// Undoes splitPartInScene: the halves go, the original and its orders return.
Result<Unit> unsplitPart(Scene& scene, const PartSplit& split);

} // namespace regio::model
