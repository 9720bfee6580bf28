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

} // namespace

MergedModel mergeTriangles(const TriangleSoup& soup, const MergeOptions& options)
{
    MergedModel out;
    out.counts.trianglesIn = soup.triangles.size();
    const std::vector<int> map = weld(soup.positions, options.distance, out.positions);
    out.counts.weldedVertices = soup.positions.size() - out.positions.size();

    // Step 2: triangles with area, each once.
    struct Triangle {
        std::array<int, 3> v;
        int material, mesh;
        Vec3 normal;
        double area;
    };
    std::vector<Triangle> triangles;
    std::set<std::array<int, 3>> seen;
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
        std::array<int, 3> sorted = v;
        std::sort(sorted.begin(), sorted.end());
        if (!seen.insert(sorted).second) {
            ++out.counts.duplicate;
            continue;
        }
        triangles.push_back({v, t.material, t.mesh, cross / twice, twice / 2.0});
    }

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

    // Step 5: corners on a straight edge that only their own face uses.
    std::vector<int> uses(out.positions.size(), 0);
    for (const MergedFace& f : out.faces)
        for (const int v : f.loop)
            ++uses[std::size_t(v)];
    for (MergedFace& f : out.faces) {
        for (std::size_t i = 0; f.loop.size() > 3 && i < f.loop.size();) {
            const std::size_t n = f.loop.size();
            const Vec3& a = out.positions[std::size_t(f.loop[(i + n - 1) % n])];
            const Vec3& b = out.positions[std::size_t(f.loop[i])];
            const Vec3& c = out.positions[std::size_t(f.loop[(i + 1) % n])];
            const Vec3 u = b - a, v = c - b;
            const bool straight =
                glm::length(glm::cross(u, v)) <= 1e-9 * glm::length(u) * glm::length(v) && glm::dot(u, v) > 0.0;
            if (straight && uses[std::size_t(f.loop[i])] == 1)
                f.loop.erase(f.loop.begin() + std::ptrdiff_t(i));
            else
                ++i;
        }
    }
    out.counts.faces = out.faces.size();
    return out;
}

} // namespace regio::importer
