#include "solver/prepare/pieces.h"

#include "model/geometry/edge_key.h"
#include "solver/prepare/face_polygon.h"
#include "solver/prepare/partition.h"
#include "solver/prepare/regional_tree.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <unordered_map>
#include <utility>
#include <vector>

namespace regio::solver {

namespace {

// A convex part of an element on its way down the trees: a loop of indices
// into PreparedScene::pieceVertices.
struct Work {
    std::vector<int> loop;
    int element = -1;
    bool centred = false; // has points inside its edges: triangulated around its centroid
};

struct CutKey {
    int lo = 0, hi = 0, plane = 0;
    bool operator==(const CutKey&) const = default;
};

struct CutKeyHash {
    size_t operator()(const CutKey& k) const
    {
        std::uint64_t h = std::uint64_t(std::uint32_t(k.lo)) * 0x9E3779B97F4A7C15ull;
        h ^= (std::uint64_t(std::uint32_t(k.hi)) + 0x7F4A7C15ull + (h << 6) + (h >> 2)) * 0xC2B2AE3D27D4EB4Full;
        h ^= (std::uint64_t(std::uint32_t(k.plane)) + (h << 6) + (h >> 2)) * 0x165667B19E3779F9ull;
        return size_t(h ^ (h >> 29));
    }
};

// A face's cut points by position: cells of kCutCell metres, keyed by face
// and cell, so looking for the cut points near an edge or a new point reads a
// few cells instead of every cut point of the face (a large floor cut by a
// thousand regions has tens of thousands of them).
struct CutCell {
    int face;
    std::int64_t x, y, z;
    bool operator==(const CutCell&) const = default;
};

struct CutCellHash {
    size_t operator()(const CutCell& c) const
    {
        constexpr std::uint64_t k = 0x9E3779B97F4A7C15u;
        auto mix = [](std::uint64_t h, std::int64_t v) {
            return h ^ (static_cast<std::uint64_t>(v) + k + (h << 6) + (h >> 2));
        };
        std::uint64_t h = static_cast<std::uint64_t>(static_cast<std::uint32_t>(c.face)) * k;
        h = mix(mix(mix(h, c.x), c.y), c.z);
        return static_cast<size_t>(h);
    }
};

class PieceBuilder {
public:
    PieceBuilder(PreparedScene& scene, std::span<const std::vector<int>> elementLoops)
        : m_scene(scene)
        , m_elementLoops(elementLoops)
        , m_perNode(scene.nodes.size())
        , m_faceCuts(scene.faces.size())
    {
    }

    void pushFace(int face)
    {
        const InputFace& input = m_scene.faces[size_t(face)];
        if (input.polygon.size() < 3 || input.elements.empty())
            return;
        std::vector<Work> pieces;
        pieces.reserve(input.elements.size());
        for (int e : input.elements) {
            if (size_t(e) < m_elementLoops.size() && m_elementLoops[size_t(e)].size() > 3) {
                pieces.push_back({m_elementLoops[size_t(e)], e, true});
                continue;
            }
            const Element& element = m_scene.elements[size_t(e)];
            pieces.push_back({{element.vertices[0], element.vertices[1], element.vertices[2]}, e});
        }
        m_face = face;
        if (m_scene.regionalRoot < 0) {
            lose(pieces);
            return;
        }
        pushRegional(m_scene.regionalRoot, input.polygon, std::move(pieces));
    }

    void finish();

private:
    void collectOnEdge(int face, int a, int b, std::vector<int>& into);
    // The cut points of `face` in the cells the box [lo, hi] (widened by
    // kMergeDistance) reaches, ascending: a superset of those within
    // kMergeDistance of the box, in the order of m_faceCuts.
    void cutsNear(int face, const Vec3& lo, const Vec3& hi, std::vector<int>& into) const;
    static std::int64_t cellIndex(double v) { return static_cast<std::int64_t>(std::floor(v / kCutCell)); }
    static CutCell cellOf(int face, const Vec3& p) { return {face, cellIndex(p.x), cellIndex(p.y), cellIndex(p.z)}; }
    void insertEdgePoints(Work& piece);
    void findOutlineVertices();
    bool mayTouchOtherFaces(int v) const { return size_t(v) >= m_outlineFace.size() || m_outlineFace[size_t(v)] >= 0; }
    void collectContacts(int face, int a, int b, std::vector<int>& into);

