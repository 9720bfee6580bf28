#include "model/geometry/convex_decomposition.h"

#include "model/geometry/edge_key.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>

namespace regio::model {

namespace {

using V2 = glm::dvec2;

double cross(const V2& a, const V2& b) { return a.x * b.y - a.y * b.x; }

// How far b lies to the left of the line a -> c (positive: a left turn at b,
// a convex corner of a counter-clockwise loop).
double cornerHeight(const V2& a, const V2& b, const V2& c)
{
    double base = glm::length(c - a);
    if (base == 0.0)
        return 0.0;
    return cross(b - a, c - b) / base;
}

// A loop vertex that stays, with the collinear vertices set aside on the edge
// to the next kept vertex.
struct Kept {
    int id;
    std::vector<int> after;
};

std::vector<Kept> dropCollinear(const std::vector<V2>& p, const Polygon2Loop& loop, double eps)
{
    std::vector<Kept> ring;
    for (int id : loop)
        ring.push_back({id, {}});
    bool changed = true;
    while (changed && ring.size() > 3) {
        changed = false;
        const size_t n = ring.size();
        for (size_t i = 0; i < n; ++i) {
            Kept& prev = ring[(i + n - 1) % n];
            const Kept& cur = ring[i];
            const Kept& next = ring[(i + 1) % n];
            const V2 a = p[size_t(prev.id)], b = p[size_t(cur.id)], c = p[size_t(next.id)];
            V2 ac = c - a;
            double len = glm::length(ac);
            if (len <= eps || std::abs(cross(ac, b - a)) / len > eps || glm::dot(b - a, ac) <= 0.0 ||
                glm::dot(c - b, ac) <= 0.0)
                continue;
            prev.after.push_back(cur.id);
            prev.after.insert(prev.after.end(), cur.after.begin(), cur.after.end());
            ring.erase(ring.begin() + std::ptrdiff_t(i));
            changed = true;
            break;
        }
    }
    return ring;
}

Polygon2Loop ids(const std::vector<Kept>& ring)
{
    Polygon2Loop out;
    for (const Kept& k : ring)
        out.push_back(k.id);
    return out;
}

// Inside or on the counter-clockwise triangle abc, within eps.
bool insideOrOn(const V2& q, const V2& a, const V2& b, const V2& c, double eps)
{
    const V2 corners[3] = {a, b, c};
    for (int e = 0; e < 3; ++e) {
        V2 from = corners[e];
        V2 edge = corners[(e + 1) % 3] - from;
        double len = glm::length(edge);
        if (len == 0.0)
            continue;
        if (cross(edge, q - from) / len < -eps)
            return false;
    }
    return true;
}

bool strictlyInside(const V2& q, const V2& a, const V2& b, const V2& c, double eps)
{
    const V2 corners[3] = {a, b, c};
    for (int e = 0; e < 3; ++e) {
        V2 from = corners[e];
        V2 edge = corners[(e + 1) % 3] - from;
        double len = glm::length(edge);
        if (len == 0.0 || cross(edge, q - from) / len <= eps)
            return false;
    }
    return true;
}

// Joins a clockwise hole into the counter-clockwise polygon through a bridge
// from the hole's rightmost vertex M to a vertex P of the polygon that M sees.
bool bridgeHole(const std::vector<V2>& p, Polygon2Loop& poly, const Polygon2Loop& hole, double eps)
{
    size_t m = 0;
    for (size_t i = 1; i < hole.size(); ++i)
        if (p[size_t(hole[i])].x > p[size_t(hole[m])].x)
            m = i;
    const V2 M = p[size_t(hole[m])];
    const size_t n = poly.size();

    // The nearest polygon edge hit by the ray from M towards +x.
    double bestX = std::numeric_limits<double>::infinity();
    size_t hitEdge = n;
    for (size_t i = 0; i < n; ++i) {
        V2 a = p[size_t(poly[i])], b = p[size_t(poly[(i + 1) % n])];
        if ((a.y > M.y && b.y > M.y) || (a.y < M.y && b.y < M.y))
            continue;
        double x;
        if (a.y == b.y)
            x = std::min(a.x, b.x) >= M.x ? std::min(a.x, b.x) : std::max(a.x, b.x);
        else
            x = a.x + (M.y - a.y) / (b.y - a.y) * (b.x - a.x);
        if (x >= M.x - eps && x < bestX) {
            bestX = x;
            hitEdge = i;
        }
    }
    if (hitEdge == n)
        return false;
    const V2 I{bestX, M.y};
    size_t a = hitEdge, b = (hitEdge + 1) % n;
    size_t target;
    if (glm::length(p[size_t(poly[a])] - I) <= eps) {
        target = a;
    } else if (glm::length(p[size_t(poly[b])] - I) <= eps) {
        target = b;
    } else {
        target = p[size_t(poly[a])].x > p[size_t(poly[b])].x ? a : b;
        // A reflex vertex inside triangle (M, I, P) would hide P from M; the
        // one closest in angle to the ray is visible.
        V2 P = p[size_t(poly[target])];
        V2 t0 = M, t1 = I, t2 = P;
        if (cross(t1 - t0, t2 - t0) < 0.0)
            std::swap(t1, t2);
        double bestCos = -2.0, bestDist = 0.0;
        for (size_t i = 0; i < n; ++i) {
            if (i == target)
                continue;
            V2 r = p[size_t(poly[i])];
            V2 prev = p[size_t(poly[(i + n - 1) % n])], next = p[size_t(poly[(i + 1) % n])];
            if (cornerHeight(prev, r, next) >= 0.0 || !insideOrOn(r, t0, t1, t2, eps))
                continue;
            V2 d = r - M;
            double dist = glm::length(d);
            if (dist <= eps)
                continue;
            double c = d.x / dist;
            if (c > bestCos + 1e-12 || (std::abs(c - bestCos) <= 1e-12 && dist < bestDist)) {
                bestCos = c;
                bestDist = dist;
                target = i;
            }
        }
    }
    Polygon2Loop merged(poly.begin(), poly.begin() + std::ptrdiff_t(target) + 1);
    for (size_t k = 0; k <= hole.size(); ++k)
        merged.push_back(hole[(m + k) % hole.size()]);
    merged.insert(merged.end(), poly.begin() + std::ptrdiff_t(target), poly.end());
    poly = std::move(merged);
    return true;
}

Result<std::vector<Polygon2Loop>> earClip(const std::vector<V2>& p, Polygon2Loop v, double eps)
{
    std::vector<Polygon2Loop> triangles;
    // Two passes per ear: first with vertices on the ear's border blocking it
    // (safe), then only vertices strictly inside (for touching holes).
    size_t start = 0;
    while (v.size() > 3) {
        const size_t n = v.size();
        std::vector<char> reflex(n);
        for (size_t i = 0; i < n; ++i)
            reflex[i] = cornerHeight(p[size_t(v[(i + n - 1) % n])], p[size_t(v[i])], p[size_t(v[(i + 1) % n])]) <= eps;
        size_t ear = n;
        for (int pass = 0; pass < 2 && ear == n; ++pass) {
            for (size_t k = 0; k < n && ear == n; ++k) {
                size_t i = (start + k) % n;
                if (reflex[i])
                    continue;
                size_t ia = (i + n - 1) % n, ic = (i + 1) % n;
                V2 a = p[size_t(v[ia])], b = p[size_t(v[i])], c = p[size_t(v[ic])];
                bool blocked = false;
                for (size_t j = 0; j < n && !blocked; ++j) {
                    if (j == ia || j == i || j == ic || !reflex[j])
                        continue;
                    V2 q = p[size_t(v[j])];
                    if (glm::length(q - a) <= eps || glm::length(q - b) <= eps || glm::length(q - c) <= eps)
                        continue;
                    blocked = pass == 0 ? insideOrOn(q, a, b, c, eps) : strictlyInside(q, a, b, c, eps);
                }
                if (!blocked)
                    ear = i;
            }
        }
        if (ear == n)
            return makeError(
                "the cut outline could not be split into convex faces "
                "(it is self-intersecting or degenerate)");
        triangles.push_back({v[(ear + n - 1) % n], v[ear], v[(ear + 1) % n]});
        v.erase(v.begin() + std::ptrdiff_t(ear));
        start = ear == 0 ? 0 : ear - 1;
    }
    triangles.push_back(v);
    return triangles;
}

bool isConvexLoop(const std::vector<V2>& p, const Polygon2Loop& loop, double eps)
{
    const size_t n = loop.size();
    for (size_t i = 0; i < n; ++i)
        if (cornerHeight(p[size_t(loop[(i + n - 1) % n])], p[size_t(loop[i])], p[size_t(loop[(i + 1) % n])]) < -eps)
            return false;
    return true;
}

// The union of P (holding a -> b) and Q (holding b -> a) across that edge.
Polygon2Loop mergeAcross(const Polygon2Loop& P, const Polygon2Loop& Q, int a, int b)
{
    auto rotateToStartAfter = [](const Polygon2Loop& loop, int from, int to) {
        // Starts the loop at `to` where the edge from -> to occurs.
        const size_t n = loop.size();
        for (size_t i = 0; i < n; ++i)
            if (loop[i] == from && loop[(i + 1) % n] == to) {
                Polygon2Loop out;
                for (size_t k = 1; k <= n; ++k)
                    out.push_back(loop[(i + k) % n]);
                return out;
            }
        return Polygon2Loop{};
    };
    Polygon2Loop p = rotateToStartAfter(P, a, b); // b ... a
    Polygon2Loop q = rotateToStartAfter(Q, b, a); // a ... b
    p.insert(p.end(), q.begin() + 1, q.end() - 1);
    return p;
}

// Hertel-Mehlhorn: drop every diagonal whose removal keeps the union convex.
std::vector<Polygon2Loop> mergeConvex(const std::vector<V2>& p, std::vector<Polygon2Loop> pieces, double eps)
{
    std::unordered_map<std::uint64_t, int> owner;
    for (int k = 0; k < int(pieces.size()); ++k)
        for (size_t i = 0; i < pieces[size_t(k)].size(); ++i)
            owner[edgeKey(pieces[size_t(k)][i], pieces[size_t(k)][(i + 1) % pieces[size_t(k)].size()])] = k;
    std::vector<char> alive(pieces.size(), 1);
    for (int k = 0; k < int(pieces.size()); ++k) {
        bool merged = true;
        while (merged && alive[size_t(k)]) {
            merged = false;
            const Polygon2Loop& piece = pieces[size_t(k)];
            for (size_t i = 0; i < piece.size() && !merged; ++i) {
                int a = piece[i], b = piece[(i + 1) % piece.size()];
                auto twin = owner.find(edgeKey(b, a));
                if (twin == owner.end() || twin->second == k || !alive[size_t(twin->second)])
                    continue;
                int other = twin->second;
                Polygon2Loop candidate = mergeAcross(piece, pieces[size_t(other)], a, b);
                if (candidate.size() < 3 || !isConvexLoop(p, candidate, eps))
                    continue;
                owner.erase(edgeKey(a, b));
                owner.erase(edgeKey(b, a));
                for (size_t j = 0; j < pieces[size_t(other)].size(); ++j) {
                    const Polygon2Loop& o = pieces[size_t(other)];
                    auto it = owner.find(edgeKey(o[j], o[(j + 1) % o.size()]));
                    if (it != owner.end() && it->second == other)
                        it->second = k;
                }
                alive[size_t(other)] = 0;
                pieces[size_t(k)] = std::move(candidate);
                merged = true;
            }
        }
    }
    std::vector<Polygon2Loop> out;
    for (size_t k = 0; k < pieces.size(); ++k)
        if (alive[k])
            out.push_back(std::move(pieces[k]));
    return out;
}

} // namespace

double signedArea2(const std::vector<glm::dvec2>& points, const Polygon2Loop& loop)
{
    double area = 0.0;
    for (size_t i = 0; i < loop.size(); ++i)
        area += cross(points[size_t(loop[i])], points[size_t(loop[(i + 1) % loop.size()])]);
    return area;
}

Result<std::vector<Polygon2Loop>> convexDecomposition(const std::vector<glm::dvec2>& points, const Polygon2Loop& outer,
                                                      const std::vector<Polygon2Loop>& holes, double eps)
{
    if (signedArea2(points, outer) <= eps * eps)
        return makeError("the cut outline is degenerate (it has no area) or runs clockwise");
    std::vector<std::vector<Kept>> rings;
    rings.push_back(dropCollinear(points, outer, eps));
    for (const Polygon2Loop& hole : holes)
        rings.push_back(dropCollinear(points, hole, eps));
    for (const auto& ring : rings)
        if (ring.size() < 3)
            return makeError("the cut outline is degenerate (it has no area)");

    if (holes.empty() && isConvexLoop(points, ids(rings[0]), eps)) {
        // The common case (any cut of a convex part): one piece, exactly the loop.
        return std::vector<Polygon2Loop>{outer};
    }

    Polygon2Loop poly = ids(rings[0]);
    // Rightmost hole first, so later bridges never cross earlier ones.
    std::vector<size_t> order;
    for (size_t h = 1; h < rings.size(); ++h)
        order.push_back(h);
    auto maxX = [&](size_t h) {
        double x = -std::numeric_limits<double>::infinity();
        for (const Kept& k : rings[h])
            x = std::max(x, points[size_t(k.id)].x);
        return x;
    };
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return maxX(a) > maxX(b); });
    for (size_t h : order)
        if (!bridgeHole(points, poly, ids(rings[h]), eps))
            return makeError("a hole of the cut outline lies outside it");

    auto triangles = earClip(points, std::move(poly), eps);
    if (!triangles)
        return triangles.error();
    std::vector<Polygon2Loop> pieces = mergeConvex(points, std::move(*triangles), eps);

    // Put the collinear vertices back on the piece edge they lie on.
    std::unordered_map<std::uint64_t, size_t> pieceWithEdge;
    for (size_t k = 0; k < pieces.size(); ++k)
        for (size_t i = 0; i < pieces[k].size(); ++i)
            pieceWithEdge[edgeKey(pieces[k][i], pieces[k][(i + 1) % pieces[k].size()])] = k;
    for (const auto& ring : rings)
        for (size_t r = 0; r < ring.size(); ++r) {
            if (ring[r].after.empty())
                continue;
            int from = ring[r].id, to = ring[(r + 1) % ring.size()].id;
            auto it = pieceWithEdge.find(edgeKey(from, to));
            if (it == pieceWithEdge.end())
                return makeError("the cut outline could not be split into convex faces");
            // Earlier insertions may have shifted positions: find the edge again.
            Polygon2Loop& piece = pieces[it->second];
            size_t at = 0;
            while (at < piece.size() && !(piece[at] == from && piece[(at + 1) % piece.size()] == to))
                ++at;
            piece.insert(piece.begin() + std::ptrdiff_t(at) + 1, ring[r].after.begin(), ring[r].after.end());
        }
    return pieces;
}

} // namespace regio::model
