#include "model/edit/edit_regions.h"

#include "model/edit/edit_support.h"

#include <algorithm>
#include <unordered_set>

namespace regio::model {

namespace {

int regionIndex(const Scene& scene, const std::string& regionId)
{
    for (int r = 0; r < int(scene.regions.size()); ++r)
        if (scene.regions[size_t(r)].id == regionId)
            return r;
    return -1;
}

Check checkBox(const Vec3& min, const Vec3& max, const std::string& pointer)
{
    if (!edit::isFinite(min) || !edit::isFinite(max))
        return makeError("region corners must be finite numbers", pointer);
    static const char* const kAxes[] = {"x", "y", "z"};
    for (int a = 0; a < 3; ++a)
        if (!(min[a] < max[a]))
            return makeError(std::string("a region needs min < max on every axis (") + kAxes[a] + ": " +
                                 std::to_string(min[a]) + " >= " + std::to_string(max[a]) + ")",
                             pointer);
    return success();
}

Check checkOrder(const Scene& scene, const std::vector<std::string>& order, const std::string& pointer)
{
    std::unordered_set<std::string> seen;
    for (size_t i = 0; i < order.size(); ++i) {
        const std::string& faceId = order[i];
        std::string entry = pointer + "/bspOrder/" + std::to_string(i);
        if (!scene.locateFace(faceId).valid())
            return makeError("the BSP order names \"" + faceId + "\", which is not a face", entry);
        if (!seen.insert(faceId).second)
            return makeError("the BSP order names \"" + faceId + "\" twice", entry);
    }
    return success();
}

} // namespace

Result<int> addRegion(Scene& scene, Region region, int index)
{
    int count = int(scene.regions.size());
    if (index < -1 || index > count)
        return makeError("region index " + std::to_string(index) + " is out of range");
    if (index == -1)
        index = count;
    if (Check check = edit::checkNewId(scene, region.id, "region"); !check)
        return check.error();
    if (Check check = checkBox(region.min, region.max, regionPointer(index)); !check)
        return check.error();
    if (Check check = checkOrder(scene, region.bspOrder, regionPointer(index)); !check)
        return check.error();
    scene.regions.insert(scene.regions.begin() + index, std::move(region));
    return index;
}

Result<RemovedRegion> removeRegion(Scene& scene, const std::string& regionId)
{
    int r = regionIndex(scene, regionId);
    if (r < 0)
        return edit::unknown("region", regionId);
    RemovedRegion removed{std::move(scene.regions[size_t(r)]), r};
    scene.regions.erase(scene.regions.begin() + r);
    return removed;
}

Result<Unit> renameRegion(Scene& scene, const std::string& regionId, const std::string& newId)
{
    Region* region = scene.findRegion(regionId);
    if (!region)
        return edit::unknown("region", regionId);
    if (newId == regionId)
        return Unit{};
    if (Check check = edit::checkNewId(scene, newId, "region"); !check)
        return check.error();
    region->id = newId;
    return Unit{};
}

Result<std::string> setRegionName(Scene& scene, const std::string& regionId, std::string name)
{
    Region* region = scene.findRegion(regionId);
    if (!region)
        return edit::unknown("region", regionId);
    std::swap(region->name, name);
    return name;
}

Result<RegionBox> setRegionBox(Scene& scene, const std::string& regionId, const Vec3& min, const Vec3& max)
{
    int r = regionIndex(scene, regionId);
    if (r < 0)
        return edit::unknown("region", regionId);
    if (Check check = checkBox(min, max, regionPointer(r)); !check)
        return check.error();
    Region& region = scene.regions[size_t(r)];
    RegionBox previous{region.min, region.max};
    region.min = min;
    region.max = max;
    return previous;
}

Result<std::vector<std::string>> setBspOrder(Scene& scene, const std::string& regionId, std::vector<std::string> order)
{
    int r = regionIndex(scene, regionId);
    if (r < 0)
        return edit::unknown("region", regionId);
    if (Check check = checkOrder(scene, order, regionPointer(r)); !check)
        return check.error();
    std::swap(scene.regions[size_t(r)].bspOrder, order);
    return order;
}

Result<int> insertBspEntry(Scene& scene, const std::string& regionId, const std::string& faceId, int index)
{
    int r = regionIndex(scene, regionId);
    if (r < 0)
        return edit::unknown("region", regionId);
    auto& order = scene.regions[size_t(r)].bspOrder;
    if (index < -1 || index > int(order.size()))
        return makeError("BSP order position " + std::to_string(index) + " is out of range",
                         regionPointer(r) + "/bspOrder");
    if (index == -1)
        index = int(order.size());
    if (!scene.locateFace(faceId).valid())
        return edit::unknown("face", faceId);
    if (std::find(order.begin(), order.end(), faceId) != order.end())
        return makeError("\"" + faceId + "\" is already in the BSP order of \"" + regionId + "\"",
                         regionPointer(r) + "/bspOrder");
    order.insert(order.begin() + index, faceId);
    return index;
}

Result<BspEntry> removeBspEntry(Scene& scene, const std::string& regionId, int index)
{
    int r = regionIndex(scene, regionId);
    if (r < 0)
        return edit::unknown("region", regionId);
    auto& order = scene.regions[size_t(r)].bspOrder;
    if (index < 0 || index >= int(order.size()))
        return makeError("BSP order position " + std::to_string(index) + " is out of range",
                         regionPointer(r) + "/bspOrder");
    BspEntry entry{std::move(order[size_t(index)]), index};
    order.erase(order.begin() + index);
    return entry;
}

Result<Unit> moveBspEntry(Scene& scene, const std::string& regionId, int from, int to)
{
    int r = regionIndex(scene, regionId);
    if (r < 0)
        return edit::unknown("region", regionId);
    auto& order = scene.regions[size_t(r)].bspOrder;
    int count = int(order.size());
    if (from < 0 || from >= count || to < 0 || to >= count)
        return makeError("BSP order positions " + std::to_string(from) + " -> " + std::to_string(to) +
                             " are out of range",
                         regionPointer(r) + "/bspOrder");
    // A rotation of the range between the two positions is exactly "take out,
    // insert at": its inverse is the rotation the other way.
    if (from < to)
        std::rotate(order.begin() + from, order.begin() + from + 1, order.begin() + to + 1);
    else if (to < from)
        std::rotate(order.begin() + to, order.begin() + from, order.begin() + from + 1);
    return Unit{};
}

BspOrderSnapshots removeFacesFromBspOrders(Scene& scene, const std::vector<std::string>& faceIds)
{
    BspOrderSnapshots snapshots;
    if (faceIds.empty())
        return snapshots;
    std::unordered_set<std::string> gone(faceIds.begin(), faceIds.end());
    for (Region& region : scene.regions) {
        auto named = [&](const std::string& id) { return gone.count(id) > 0; };
        if (std::none_of(region.bspOrder.begin(), region.bspOrder.end(), named))
            continue;
        snapshots.push_back({region.id, region.bspOrder});
        std::erase_if(region.bspOrder, named);
    }
    return snapshots;
}

void restoreBspOrders(Scene& scene, const BspOrderSnapshots& snapshots)
{
    for (const BspOrderSnapshot& snapshot : snapshots)
        if (Region* region = scene.findRegion(snapshot.regionId))
            region->bspOrder = snapshot.order;
}

void renameFaceInBspOrders(Scene& scene, const std::string& faceId, const std::string& newId)
{
    for (Region& region : scene.regions)
        std::replace(region.bspOrder.begin(), region.bspOrder.end(), faceId, newId);
}

const Region* regionOrderingFace(const Scene& scene, const std::string& faceId)
{
    for (const Region& region : scene.regions)
        if (std::find(region.bspOrder.begin(), region.bspOrder.end(), faceId) != region.bspOrder.end())
            return &region;
    return nullptr;
}

} // namespace regio::model