    const Vec3& vertex(int v) const { return m_scene.pieceVertices[size_t(v)]; }

    // One key per distinct plane (bit for bit): BSP nodes in different
    // subtrees that carry the same face's plane, or a face plane equal to a
    // separating plane, cut an edge at one shared point.
    int planeKey(const Plane& plane)
    {
        std::array<std::uint64_t, 4> bits{};
        std::memcpy(&bits[0], &plane.normal.x, sizeof(double));
        std::memcpy(&bits[1], &plane.normal.y, sizeof(double));
        std::memcpy(&bits[2], &plane.normal.z, sizeof(double));
        std::memcpy(&bits[3], &plane.d, sizeof(double));
        return m_planeKeys.try_emplace(bits, int(m_planeKeys.size())).first->second;
    }

    // The point where edge a-b crosses `plane`, computed from the lower vertex
    // index and made once per (edge, plane): bit-identical for every piece
    // that has this edge, on either side of the cut.
    int cutVertex(int a, int b, const Plane& plane, int planeKey)
    {
        const int lo = std::min(a, b), hi = std::max(a, b);
        auto [it, inserted] = m_cuts.try_emplace(CutKey{lo, hi, planeKey}, -1);
        if (!inserted)
            return it->second;
        const Vec3 p = vertex(lo), q = vertex(hi);
        const double sp = plane.signedDistance(p), sq = plane.signedDistance(q);
        const Vec3 x = p + (q - p) * (sp / (sp - sq));
        // The same point may come from another plane through the same line
        // of the face (one surface seen as a separating plane in one cell and
        // as a face plane in another), or from the crossing of two cut lines
        // reached in the other order in another cell: one point, not two a
        // rounding apart.
        // The first such point in the face's order (the lowest index).
        std::vector<int>& near = m_nearScratch;
        near.clear();
        cutsNear(m_face, x, x, near);
        for (int other : near)
            if (glm::length(vertex(other) - x) <= kMergeDistance)
                return it->second = other;
        it->second = int(m_scene.pieceVertices.size());
        m_scene.pieceVertices.push_back(x);
        m_faceCuts[size_t(m_face)].push_back(it->second);
        m_cutCells[cellOf(m_face, x)].push_back(it->second);
        return it->second;
    }

    // model::splitPolygon on index loops: vertices within eps go to both sides.
    void split(const Work& piece, const Plane& plane, int planeKey, std::vector<Work>& front, std::vector<Work>& back)
    {
        const size_t n = piece.loop.size();
        m_distance.resize(n);
        bool anyFront = false, anyBack = false;
        double sum = 0.0;
        for (size_t i = 0; i < n; ++i) {
            m_distance[i] = plane.signedDistance(vertex(piece.loop[i]));
            anyFront |= m_distance[i] > kEps;
            anyBack |= m_distance[i] < -kEps;
            sum += m_distance[i];
        }
        if (!anyFront || !anyBack) {
            // Wholly on one side, or (a speck within eps of the plane) on the
            // side its vertices lean to.
            (anyFront || (!anyBack && sum >= 0.0) ? front : back).push_back(piece);
            return;
        }
        // Centred stays: a side may keep T-vertices of the element loop.
        Work f{{}, piece.element, piece.centred}, b{{}, piece.element, piece.centred};
        for (size_t i = 0; i < n; ++i) {
            const size_t j = (i + 1) % n;
            const double sa = m_distance[i], sb = m_distance[j];
            if (sa >= -kEps)
                f.loop.push_back(piece.loop[i]);
            if (sa <= kEps)
                b.loop.push_back(piece.loop[i]);
            if ((sa > kEps && sb < -kEps) || (sa < -kEps && sb > kEps)) {
                const int cut = cutVertex(piece.loop[i], piece.loop[j], plane, planeKey);
                f.loop.push_back(cut);
                b.loop.push_back(cut);
            }
        }
        // A convex polygon with vertices strictly on both sides keeps at least
        // three on each.
        front.push_back(std::move(f));
        back.push_back(std::move(b));
    }

