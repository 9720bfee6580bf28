#include "output/midpoint_cut.h"

#include "output/flat_index.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <bit>
#include <limits>
#include <utility>

namespace regio::output {

namespace {

// New corners stay this far from every other corner of their triangles
// (and, for files, of the mesh): see CutFor. Kept with a margin, so that
// the rounding to floats cannot bring two corners closer.
constexpr double kMinSeparation = 1.25e-3 + 1e-6;
// For files, no piece is thinner than this: a reader that takes a corner
// within a millimetre of a triangle's side as lying on it (the importer
// does) would split the triangle there and fold it.
constexpr double kMinHeight = 1.05e-3;

// A triangle side's successor in its triangle.
size_t nextSide(size_t side) { return side - side % 3 + (side % 3 + 1) % 3; }

// The edges of a triangle mesh, each once: per triangle side (3 t + k, from
// corner k to corner k + 1) the index of its edge. The sides are bucketed
// by their lower vertex; within a vertex's few sides, equal upper vertices
// are one edge.
std::vector<std::uint32_t> edgesOfSides(const std::vector<std::uint32_t>& indices, size_t vertexCount,
                                        size_t& edgeCount)
{
    const size_t sides = indices.size();
    const auto ends = [&](size_t side) {
        const std::uint32_t a = indices[side], b = indices[nextSide(side)];
        return std::pair(std::min(a, b), std::max(a, b));
    };
    std::vector<std::uint32_t> start(vertexCount + 1, 0);
    for (size_t side = 0; side < sides; ++side)
        ++start[ends(side).first + 1];
    for (size_t v = 0; v < vertexCount; ++v)
        start[v + 1] += start[v];
    std::vector<std::uint32_t> bucket(sides);
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (size_t side = 0; side < sides; ++side)
        bucket[fill[ends(side).first]++] = std::uint32_t(side);
    std::vector<std::uint32_t> edgeOf(sides);
    edgeCount = 0;
    for (size_t v = 0; v < vertexCount; ++v)
        for (std::uint32_t i = start[v]; i < start[v + 1]; ++i) {
            const std::uint32_t upper = ends(bucket[i]).second;
            std::uint32_t j = start[v];
            while (j < i && ends(bucket[j]).second != upper)
                ++j;
            edgeOf[bucket[i]] = j < i ? edgeOf[bucket[j]] : std::uint32_t(edgeCount++);
        }
    return edgeOf;
}

// The height of triangle a, b, c over its longest side.
double height(const Vec3& a, const Vec3& b, const Vec3& c)
{
    const double longest = std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
    return longest > 0.0 ? glm::length(glm::cross(b - a, c - a)) / longest : 0.0;
}

// How a triangle is cut at the midpoints of the sides `split` marks (side
// k from corner k to corner k + 1): its corners turned by `turn` so that
// the cut sides come first (side 0 when one is cut, sides 0 and 1 when
// two), then the pieces as corners a, b, c (0-2, turned) and the midpoints
// ab, bc, ca (3-5). The quad left by two cuts is split along its shorter
// diagonal: a-bc when `fromA`, else ab-c.
struct Pieces {
    size_t turn = 0;
    int count = 0; // pieces
    int corners[4][3]{};
};

size_t turnOf(const bool (&split)[3])
{
    const int cuts = int(split[0]) + int(split[1]) + int(split[2]);
    if (cuts == 1)
        return split[0] ? 0 : (split[1] ? 1 : 2);
    if (cuts == 2)
        return !split[2] ? 0 : (!split[0] ? 1 : 2);
    return 0;
}

Pieces piecesOf(const bool (&split)[3], bool fromA)
{
    enum { A, B, C, AB, BC, CA };
    Pieces p;
    p.turn = turnOf(split);
    const auto piece = [&](int u, int v, int w) {
        p.corners[p.count][0] = u;
        p.corners[p.count][1] = v;
        p.corners[p.count][2] = w;
        ++p.count;
    };
    switch (int(split[0]) + int(split[1]) + int(split[2])) {
    case 0: piece(A, B, C); break;
    case 1:
        piece(A, AB, C);
        piece(AB, B, C);
        break;
    case 2:
        piece(AB, B, BC);
        if (fromA) {
            piece(A, AB, BC);
            piece(A, BC, C);
        } else {
            piece(A, AB, C);
            piece(AB, BC, C);
        }
        break;
    default:
        piece(A, AB, CA);
        piece(AB, B, BC);
        piece(CA, BC, C);
        piece(AB, BC, CA);
    }
    return p;
}

// The six points of a cut triangle (corners turned by `turn`, then the
// midpoints), and whether its quad is split from a.
void cutPoints(const Vec3 (&corner)[3], size_t turn, Vec3 (&points)[6], bool& fromA)
{
    for (size_t k = 0; k < 3; ++k)
        points[k] = corner[(turn + k) % 3];
    for (size_t k = 0; k < 3; ++k)
        points[3 + k] = 0.5 * (points[k] + points[(k + 1) % 3]);
    fromA = glm::length(points[4] - points[0]) <= glm::length(points[2] - points[3]);
}

// The least height of the pieces.
double thinnest(const Vec3 (&corner)[3], const bool (&split)[3])
{
    Vec3 points[6];
    bool fromA = true;
    cutPoints(corner, turnOf(split), points, fromA);
    const Pieces pieces = piecesOf(split, fromA);
    double least = std::numeric_limits<double>::infinity();
    for (int i = 0; i < pieces.count; ++i) {
        const int* c = pieces.corners[i];
        least = std::min(least, height(points[c[0]], points[c[1]], points[c[2]]));
    }
    return least;
}

} // namespace

std::vector<std::uint32_t> MidpointCut::placesOf(const std::vector<std::uint32_t>& corner) const
{
    // Vertices of one face at one place (the same float coordinates) are
    // numbered as the first of them that the corners name.
    struct Place {
        int face;
        std::uint32_t x, y, z;
        bool operator==(const Place&) const = default;
    };
    struct PlaceHash {
        std::uint64_t operator()(const Place& p) const { return hashIntegers({p.face, p.x, p.y, p.z}); }
    };
    FlatIndex<Place, PlaceHash> index(corner.size() / 2);
    std::vector<std::uint32_t> first; // per place: the first vertex seen there
    constexpr std::uint32_t kUnseen = ~std::uint32_t(0);
    std::vector<std::uint32_t> canonical(m_mesh.vertexCount(), kUnseen);
    std::vector<std::uint32_t> placed(corner.size());
    for (size_t i = 0; i < corner.size(); ++i) {
        const std::uint32_t v = corner[i];
        if (canonical[v] == kUnseen) {
            const glm::vec3& p = m_mesh.positions[v];
            const auto [place, added] =
                index.insert({m_faceOf[v], std::bit_cast<std::uint32_t>(p.x), std::bit_cast<std::uint32_t>(p.y),
                              std::bit_cast<std::uint32_t>(p.z)});
            if (added)
                first.push_back(v);
            canonical[v] = first[place];
        }
        placed[i] = canonical[v];
    }
    return placed;
}

// Every corner of the mesh so far on a grid, for the search that files need.
struct MidpointCut::Apart {
    PointGrid grid{2.0 * kMinSeparation};
    std::vector<Vec3> points;

