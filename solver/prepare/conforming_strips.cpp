#include "solver/prepare/conforming_strips.h"

#include "model/geometry/edge_key.h"
#include "model/geometry/geometry.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <unordered_set>
#include <utility>

namespace regio::solver {

namespace {

using model::edgeKey;
using model::undirectedEdgeKey;
using model::Vec3;

// Corners closer than this are one point; a point closer than this to a
// segment lies on it. Pieces come from exact clips of one polygon, so their
// shared corners agree far below it.
constexpr double kWeld = model::kDistanceEpsilon;

double distanceToSegment(const Vec3& p, const Vec3& a, const Vec3& b, double& t)
{
    const Vec3 ab = b - a;
    const double length2 = glm::dot(ab, ab);
    t = length2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
    return glm::length(a + ab * t - p);
}

// Points on the outlines of the pieces, in a uniform grid of cells about a
// patch wide, for welding and for the points that lie on an edge.
class OutlinePoints {
public:
    OutlinePoints(const std::vector<Vec3>& points, double cell)
        : m_points(points)
        , m_cell(cell)
    {
    }

    // The index of an outline point within kWeld of p, or -1.
    int find(const Vec3& p) const
    {
        const Key k = keyOf(p);
        for (long long dx = -1; dx <= 1; ++dx)
            for (long long dy = -1; dy <= 1; ++dy)
                for (long long dz = -1; dz <= 1; ++dz) {
                    const auto it = m_cells.find(pack({k[0] + dx, k[1] + dy, k[2] + dz}));
                    if (it == m_cells.end())
                        continue;
                    for (int i : it->second)
                        if (glm::length(m_points[size_t(i)] - p) <= kWeld)
                            return i;
                }
        return -1;
    }

    void add(int index) { m_cells[pack(keyOf(m_points[size_t(index)]))].push_back(index); }

    // Outline points strictly inside segment a-b (not a or b), ordered from a.
    std::vector<int> inside(int a, int b) const
    {
        const Vec3 &pa = m_points[size_t(a)], &pb = m_points[size_t(b)];
        const Key lo = keyOf(glm::min(pa, pb) - Vec3(kWeld)), hi = keyOf(glm::max(pa, pb) + Vec3(kWeld));
        std::vector<std::pair<double, int>> found;
        for (long long x = lo[0]; x <= hi[0]; ++x)
            for (long long y = lo[1]; y <= hi[1]; ++y)
                for (long long z = lo[2]; z <= hi[2]; ++z) {
                    const auto it = m_cells.find(pack({x, y, z}));
                    if (it == m_cells.end())
                        continue;
                    for (int i : it->second) {
                        if (i == a || i == b)
                            continue;
                        double t = 0.0;
                        if (distanceToSegment(m_points[size_t(i)], pa, pb, t) <= kWeld && t > 0.0 && t < 1.0)
                            found.emplace_back(t, i);
                    }
                }
        std::sort(found.begin(), found.end());
        std::vector<int> out;
        out.reserve(found.size());
        for (const auto& [t, i] : found)
            out.push_back(i);
        return out;
    }

private:
    using Key = std::array<long long, 3>;
    Key keyOf(const Vec3& p) const
    {
        return {std::llround(std::floor(p.x / m_cell)), std::llround(std::floor(p.y / m_cell)),
                std::llround(std::floor(p.z / m_cell))};
    }
    static std::uint64_t pack(const Key& k)
    {
        // 21 bits per axis: cells of a patch size, scenes far below 2^20 patches across.
        const auto bits = [](long long v) { return std::uint64_t(v) & 0x1fffffu; };
        return bits(k[0]) | (bits(k[1]) << 21) | (bits(k[2]) << 42);
    }

