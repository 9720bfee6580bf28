#include "model/geometry/plane_cut.h"

#include "model/edit/edit_support.h"
#include "model/geometry/convex_decomposition.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <unordered_map>
#include <unordered_set>

namespace regio::model {

namespace {

// Merges positions closer than kDistanceEpsilon into one vertex, so the two
// faces beside a cut edge get the same new corner although each computed it.
class Welder {
public:
    explicit Welder(std::vector<Vec3>& out)
        : m_out(out)
    {
    }

    int add(const Vec3& p)
    {
        std::array<std::int64_t, 3> cell = cellOf(p);
        for (std::int64_t dx = -1; dx <= 1; ++dx)
            for (std::int64_t dy = -1; dy <= 1; ++dy)
                for (std::int64_t dz = -1; dz <= 1; ++dz) {
                    auto it = m_grid.find({cell[0] + dx, cell[1] + dy, cell[2] + dz});
                    if (it == m_grid.end())
                        continue;
                    for (int index : it->second)
                        if (glm::length(m_out[size_t(index)] - p) <= kDistanceEpsilon)
                            return index;
                }
        int index = int(m_out.size());
        m_out.push_back(p);
        m_grid[cell].push_back(index);
        return index;
    }

private:
    static constexpr double kCell = 4.0 * kDistanceEpsilon;
    static std::array<std::int64_t, 3> cellOf(const Vec3& p)
    {
        return {std::int64_t(std::floor(p.x / kCell)), std::int64_t(std::floor(p.y / kCell)),
                std::int64_t(std::floor(p.z / kCell))};
    }
    std::vector<Vec3>& m_out;
    std::map<std::array<std::int64_t, 3>, std::vector<int>> m_grid;
};

using EdgeCounts = std::map<std::pair<int, int>, int>;

EdgeCounts directedEdges(const std::vector<std::vector<int>>& loops)
{
    EdgeCounts counts;
    for (const auto& loop : loops)
        for (size_t i = 0; i < loop.size(); ++i)
            ++counts[{loop[i], loop[(i + 1) % loop.size()]}];
    return counts;
}

// Every edge traversed once each way (after welding coincident vertices).
bool isClosed(const Part& part)
{
    std::vector<Vec3> welded;
    Welder welder(welded);
    std::vector<int> canonical;
    for (const Vec3& v : part.vertices)
        canonical.push_back(welder.add(v));
    std::vector<std::vector<int>> loops;
    for (const Face& face : part.faces) {
        std::vector<int> loop;
        for (int index : face.loop)
            loop.push_back(canonical[size_t(index)]);
        loops.push_back(std::move(loop));
    }
    EdgeCounts counts = directedEdges(loops);
    for (const auto& [edge, count] : counts) {
        if (edge.first == edge.second)
            return false;
        auto twin = counts.find({edge.second, edge.first});
        if (twin == counts.end() || twin->second != count)
            return false;
    }
    return !counts.empty();
}

// Ids claimed by either new part: face ids must be unique across both.
class IdClaims {
public:
    std::string claim(const std::string& id)
    {
        std::string candidate = id;
        for (int n = 2; m_used.count(candidate); ++n)
            candidate = id + "-" + std::to_string(n);
        m_used.insert(candidate);
        return candidate;
    }

private:
    std::unordered_set<std::string> m_used;
};

// One of the two parts being built.
struct CutSide {
    Part part;
    Welder welder{part.vertices};

    CutSide() = default;
    CutSide(const CutSide&) = delete;