    // The face polygon spans `plane`: cut it as the builders did
    // (partition.h) and the element pieces with it; if neither side is
    // kept, the pieces are lost.
    template <class Recurse>
    void spanning(const std::vector<Vec3>& face, std::vector<Work> pieces, const Plane& plane, int planeKey,
                  int frontChild, int backChild, Recurse&& recurse)
    {
        spanning(splitAcross(face, plane, kEps), std::move(pieces), plane, planeKey, frontChild, backChild, recurse);
    }

    template <class Recurse>
    void spanning(PlaneSplit sides, std::vector<Work> pieces, const Plane& plane, int planeKey, int frontChild,
                  int backChild, Recurse&& recurse)
    {
        const bool keepFront = !sides.front.empty();
        const bool keepBack = !sides.back.empty();
        if (keepFront && keepBack) {
            std::vector<Work> front, back;
            for (const Work& piece : pieces)
                split(piece, plane, planeKey, front, back);
            pieces.clear();
            recurse(backChild, std::move(sides.back), std::move(back));
            recurse(frontChild, std::move(sides.front), std::move(front));
        } else if (keepFront) {
            // The builder dropped the back sliver: the face lives on in front
            // only, and so do its elements (uncut).
            recurse(frontChild, std::move(sides.front), std::move(pieces));
        } else if (keepBack) {
            recurse(backChild, std::move(sides.back), std::move(pieces));
        } else {
            lose(pieces);
        }
    }

    // The regional tree, as assignToCells took the face (partition.h).
    void pushRegional(int index, std::vector<Vec3> face, std::vector<Work> pieces)
    {
        const RegionalNode& node = m_scene.regionalNodes[size_t(index)];
        if (node.isLeaf()) {
            pushBsp(m_scene.regions[size_t(node.region)].bspRoot, std::move(face), std::move(pieces));
            return;
        }
        PlaneSplit sides;
        switch (routeAtSeparatingPlane(face, node.axis, node.position, sides)) {
        case model::Side::Front: pushRegional(node.front, std::move(face), std::move(pieces)); return;
        case model::Side::Back: pushRegional(node.back, std::move(face), std::move(pieces)); return;
        case model::Side::On: return; // never: routeAtSeparatingPlane picks a side
        case model::Side::Spanning: {
            const Plane plane = separatingPlane(node.axis, node.position);
            spanning(std::move(sides), std::move(pieces), plane, planeKey(plane), node.front, node.back,
                     [&](int child, std::vector<Vec3> f, std::vector<Work> p) {
                         pushRegional(child, std::move(f), std::move(p));
                     });
            return;
        }
        }
    }

    bool nodeHoldsFace(const BspNode& node) const
    {
        for (int i = 0; i < node.fragmentCount; ++i)
            if (m_scene.fragments[size_t(node.firstFragment + i)].properties == m_face)
                return true;
        return false;
    }

    // The BSP tree, as the builder took the face (partition.h): it stops at
    // the node holding its fragments (its plane), otherwise goes front, back
    // or is split.
    void pushBsp(int index, std::vector<Vec3> face, std::vector<Work> pieces)
    {
        if (index < 0) {
            lose(pieces);
            return;
        }
        const BspNode& node = m_scene.nodes[size_t(index)];
        const model::Side side = nodeHoldsFace(node) ? model::Side::On : model::classifyPolygon(face, node.plane, kEps);
        switch (side) {
        case model::Side::On: {
            auto& into = m_perNode[size_t(index)];
            for (Work& p : pieces)
                into.push_back(std::move(p));
            return;
        }
        case model::Side::Front: pushBsp(node.front, std::move(face), std::move(pieces)); return;
        case model::Side::Back: pushBsp(node.back, std::move(face), std::move(pieces)); return;
        case model::Side::Spanning:
            spanning(face, std::move(pieces), node.plane, planeKey(node.plane), node.front, node.back,
                     [&](int child, std::vector<Vec3> f, std::vector<Work> p) {
                         pushBsp(child, std::move(f), std::move(p));
                     });
            return;
        }
    }

