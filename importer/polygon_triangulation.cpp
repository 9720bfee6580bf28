#include "importer/polygon_triangulation.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace regio::importer {

namespace {

using model::Vec3;

struct Point2 {
    double x;
    double y;
};

double cross(Point2 o, Point2 a, Point2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

std::vector<std::array<int, 3>> fan(int n)
{
    std::vector<std::array<int, 3>> out;
    for (int i = 1; i + 1 < n; ++i)
        out.push_back({0, i, i + 1});
    return out;
}

} // namespace

std::vector<std::array<int, 3>> triangulatePolygon(std::span<const Vec3> corners)
{
    const int n = int(corners.size());
    if (n < 3)
        return {};
    if (n == 3)
        return {{0, 1, 2}};
    // Newell's normal: the polygon's area vector, right for concave outlines.
    Vec3 normal{0.0};
    for (int i = 0; i < n; ++i) {
        const Vec3& a = corners[std::size_t(i)];
        const Vec3& b = corners[std::size_t((i + 1) % n)];
        normal += Vec3{(a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y)};
    }
    if (!(glm::length(normal) > 0.0) || !std::isfinite(glm::length(normal)))
        return {};
    if (n > kMaxClippedCorners)
        return fan(n);
    // Drop the normal's largest axis: the projection keeps the polygon's
    // shape and, with the sign below, its turning direction.
    const Vec3 m = glm::abs(normal);
    const int drop = m.x >= m.y && m.x >= m.z ? 0 : (m.y >= m.z ? 1 : 2);
    const double sign = normal[drop] >= 0.0 ? 1.0 : -1.0;
    std::vector<Point2> p(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
        const Vec3& c = corners[std::size_t(i)];
        const int u = (drop + 1) % 3;
        const int v = (drop + 2) % 3;
        p[std::size_t(i)] = {c[u], c[v] * sign}; // counter-clockwise in (u, v) now
    }

    std::vector<int> left(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i)
        left[std::size_t(i)] = i;
    std::vector<std::array<int, 3>> out;
    const auto isEar = [&](std::size_t k) {
        const std::size_t count = left.size();
        const int a = left[(k + count - 1) % count];
        const int b = left[k];
        const int c = left[(k + 1) % count];
        const Point2 pa = p[std::size_t(a)], pb = p[std::size_t(b)], pc = p[std::size_t(c)];
        if (cross(pa, pb, pc) <= 0.0)
            return false; // a reflex or flat corner
        for (const int o : left) {
            if (o == a || o == b || o == c)
                continue;
            const Point2 q = p[std::size_t(o)];
            const auto same = [&](Point2 r) { return q.x == r.x && q.y == r.y; };
            if (same(pa) || same(pb) || same(pc))
                continue; // a repeated corner touches the ear, never cuts it
            if (cross(pa, pb, q) >= 0.0 && cross(pb, pc, q) >= 0.0 && cross(pc, pa, q) >= 0.0)
                return false; // another corner inside (or on) the ear
        }
        return true;
    };
    std::size_t cursor = 0; // the search goes on after the last ear: a convex outline costs n^2, not n^3
    while (left.size() > 3) {
        bool clipped = false;
        for (std::size_t step = 0; step < left.size(); ++step) {
            const std::size_t k = (cursor + step) % left.size();
            if (!isEar(k))
                continue;
            const std::size_t count = left.size();
            out.push_back({left[(k + count - 1) % count], left[k], left[(k + 1) % count]});
            left.erase(left.begin() + std::ptrdiff_t(k));
            cursor = k % left.size();
            clipped = true;
            break;
        }
        if (!clipped) {
            // Only flat corners left (collinear runs) have no area to lose;
            // anything else is an outline that crosses itself.
            bool flat = true;
            for (std::size_t k = 0; k < left.size() && flat; ++k) {
                const std::size_t count = left.size();
                flat = std::abs(cross(p[std::size_t(left[(k + count - 1) % count])], p[std::size_t(left[k])],
                                      p[std::size_t(left[(k + 1) % count])])) == 0.0;
            }
            return flat ? out : fan(n);
        }
    }
    const double last = cross(p[std::size_t(left[0])], p[std::size_t(left[1])], p[std::size_t(left[2])]);
    if (last < 0.0)
        return fan(n); // the last three turn backwards: the outline crosses itself
    if (last > 0.0)
        out.push_back({left[0], left[1], left[2]});
    return out;
}

} // namespace regio::importer