    // Adds a piece; returns false when welding collapsed it below a triangle.
    bool addFace(const std::vector<Vec3>& positions, const std::string& id, const std::string& material)
    {
        std::vector<int> loop;
        for (const Vec3& p : positions) {
            int index = welder.add(p);
            if (loop.empty() || loop.back() != index)
                loop.push_back(index);
        }
        while (loop.size() > 1 && loop.front() == loop.back())
            loop.pop_back();
        if (loop.size() < 3)
            return false;
        part.faces.push_back({id, std::move(loop), material});
        return true;
    }
};

// Chains the half-edges left open on one side into loops. At a vertex where
// two loops touch, the walk takes the sharpest left turn about `normal`, which
// keeps each loop on one piece of the cut instead of a figure eight.
Result<std::vector<std::vector<int>>> chainLoops(const std::vector<Vec3>& vertices,
                                                 std::vector<std::pair<int, int>> halfEdges, const Vec3& normal)
{
    std::unordered_map<int, std::vector<size_t>> outgoing;
    for (size_t e = 0; e < halfEdges.size(); ++e)
        outgoing[halfEdges[e].first].push_back(e);
    std::vector<char> used(halfEdges.size(), 0);
    std::vector<std::vector<int>> loops;
    for (size_t first = 0; first < halfEdges.size(); ++first) {
        if (used[first])
            continue;
        used[first] = 1;
        std::vector<int> loop{halfEdges[first].first};
        int start = halfEdges[first].first;
        int current = halfEdges[first].second;
        Vec3 incoming = vertices[size_t(current)] - vertices[size_t(start)];
        while (current != start) {
            loop.push_back(current);
            size_t best = halfEdges.size();
            double bestTurn = -10.0;
            for (size_t e : outgoing[current]) {
                if (used[e])
                    continue;
                Vec3 out = vertices[size_t(halfEdges[e].second)] - vertices[size_t(current)];
                double turn = std::atan2(glm::dot(normal, glm::cross(incoming, out)), glm::dot(incoming, out));
                if (turn > bestTurn) {
                    bestTurn = turn;
                    best = e;
                }
            }
            if (best == halfEdges.size() || loop.size() > halfEdges.size())
                return makeError("the cut left an open outline; is the part closed?");
            used[best] = 1;
            int next = halfEdges[best].second;
            incoming = vertices[size_t(next)] - vertices[size_t(current)];
            current = next;
        }
        loops.push_back(std::move(loop));
    }
    return loops;
}

bool containsPoint(const std::vector<glm::dvec2>& p, const std::vector<int>& loop, glm::dvec2 q)
{
    bool inside = false;
    for (size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) {
        glm::dvec2 a = p[size_t(loop[i])], b = p[size_t(loop[j])];
        if ((a.y > q.y) != (b.y > q.y) && q.x < (b.x - a.x) * (q.y - a.y) / (b.y - a.y) + a.x)
            inside = !inside;
    }
    return inside;
}

// Closes one side: the half-edges its faces leave unpaired all lie in the cut
// plane; the caps are their twins, split into convex faces.
Result<std::vector<std::string>> addCaps(CutSide& side, IdClaims& claims, const Plane& plane)
{
    std::vector<std::vector<int>> loops;
    for (const Face& face : side.part.faces)
        loops.push_back(face.loop);
    EdgeCounts counts = directedEdges(loops);
    std::vector<std::pair<int, int>> capEdges;
    const auto& vertices = side.part.vertices;
    for (const auto& [edge, count] : counts) {
        auto twin = counts.find({edge.second, edge.first});
        int open = count - (twin == counts.end() ? 0 : twin->second);
        if (open <= 0)
            continue;
        for (int index : {edge.first, edge.second})
            if (std::abs(plane.signedDistance(vertices[size_t(index)])) > 4.0 * kDistanceEpsilon)
                return makeError("the part is not closed along the cut, so it cannot be capped");
        for (int k = 0; k < open; ++k)
            capEdges.push_back({edge.second, edge.first});
    }
    if (capEdges.empty())
        return std::vector<std::string>{};

    // Outer loops turn counter-clockwise about the cap normal. That is -n on
    // the front of an ordinary solid and +n for an inside-out one (a room);
    // the total signed area decides, since outer loops enclose their holes.
    double area = 0.0;
    for (auto [a, b] : capEdges)
        area += glm::dot(plane.normal, glm::cross(vertices[size_t(a)], vertices[size_t(b)]));
    Vec3 normal = area >= 0.0 ? plane.normal : -plane.normal;

    auto chained = chainLoops(vertices, capEdges, normal);
    if (!chained)
        return chained.error();

    // A 2-D frame in the plane with u x w = normal: loops counter-clockwise
    // about the normal have positive area there.
    Vec3 helper = std::abs(normal.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    Vec3 u = glm::normalize(glm::cross(helper, normal));
    Vec3 w = glm::cross(normal, u);
    std::vector<glm::dvec2> points(vertices.size());
    for (size_t i = 0; i < vertices.size(); ++i)
        points[i] = {glm::dot(vertices[i], u), glm::dot(vertices[i], w)};

    std::vector<std::vector<int>> outers, holes;
    for (auto& loop : *chained) {
        double a = signedArea2(points, loop);
        if (std::abs(a) <= 2.0 * kAreaEpsilon)
            continue; // a zero-area sliver of welded vertices: nothing to cap
        (a > 0.0 ? outers : holes).push_back(std::move(loop));
    }
    // Each hole belongs to the smallest outer loop around it.
    std::vector<std::vector<std::vector<int>>> holesOf(outers.size());
    for (auto& hole : holes) {
        size_t owner = outers.size();
        double ownerArea = 0.0;
        for (size_t o = 0; o < outers.size(); ++o) {
            int votes = 0;
            for (size_t i = 0; i < hole.size(); ++i) {
                glm::dvec2 mid = 0.5 * (points[size_t(hole[i])] + points[size_t(hole[(i + 1) % hole.size()])]);
                votes += containsPoint(points, outers[o], mid) ? 1 : -1;
            }
            double a = signedArea2(points, outers[o]);
            if (votes > 0 && (owner == outers.size() || a < ownerArea)) {
                owner = o;
                ownerArea = a;
            }
        }
        if (owner == outers.size())
            return makeError("the cut outline of \"" + side.part.id + "\" has a hole outside every outline");
        holesOf[owner].push_back(std::move(hole));
    }

    std::vector<std::vector<int>> capLoops;
    for (size_t o = 0; o < outers.size(); ++o) {
        auto pieces = convexDecomposition(points, outers[o], holesOf[o], kDistanceEpsilon);
        if (!pieces)
            return pieces.error();
        for (auto& piece : *pieces)
            capLoops.push_back(std::move(piece));
    }
    std::vector<std::string> ids;
    for (size_t c = 0; c < capLoops.size(); ++c) {
        std::string id = side.part.id + ".cut" + (capLoops.size() > 1 ? std::to_string(c + 1) : "");
        ids.push_back(claims.claim(id));
        side.part.faces.push_back({ids.back(), std::move(capLoops[c]), {}});
    }
    return ids;
}

} // namespace

std::string cutPieceId(const std::string& faceId, const std::string& sourcePartId, const std::string& newPartId)
{
    std::string renamed = edit::replacePrefix(faceId, sourcePartId, newPartId);
    return renamed != faceId || sourcePartId == newPartId ? renamed : newPartId + "." + faceId;
}

Result<PlaneCut> splitPart(const Part& source, const Plane& inputPlane, const std::string& frontId,
                           const std::string& backId, CutCaps caps)
{
    if (frontId.empty() || backId.empty())
        return makeError("both parts of a cut need a non-empty id");
    if (frontId == backId)
        return makeError("the two parts of a cut need different ids (both are \"" + frontId + "\")");
    double length = glm::length(inputPlane.normal);
    if (!edit::isFinite(inputPlane.normal) || !std::isfinite(inputPlane.d) || length < 1e-12)
        return makeError("the cutting plane needs a finite, non-zero normal");
    const Plane plane{inputPlane.normal / length, inputPlane.d / length};
    for (const Vec3& v : source.vertices)
        if (!edit::isFinite(v))
            return makeError("\"" + source.id + "\" has a vertex that is not a finite number");
    for (const Face& face : source.faces) {
        if (face.loop.size() < 3)
            return makeError("face \"" + face.id + "\" has fewer than 3 vertices");
        for (int index : face.loop)
            if (index < 0 || index >= int(source.vertices.size()))
                return makeError("face \"" + face.id + "\" names a vertex the part does not have");
    }

    bool front = false, back = false;
    for (const Vec3& v : source.vertices) {
        double s = plane.signedDistance(v);
        front |= s > kDistanceEpsilon;
        back |= s < -kDistanceEpsilon;
    }
    if (!front || !back)
        return makeError("the plane misses \"" + source.id + "\": the whole part lies on one side of it");

    CutSide sides[2];
    sides[0].part.id = frontId;
    sides[1].part.id = backId;
    IdClaims claims;
    for (CutSide& side : sides) {
        side.part.name = source.name;
        side.part.material = source.material;
        claims.claim(side.part.id);
    }

    PlaneCut cut;
    std::vector<Vec3> frontPiece, backPiece;
    for (const Face& face : source.faces) {
        std::vector<Vec3> positions = loopPositions(source.vertices, face.loop);
        PlaneCut::FacePieces pieces{face.id, {}};
        auto add = [&](int s, const std::vector<Vec3>& piece) {
            CutSide& side = sides[s];
            std::string id = claims.claim(cutPieceId(face.id, source.id, side.part.id));
            if (side.addFace(piece, id, face.material))
                pieces.pieceIds.push_back(id);
        };
        switch (classifyPolygon(positions, plane)) {
        case Side::Front: add(0, positions); break;
        case Side::Back: add(1, positions); break;
        case Side::On:
            // The solid lies on the side the face's normal points away from.
            add(glm::dot(polygonNormal(positions), plane.normal) < 0.0 ? 0 : 1, positions);
            break;
        case Side::Spanning:
            splitPolygon(positions, plane, frontPiece, backPiece);
            if (!frontPiece.empty())
                add(0, frontPiece);
            if (!backPiece.empty())
                add(1, backPiece);
            break;
        }
        cut.pieces.push_back(std::move(pieces));
    }

    if (caps == CutCaps::Close && isClosed(source)) {
        auto frontCaps = addCaps(sides[0], claims, plane);
        if (!frontCaps)
            return frontCaps.error();
        auto backCaps = addCaps(sides[1], claims, plane);
        if (!backCaps)
            return backCaps.error();
        cut.frontCaps = std::move(*frontCaps);
        cut.backCaps = std::move(*backCaps);
    }
    cut.front = std::move(sides[0].part);
    cut.back = std::move(sides[1].part);
    return cut;
}

} // namespace regio::model