    void lose(const std::vector<Work>& pieces)
    {
        for (const Work& p : pieces) {
            ++m_scene.stats.lostPieces;
            std::vector<Vec3> loop;
            for (int v : p.loop)
                loop.push_back(vertex(v));
            m_scene.stats.lostPieceArea += model::polygonArea(loop);
        }
    }

    static constexpr double kEps = model::kDistanceEpsilon; // the builders' epsilon
    static constexpr double kMergeDistance = 1e-9;          // metres; far below any mesh size
    static constexpr double kCutCell = 0.25;                // metres: the cell of the cut-point grid

    PreparedScene& m_scene;
    std::span<const std::vector<int>> m_elementLoops;
    std::vector<std::vector<Work>> m_perNode;
    std::unordered_map<CutKey, int, CutKeyHash> m_cuts;
    std::vector<std::vector<int>> m_faceCuts;                              // per input face: its cut points
    std::unordered_map<CutCell, std::vector<int>, CutCellHash> m_cutCells; // the same by position
    std::vector<int> m_nearScratch;                                        // cutVertex's
    std::vector<int> m_edgeScratch;                                        // collectOnEdge's
    struct BitsHash {
        size_t operator()(const std::array<std::uint64_t, 4>& b) const
        {
            std::uint64_t h = 0;
            for (std::uint64_t x : b)
                h = (h ^ x) * 0x100000001B3ull + (h >> 31);
            return size_t(h);
        }
    };
    std::unordered_map<std::array<std::uint64_t, 4>, int, BitsHash> m_planeKeys;
    std::vector<double> m_distance;
    int m_face = -1;
    // The element corners on the outline of their face's mesh (per vertex:
    // its face, -1 inside a mesh), by position in cells keyed with face -1.
    std::vector<int> m_outlineFace;
    std::unordered_map<CutCell, std::vector<int>, CutCellHash> m_outlineCells;
    // Metres: faces meeting along a line. The builders' epsilon, not less:
    // coordinates read from model files are rounded to 32-bit floats, which
    // moves a corner by up to a few 1e-7 m in a room of a few metres, and a
    // corner missed would leave a T-vertex between the two faces' meshes.
    static constexpr double kContactDistance = model::kDistanceEpsilon;
};

void PieceBuilder::cutsNear(int face, const Vec3& lo, const Vec3& hi, std::vector<int>& into) const
{
    const std::vector<int>& all = m_faceCuts[size_t(face)];
    const std::int64_t x0 = cellIndex(lo.x - kMergeDistance), x1 = cellIndex(hi.x + kMergeDistance);
    const std::int64_t y0 = cellIndex(lo.y - kMergeDistance), y1 = cellIndex(hi.y + kMergeDistance);
    const std::int64_t z0 = cellIndex(lo.z - kMergeDistance), z1 = cellIndex(hi.z + kMergeDistance);
    const double cells = double(x1 - x0 + 1) * double(y1 - y0 + 1) * double(z1 - z0 + 1);
    if (cells >= double(all.size())) { // as cheap to read them all
        into.insert(into.end(), all.begin(), all.end());
        return;
    }
    const size_t first = into.size();
    for (std::int64_t x = x0; x <= x1; ++x)
        for (std::int64_t y = y0; y <= y1; ++y)
            for (std::int64_t z = z0; z <= z1; ++z)
                if (auto it = m_cutCells.find({face, x, y, z}); it != m_cutCells.end())
                    into.insert(into.end(), it->second.begin(), it->second.end());
    std::sort(into.begin() + std::ptrdiff_t(first), into.end());
}

// Cut points of the piece's face lying strictly inside segment a-b. The cut
// points were computed on the element edges and on sub-segments of them, so
// they lie on a-b up to rounding; the tolerance is far below any mesh size.
void PieceBuilder::collectOnEdge(int face, int a, int b, std::vector<int>& into)
{
    const Vec3 pa = vertex(a), d = vertex(b) - pa;
    const double length2 = glm::dot(d, d);
    if (length2 <= 0.0)
        return;
    // One scratch list for every edge: this runs for every edge of every piece.
    std::vector<int>& near = m_edgeScratch;
    near.clear();
    cutsNear(face, glm::min(pa, vertex(b)), glm::max(pa, vertex(b)), near);
    for (int x : near) {
        if (x == a || x == b)
            continue;
        const Vec3 r = vertex(x) - pa;
        const double t = glm::dot(r, d) / length2;
        if (t <= 1e-12 || t >= 1.0 - 1e-12)
            continue;
        if (glm::length(r - d * t) <= kMergeDistance)
            into.push_back(x);
    }
}

// Where two faces meet along a line (a wall on the floor, a block's side on
// the floor's outline around it), each face's mesh divides the line at its
// own points: T-vertices between the faces, through which the rasteriser can
// let a pixel fall between the two and see what lies behind. So the corners
// on the outline of every face's mesh are collected here, and pieces take
// those of other faces that lie on their edges, as they take cut points.
void PieceBuilder::findOutlineVertices()
{
    m_outlineFace.assign(m_scene.vertices.size(), -1);
    // Directed edges, sorted: an edge without its reverse is on the outline.
    std::vector<std::uint64_t> directed;
    for (size_t f = 0; f < m_scene.faces.size(); ++f) {
        directed.clear();
        for (int e : m_scene.faces[f].elements) {
            const auto& v = m_scene.elements[size_t(e)].vertices;
            for (int i = 0; i < 3; ++i)
                directed.push_back(model::edgeKey(v[size_t(i)], v[size_t((i + 1) % 3)]));
        }
        std::sort(directed.begin(), directed.end());
        for (std::uint64_t edge : directed) {
            const int a = int(edge >> 32), b = int(edge & 0xffffffffu);
            if (std::binary_search(directed.begin(), directed.end(), model::edgeKey(b, a)))
                continue;
            for (int v : {a, b})
                if (m_outlineFace[size_t(v)] < 0) {
                    m_outlineFace[size_t(v)] = int(f);
                    m_outlineCells[cellOf(-1, vertex(v))].push_back(v);
                }
        }
    }
}

// The outline corners of faces other than `face` strictly inside segment a-b.
void PieceBuilder::collectContacts(int face, int a, int b, std::vector<int>& into)
{
    const Vec3 pa = vertex(a), d = vertex(b) - pa;
    const double length2 = glm::dot(d, d);
    if (length2 <= 0.0 || m_outlineCells.empty())
        return;
    const auto consider = [&](const std::vector<int>& vertices) {
        for (int v : vertices) {
            if (m_outlineFace[size_t(v)] == face || v == a || v == b)
                continue;
            const Vec3 r = vertex(v) - pa;
            const double t = glm::dot(r, d) / length2;
            if (t * t * length2 <= kContactDistance * kContactDistance ||
                (1.0 - t) * (1.0 - t) * length2 <= kContactDistance * kContactDistance || t <= 0.0 || t >= 1.0)
                continue;
            if (glm::length(r - d * t) <= kContactDistance)
                into.push_back(v);
        }
    };
    const Vec3 lo = glm::min(pa, vertex(b)), hi = glm::max(pa, vertex(b));
    const std::int64_t x0 = cellIndex(lo.x - kContactDistance), x1 = cellIndex(hi.x + kContactDistance);
    const std::int64_t y0 = cellIndex(lo.y - kContactDistance), y1 = cellIndex(hi.y + kContactDistance);
    const std::int64_t z0 = cellIndex(lo.z - kContactDistance), z1 = cellIndex(hi.z + kContactDistance);
    // A long diagonal edge of a large scene spans more cells than there are
    // outline cells at all (a 4 km edge: 10^8 of them): then reading every
    // outline cell is the cheaper walk, and it is the same answer.
    const double cells = double(x1 - x0 + 1) * double(y1 - y0 + 1) * double(z1 - z0 + 1);
    if (cells >= double(m_outlineCells.size())) {
        for (const auto& [cell, vertices] : m_outlineCells)
            if (cell.x >= x0 && cell.x <= x1 && cell.y >= y0 && cell.y <= y1 && cell.z >= z0 && cell.z <= z1)
                consider(vertices);
        return;
    }
    for (std::int64_t x = x0; x <= x1; ++x)
        for (std::int64_t y = y0; y <= y1; ++y)
            for (std::int64_t z = z0; z <= z1; ++z)
                if (const auto it = m_outlineCells.find({-1, x, y, z}); it != m_outlineCells.end())
                    consider(it->second);
}

// A region's BSP planes end at its cell: an element cut by one has a
// neighbour across the cell border that is not, and the cut point on their
// shared edge would be a T-vertex. Every piece gets every cut point lying on
// its edges, so the pieces of a face meet edge to edge with bit-identical
// vertices; loops that gained such points are triangulated around their
// centroid (a fan from a corner would make triangles of no area).
void PieceBuilder::insertEdgePoints(Work& piece)
{
    const int face = m_scene.elements[size_t(piece.element)].properties;
    const bool cuts = !m_faceCuts[size_t(face)].empty();
    std::vector<int> loop;
    std::vector<int> inner;
    int grownEdges = 0;
    size_t apex = 0; // in `loop`: the corner after the last grown edge
    const size_t n = piece.loop.size();
    for (size_t i = 0; i < n; ++i) {
        const int a = piece.loop[i], b = piece.loop[(i + 1) % n];
        loop.push_back(a);
        inner.clear();
        if (cuts)
            collectOnEdge(face, a, b, inner);
        if (mayTouchOtherFaces(a) && mayTouchOtherFaces(b))
            collectContacts(face, a, b, inner);
        if (inner.empty())
            continue;
        ++grownEdges;
        const Vec3 pa = vertex(a), d = vertex(b) - pa;
        // By position along the edge, then by id: the same loop whatever
        // order the points were collected in.
        std::sort(inner.begin(), inner.end(), [&](int x, int y) {
            const double tx = glm::dot(vertex(x) - pa, d), ty = glm::dot(vertex(y) - pa, d);
            return tx < ty || (tx == ty && x < y);
        });
        // One point per position: where two walls meet the floor, both
        // bring a corner to the same place.
        inner.erase(
            std::unique(inner.begin(), inner.end(),
                        [&](int x, int y) { return x == y || glm::length(vertex(x) - vertex(y)) <= kContactDistance; }),
            inner.end());
        loop.insert(loop.end(), inner.begin(), inner.end());
        apex = (loop.size() + 1) % (loop.size() + n - i - 1); // the corner after b, once the loop is complete
    }
    if (grownEdges == 0)
        return;
    // Points on one edge of a convex piece without others: a fan from the
    // corner after that edge (two triangles for one point, where a fan
    // around the centroid makes four). Points on several edges, or a loop
    // that had some already: around the centroid, since a fan from a corner
    // would make triangles of no area.
    if (grownEdges == 1 && !piece.centred) {
        std::rotate(loop.begin(), loop.begin() + std::ptrdiff_t(apex), loop.end());
        piece.loop = std::move(loop);
        return;
    }
    piece.loop = std::move(loop);
    piece.centred = true;
}

void PieceBuilder::finish()
{
    findOutlineVertices();
    for (auto& nodePieces : m_perNode)
        for (Work& w : nodePieces)
            insertEdgePoints(w);
    std::vector<Piece>& out = m_scene.pieces;
    for (size_t n = 0; n < m_scene.nodes.size(); ++n) {
        BspNode& node = m_scene.nodes[n];
        std::vector<Work>& pieces = m_perNode[n];
        node.firstPiece = int(out.size());
        // Groups [F solid | F open | O open | O solid] (prepared_scene.h).
        auto groupOf = [&](const Work& w) {
            const Properties& p = m_scene.properties[size_t(m_scene.elements[size_t(w.element)].properties)];
            const bool forward = glm::dot(p.plane.normal, node.plane.normal) > 0.0;
            return forward ? (p.solid ? 0 : 1) : (p.solid ? 3 : 2);
        };
        int counts[4] = {0, 0, 0, 0};
        for (int g = 0; g < 4; ++g)
            for (const Work& w : pieces) {
                if (groupOf(w) != g)
                    continue;
                Element& element = m_scene.elements[size_t(w.element)];
                if (element.node < 0)
                    element.node = int(n);
                if (w.centred) {
                    Vec3 centre{0.0};
                    for (int v : w.loop)
                        centre += vertex(v);
                    const int c = int(m_scene.pieceVertices.size());
                    m_scene.pieceVertices.push_back(centre / double(w.loop.size()));
                    for (size_t k = 0; k < w.loop.size(); ++k) {
                        out.push_back({{c, w.loop[k], w.loop[(k + 1) % w.loop.size()]}, w.element});
                        ++counts[g];
                    }
                    continue;
                }
                // Fan triangulation of the convex piece.
                for (size_t k = 1; k + 1 < w.loop.size(); ++k) {
                    out.push_back({{w.loop[0], w.loop[k], w.loop[k + 1]}, w.element});
                    ++counts[g];
                }
            }
        node.pieceCount = counts[0] + counts[1] + counts[2] + counts[3];
        node.forwardPieces = counts[0] + counts[1];
        node.forwardSolidPieces = counts[0];
        node.oppositeSolidPieces = counts[3];
        pieces.clear();
        pieces.shrink_to_fit();
    }
}

// Numbers the vertices in the order the pieces first use them and drops
// those no piece uses. A render walks the pieces node by node and transforms
// each vertex it meets (Visibility): in this order those reads run nearly in
// sequence, where in the mesh's order they jump about (adaptive subdivision
// appends its vertices at the end). Only the numbering changes, never a
// coordinate, so every render paints the same pixels.
void numberVerticesByFirstUse(PreparedScene& scene)
{
    std::vector<int> renumbered(scene.pieceVertices.size(), -1);
    std::vector<Vec3> vertices;
    vertices.reserve(scene.pieceVertices.size());
    for (Piece& piece : scene.pieces)
        for (int& v : piece.vertices) {
            int& number = renumbered[size_t(v)];
            if (number < 0) {
                number = int(vertices.size());
                vertices.push_back(scene.pieceVertices[size_t(v)]);
            }
            v = number;
        }
    scene.pieceVertices = std::move(vertices);
}

} // namespace

void buildPieces(PreparedScene& scene, std::span<const std::vector<int>> elementLoops)
{
    scene.pieceVertices = scene.vertices;
    scene.pieces.clear();
    scene.stats.lostPieces = 0;
    scene.stats.lostPieceArea = 0.0;
    for (Element& e : scene.elements)
        e.node = -1;
    PieceBuilder builder(scene, elementLoops);
    for (size_t f = 0; f < scene.faces.size(); ++f)
        builder.pushFace(int(f));
    builder.finish();
    numberVerticesByFirstUse(scene);
    for (Patch& p : scene.patches)
        p.node = p.elementCount > 0 ? scene.elements[size_t(p.firstElement)].node : -1;
    scene.stats.pieces = int(scene.pieces.size());
    static std::atomic<std::uint64_t> builds{0};
    scene.piecesStamp = ++builds;
}

} // namespace regio::solver
