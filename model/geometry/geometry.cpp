#include "model/geometry/geometry.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <tuple>

namespace regio::model {

double Plane::signedDistance(const Vec3& p) const { return glm::dot(normal, p) + d; }

Plane Plane::fromPointNormal(const Vec3& point, const Vec3& normal)
{
    Vec3 n = glm::normalize(normal);
    return Plane{n, -glm::dot(n, point)};
}

void Box3::extend(const Vec3& p)
{
    if (empty) {
        min = max = p;
        empty = false;
        return;
    }
    min = glm::min(min, p);
    max = glm::max(max, p);
}

void Box3::extend(const Box3& other)
{
    if (other.empty)
        return;
    extend(other.min);
    extend(other.max);
}

bool Box3::overlapsInterior(const Box3& other, double eps) const
{
    if (empty || other.empty)
        return false;
    for (int a = 0; a < 3; ++a)
        if (max[a] <= other.min[a] + eps || other.max[a] <= min[a] + eps)
            return false;
    return true;
}

bool Box3::contains(const Vec3& p, double eps) const
{
    if (empty)
        return false;
    for (int a = 0; a < 3; ++a)
        if (p[a] < min[a] - eps || p[a] > max[a] + eps)
            return false;
    return true;
}

Vec3 newellNormal(std::span<const Vec3> loop)
{
    Vec3 n{0.0};
    const size_t count = loop.size();
    for (size_t i = 0; i < count; ++i) {
        const Vec3& a = loop[i];
        const Vec3& b = loop[(i + 1) % count];
        n.x += (a.y - b.y) * (a.z + b.z);
        n.y += (a.z - b.z) * (a.x + b.x);
        n.z += (a.x - b.x) * (a.y + b.y);
    }
    return n;
}

double polygonArea(std::span<const Vec3> loop) { return 0.5 * glm::length(newellNormal(loop)); }

Vec3 polygonNormal(std::span<const Vec3> loop)
{
    Vec3 n = newellNormal(loop);
    double len = glm::length(n);
    return len > kAreaEpsilon ? n / len : Vec3{0.0};
}

void startAtLeastCorner(std::vector<int>& loop, std::span<const Vec3> positions)
{
    const auto least = std::min_element(loop.begin(), loop.end(), [&](int a, int b) {
        const Vec3 &p = positions[std::size_t(a)], &q = positions[std::size_t(b)];
        return std::tie(p.x, p.y, p.z) < std::tie(q.x, q.y, q.z);
    });
    std::rotate(loop.begin(), least, loop.end());
}

Vec3 polygonCentroid(std::span<const Vec3> loop)
{
    // Area-weighted centroid of the fan triangles; falls back to the vertex
    // mean for degenerate loops.
    if (loop.empty())
        return Vec3{0.0};
    Vec3 normal = polygonNormal(loop);
    Vec3 sum{0.0};
    double total = 0.0;
    for (size_t i = 1; i + 1 < loop.size(); ++i) {
        double w = glm::dot(glm::cross(loop[i] - loop[0], loop[i + 1] - loop[0]), normal);
        sum += w * (loop[0] + loop[i] + loop[i + 1]) / 3.0;
        total += w;
    }
    if (std::abs(total) > kAreaEpsilon)
        return sum / total;
    Vec3 mean{0.0};
    for (const Vec3& p : loop)
        mean += p;
    return mean / double(loop.size());
}

Plane polygonPlane(std::span<const Vec3> loop)
{
    Vec3 n = polygonNormal(loop);
    if (n == Vec3{0.0})
        return Plane{Vec3{0.0}, 0.0};
    Vec3 mean{0.0};
    for (const Vec3& p : loop)
        mean += p;
    mean /= double(loop.size());
    return Plane{n, -glm::dot(n, mean)};
}

double planarityDeviation(std::span<const Vec3> loop)
{
    Plane plane = polygonPlane(loop);
    double worst = 0.0;
    for (const Vec3& p : loop)
        worst = std::max(worst, std::abs(plane.signedDistance(p)));
    return worst;
}

bool isConvex(std::span<const Vec3> loop, const Vec3& normal, double eps)
{
    const size_t count = loop.size();
    if (count < 3)
        return false;
    for (size_t i = 0; i < count; ++i) {
        const Vec3& a = loop[(i + count - 1) % count];
        const Vec3& b = loop[i];
        const Vec3& c = loop[(i + 1) % count];
        Vec3 e0 = b - a;
        Vec3 e1 = c - b;
        // Turn measured as a distance: |e0 x e1| / |e0| is how far c leaves
        // the line through a, b; negative means a right turn (reflex corner).
        double len = glm::length(e0);
        if (len < eps)
            continue;
        double turn = glm::dot(glm::cross(e0, e1), normal) / len;
        if (turn < -eps)
            return false;
    }
    // A star or a loop winding twice passes the per-corner test: its exterior
    // angles add up to a multiple of 2 pi greater than one.
    double turning = 0.0;
    for (size_t i = 0; i < count; ++i) {
        Vec3 e0 = loop[i] - loop[(i + count - 1) % count];
        Vec3 e1 = loop[(i + 1) % count] - loop[i];
        if (glm::length(e0) < eps || glm::length(e1) < eps)
            continue;
        turning += std::atan2(glm::dot(glm::cross(e0, e1), normal), glm::dot(e0, e1));
    }
    return std::abs(turning - 2.0 * std::numbers::pi) < 1e-6;
}

double shortestEdge(std::span<const Vec3> loop)
{
    double shortest = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < loop.size(); ++i)
        shortest = std::min(shortest, glm::length(loop[(i + 1) % loop.size()] - loop[i]));
    return shortest;
}

Side classifyPolygon(std::span<const Vec3> loop, const Plane& plane, double eps)
{
    bool front = false;
    bool back = false;
    for (const Vec3& p : loop) {
        double s = plane.signedDistance(p);
        front |= s > eps;
        back |= s < -eps;
    }
    if (front && back)
        return Side::Spanning;
    if (front)
        return Side::Front;
    if (back)
        return Side::Back;
    return Side::On;
}

void splitPolygon(std::span<const Vec3> loop, const Plane& plane, std::vector<Vec3>& front, std::vector<Vec3>& back,
                  double eps)
{
    front.clear();
    back.clear();
    const size_t count = loop.size();
    for (size_t i = 0; i < count; ++i) {
        const Vec3& a = loop[i];
        const Vec3& b = loop[(i + 1) % count];
        double sa = plane.signedDistance(a);
        double sb = plane.signedDistance(b);
        if (sa >= -eps)
            front.push_back(a);
        if (sa <= eps)
            back.push_back(a);
        if ((sa > eps && sb < -eps) || (sa < -eps && sb > eps)) {
            Vec3 p = a + (b - a) * (sa / (sa - sb));
            front.push_back(p);
            back.push_back(p);
        }
    }
    if (front.size() < 3)
        front.clear();
    if (back.size() < 3)
        back.clear();
}

std::vector<Vec3> loopPositions(std::span<const Vec3> vertices, std::span<const int> loop)
{
    std::vector<Vec3> positions;
    positions.reserve(loop.size());
    for (int index : loop)
        positions.push_back(vertices[size_t(index)]);
    return positions;
}

} // namespace regio::model
