#include "model/geometry/region_clip.h"

#include "model/geometry/winged_edge.h"
#include "model/validation/validation.h"
#include "model/validation/validation_detail.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <unordered_set>

namespace regio::model {

namespace {

// The region boxes validation measures against; malformed boxes (min >= max,
// non-finite) are reported there and ignored here (empty box).
std::vector<Box3> regionBoxes(const Scene& scene)
{
    std::vector<Box3> boxes(scene.regions.size());
    for (size_t r = 0; r < boxes.size(); ++r) {
        const Region& region = scene.regions[r];
        bool ok = true;
        for (int a = 0; a < 3; ++a)
            ok = ok && std::isfinite(region.min[a]) && std::isfinite(region.max[a]) && region.min[a] < region.max[a];
        if (ok) {
            boxes[r].extend(region.min);
            boxes[r].extend(region.max);
        }
    }
    return boxes;
}

bool loopValid(const Part& part, const Face& face)
{
    if (face.loop.size() < 3)
        return false;
    for (int v : face.loop)
        if (v < 0 || size_t(v) >= part.vertices.size())
            return false;
    return true;
}

// The vertices the part's faces stand on (a stray vertex is not geometry).
std::vector<Vec3> usedVertices(const Part& part)
{
    std::vector<char> used(part.vertices.size(), 0);
    for (const Face& face : part.faces)
        if (loopValid(part, face))
            for (int v : face.loop)
                used[size_t(v)] = 1;
    std::vector<Vec3> out;
    for (size_t v = 0; v < used.size(); ++v)
        if (used[v])
            out.push_back(part.vertices[v]);
    return out;
}

bool partInsideBox(const std::vector<Vec3>& vertices, const Box3& box)
{
    return !box.empty && !vertices.empty() &&
           std::all_of(vertices.begin(), vertices.end(), [&](const Vec3& v) { return box.contains(v); });
}

bool partTouchesBox(const Part& part, const Box3& box)
{
    if (box.empty)
        return false;
    for (const Face& face : part.faces)
        if (loopValid(part, face) && faceTouchesRegionBox(loopPositions(part.vertices, face.loop), box))
            return true;
    return false;
}

// Closed with its normals pointing out: a solid, whose pieces get caps. A
// closed shell facing inwards is a room seen from inside (makeRoom); capping
// its pieces would build walls across the room at the region boundaries.
bool isSolid(const Part& part)
{
    if (!WingedEdgeMesh::build(part).isClosed())
        return false;
    double volume = 0.0; // divergence theorem: sum of (area vector . point) / 3
    for (const Face& face : part.faces)
        if (loopValid(part, face)) {
            const std::vector<Vec3> loop = loopPositions(part.vertices, face.loop);
            volume += glm::dot(newellNormal(loop), loop.front()) / 6.0;
        }
    return volume > 0.0;
}

// A part id that is not in use, for pieces that get their final name later.
std::string temporaryId(const Scene& scene, const std::string& base, int& counter)
{
    std::string id;
    do
        id = base + "-piece" + std::to_string(++counter);
    while (scene.idInUse(id));
    return id;
}

struct Piece {
    std::string id;
    int region = -1; // -1: outside every box
};

// Extreme signed distances of the part's vertices from a plane.
std::pair<double, double> sideRange(const Part& part, const Plane& plane)
{
    double lowest = std::numeric_limits<double>::infinity(), highest = -lowest;
    for (const Vec3& v : usedVertices(part)) {
        const double s = plane.signedDistance(v);
        lowest = std::min(lowest, s);
        highest = std::max(highest, s);
    }
    return {lowest, highest};
}

// An axis-aligned plane with every box of `group` on one side (touching
// allowed), found on the limit lists as the regional tree finds it (§5.2).
std::optional<std::pair<int, double>> separatingPlane(const std::vector<Box3>& boxes, std::vector<int> group)
{
    for (int axis = 0; axis < 3; ++axis) {
        std::sort(group.begin(), group.end(),
                  [&](int a, int b) { return boxes[size_t(a)].min[axis] < boxes[size_t(b)].min[axis]; });
        double reach = -std::numeric_limits<double>::infinity();
        for (size_t i = 0; i + 1 < group.size(); ++i) {
            reach = std::max(reach, boxes[size_t(group[i])].max[axis]);
            if (reach <= boxes[size_t(group[i + 1])].min[axis] + kDistanceEpsilon)
                return std::pair{axis, reach};
        }
    }
    return std::nullopt;
}

// Cuts a piece down the tree of separating planes between the boxes, so it
// falls apart into one piece per region cell it reaches, then cuts away what
// sticks out of the cell's box (that lies outside every region).
struct Clipper {
    Clipper(Scene& sceneToCut, const std::vector<Box3>& regionBoxes, const std::string& clippedPartId, CutCaps cutCaps,
            RegionClip& clipRecord)
        : scene(sceneToCut)
        , boxes(regionBoxes)
        , partId(clippedPartId)
        , capping(cutCaps)
        , record(clipRecord)
    {
    }

