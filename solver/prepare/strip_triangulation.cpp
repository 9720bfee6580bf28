#include "solver/prepare/strip_triangulation.h"

#include "solver/prepare/divisions.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace regio::solver {

namespace {

double minAngle2D(const Vec2& a, const Vec2& b, const Vec2& c)
{
    auto angle = [](const Vec2& p, const Vec2& q, const Vec2& r) {
        Vec2 u = q - p, v = r - p;
        double lu = glm::length(u), lv = glm::length(v);
        if (lu <= 0.0 || lv <= 0.0)
            return 0.0;
        return std::acos(std::clamp(glm::dot(u, v) / (lu * lv), -1.0, 1.0));
    };
    return std::min({angle(a, b, c), angle(b, c, a), angle(c, a, b)});
}

// How close (in strip heights) a cut may pass by a corner before it snaps to it.
constexpr double kSnap = 0.5;
// How far (in strip heights) one end of a cut may move onto a corner of its side.
constexpr double kSideSnap = 0.25;

double cross2(const Vec2& a, const Vec2& b, const Vec2& c)
{
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

class StripBuilder {
public:
    StripBuilder(std::span<const Vec2> polygon, double patchSize)
        : m_patchSize(patchSize)
    {
        m_mesh.points.assign(polygon.begin(), polygon.end());
        double extent = 0.0;
        for (const Vec2& p : polygon)
            extent = std::max({extent, std::abs(p.x), std::abs(p.y)});
        // Relative tolerance: coordinates are metres at room scale.
        m_eps = 1e-9 * std::max(1.0, extent);
        m_areaEps = m_eps * m_eps;
    }

    StripMesh2D run()
    {
        const int n = int(m_mesh.points.size());
        if (n < 3 || !(m_patchSize > 0.0))
            return std::move(m_mesh);
        const auto& pts = m_mesh.points;
        double ymin = pts[0].y, ymax = pts[0].y;
        for (const Vec2& p : pts) {
            ymin = std::min(ymin, p.y);
            ymax = std::max(ymax, p.y);
        }
        const double height = ymax - ymin;
        if (height <= m_eps)
            return std::move(m_mesh);

        // Corners: the ends of the bottom and top (an edge or a single vertex).
        int bottomLeft = -1, bottomRight = -1, topLeft = -1, topRight = -1;
        for (int i = 0; i < n; ++i) {
            if (pts[size_t(i)].y <= ymin + m_eps) {
                if (bottomLeft < 0 || pts[size_t(i)].x < pts[size_t(bottomLeft)].x)
                    bottomLeft = i;
                if (bottomRight < 0 || pts[size_t(i)].x > pts[size_t(bottomRight)].x)
                    bottomRight = i;
            }
            if (pts[size_t(i)].y >= ymax - m_eps) {
                if (topLeft < 0 || pts[size_t(i)].x < pts[size_t(topLeft)].x)
                    topLeft = i;
                if (topRight < 0 || pts[size_t(i)].x > pts[size_t(topRight)].x)
                    topRight = i;
            }
        }
        // Both side chains run upwards: right = bottomRight .. topRight (CCW),
        // left = bottomLeft .. topLeft (clockwise).
        std::vector<int> right, left;
        for (int i = bottomRight;; i = (i + 1) % n) {
            right.push_back(i);
            if (i == topRight)
                break;
        }
        for (int i = bottomLeft;; i = (i + n - 1) % n) {
            left.push_back(i);
            if (i == topLeft)
                break;
        }

        // As many strips as the patch size asks for.
        const int strips = divisionsOf(height, m_patchSize);
        std::vector<double> cutY(size_t(strips) + 1);
        std::vector<std::vector<int>> cuts(size_t(strips) + 1);
        for (int j = 0; j <= strips; ++j) {
            if (j == 0 || j == strips) {
                cutY[size_t(j)] = j == 0 ? ymin : ymax;
            } else {
                // Equal strips over what is left; but a cut passing just beside
                // a corner would leave a tiny piece of side, and every triangle
                // on it would be a sliver, so the cut moves onto the nearest
                // corner within half a strip. Strips stay between half and one
                // and a half of the nominal height.
                const double previous = cutY[size_t(j - 1)];
                const double step = (ymax - previous) / double(strips - j + 1);
                double cut = previous + step;
                double nearest = kSnap * step;
                for (int i = 0; i < n; ++i) {
                    const double y = pts[size_t(i)].y;
                    if (y > previous + m_eps && y < ymax - m_eps && std::abs(y - (previous + step)) < nearest) {
                        nearest = std::abs(y - (previous + step));
                        cut = y;
                    }
                }
                cutY[size_t(j)] = cut;
            }
            // Each end of the cut may still move onto a corner of its own side
            // (by a quarter strip): the cut then tilts a little, which keeps
            // the strips convex and spares a sliver on the other side.
            const double sideSnap = j > 0 && j < strips ? kSideSnap * (ymax - ymin) / double(strips) : 0.0;
            int l = j == 0 ? bottomLeft : j == strips ? topLeft : crossing(left, cutY[size_t(j)], sideSnap);
            int r = j == 0 ? bottomRight : j == strips ? topRight : crossing(right, cutY[size_t(j)], sideSnap);
            cuts[size_t(j)] = divide(l, r, true);
        }

        for (int j = 0; j < strips; ++j) {
            const std::vector<int>& bottom = cuts[size_t(j)];
            const std::vector<int>& top = cuts[size_t(j + 1)];
            std::vector<int> loop(bottom.begin(), bottom.end());
            appendSide(right, bottom.back(), top.back(), false, loop);
            loop.insert(loop.end(), top.rbegin(), top.rend());
            appendSide(left, top.front(), bottom.front(), true, loop);
            // A single-point bottom or top appears at both ends of a side.
            std::vector<int> strip;
            for (int index : loop)
                if (strip.empty() || strip.back() != index)
                    strip.push_back(index);
            while (strip.size() > 1 && strip.front() == strip.back())
                strip.pop_back();
            if (strip.size() >= 3)
                triangulateStrip(strip);
        }
        return std::move(m_mesh);
    }

private:
    // Where the upward chain crosses height y: its corner nearest to y when
    // within `snap` (or eps), else a new point on the chain edge that spans y.
    int crossing(const std::vector<int>& chain, double y, double snap)
    {
        int nearest = -1;
        for (int index : chain) {
            const double distance = std::abs(m_mesh.points[size_t(index)].y - y);
            if (distance <= std::max(snap, m_eps) &&
                (nearest < 0 || distance < std::abs(m_mesh.points[size_t(nearest)].y - y)))
                nearest = index;
        }
        if (nearest >= 0)
            return nearest;
        for (size_t i = 0; i + 1 < chain.size(); ++i) {
            const Vec2 a = m_mesh.points[size_t(chain[i])];
            const Vec2 b = m_mesh.points[size_t(chain[i + 1])];
            if ((a.y < y && y < b.y) || (b.y < y && y < a.y)) {
                double t = (y - a.y) / (b.y - a.y);
                return addPoint(Vec2{a.x + (b.x - a.x) * t, y});
            }
        }
        // Unreachable for a convex polygon spanning y; keep the nearest corner.
        int best = chain.front();
        for (int index : chain)
            if (std::abs(m_mesh.points[size_t(index)].y - y) < std::abs(m_mesh.points[size_t(best)].y - y))
                best = index;
        return best;
    }

    int addPoint(const Vec2& p)
    {
        m_mesh.points.push_back(p);
        return int(m_mesh.points.size()) - 1;
    }

    // The points from a to b with the segment divided into pieces no longer
    // than the patch size; a == b gives the single point.
    std::vector<int> divide(int a, int b, bool includeEnds)
    {
        std::vector<int> out;
        if (includeEnds)
            out.push_back(a);
        if (a == b)
            return out;
        const Vec2 pa = m_mesh.points[size_t(a)], pb = m_mesh.points[size_t(b)];
        const int pieces = divisionsOf(glm::length(pb - pa), m_patchSize);
        for (int i = 1; i < pieces; ++i)
            out.push_back(addPoint(pa + (pb - pa) * (double(i) / double(pieces))));
        if (includeEnds)
            out.push_back(b);
        return out;
    }

    // Appends the side of a strip strictly between its cut points `from` and
    // `to`: the chain's corners between them and the division points of the
    // side's pieces. `downwards` walks the (upward) chain backwards.
    void appendSide(const std::vector<int>& chain, int from, int to, bool downwards, std::vector<int>& loop)
    {
        const double y0 = std::min(m_mesh.points[size_t(from)].y, m_mesh.points[size_t(to)].y);
        const double y1 = std::max(m_mesh.points[size_t(from)].y, m_mesh.points[size_t(to)].y);
        std::vector<int> inside;
        for (int index : chain) {
            double y = m_mesh.points[size_t(index)].y;
            if (index != from && index != to && y > y0 + m_eps && y < y1 - m_eps)
                inside.push_back(index);
        }
        if (downwards)
            std::reverse(inside.begin(), inside.end());
        int previous = from;
        for (int index : inside) {
            std::vector<int> between = divide(previous, index, false);
            loop.insert(loop.end(), between.begin(), between.end());
            loop.push_back(index);
            previous = index;
        }
        std::vector<int> between = divide(previous, to, false);
        loop.insert(loop.end(), between.begin(), between.end());
    }

    // Lengthwise zig-zag ("L direction") between the lower and upper chains of
    // a convex strip, from its leftmost to its rightmost corner; the first and
    // last triangles close the two ends.
    void triangulateStrip(const std::vector<int>& strip)
    {
        const auto& pts = m_mesh.points;
        const int n = int(strip.size());
        if (n == 3) {
            emit(strip[0], strip[1], strip[2]);
            return;
        }
        auto lessLeft = [&](int i, int j) {
            const Vec2 &p = pts[size_t(strip[size_t(i)])], &q = pts[size_t(strip[size_t(j)])];
            if (std::abs(p.x - q.x) > m_eps)
                return p.x < q.x;
            return p.y < q.y;
        };
        int s = 0, e = 0;
        for (int i = 1; i < n; ++i) {
            if (lessLeft(i, s))
                s = i;
            if (lessLeft(e, i))
                e = i;
        }
        std::vector<int> lo, up;
        for (int i = s;; i = (i + 1) % n) {
            lo.push_back(strip[size_t(i)]);
            if (i == e)
                break;
        }
        for (int i = s;; i = (i + n - 1) % n) {
            up.push_back(strip[size_t(i)]);
            if (i == e)
                break;
        }
        const int A = int(lo.size()) - 1, B = int(up.size()) - 1;
        emit(lo[0], lo[1], up[1]);
        // Dynamic programming over the rungs (a, b) = (lo[a], up[b]): the
        // zig-zag whose worst triangle is best (ties: the larger sum of the
        // triangles' smallest angles). A chain may step onto the far end e only
        // when the other is one step before it, so both finish together.
        const int width = B + 1;
        struct Cell {
            double worst = -1.0; // -1 = unreachable
            double sum = 0.0;
            bool fromLo = false;
        };
        std::vector<Cell> table(size_t((A + 1) * width));
        auto cell = [&](int a, int b) -> Cell& { return table[size_t(a * width + b)]; };
        cell(1, 1) = Cell{std::numeric_limits<double>::infinity(), 0.0, false};
        auto done = [&](int a, int b) { return (a == A && b == B - 1) || (a == A - 1 && b == B); };
        auto offer = [&](int a, int b, double worst, double sum, bool fromLo) {
            Cell& c = cell(a, b);
            if (worst > c.worst + 1e-12 || (std::abs(worst - c.worst) <= 1e-12 && sum > c.sum))
                c = Cell{worst, sum, fromLo};
        };
        for (int diagonal = 2; diagonal <= A + B; ++diagonal)
            for (int a = std::max(1, diagonal - B); a <= std::min(A, diagonal - 1); ++a) {
                const int b = diagonal - a;
                const Cell here = cell(a, b);
                if (here.worst < 0.0 || done(a, b))
                    continue;
                if (a < A && (a + 1 < A || b == B - 1)) {
                    double q = quality(lo[size_t(a)], lo[size_t(a + 1)], up[size_t(b)]);
                    offer(a + 1, b, std::min(here.worst, q), here.sum + q, true);
                }
                if (b < B && (b + 1 < B || a == A - 1)) {
                    double q = quality(lo[size_t(a)], up[size_t(b + 1)], up[size_t(b)]);
                    offer(a, b + 1, std::min(here.worst, q), here.sum + q, false);
                }
            }
        int a = A, b = B - 1;
        if (A >= 1 && B >= 1 && cell(A - 1, B).worst > cell(A, B - 1).worst) {
            a = A - 1;
            b = B;
        }
        // Walk back from the final rung, then emit in order.
        std::vector<Triangle> path;
        while (!(a == 1 && b == 1)) {
            if (cell(a, b).fromLo) {
                path.push_back({lo[size_t(a - 1)], lo[size_t(a)], up[size_t(b)]});
                --a;
            } else {
                path.push_back({lo[size_t(a)], up[size_t(b)], up[size_t(b - 1)]});
                --b;
            }
        }
        for (auto it = path.rbegin(); it != path.rend(); ++it)
            emit((*it)[0], (*it)[1], (*it)[2]);
    }

    double quality(int a, int b, int c) const
    {
        const auto& pts = m_mesh.points;
        if (cross2(pts[size_t(a)], pts[size_t(b)], pts[size_t(c)]) <= m_areaEps)
            return 0.0;
        return minAngle2D(pts[size_t(a)], pts[size_t(b)], pts[size_t(c)]);
    }

    void emit(int a, int b, int c)
    {
        // Zero-area triangles add nothing to the cover; leave them out.
        if (cross2(m_mesh.points[size_t(a)], m_mesh.points[size_t(b)], m_mesh.points[size_t(c)]) > m_areaEps)
            m_mesh.triangles.push_back({a, b, c});
    }

    StripMesh2D m_mesh;
    double m_patchSize;
    double m_eps = 1e-9;
    double m_areaEps = 1e-18;
};

} // namespace

StripMesh2D stripTriangulate2D(std::span<const Vec2> polygon, double patchSize)
{
    return StripBuilder(polygon, patchSize).run();
}

StripMesh stripTriangulate(std::span<const model::Vec3> loop, const model::Vec3& normal, double patchSize)
{
    StripMesh out;
    const size_t n = loop.size();
    if (n < 3)
        return out;
    // The frame: origin at the start of the longest edge, x along it, so the
    // longest edge is the bottom of the first strip.
    size_t longest = 0;
    double longestLength = -1.0;
    for (size_t i = 0; i < n; ++i) {
        double length = glm::length(loop[(i + 1) % n] - loop[i]);
        if (length > longestLength) {
            longestLength = length;
            longest = i;
        }
    }
    const model::Vec3 origin = loop[longest];
    const model::Vec3 xAxis = glm::normalize(loop[(longest + 1) % n] - origin);
    const model::Vec3 yAxis = glm::normalize(glm::cross(normal, xAxis));
    std::vector<Vec2> flat;
    flat.reserve(n);
    for (const model::Vec3& p : loop)
        flat.push_back(Vec2{glm::dot(p - origin, xAxis), glm::dot(p - origin, yAxis)});
    StripMesh2D mesh = stripTriangulate2D(flat, patchSize);
    out.points.assign(loop.begin(), loop.end());
    for (size_t i = n; i < mesh.points.size(); ++i)
        out.points.push_back(origin + xAxis * mesh.points[i].x + yAxis * mesh.points[i].y);
    out.triangles = std::move(mesh.triangles);
    return out;
}

double minimumAngleDegrees(const model::Vec3& a, const model::Vec3& b, const model::Vec3& c)
{
    auto angle = [](const model::Vec3& p, const model::Vec3& q, const model::Vec3& r) {
        model::Vec3 u = q - p, v = r - p;
        double lu = glm::length(u), lv = glm::length(v);
        if (lu <= 0.0 || lv <= 0.0)
            return 0.0;
        return std::acos(std::clamp(glm::dot(u, v) / (lu * lv), -1.0, 1.0));
    };
    return std::min({angle(a, b, c), angle(b, c, a), angle(c, a, b)}) * 180.0 / std::numbers::pi;
}

} // namespace regio::solver
