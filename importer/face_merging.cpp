#include "importer/face_merging.h"

#include "model/geometry/convex_decomposition.h"
#include "model/geometry/geometry.h"
#include "model/validation/validation.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <queue>
#include <set>
#include <unordered_map>
#include <utility>

namespace regio::importer {

namespace {

// Corners closer than this to a line through two others lie on it (metres):
// half the distance by which the scene's validation lets a corner of a
// convex face turn the wrong way, well above the round-off of coordinates
// a file stores as floats.
constexpr double kOnLine = 0.5 * model::kDistanceEpsilon;

// A face the scene takes without a word: some area, flat within the
// validation's warning tolerance, convex about its own (Newell) normal as
// the validation measures it. A surface bent within the merge tolerance can
// fail the last two where corners are nearly in line.
bool acceptable(const std::vector<Vec3>& positions, const std::vector<int>& loop)
{
    const std::vector<Vec3> corners = model::loopPositions(positions, loop);
    const Vec3 newell = model::newellNormal(corners);
    const double area = 0.5 * glm::length(newell);
    if (!(area >= 10.0 * model::kMinFaceArea))
        return false;
    model::Box3 box;
    for (const Vec3& c : corners)
        box.extend(c);
    const double flat = std::max(model::kDistanceEpsilon, model::kPlanarityWarning * glm::length(box.size()));
    return model::planarityDeviation(corners) <= flat && model::isConvex(corners, newell / (2.0 * area), kOnLine);
}

// Step 1: corners within `distance` of an earlier corner take its index.
// A hash grid of cells `distance` wide finds the candidates in the 27 cells
// around a corner.
std::vector<int> weld(const std::vector<Vec3>& points, double distance, std::vector<Vec3>& welded)
{
    const double cell = std::max(distance, 1e-12);
    const auto key = [](std::int64_t x, std::int64_t y, std::int64_t z) {
        return (std::uint64_t(x) * 73856093u) ^ (std::uint64_t(y) * 19349663u) ^ (std::uint64_t(z) * 83492791u);
    };
    std::unordered_multimap<std::uint64_t, int> grid;
    std::vector<int> map(points.size(), -1);
    for (std::size_t i = 0; i < points.size(); ++i) {
        const Vec3& p = points[i];
        const auto cx = std::int64_t(std::floor(p.x / cell)), cy = std::int64_t(std::floor(p.y / cell)),
                   cz = std::int64_t(std::floor(p.z / cell));
        int found = -1;
        for (std::int64_t dx = -1; dx <= 1 && found < 0; ++dx)
            for (std::int64_t dy = -1; dy <= 1 && found < 0; ++dy)
                for (std::int64_t dz = -1; dz <= 1 && found < 0; ++dz) {
                    const auto [from, to] = grid.equal_range(key(cx + dx, cy + dy, cz + dz));
                    for (auto it = from; it != to; ++it)
                        if (glm::length(welded[std::size_t(it->second)] - p) <= distance) {
                            found = it->second;
                            break;
                        }
                }
        if (found < 0) {
            found = int(welded.size());
            welded.push_back(p);
            grid.emplace(key(cx, cy, cz), found);
        }
        map[i] = found;
    }
    return map;
}

using Edge = std::pair<int, int>; // directed: from, to

// A group's polygons while they are merged: loops of vertex indices and, for
// every directed edge of a loop, the loop it belongs to.
struct Merger {
    const std::vector<Vec3>& positions;
    std::vector<std::vector<int>> loops; // empty once merged into another
    std::map<Edge, int> owner;

