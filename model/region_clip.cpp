#include "model/region_clip.h"

#include "model/validation.h"
#include "model/validation_detail.h"
#include "model/winged_edge.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
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

// A part id that is not in use, for pieces that get their final name later.
std::string temporaryId(const Scene& scene, const std::string& base, int& counter)
{
    std::string id;
    do
        id = base + "-piece" + std::to_string(++counter);
    while (scene.idInUse(id));
    return id;
}

// The six planes of box r, normals pointing into it. Faces on the outside
// of the union of the boxes come first: cutting away what lies outside every
// region before cutting between neighbours leaves one outside piece instead
// of one per neighbour.
std::vector<Plane> cutPlanes(const std::vector<Box3>& boxes, size_t r)
{
    const Box3& box = boxes[r];
    std::vector<Plane> outer, inner;
    for (int axis = 0; axis < 3; ++axis) {
        for (int side = 0; side < 2; ++side) {
            const double at = side == 0 ? box.max[axis] : box.min[axis];
            Vec3 normal{0.0};
            normal[axis] = side == 0 ? -1.0 : 1.0;
            // Does another box lie against this face?
            bool shared = false;
            for (size_t o = 0; o < boxes.size() && !shared; ++o) {
                const Box3& other = boxes[o];
                if (o == r || other.empty)
                    continue;
                const double facing = side == 0 ? other.min[axis] : other.max[axis];
                bool overlaps = std::abs(facing - at) <= kDistanceEpsilon;
                for (int a = 0; a < 3 && overlaps; ++a)
                    if (a != axis)
                        overlaps = other.min[a] < box.max[a] - kDistanceEpsilon &&
                                   box.min[a] < other.max[a] - kDistanceEpsilon;
                shared = overlaps;
            }
            Vec3 point = box.min;
            point[axis] = at;
            (shared ? inner : outer).push_back(Plane::fromPointNormal(point, normal));
        }
    }
    outer.insert(outer.end(), inner.begin(), inner.end());
    return outer;
}

struct Piece {
    std::string id;
    int region = -1; // -1: outside every box
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
    const CutCaps capping = WingedEdgeMesh::build(*source).isClosed() ? CutCaps::Close : CutCaps::Open;
    const std::vector<Box3> boxes = regionBoxes(scene);
    // All or nothing: a refused cut puts back the scene as it was.
    Scene before = scene;
    auto refuse = [&](Diagnostic error) {
        scene = std::move(before);
        return error;
    };

    RegionClip clip;
    clip.partId = partId;
    std::unordered_set<std::string> caps; // current ids of cap faces (and of their pieces)
    int counter = 0;
    std::vector<std::string> pending{partId};
    std::vector<Piece> done;
    for (size_t r = 0; r < boxes.size(); ++r) {
        const Box3& box = boxes[r];
        std::vector<std::string> next;
        for (const std::string& id : pending) {
            if (!partTouchesBox(*scene.findPart(id), box)) {
                next.push_back(id);
                continue;
            }
            // Cut by every plane of the box that crosses the piece; the
            // inside goes on, the outside waits for the next boxes.
            std::string current = id;
            bool outside = false;
            for (const Plane& plane : cutPlanes(boxes, r)) {
                double lowest = std::numeric_limits<double>::infinity(), highest = -lowest;
                for (const Vec3& v : usedVertices(*scene.findPart(current))) {
                    const double s = plane.signedDistance(v);
                    lowest = std::min(lowest, s);
                    highest = std::max(highest, s);
                }
                if (lowest >= -kDistanceEpsilon)
                    continue; // inside this face of the box
                if (highest <= kDistanceEpsilon) {
                    outside = true; // only touches the box
                    break;
                }
                // The inside is the front: it keeps the part's place in its
                // object, so the pieces end up in region order.
                const std::string insideId = temporaryId(scene, partId, counter);
                const std::string outsideId = temporaryId(scene, partId, counter); // counter moved on
                auto split = splitPartInScene(scene, current, plane, insideId, outsideId, capping);
                if (!split)
                    return refuse(split.error());
                for (const PlaneCut::FacePieces& pieces : split->pieces)
                    if (caps.erase(pieces.sourceId))
                        caps.insert(pieces.pieceIds.begin(), pieces.pieceIds.end());
                caps.insert(split->frontCaps.begin(), split->frontCaps.end());
                caps.insert(split->backCaps.begin(), split->backCaps.end());
                clip.splits.push_back(std::move(*split));
                next.push_back(outsideId);
                current = insideId;
            }
            if (outside)
                next.push_back(current);
            else
                done.push_back({current, int(r)});
        }
        pending = std::move(next);
    }
    for (const std::string& id : pending)
        done.push_back({id, -1});
    if (clip.splits.empty())
        return refuse(makeError("no region plane crosses part '" + partId + "' far enough to cut it", "", {partId}));

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
