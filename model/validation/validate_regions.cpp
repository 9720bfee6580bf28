// Validation of the regions (paper §5.2) and their BSP root-patch orders
// (§5.3): boxes that the regional tree can separate, parts that lie inside
// them, and orders that name faces of their own region.
#include "model/validation/validation.h"
#include "model/validation/validation_detail.h"

#include <algorithm>
#include <cmath>
#include <unordered_set>

namespace regio::model::detail {

double areaInsideBox(std::span<const Vec3> loop, const Box3& box)
{
    if (box.empty || loop.size() < 3)
        return 0.0;
    std::vector<Vec3> current(loop.begin(), loop.end());
    std::vector<Vec3> outside, inside;
    for (int axis = 0; axis < 3; ++axis) {
        Vec3 normal{0.0};
        normal[axis] = 1.0;
        // Keep the back side of "x <= max" and of "-x <= -min".
        for (const Plane& plane : {Plane{normal, -box.max[axis]}, Plane{-normal, box.min[axis]}}) {
            splitPolygon(current, plane, outside, inside);
            if (inside.empty())
                return 0.0;
            current.swap(inside);
        }
    }
    return polygonArea(current);
}

namespace {

bool isFinite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// The closed boxes share a point (within kDistanceEpsilon).
bool closedBoxesMeet(const Box3& a, const Box3& b)
{
    if (a.empty || b.empty)
        return false;
    for (int axis = 0; axis < 3; ++axis)
        if (a.max[axis] < b.min[axis] - kDistanceEpsilon || b.max[axis] < a.min[axis] - kDistanceEpsilon)
            return false;
    return true;
}

std::string quotedList(const std::vector<std::string_view>& ids)
{
    std::string text;
    for (size_t i = 0; i < ids.size(); ++i)
        text += (i == 0 ? "" : (i + 1 == ids.size() ? " and " : ", ")) + quoted(ids[i]);
    return text;
}

// Region boxes that are usable for the geometric rules; empty boxes mark
// regions already reported as malformed.
std::vector<Box3> checkRegionBoxes(ValidationContext& context)
{
    const auto& regions = context.scene.regions;
    std::vector<Box3> boxes(regions.size());
    for (size_t r = 0; r < regions.size(); ++r) {
        const Region& region = regions[r];
        const std::string name = "region " + quoted(region.id);
        bool ok = true;
        for (const char* key : {"min", "max"}) {
            const Vec3& corner = key[1] == 'i' ? region.min : region.max;
            if (!isFinite(corner)) {
                context.error(name + ": " + key + " is not a finite point", regionPointer(r) + "/" + key, {region.id});
                ok = false;
            }
        }
        if (ok) {
            static const char* kAxis[3] = {"x", "y", "z"};
            for (int a = 0; a < 3 && ok; ++a) {
                if (region.min[a] >= region.max[a]) {
                    context.error(name + " is empty: its min " + kAxis[a] + " (" + formatValue(region.min[a]) +
                                      ") is not below its max " + kAxis[a] + " (" + formatValue(region.max[a]) + ")",
                                  regionPointer(r), {region.id});
                    ok = false;
                }
            }
        }
        if (ok) {
            boxes[r].extend(region.min);
            boxes[r].extend(region.max);
        }
    }
    return boxes;
}

// Overlapping boxes, then (when none overlap) boxes that interlock so that no
// axis-aligned plane separates them: the regional tree needs such a plane at
// every inner node (§5.2).
void checkRegionLayout(ValidationContext& context, const std::vector<Box3>& boxes)
{
    const auto& regions = context.scene.regions;
    bool overlap = false;
    for (size_t j = 0; j < boxes.size(); ++j)
        for (size_t i = 0; i < j; ++i)
            if (boxes[i].overlapsInterior(boxes[j])) {
                overlap = true;
                context.error("region " + quoted(regions[j].id) + " overlaps region " + quoted(regions[i].id) +
                                  "; regions must not share any volume (touching is fine)",
                              regionPointer(j), {regions[j].id});
            }
    if (overlap)
        return;

    std::vector<std::vector<int>> pending(1);
    for (size_t r = 0; r < boxes.size(); ++r)
        if (!boxes[r].empty)
            pending[0].push_back(int(r));
    while (!pending.empty()) {
        std::vector<int> group = std::move(pending.back());
        pending.pop_back();
        if (group.size() < 2)
            continue;
        bool split = false;
        for (int axis = 0; axis < 3 && !split; ++axis) {
            std::sort(group.begin(), group.end(),
                      [&](int a, int b) { return boxes[size_t(a)].min[axis] < boxes[size_t(b)].min[axis]; });
            double reach = -INFINITY;
            for (size_t i = 0; i + 1 < group.size(); ++i) {
                reach = std::max(reach, boxes[size_t(group[i])].max[axis]);
                if (reach <= boxes[size_t(group[i + 1])].min[axis] + kDistanceEpsilon) {
                    pending.emplace_back(group.begin(), group.begin() + std::ptrdiff_t(i + 1));
                    pending.emplace_back(group.begin() + std::ptrdiff_t(i + 1), group.end());
                    split = true;
                    break;
                }
            }
        }
        if (!split) {
            std::sort(group.begin(), group.end());
            std::vector<std::string_view> ids;
            for (int r : group)
                ids.push_back(regions[size_t(r)].id);
            context.error("regions " + quotedList(ids) +
                              " interlock: no axis-aligned plane separates them, so the regional tree "
                              "cannot be built; reshape them into boxes that can be cut apart",
                          regionPointer(size_t(group.front())), {regions[size_t(group.front())].id});
        }
    }
}

void checkPartsInRegions(ValidationContext& context, const std::vector<Box3>& boxes)
{
    if (std::all_of(boxes.begin(), boxes.end(), [](const Box3& box) { return box.empty; }))
        return;
    const Scene& scene = context.scene;
    std::vector<Vec3> positions;
    for (size_t o = 0; o < scene.objects.size(); ++o) {
        for (size_t p = 0; p < scene.objects[o].parts.size(); ++p) {
            const Part& part = scene.objects[o].parts[p];
            const std::vector<char>& usable = context.faceUsable[o][p];
            // The vertices the usable faces stand on.
            std::vector<char> used(part.vertices.size(), 0);
            Box3 bounds;
            for (size_t f = 0; f < part.faces.size(); ++f)
                if (usable[f])
                    for (int v : part.faces[f].loop) {
                        used[size_t(v)] = 1;
                        bounds.extend(part.vertices[size_t(v)]);
                    }
            if (bounds.empty)
                continue;
            auto inside = [&](const Box3& box) {
                for (size_t v = 0; v < used.size(); ++v)
                    if (used[v] && !box.contains(part.vertices[v]))
                        return false;
                return true;
            };
            if (std::any_of(boxes.begin(), boxes.end(), inside))
                continue;

            std::vector<std::string_view> touched;
            for (size_t r = 0; r < boxes.size(); ++r) {
                if (!closedBoxesMeet(bounds, boxes[r]))
                    continue;
                for (size_t f = 0; f < part.faces.size(); ++f) {
                    if (!usable[f])
                        continue;
                    positions = loopPositions(part.vertices, part.faces[f].loop);
                    if (areaInsideBox(positions, boxes[r]) >= kMinFaceArea) {
                        touched.push_back(scene.regions[r].id);
                        break;
                    }
                }
            }
            bool outsideAll = false;
            for (size_t v = 0; v < used.size() && !outsideAll; ++v)
                if (used[v] && std::none_of(boxes.begin(), boxes.end(),
                                            [&](const Box3& box) { return box.contains(part.vertices[v]); }))
                    outsideAll = true;

            const std::string name = "part " + quoted(part.id);
            if (touched.empty()) {
                context.warning(name +
                                    " lies outside every region; the solver still files it in the "
                                    "regional-tree cell on its side of the separating planes, but no "
                                    "region box or BSP order covers it: enlarge a region or add one",
                                partPointer(o, p), partPath(context, o, p));
            } else {
                context.warning(name +
                                    (touched.size() == 1 ? " straddles the boundary of region "
                                                         : " straddles the boundaries of regions ") +
                                    quotedList(touched) + (outsideAll ? " and partly lies outside every region" : "") +
                                    ": the solver will clip it at the separating planes",
                                partPointer(o, p), partPath(context, o, p));
            }
        }
    }
}

void checkBspOrders(ValidationContext& context, const std::vector<Box3>& boxes)
{
    const Scene& scene = context.scene;
    std::vector<Vec3> positions;
    for (size_t r = 0; r < scene.regions.size(); ++r) {
        const Region& region = scene.regions[r];
        std::unordered_map<std::string_view, size_t> listed;
        for (size_t k = 0; k < region.bspOrder.size(); ++k) {
            const std::string& faceId = region.bspOrder[k];
            const std::string pointer = regionPointer(r) + "/bspOrder/" + std::to_string(k);
            auto [first, fresh] = listed.try_emplace(faceId, k);
            if (!fresh) {
                context.warning("face " + quoted(faceId) + " is listed twice in the BSP order of region " +
                                    quoted(region.id) + " (first at position " + std::to_string(first->second) +
                                    "); the later entry has no effect",
                                pointer, {region.id});
                continue;
            }
            auto found = context.faceIndex.find(faceId);
            if (found == context.faceIndex.end()) {
                context.error("the BSP order of region " + quoted(region.id) + " names " + quoted(faceId) +
                                  ", which is not a face of the scene",
                              pointer, {region.id});
                continue;
            }
            const FaceLocation at = found->second;
            if (boxes[r].empty || !context.usable(at))
                continue;
            const Part& part = context.part(at.object, at.part);
            positions = loopPositions(part.vertices, part.faces[size_t(at.face)].loop);
            if (polygonArea(positions) < kMinFaceArea)
                continue; // reported as a zero-area face; it has no inside or outside
            if (areaInsideBox(positions, boxes[r]) < kMinFaceArea)
                context.error("the BSP order of region " + quoted(region.id) + " names face " + quoted(faceId) +
                                  ", which lies outside the region; a region's BSP order may only name "
                                  "faces inside its box",
                              pointer, {region.id});
        }
    }
}

} // namespace

void validateRegions(ValidationContext& context)
{
    const std::vector<Box3> boxes = checkRegionBoxes(context);
    checkRegionLayout(context, boxes);
    checkPartsInRegions(context, boxes);
    checkBspOrders(context, boxes);
}

} // namespace regio::model::detail