    // The union of the loops on either side of the edge u -> v, or nothing
    // when it is not a simple convex polygon.
    bool merge(int u, int v)
    {
        const auto p = owner.find({u, v}), q = owner.find({v, u});
        if (p == owner.end() || q == owner.end() || p->second == q->second)
            return false;
        const std::vector<int>& P = loops[std::size_t(p->second)];
        const std::vector<int>& Q = loops[std::size_t(q->second)];
        // P rotated to run v ... u, then Q from u's successor to v's predecessor.
        std::vector<int> joined;
        const auto start = std::size_t(std::find(P.begin(), P.end(), v) - P.begin());
        for (std::size_t i = 0; i < P.size(); ++i)
            joined.push_back(P[(start + i) % P.size()]);
        const auto from = std::size_t(std::find(Q.begin(), Q.end(), u) - Q.begin());
        for (std::size_t i = 1; i + 1 < Q.size(); ++i)
            joined.push_back(Q[(from + i) % Q.size()]);
        std::vector<int> sorted = joined;
        std::sort(sorted.begin(), sorted.end());
        if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end() || !acceptable(positions, joined))
            return false; // touches itself at a corner, or reflex
        const int into = p->second, gone = q->second;
        owner.erase({u, v});
        owner.erase({v, u});
        for (std::size_t i = 0; i < joined.size(); ++i)
            owner[{joined[i], joined[(i + 1) % joined.size()]}] = into;
        loops[std::size_t(into)] = std::move(joined);
        loops[std::size_t(gone)].clear();
        return true;
    }
};

// A surface by its outline: the boundary edges (those whose reverse is not
// in the surface) chained into loops, one outer loop and its holes, cut into
// convex polygons by model::convexDecomposition. Vertices inside the surface
// disappear, so a finely triangulated wall comes back as one face. Empty
// when the outline is not that simple (a corner where the surface touches
// itself, two outer loops) or the decomposition refuses: the caller merges
// the triangles instead.
std::vector<std::vector<int>> byOutline(const std::vector<Vec3>& positions, const std::vector<std::array<int, 3>>& tris,
                                        const Vec3& normal)
{
    std::set<Edge> edges;
    for (const auto& t : tris)
        for (std::size_t k = 0; k < 3; ++k)
            edges.insert({t[k], t[(k + 1) % 3]});
    std::map<int, int> next; // boundary edge from -> to
    for (const Edge& e : edges)
        if (!edges.contains({e.second, e.first}) && !next.emplace(e.first, e.second).second)
            return {}; // two boundary edges leave one corner: the surface touches itself there
    // A frame in the plane; the loops in it.
    const Vec3 axis = std::abs(normal.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    const Vec3 u = glm::normalize(glm::cross(axis, normal)), v = glm::cross(normal, u);
    std::vector<glm::dvec2> points;
    std::vector<int> global;
    std::map<int, int> local;
    const auto localOf = [&](int w) {
        const auto [it, fresh] = local.emplace(w, int(points.size()));
        if (fresh) {
            const Vec3& p = positions[std::size_t(w)];
            points.push_back({glm::dot(p, u), glm::dot(p, v)});
            global.push_back(w);
        }
        return it->second;
    };
    std::vector<model::Polygon2Loop> outers, holes;
    std::set<int> done;
    for (const auto& [start, unused] : next) {
        if (done.contains(start))
            continue;
        model::Polygon2Loop loop;
        for (int w = start; !done.contains(w);) {
            done.insert(w);
            loop.push_back(localOf(w));
            const auto it = next.find(w);
            if (it == next.end())
                return {};
            w = it->second;
        }
        if (loop.size() < 3)
            return {};
        (model::signedArea2(points, loop) > 0.0 ? outers : holes).push_back(std::move(loop));
    }
    if (outers.size() != 1)
        return {};
    const auto pieces = model::convexDecomposition(points, outers.front(), holes, kOnLine);
    if (!pieces)
        return {};
    std::vector<std::vector<int>> out;
    for (const model::Polygon2Loop& piece : *pieces) {
        std::vector<int> loop;
        for (const int i : piece)
            loop.push_back(global[std::size_t(i)]);
        if (!acceptable(positions, loop))
            return {};
        out.push_back(std::move(loop));
    }
    return out;
}

// Step 2b: T-junctions. Where a corner of one triangle lies inside an edge
// of another of the same mesh (a finer neighbour, a hole filled with long
// edges), the two share no edge and would not join one surface. Such a
// corner is an end of an edge that only one triangle of its mesh uses, and
// so is the edge it lies on: only those are searched (none in a closed,
// conforming mesh). A triangle with corners on its edges becomes a fan
// around its centroid, which the outline drops again (step 4).
struct TTriangle {
    std::array<int, 3> v;
    int material, mesh;
    Vec3 normal;
    double area;
};

constexpr double kMaxCellsAlongAnEdge = 4096.0;

std::size_t splitTJunctions(std::vector<TTriangle>& triangles, std::vector<Vec3>& positions, double distance)
{
    std::map<std::array<int, 3>, int> uses; // (mesh, low, high) -> triangles
    for (const TTriangle& t : triangles)
        for (std::size_t k = 0; k < 3; ++k)
            ++uses[{t.mesh, std::min(t.v[k], t.v[(k + 1) % 3]), std::max(t.v[k], t.v[(k + 1) % 3])}];
    // The ends of open edges, by mesh, in a hash grid as wide as the
    // median open edge is long.
    std::vector<std::pair<int, int>> ends; // (mesh, vertex)
    std::vector<double> lengths;
    for (const auto& [key, count] : uses)
        if (count == 1) {
            ends.push_back({key[0], key[1]});
            ends.push_back({key[0], key[2]});
            lengths.push_back(glm::length(positions[std::size_t(key[2])] - positions[std::size_t(key[1])]));
        }
    if (lengths.empty())
        return 0;
    std::sort(ends.begin(), ends.end());
    ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
    std::nth_element(lengths.begin(), lengths.begin() + std::ptrdiff_t(lengths.size() / 2), lengths.end());
    const double cell = std::max(lengths[lengths.size() / 2], 4.0 * distance);
    const auto cellOf = [&](const Vec3& p) {
        return std::array<std::int64_t, 3>{std::int64_t(std::floor(p.x / cell)), std::int64_t(std::floor(p.y / cell)),
                                           std::int64_t(std::floor(p.z / cell))};
    };
    std::map<std::array<std::int64_t, 3>, std::vector<std::pair<int, int>>> grid;
    for (const auto& e : ends)
        grid[cellOf(positions[std::size_t(e.second)])].push_back(e);

    std::size_t split = 0;
    std::vector<TTriangle> out;
    out.reserve(triangles.size());
    for (const TTriangle& t : triangles) {
        // Per edge, the corners inside it, by their distance from its start.
        std::array<std::vector<std::pair<double, int>>, 3> inside;
        bool any = false;
        for (std::size_t k = 0; k < 3; ++k) {
            const int a = t.v[k], b = t.v[(k + 1) % 3];
            if (uses[{t.mesh, std::min(a, b), std::max(a, b)}] != 1)
                continue;
            const Vec3 pa = positions[std::size_t(a)], pb = positions[std::size_t(b)];
            const double length = glm::length(pb - pa);
            const Vec3 along = (pb - pa) / length;
            // The cells along the edge and those next to them. An edge
            // thousands of cells long (a ground plane under a finely cut
            // model) is not searched: its neighbours are not that.
            const double steps = std::ceil(length / cell);
            if (!(steps <= kMaxCellsAlongAnEdge))
                continue;
            std::set<std::array<std::int64_t, 3>> visited;
            for (int step = 0; step <= int(steps); ++step) {
                const auto c = cellOf(pa + along * std::min(step * cell, length));
                for (std::int64_t dx = -1; dx <= 1; ++dx)
                    for (std::int64_t dy = -1; dy <= 1; ++dy)
                        for (std::int64_t dz = -1; dz <= 1; ++dz) {
                            const std::array<std::int64_t, 3> n{c[0] + dx, c[1] + dy, c[2] + dz};
                            if (!visited.insert(n).second)
                                continue;
                            const auto it = grid.find(n);
                            if (it == grid.end())
                                continue;
                            for (const auto& [mesh, w] : it->second) {
                                if (mesh != t.mesh || w == a || w == b)
                                    continue;
                                const Vec3 p = positions[std::size_t(w)];
                                const double u = glm::dot(p - pa, along);
                                if (u <= distance || u >= length - distance ||
                                    glm::length(p - (pa + along * u)) > distance)
                                    continue;
                                inside[k].push_back({u, w});
                            }
                        }
            }
            std::sort(inside[k].begin(), inside[k].end());
            any = any || !inside[k].empty();
        }
        if (!any) {
            out.push_back(t);
            continue;
        }
        ++split;
        const int centre = int(positions.size());
        positions.push_back(
            (positions[std::size_t(t.v[0])] + positions[std::size_t(t.v[1])] + positions[std::size_t(t.v[2])]) / 3.0);
        for (std::size_t k = 0; k < 3; ++k) {
            std::vector<int> chain{t.v[k]};
            for (const auto& [u, w] : inside[k])
                chain.push_back(w);
            chain.push_back(t.v[(k + 1) % 3]);
            for (std::size_t i = 0; i + 1 < chain.size(); ++i) {
                const Vec3 &p0 = positions[std::size_t(centre)], &p1 = positions[std::size_t(chain[i])],
                           &p2 = positions[std::size_t(chain[i + 1])];
                out.push_back({{centre, chain[i], chain[i + 1]},
                               t.material,
                               t.mesh,
                               t.normal,
                               glm::length(glm::cross(p1 - p0, p2 - p0)) / 2.0});
            }
        }
    }
    triangles = std::move(out);
    return split;
}

} // namespace

MergedModel mergeTriangles(const TriangleSoup& soup, const MergeOptions& options)
{
    MergedModel out;
    out.counts.trianglesIn = soup.triangles.size();
    const std::vector<int> map = weld(soup.positions, options.distance, out.positions);
    out.counts.weldedVertices = soup.positions.size() - out.positions.size();

    // Step 2: triangles with area, each once.
    using Triangle = TTriangle;
    std::vector<Triangle> triangles;
    std::set<std::array<int, 4>> seen;
    for (const SoupTriangle& t : soup.triangles) {
        std::array<int, 3> v{};
        for (std::size_t k = 0; k < 3; ++k)
            v[k] = map[std::size_t(t.corners[k])];
        const Vec3 &a = out.positions[std::size_t(v[0])], &b = out.positions[std::size_t(v[1])],
                   &c = out.positions[std::size_t(v[2])];
        const Vec3 cross = glm::cross(b - a, c - a);
        const double twice = glm::length(cross);
        const double longest = std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
        if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0] || twice <= 1e-9 * longest * longest ||
            twice < 20.0 * model::kMinFaceArea) {
            ++out.counts.degenerate;
            continue;
        }
        // The same triangle twice in one mesh, wound the same way. Wound the
        // other way it is the back of a thin sheet (a solid's face on
        // another's, a leaf seen from both sides), which stays.
        const auto first = std::size_t(std::min_element(v.begin(), v.end()) - v.begin());
        const std::array<int, 4> key{t.mesh, v[first], v[(first + 1) % 3], v[(first + 2) % 3]};
        if (!seen.insert(key).second) {
            ++out.counts.duplicate;
            continue;
        }
        triangles.push_back({v, t.material, t.mesh, cross / twice, twice / 2.0});
    }

    out.counts.tJunctions = splitTJunctions(triangles, out.positions, options.distance);

    // Step 3: flat surfaces by flood fill over shared edges.
    std::map<Edge, std::vector<int>> byEdge; // undirected (low, high) -> triangles
    for (std::size_t i = 0; i < triangles.size(); ++i)
        for (std::size_t k = 0; k < 3; ++k) {
            const int a = triangles[i].v[k], b = triangles[i].v[(k + 1) % 3];
            byEdge[{std::min(a, b), std::max(a, b)}].push_back(int(i));
        }
    const double cosine = std::cos(options.angleDegrees * std::numbers::pi / 180.0);
    std::vector<int> group(triangles.size(), -1);
    std::vector<std::vector<int>> groups;
    for (std::size_t seed = 0; seed < triangles.size(); ++seed) {
        if (group[seed] >= 0)
            continue;
        const Triangle& s = triangles[seed];
        const Vec3 origin = out.positions[std::size_t(s.v[0])];
        const int id = int(groups.size());
        groups.emplace_back();
        std::queue<int> todo;
        todo.push(int(seed));
        group[seed] = id;
        while (!todo.empty()) {
            const int t = todo.front();
            todo.pop();
            groups.back().push_back(t);
            for (std::size_t k = 0; k < 3; ++k) {
                const int a = triangles[std::size_t(t)].v[k], b = triangles[std::size_t(t)].v[(k + 1) % 3];
                for (const int n : byEdge[{std::min(a, b), std::max(a, b)}]) {
                    const Triangle& o = triangles[std::size_t(n)];
                    if (group[std::size_t(n)] >= 0 || o.material != s.material || o.mesh != s.mesh ||
                        glm::dot(o.normal, s.normal) < cosine)
                        continue;
                    const bool flat = std::all_of(o.v.begin(), o.v.end(), [&](int w) {
                        return std::abs(glm::dot(out.positions[std::size_t(w)] - origin, s.normal)) <= options.distance;
                    });
                    if (!flat)
                        continue;
                    group[std::size_t(n)] = id;
                    todo.push(n);
                }
            }
        }
    }
    out.counts.surfaces = groups.size();

    // Step 4: each surface merged into convex polygons, longest edges first.
    for (const std::vector<int>& members : groups) {
        Vec3 normal{0.0};
        for (const int t : members)
            normal += triangles[std::size_t(t)].normal * triangles[std::size_t(t)].area;
        normal = glm::normalize(normal);
        std::vector<std::array<int, 3>> corners;
        for (const int t : members)
            corners.push_back(triangles[std::size_t(t)].v);
        const Triangle& first = triangles[std::size_t(members.front())];
        if (members.size() > 1) {
            std::vector<std::vector<int>> outline = byOutline(out.positions, corners, normal);
            if (!outline.empty()) {
                for (std::vector<int>& loop : outline)
                    out.faces.push_back({std::move(loop), first.material, first.mesh});
                continue;
            }
        }
        Merger merger{out.positions, {}, {}};
        std::vector<std::pair<double, Edge>> shared;
        for (const int t : members) {
            const Triangle& tri = triangles[std::size_t(t)];
            const int loop = int(merger.loops.size());
            merger.loops.push_back({tri.v[0], tri.v[1], tri.v[2]});
            for (std::size_t k = 0; k < 3; ++k) {
                const Edge e{tri.v[k], tri.v[(k + 1) % 3]};
                merger.owner[e] = loop;
                if (e.first < e.second)
                    shared.push_back(
                        {glm::length(out.positions[std::size_t(e.second)] - out.positions[std::size_t(e.first)]), e});
            }
        }
        std::sort(shared.begin(), shared.end(), [](const auto& x, const auto& y) {
            return x.first != y.first ? x.first > y.first : x.second < y.second;
        });
        for (const auto& [length, e] : shared)
            (void)merger.merge(e.first, e.second);
        for (std::vector<int>& loop : merger.loops)
            if (!loop.empty())
                out.faces.push_back({std::move(loop), first.material, first.mesh});
    }

    // Step 5: corners on a straight edge, in every face that has them: a
    // point that only divides an edge (its own face's, or one two faces
    // share) goes from every face at once, so shared edges stay shared. A
    // corner of any face (a T-junction's) stays in all of them.
    const auto straightAt = [&](const MergedFace& f, std::size_t i) {
        const std::size_t n = f.loop.size();
        const Vec3& a = out.positions[std::size_t(f.loop[(i + n - 1) % n])];
        const Vec3& b = out.positions[std::size_t(f.loop[i])];
        const Vec3& c = out.positions[std::size_t(f.loop[(i + 1) % n])];
        const Vec3 ac = c - a;
        const double length = glm::length(ac);
        return length > 0.0 && glm::length(glm::cross(b - a, ac)) / length <= kOnLine && glm::dot(b - a, ac) > 0.0 &&
               glm::dot(c - b, ac) > 0.0;
    };
    std::vector<int> uses(out.positions.size(), 0), straightUses(out.positions.size(), 0);
    for (const MergedFace& f : out.faces)
        for (std::size_t i = 0; i < f.loop.size(); ++i) {
            ++uses[std::size_t(f.loop[i])];
            if (straightAt(f, i))
                ++straightUses[std::size_t(f.loop[i])];
        }
    for (MergedFace& f : out.faces) {
        std::vector<int> kept;
        for (std::size_t i = 0; i < f.loop.size(); ++i) {
            const auto v = std::size_t(f.loop[i]);
            if (uses[v] != straightUses[v] || f.loop.size() - (i - kept.size()) <= 3)
                kept.push_back(f.loop[i]);
        }
        // Dropping a corner can tip a face that was barely convex about its
        // own normal over the validation's edge; it then keeps its corners.
        if (kept.size() != f.loop.size() && acceptable(out.positions, kept))
            f.loop = std::move(kept);
        // Every loop starts at its least corner (by x, then y, then z): the
        // solver strips a face from its first corner (paper §5.4), and where
        // a file gives no start, the geometry alone should choose it.
        model::startAtLeastCorner(f.loop, out.positions);
    }
    out.counts.faces = out.faces.size();
    return out;
}

} // namespace regio::importer