    const std::vector<Vec3>& m_points;
    double m_cell;
    std::unordered_map<std::uint64_t, std::vector<int>> m_cells;
};

// The edge of `piece` (its first corner's index) that p lies on, or -1.
int outlineEdge(const Vec3& p, const std::vector<Vec3>& piece)
{
    for (size_t i = 0; i < piece.size(); ++i) {
        double t = 0.0;
        if (distanceToSegment(p, piece[i], piece[(i + 1) % piece.size()], t) <= kWeld)
            return int(i);
    }
    return -1;
}

// What may move: a corner of any piece is the geometry and stays; a point
// the strips put on a piece's edge may move only along that edge's line; a
// point inside a piece anywhere.
struct PointRole {
    bool corner = false;
    bool onEdge = false;
    Vec3 a{0.0}, b{0.0}; // the edge's line when onEdge
};

double worstAngle(const std::vector<Vec3>& points, const Triangle& t)
{
    return minimumAngleDegrees(points[size_t(t[0])], points[size_t(t[1])], points[size_t(t[2])]);
}

// Lawson's flips: an edge inside the mesh whose two triangles form a convex
// quadrilateral is swapped for the other diagonal when that raises the
// smaller of their smallest angles. The fans that close T-vertices leave
// thin triangles where the points of two pieces nearly meet; the flips
// widen them. The outline (the face's and the covers') is never crossed,
// and neither is a line between two pieces (`fixed`, undirected edges):
// some are shadow lines (solver/prepare/shadow_lines.h), which the mesh
// must keep as edges.
void improveByFlips(const std::vector<Vec3>& points, std::vector<Triangle>& triangles, const Vec3& normal,
                    const std::vector<char>& touchedPoint, const std::unordered_set<std::uint64_t>& fixed)
{
    const auto ccw = [&](int a, int b, int c) {
        return glm::dot(glm::cross(points[size_t(b)] - points[size_t(a)], points[size_t(c)] - points[size_t(a)]),
                        normal) > 0.0;
    };
    std::unordered_map<std::uint64_t, int> owner; // directed edge -> its triangle
    owner.reserve(triangles.size() * 3);
    const auto own = [&](int t) {
        for (int i = 0; i < 3; ++i)
            owner[edgeKey(triangles[size_t(t)][size_t(i)], triangles[size_t(t)][size_t((i + 1) % 3)])] = t;
    };
    // Only around the points the fans and collapses touched: elsewhere the
    // strips are as the strip method made them.
    std::vector<int> active;
    for (size_t t = 0; t < triangles.size(); ++t) {
        own(int(t));
        const Triangle& tri = triangles[t];
        if (touchedPoint[size_t(tri[0])] || touchedPoint[size_t(tri[1])] || touchedPoint[size_t(tri[2])])
            active.push_back(int(t));
    }
    for (int pass = 0; pass < 32 && !active.empty(); ++pass) {
        std::vector<int> next;
        for (int t : active)
            for (int i = 0; i < 3; ++i) {
                const Triangle tri = triangles[size_t(t)];
                const int a = tri[size_t(i)], b = tri[size_t((i + 1) % 3)], c = tri[size_t((i + 2) % 3)];
                const auto other = owner.find(edgeKey(b, a));
                if (other == owner.end() || fixed.count(undirectedEdgeKey(a, b)) != 0)
                    continue;
                const int o = other->second;
                const Triangle& u = triangles[size_t(o)];
                int d = -1;
                for (int k = 0; k < 3; ++k)
                    if (u[size_t(k)] != a && u[size_t(k)] != b)
                        d = u[size_t(k)];
                // Convex: the new diagonal c-d has a and b on either side.
                if (d < 0 || !ccw(c, a, d) || !ccw(d, b, c))
                    continue;
                const Triangle first{c, a, d}, second{d, b, c};
                const double before = std::min(worstAngle(points, tri), worstAngle(points, u));
                const double after = std::min(worstAngle(points, first), worstAngle(points, second));
                if (after <= before + 1e-9)
                    continue;
                owner.erase(edgeKey(a, b));
                owner.erase(edgeKey(b, a));
                triangles[size_t(t)] = first;
                triangles[size_t(o)] = second;
                own(t);
                own(o);
                next.push_back(t);
                next.push_back(o);
                break; // t changed: its edges are looked at again next pass
            }
        std::sort(next.begin(), next.end());
        next.erase(std::unique(next.begin(), next.end()), next.end());
        active = std::move(next);
    }
}

// Where the strips of two pieces divide their common line at points a few
// millimetres apart, the T-vertex fans leave a triangle with a tiny edge that
// no flip can widen. Such an edge is collapsed: its movable end moves onto
// the other (along its line when it lies on a piece's edge), if every
// triangle around it stays counter-clockwise and the worst angle among them
// gets better. Shortest edges first.
void collapseShortEdges(const std::vector<Vec3>& points, std::vector<PointRole>& roles,
                        std::vector<Triangle>& triangles, const Vec3& normal, double patchSize,
                        std::vector<char>& touchedPoint)
{
    std::vector<std::vector<int>> around(points.size());
    for (size_t t = 0; t < triangles.size(); ++t)
        for (int v : triangles[t])
            around[size_t(v)].push_back(int(t));
    std::vector<std::pair<double, std::pair<int, int>>> edges;
    for (const Triangle& t : triangles)
        for (int i = 0; i < 3; ++i) {
            const int u = t[size_t(i)], v = t[size_t((i + 1) % 3)];
            const double length = glm::length(points[size_t(u)] - points[size_t(v)]);
            if (length < 0.5 * patchSize) {
                edges.push_back({length, {u, v}});
                edges.push_back({length, {v, u}});
            }
        }
    std::sort(edges.begin(), edges.end());
    std::vector<char> dead(triangles.size(), 0);
    const auto area = [&](const Triangle& t) {
        return glm::dot(
            glm::cross(points[size_t(t[1])] - points[size_t(t[0])], points[size_t(t[2])] - points[size_t(t[0])]),
            normal);
    };
    for (const auto& [length, edge] : edges) {
        const auto [u, v] = edge;
        const PointRole& role = roles[size_t(u)];
        if (role.corner || around[size_t(u)].empty())
            continue;
        if (role.onEdge) {
            const Vec3 d = glm::normalize(role.b - role.a);
            const Vec3 off = points[size_t(v)] - role.a;
            if (glm::length(off - d * glm::dot(off, d)) > kWeld)
                continue;
        }
        bool joined = false, valid = true;
        double before = 180.0, after = 180.0;
        for (int t : around[size_t(u)]) {
            if (dead[size_t(t)])
                continue;
            Triangle moved = triangles[size_t(t)];
            before = std::min(before, worstAngle(points, moved));
            bool hasV = false;
            for (int& w : moved) {
                hasV = hasV || w == v;
                if (w == u)
                    w = v;
            }
            if (hasV) {
                joined = true;
                continue;
            }
            if (area(moved) <= 0.0)
                valid = false;
            else
                after = std::min(after, worstAngle(points, moved));
        }
        if (!joined || !valid || after <= before)
            continue;
        for (int t : around[size_t(u)]) {
            if (dead[size_t(t)])
                continue;
            Triangle& moved = triangles[size_t(t)];
            if (std::find(moved.begin(), moved.end(), v) != moved.end()) {
                dead[size_t(t)] = 1;
                continue;
            }
            std::replace(moved.begin(), moved.end(), u, v);
            around[size_t(v)].push_back(t);
        }
        around[size_t(u)].clear();
        touchedPoint[size_t(v)] = 1;
    }
    size_t kept = 0;
    for (size_t t = 0; t < triangles.size(); ++t)
        if (!dead[t])
            triangles[kept++] = triangles[t];
    triangles.resize(kept);
}

// The edges of `mesh` along the pieces' edges (undirectedEdgeKeys):
// between consecutive points of the mesh on each piece edge, once the
// T-vertices are closed and the short edges collapsed (points no triangle
// uses any more are skipped).
std::unordered_set<std::uint64_t> linesBetweenPieces(const std::vector<std::vector<Vec3>>& pieces,
                                                     const OutlinePoints& outline, const StripMesh& mesh)
{
    std::vector<char> used(mesh.points.size(), 0);
    for (const Triangle& t : mesh.triangles)
        for (int v : t)
            used[size_t(v)] = 1;
    std::unordered_set<std::uint64_t> fixed;
    for (const std::vector<Vec3>& piece : pieces)
        for (size_t i = 0; i < piece.size(); ++i) {
            const int a = outline.find(piece[i]), b = outline.find(piece[(i + 1) % piece.size()]);
            if (a < 0 || b < 0)
                continue;
            int previous = a;
            std::vector<int> along = outline.inside(a, b);
            along.push_back(b);
            for (int v : along) {
                if (!used[size_t(v)])
                    continue;
                fixed.insert(undirectedEdgeKey(previous, v));
                previous = v;
            }
        }
    return fixed;
}

} // namespace

StripMesh stripTriangulatePieces(const std::vector<std::vector<Vec3>>& pieces, const Vec3& normal, double patchSize)
{
    if (pieces.size() == 1)
        return stripTriangulate(pieces.front(), normal, patchSize);

    StripMesh out;
    OutlinePoints outline(out.points, std::max(patchSize, 1e3 * kWeld));
    std::vector<Triangle> triangles;
    std::vector<PointRole> roles;
    for (const std::vector<Vec3>& piece : pieces) {
        const StripMesh mesh = stripTriangulate(piece, normal, patchSize);
        std::vector<int> index(mesh.points.size());
        for (size_t i = 0; i < mesh.points.size(); ++i) {
            const Vec3& p = mesh.points[i];
            const bool corner = i < piece.size();
            const int edge = corner ? -1 : outlineEdge(p, piece);
            const bool outlinePoint = corner || edge >= 0;
            int found = outlinePoint ? outline.find(p) : -1;
            if (found < 0) {
                found = int(out.points.size());
                out.points.push_back(p);
                roles.push_back({});
                if (outlinePoint)
                    outline.add(found);
                if (edge >= 0)
                    roles.back() = {false, true, piece[size_t(edge)], piece[(size_t(edge) + 1) % piece.size()]};
            }
            if (corner)
                roles[size_t(found)].corner = true;
            index[i] = found;
        }
        for (const Triangle& t : mesh.triangles)
            triangles.push_back({index[size_t(t[0])], index[size_t(t[1])], index[size_t(t[2])]});
    }

    std::vector<int> fanned; // the corners of the triangles fanned below
    // Close the T-vertices: the corners of neighbouring pieces go into the
    // edges they lie on. Only edges along a piece's outline can hold one (a
    // point of another piece is never inside this one), but checking every
    // edge costs little and needs no bookkeeping.
    for (const Triangle& t : triangles) {
        std::array<std::vector<int>, 3> extra;
        int splitEdges = 0, lastSplit = 0;
        for (int e = 0; e < 3; ++e) {
            extra[size_t(e)] = outline.inside(t[size_t(e)], t[size_t((e + 1) % 3)]);
            if (!extra[size_t(e)].empty()) {
                ++splitEdges;
                lastSplit = e;
            }
        }
        if (splitEdges == 0) {
            out.triangles.push_back(t);
            continue;
        }
        fanned.insert(fanned.end(), t.begin(), t.end());
        // The triangle's outline with the inserted points, counter-clockwise,
        // starting at the corner opposite the (last) split edge.
        std::vector<int> loop;
        const int start = (lastSplit + 2) % 3;
        for (int s = 0; s < 3; ++s) {
            const int e = (start + s) % 3;
            loop.push_back(t[size_t(e)]);
            loop.insert(loop.end(), extra[size_t(e)].begin(), extra[size_t(e)].end());
        }
        if (splitEdges == 1) {
            for (size_t i = 1; i + 1 < loop.size(); ++i)
                out.triangles.push_back({loop[0], loop[i], loop[i + 1]});
        } else {
            const int centre = int(out.points.size());
            out.points.push_back((out.points[size_t(t[0])] + out.points[size_t(t[1])] + out.points[size_t(t[2])]) /
                                 3.0);
            roles.push_back({});
            for (size_t i = 0; i < loop.size(); ++i)
                out.triangles.push_back({centre, loop[i], loop[(i + 1) % loop.size()]});
        }
    }
    std::vector<char> touched(out.points.size(), 0);
    for (int v : fanned)
        touched[size_t(v)] = 1;
    collapseShortEdges(out.points, roles, out.triangles, normal, patchSize, touched);
    improveByFlips(out.points, out.triangles, normal, touched, linesBetweenPieces(pieces, outline, out));

    // Drop the points that collapsed away.
    std::vector<int> renumber(out.points.size(), -1);
    std::vector<Vec3> used;
    for (Triangle& t : out.triangles)
        for (int& v : t) {
            if (renumber[size_t(v)] < 0) {
                renumber[size_t(v)] = int(used.size());
                used.push_back(out.points[size_t(v)]);
            }
            v = renumber[size_t(v)];
        }
    out.points = std::move(used);
    return out;
}

} // namespace regio::solver
