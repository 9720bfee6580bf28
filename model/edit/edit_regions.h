#pragma once
// Edits of regions and their BSP root-patch orders (paper §5.2, §5.3). Each
// returns what its inverse needs and leaves the scene unchanged when refused:
//   addRegion(r, i)            <-> removeRegion(r.id) -> {region, index}
//   renameRegion(a, b)         <-> renameRegion(b, a)
//   setRegionName/Box/BspOrder return the previous value; set it back to undo
//   insertBspEntry(r, f, i)    <-> removeBspEntry(r, i) -> {face, index}
//   moveBspEntry(r, from, to)  <-> moveBspEntry(r, to, from)
// Overlapping regions are allowed while editing (an author resizing a box
// passes through such states); validation reports them live.
#include "model/result.h"
#include "model/scene.h"

#include <string>
#include <vector>

namespace regio::model {

// --- Regions ---------------------------------------------------------------

// Inserts at `index` (-1 or the count: append); returns the index used. The id
// must be fresh, min < max on every axis, the BSP order names existing faces
// once each.
Result<int> addRegion(Scene& scene, Region region, int index = -1);

struct RemovedRegion {
    Region region;
    int index = -1;
    bool operator==(const RemovedRegion&) const = default;
};
// Undo: addRegion(scene, removed.region, removed.index).
Result<RemovedRegion> removeRegion(Scene& scene, const std::string& regionId);

// Nothing refers to regions by id, so only the region changes.
Result<Unit> renameRegion(Scene& scene, const std::string& regionId, const std::string& newId);
// Returns the previous name.
Result<std::string> setRegionName(Scene& scene, const std::string& regionId, std::string name);

struct RegionBox {
    Vec3 min{0.0};
    Vec3 max{0.0};
    bool operator==(const RegionBox&) const = default;
};
// Refuses non-finite corners and min >= max on any axis; returns the previous box.
Result<RegionBox> setRegionBox(Scene& scene, const std::string& regionId, const Vec3& min, const Vec3& max);

// --- BSP orders --------------------------------------------------------------

// Replaces the whole order; every entry must name an existing face, once.
// Returns the previous order.
Result<std::vector<std::string>> setBspOrder(Scene& scene, const std::string& regionId, std::vector<std::string> order);
// Inserts `faceId` at `index` (-1 = append); refuses unknown faces and faces
// already in the order. Returns the index used.
Result<int> insertBspEntry(Scene& scene, const std::string& regionId, const std::string& faceId, int index = -1);

struct BspEntry {
    std::string faceId;
    int index = -1;
    bool operator==(const BspEntry&) const = default;
};
// Undo: insertBspEntry(scene, regionId, entry.faceId, entry.index).
Result<BspEntry> removeBspEntry(Scene& scene, const std::string& regionId, int index);
// Takes the entry at `from` out and puts it back so it ends up at `to`
// (both in [0, size)). Undo: moveBspEntry(scene, regionId, to, from).
Result<Unit> moveBspEntry(Scene& scene, const std::string& regionId, int from, int to);

// --- Keeping orders consistent when faces come and go -----------------------
// Edits that remove or replace faces (removing objects and parts, the plane
// cut) also take those faces out of every BSP order, so the scene never names
// a missing face; they return the orders as they were, for their undo.

struct BspOrderSnapshot {
    std::string regionId;
    std::vector<std::string> order;
    bool operator==(const BspOrderSnapshot&) const = default;
};
using BspOrderSnapshots = std::vector<BspOrderSnapshot>;

// Removes the given faces from every order; returns the previous orders of
// the regions that changed.
BspOrderSnapshots removeFacesFromBspOrders(Scene& scene, const std::vector<std::string>& faceIds);
// Puts snapshotted orders back (regions that no longer exist are skipped).
void restoreBspOrders(Scene& scene, const BspOrderSnapshots& snapshots);
// Every region whose order names `faceId` gets `newId` instead.
void renameFaceInBspOrders(Scene& scene, const std::string& faceId, const std::string& newId);
// The first region whose order names the face, or nullptr.
const Region* regionOrderingFace(const Scene& scene, const std::string& faceId);

} // namespace regio::model