    Scene& scene;
    const std::vector<Box3>& boxes;
    const std::string& partId;
    CutCaps capping;
    RegionClip& record;
    std::vector<Piece> done;
    std::unordered_set<std::string> caps; // current ids of cap faces (and of their pieces)
    int counter = 0;

    // Cuts `current` by `plane`; the front piece (kept at the part's place
    // in its object) and the back piece come back.
    Check cut(const std::string& current, const Plane& plane, std::string& front, std::string& back)
    {
        front = temporaryId(scene, partId, counter);
        back = temporaryId(scene, partId, counter); // the counter moved on
        auto split = splitPartInScene(scene, current, plane, front, back, capping);
        if (!split)
            return split.error();
        for (const PlaneCut::FacePieces& pieces : split->pieces)
            if (caps.erase(pieces.sourceId))
                caps.insert(pieces.pieceIds.begin(), pieces.pieceIds.end());
        caps.insert(split->frontCaps.begin(), split->frontCaps.end());
        caps.insert(split->backCaps.begin(), split->backCaps.end());
        record.splits.push_back(std::move(*split));
        return success();
    }

    Check clip(std::string piece, const std::vector<int>& group)
    {
        if (group.empty()) {
            done.push_back({piece, -1});
            return success();
        }
        // What sticks out of the group's bounds lies outside every region
        // (the piece is already inside the group's cell): cut it away first,
        // so it stays one piece instead of one per region below.
        Box3 bounds;
        for (int r : group)
            bounds.extend(boxes[size_t(r)]);
        bool inside = true;
        if (Check check = trim(piece, bounds, inside); !check)
            return check;
        if (!inside || (group.size() == 1 && !partTouchesBox(*scene.findPart(piece), bounds))) {
            done.push_back({piece, -1});
            return success();
        }
        if (group.size() == 1) {
            done.push_back({piece, group.front()});
            return success();
        }

        const auto plane = separatingPlane(boxes, group);
        if (!plane)
            return makeError("the regions overlap or interlock, so no plane separates them; fix the regions first", "",
                             {partId});
        const auto [axis, position] = *plane;
        std::vector<int> low, high;
        for (int r : group)
            (boxes[size_t(r)].max[axis] <= position + kDistanceEpsilon ? low : high).push_back(r);
        Vec3 normal{0.0};
        normal[axis] = -1.0; // front = the low side, which keeps the part's place
        Vec3 point{0.0};
        point[axis] = position;
        const Plane separating = Plane::fromPointNormal(point, normal);
        const auto [lowest, highest] = sideRange(*scene.findPart(piece), separating);
        if (lowest >= -kDistanceEpsilon)
            return clip(piece, low);
        if (highest <= kDistanceEpsilon)
            return clip(piece, high);
        std::string lowPiece, highPiece;
        if (Check check = cut(piece, separating, lowPiece, highPiece); !check)
            return check;
        if (Check check = clip(lowPiece, low); !check)
            return check;
        return clip(highPiece, high);
    }