    void add(const Vec3& p)
    {
        grid.insert(p, int(points.size()));
        points.push_back(p);
    }
    // Whether another corner lies within kMinSeparation of p without being
    // at p.
    bool crowded(const Vec3& p) const
    {
        bool near = false;
        grid.forNearest(p, [&](int other) {
            const double d = glm::length(points[size_t(other)] - p);
            near = near || (d > 1e-7 && d < kMinSeparation);
        });
        return near;
    }
};

MidpointCut::MidpointCut(LitMesh mesh, CutFor cutFor)
    : m_mesh(std::move(mesh))
    , m_original(m_mesh.vertexCount())
    , m_faceOf(m_mesh.vertexCount(), -1)
{
    m_exact.reserve(2 * m_mesh.vertexCount());
    for (const glm::vec3& p : m_mesh.positions)
        m_exact.emplace_back(p);
    for (size_t t = 0; t < m_mesh.triangleCount(); ++t)
        for (size_t k = 0; k < 3; ++k)
            m_faceOf[m_mesh.indices[3 * t + k]] = m_mesh.triangleFace[t];
    if (cutFor == CutFor::Files) {
        m_apart = std::make_unique<Apart>();
        m_apart->points.reserve(2 * m_mesh.vertexCount());
        for (const glm::vec3& p : m_mesh.positions)
            m_apart->add(Vec3(p));
    }
}

MidpointCut::~MidpointCut() = default;

size_t MidpointCut::cut(const std::function<bool(std::uint32_t, std::uint32_t)>& wanted)
{
    // Only the triangles with a side that is wanted are looked at (both
    // triangles of an edge are: `wanted` goes by the corners' values, which
    // copies of a corner share); the others stay as they are, first.
    std::vector<std::uint32_t> corner;
    std::vector<int> triangleFace;
    std::vector<char> sideWanted;
    {
        std::vector<std::uint32_t> all = std::move(m_mesh.indices);
        std::vector<int> faces = std::move(m_mesh.triangleFace);
        m_mesh.indices.clear();
        m_mesh.triangleFace.clear();
        for (size_t t = 0; t < faces.size(); ++t) {
            const bool w[3] = {wanted(all[3 * t], all[3 * t + 1]), wanted(all[3 * t + 1], all[3 * t + 2]),
                               wanted(all[3 * t + 2], all[3 * t])};
            auto& indices = w[0] || w[1] || w[2] ? corner : m_mesh.indices;
            auto& face = w[0] || w[1] || w[2] ? triangleFace : m_mesh.triangleFace;
            indices.insert(indices.end(), {all[3 * t], all[3 * t + 1], all[3 * t + 2]});
            face.push_back(faces[t]);
            if (w[0] || w[1] || w[2])
                sideWanted.insert(sideWanted.end(), {char(w[0]), char(w[1]), char(w[2])});
        }
    }
    const auto position = [&](std::uint32_t v) { return m_exact[v]; };
    size_t edgeCount = 0;
    // An edge is one whatever copy of its corners a triangle uses (the
    // smooth shading gives each element at a shadow corner its own copy):
    // cut on one side and not on the other, it would leave a T-vertex.
    const std::vector<std::uint32_t> edgeOf = edgesOfSides(placesOf(corner), m_mesh.vertexCount(), edgeCount);

    // Per edge: whether it is wanted (asked once), and whether a rule
    // forbids it (any of its triangles may).
    enum : std::uint8_t { kUnasked = 0, kWanted = 1, kUnwanted = 2, kForbidden = 4 };
    std::vector<std::uint8_t> state(edgeCount, kUnasked);
    for (size_t side = 0; side < corner.size(); ++side) {
        std::uint8_t& s = state[edgeOf[side]];
        const std::uint32_t a = corner[side], b = corner[nextSide(side)], c = corner[nextSide(nextSide(side))];
        if ((s & (kWanted | kUnwanted)) == 0)
            s |= sideWanted[side] ? kWanted : kUnwanted;
        if (!(s & kWanted) || (s & kForbidden))
            continue;
        const Vec3 mid = 0.5 * (position(a) + position(b));
        if (glm::length(position(b) - position(a)) < 2.0 * kMinSeparation ||
            glm::length(position(c) - mid) < kMinSeparation)
            s |= kForbidden;
    }
    std::vector<char> toCut(edgeCount, 0);
    for (size_t side = 0; side < corner.size(); ++side) {
        const std::uint32_t edge = edgeOf[side];
        if (state[edge] != kWanted || toCut[edge])
            continue;
        const Vec3 mid = 0.5 * (position(corner[side]) + position(corner[nextSide(side)]));
        if (m_apart && m_apart->crowded(mid)) {
            state[edge] |= kForbidden;
            continue;
        }
        toCut[edge] = 1;
        if (m_apart)
            m_apart->add(mid);
    }

    // The first round cuts the mesh's triangles into pieces at least half
    // as tall as they are; later rounds cut pieces of pieces, which thin
    // out (cut at one side, then at another). For files, no piece of a
    // later round is thinner than kMinHeight: the importer takes a corner
    // that close to a triangle's side as lying on it, splits the triangle
    // there and folds it (the Cornell box's wall came back as hundreds of
    // faces). Dropping a cut changes the pieces of the triangles on both
    // sides of the edge: again until none is too thin.
    for (bool changed = m_apart != nullptr && m_rounds > 0; changed;) {
        changed = false;
        for (size_t t = 0; t < triangleFace.size(); ++t) {
            const bool split[3] = {toCut[edgeOf[3 * t]] != 0, toCut[edgeOf[3 * t + 1]] != 0,
                                   toCut[edgeOf[3 * t + 2]] != 0};
            if (!split[0] && !split[1] && !split[2])
                continue;
            const Vec3 p[3] = {position(corner[3 * t]), position(corner[3 * t + 1]), position(corner[3 * t + 2])};
            if (thinnest(p, split) >= kMinHeight)
                continue;
            // Keep as many of its cuts as leave no piece too thin.
            int keep = -1; // a subset of the cut sides, as bits
            for (int cuts = int(split[0]) + int(split[1]) + int(split[2]) - 1; cuts > 0 && keep < 0; --cuts)
                for (int subset = 1; subset < 8 && keep < 0; ++subset) {
                    const bool trial[3] = {(subset & 1) != 0, (subset & 2) != 0, (subset & 4) != 0};
                    if (std::popcount(unsigned(subset)) == cuts && (!trial[0] || split[0]) && (!trial[1] || split[1]) &&
                        (!trial[2] || split[2]) && thinnest(p, trial) >= kMinHeight)
                        keep = subset;
                }
            for (size_t k = 0; k < 3; ++k)
                if (split[k] && !(keep > 0 && (keep >> k) & 1)) {
                    toCut[edgeOf[3 * t + k]] = 0;
                    changed = true;
                }
        }
    }

    // Cut, each copy of an edge takes its own midpoint, valued by its own
    // corners (as the smooth shading values each copy by its own element).
    size_t ownEdges = 0;
    const std::vector<std::uint32_t> ownEdgeOf = edgesOfSides(corner, m_mesh.vertexCount(), ownEdges);
    constexpr std::uint32_t kNone = ~std::uint32_t(0);
    std::vector<std::uint32_t> vertexOf(ownEdges, kNone);
    const size_t before = m_mesh.vertexCount();
    m_mesh.indices.reserve(m_mesh.indices.size() + 4 * corner.size());
    m_mesh.triangleFace.reserve(m_mesh.triangleFace.size() + 4 * triangleFace.size());
    const auto midpoint = [&](size_t side, int face) {
        std::uint32_t& vertex = vertexOf[ownEdgeOf[side]];
        if (vertex == kNone) {
            const std::uint32_t a = corner[side], b = corner[nextSide(side)];
            vertex = std::uint32_t(m_mesh.positions.size());
            m_exact.push_back(0.5 * (position(a) + position(b)));
            m_mesh.positions.push_back(glm::vec3(m_exact.back()));
            m_mesh.normals.push_back(m_mesh.normals[a]);
            m_mesh.radiosity.push_back(glm::vec3(0.0f));
            m_mesh.reflectance.push_back(m_mesh.reflectance[a]);
            m_ends.push_back(a);
            m_ends.push_back(b);
            m_faceOf.push_back(face);
        }
        return vertex;
    };
    const auto triangle = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c, int face) {
        m_mesh.indices.insert(m_mesh.indices.end(), {a, b, c});
        m_mesh.triangleFace.push_back(face);
    };
    for (size_t t = 0; t < triangleFace.size(); ++t) {
        const int face = triangleFace[t];
        bool split[3]; // side k runs from corner k to corner k + 1
        for (size_t k = 0; k < 3; ++k)
            split[k] = toCut[edgeOf[3 * t + k]] != 0;
        const Vec3 p[3] = {position(corner[3 * t]), position(corner[3 * t + 1]), position(corner[3 * t + 2])};
        Vec3 points[6];
        bool fromA = true;
        const size_t turn = turnOf(split);
        cutPoints(p, turn, points, fromA);
        const Pieces pieces = piecesOf(split, fromA);
        // The vertices of the six points: corners, and midpoints where cut.
        std::uint32_t vertex[6];
        for (size_t k = 0; k < 3; ++k) {
            const size_t side = 3 * t + (turn + k) % 3;
            vertex[k] = corner[side];
            vertex[3 + k] = split[(turn + k) % 3] ? midpoint(side, face) : kNone;
        }
        for (int i = 0; i < pieces.count; ++i)
            triangle(vertex[pieces.corners[i][0]], vertex[pieces.corners[i][1]], vertex[pieces.corners[i][2]], face);
    }
    ++m_rounds;
    return m_mesh.vertexCount() - before;
}

} // namespace regio::output