    // Cuts away the parts of `current` outside `box` (each an outside piece);
    // `inside` turns false when nothing of it is inside.
    Check trim(std::string& current, const Box3& box, bool& inside)
    {
        for (int axis = 0; axis < 3; ++axis) {
            for (int side = 0; side < 2; ++side) {
                Vec3 normal{0.0};
                normal[axis] = side == 0 ? -1.0 : 1.0; // pointing into the box
                const Plane plane = Plane::fromPointNormal(side == 0 ? box.max : box.min, normal);
                const auto [lowest, highest] = sideRange(*scene.findPart(current), plane);
                if (lowest >= -kDistanceEpsilon)
                    continue; // inside this face of the box
                if (highest <= kDistanceEpsilon) {
                    inside = false; // at most touches the box
                    return success();
                }
                std::string kept, outside;
                if (Check check = cut(current, plane, kept, outside); !check)
                    return check;
                done.push_back({outside, -1});
                current = kept;
            }
        }
        return success();
    }
};

} // namespace

double polygonAreaInBox(std::span<const Vec3> loop, const Box3& box) { return detail::areaInsideBox(loop, box); }

bool faceTouchesRegionBox(std::span<const Vec3> loop, const Box3& box)
{
    return polygonAreaInBox(loop, box) >= kMinFaceArea;
}

bool partStraddlesRegions(const Scene& scene, const Part& part)
{
    const std::vector<Box3> boxes = regionBoxes(scene);
    const std::vector<Vec3> vertices = usedVertices(part);
    if (vertices.empty())
        return false;
    if (std::any_of(boxes.begin(), boxes.end(), [&](const Box3& box) { return partInsideBox(vertices, box); }))
        return false;
    return std::any_of(boxes.begin(), boxes.end(), [&](const Box3& box) { return partTouchesBox(part, box); });
}

Result<RegionClip> clipPartToRegions(Scene& scene, const std::string& partId)
{
    const Part* source = scene.findPart(partId);
    if (!source)
        return makeError("there is no part '" + partId + "'", "", {partId});
    if (!partStraddlesRegions(scene, *source))
        return makeError("part '" + partId +
                             "' does not straddle a region boundary (it lies inside one region or outside all): "
                             "there is nothing to clip",
                         "", {partId});
    const CutCaps capping = isSolid(*source) ? CutCaps::Close : CutCaps::Open;
    const std::vector<Box3> boxes = regionBoxes(scene);
    // All or nothing: a refused cut puts back the scene as it was.
    Scene before = scene;
    auto refuse = [&](Diagnostic error) {
        scene = std::move(before);
        return error;
    };

    RegionClip clip;
    clip.partId = partId;
    Clipper clipper{scene, boxes, partId, capping, clip};
    std::vector<int> all;
    for (size_t r = 0; r < boxes.size(); ++r)
        if (!boxes[r].empty)
            all.push_back(int(r));
    if (Check check = clipper.clip(partId, all); !check)
        return refuse(check.error());
    if (clip.splits.empty())
        return refuse(makeError("no region plane crosses part '" + partId + "' far enough to cut it", "", {partId}));
    const std::vector<Piece>& done = clipper.done;
    const std::unordered_set<std::string>& caps = clipper.caps;

    // Final names after the regions.
    std::unordered_set<std::string> pieceFaces;
    for (const Piece& piece : done) {
        const std::string name =
            scene.uniqueId(partId + "-" + (piece.region >= 0 ? scene.regions[size_t(piece.region)].id : "outside"));
        if (auto renamed = renamePart(scene, piece.id, name); !renamed)
            return refuse(renamed.error());
        clip.partRenames.emplace_back(piece.id, name);
        std::vector<std::string> faceIds;
        for (const Face& face : scene.findPart(name)->faces)
            faceIds.push_back(face.id);
        for (const std::string& faceId : faceIds) {
            std::string newId = cutPieceId(faceId, piece.id, name);
            if (newId != faceId && scene.idInUse(newId))
                newId = scene.uniqueId(newId);
            if (newId != faceId) {
                if (auto renamed = renameFace(scene, faceId, newId); !renamed)
                    return refuse(renamed.error());
                clip.faceRenames.emplace_back(faceId, newId);
            }
            pieceFaces.insert(newId);
            if (caps.count(faceId))
                clip.capFaces.push_back(newId);
        }
    }

    // A region's order may only name faces inside its box.
    for (size_t r = 0; r < scene.regions.size(); ++r) {
        Region& region = scene.regions[r];
        std::vector<std::string> order;
        for (const std::string& faceId : region.bspOrder) {
            if (pieceFaces.count(faceId) && !boxes[r].empty) {
                const Scene::FaceLocation at = scene.locateFace(faceId);
                const Part& part = scene.objects[size_t(at.object)].parts[size_t(at.part)];
                const Face& face = part.faces[size_t(at.face)];
                if (!loopValid(part, face) || !faceTouchesRegionBox(loopPositions(part.vertices, face.loop), boxes[r]))
                    continue;
            }
            order.push_back(faceId);
        }
        if (order != region.bspOrder) {
            clip.bspOrders.push_back({region.id, region.bspOrder});
            region.bspOrder = std::move(order);
        }
    }

    std::unordered_set<std::string> finalIds;
    for (const auto& [from, to] : clip.partRenames)
        finalIds.insert(to);
    for (const Object& object : scene.objects)
        for (const Part& part : object.parts)
            if (finalIds.count(part.id))
                clip.pieces.push_back(part.id);
    return clip;
}

Result<Unit> unclipPart(Scene& scene, const RegionClip& clip)
{
    Scene before = scene;
    auto refuse = [&](Diagnostic error) {
        scene = std::move(before);
        return error;
    };
    restoreBspOrders(scene, clip.bspOrders);
    for (auto it = clip.faceRenames.rbegin(); it != clip.faceRenames.rend(); ++it)
        if (auto renamed = renameFace(scene, it->second, it->first); !renamed)
            return refuse(renamed.error());
    for (auto it = clip.partRenames.rbegin(); it != clip.partRenames.rend(); ++it)
        if (auto renamed = renamePart(scene, it->second, it->first); !renamed)
            return refuse(renamed.error());
    for (auto it = clip.splits.rbegin(); it != clip.splits.rend(); ++it)
        if (auto restored = unsplitPart(scene, *it); !restored)
            return refuse(restored.error());
    return Unit{};
}

} // namespace regio::model
