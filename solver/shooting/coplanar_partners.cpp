#include "solver/shooting/coplanar_partners.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <optional>
#include <utility>

namespace regio::solver {

namespace {

// Faces that may be partners share this key: the plane (normal to 1e-6, offset
// to 1e-5 m) and the material exactly. Two faces of one plane whose normals
// were computed from different corners can round apart at a cell border; they
// then simply do not grade each other, as before.
using BucketKey = std::array<long long, 10>;

BucketKey bucketKey(const Properties& p)
{
    const auto q = [](double x, double scale) { return static_cast<long long>(std::llround(x * scale)); };
    // The material's values are compared exactly: their bits.
    const auto bits = [](double x) {
        long long b = 0;
        static_assert(sizeof(b) == sizeof(x));
        std::memcpy(&b, &x, sizeof(b));
        return b;
    };
    return {q(p.plane.normal.x, 1e6), q(p.plane.normal.y, 1e6), q(p.plane.normal.z, 1e6), q(p.plane.d, 1e5),
            bits(p.reflectance.x),    bits(p.reflectance.y),    bits(p.reflectance.z),    bits(p.emission.x),
            bits(p.emission.y),       bits(p.emission.z)};
}

struct Extent {
    int face = -1;
    model::Box3 box; // swept along x; faces whose boxes do not touch are passed over
};

// The boxes meet or touch (within the distance tolerance).
bool touch(const model::Box3& a, const model::Box3& b)
{
    for (int axis = 0; axis < 3; ++axis)
        if (a.min[axis] > b.max[axis] + model::kDistanceEpsilon || b.min[axis] > a.max[axis] + model::kDistanceEpsilon)
            return false;
    return true;
}

// Where segment cd lies along segment ab when both lie on one line: the
// common part as distances from a towards b (empty when they are not on one
// line or share no more than a point).
std::optional<std::pair<double, double>> commonPart(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d)
{
    const Vec3 ab = b - a;
    const double length = glm::length(ab);
    if (length <= model::kDistanceEpsilon)
        return std::nullopt;
    const Vec3 u = ab / length;
    const auto offLine = [&](const Vec3& p) { return glm::length(glm::cross(p - a, u)); };
    if (offLine(c) > model::kDistanceEpsilon || offLine(d) > model::kDistanceEpsilon)
        return std::nullopt;
    const double tc = glm::dot(c - a, u), td = glm::dot(d - a, u);
    const double lo = std::max(0.0, std::min(tc, td)), hi = std::min(length, std::max(tc, td));
    if (hi - lo <= model::kDistanceEpsilon)
        return std::nullopt;
    return std::pair{lo, hi};
}

} // namespace

double collinearOverlap(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d)
{
    const auto part = commonPart(a, b, c, d);
    return part ? part->second - part->first : 0.0;
}

std::vector<std::vector<SharedOutline>> sharedOutlines(const PreparedScene& scene)
{
    std::vector<std::vector<SharedOutline>> shared(scene.faces.size());
    std::map<BucketKey, std::vector<Extent>> buckets;
    for (size_t f = 0; f < scene.faces.size(); ++f) {
        const InputFace& face = scene.faces[f];
        if (face.polygon.size() < 3 || face.elements.empty())
            continue;
        Extent e{int(f), {}};
        for (const Vec3& p : face.polygon)
            e.box.extend(p);
        buckets[bucketKey(scene.properties[f])].push_back(e);
    }
    for (auto& [key, faces] : buckets) {
        // Sweep along x: only faces whose x ranges meet can touch.
        std::sort(faces.begin(), faces.end(),
                  [](const Extent& x, const Extent& y) { return x.box.min.x < y.box.min.x; });
        for (size_t i = 0; i < faces.size(); ++i) {
            const std::vector<Vec3>& p = scene.faces[size_t(faces[i].face)].polygon;
            for (size_t j = i + 1;
                 j < faces.size() && faces[j].box.min.x <= faces[i].box.max.x + model::kDistanceEpsilon; ++j) {
                if (!touch(faces[i].box, faces[j].box))
                    continue;
                const std::vector<Vec3>& q = scene.faces[size_t(faces[j].face)].polygon;
                for (size_t k = 0; k < p.size(); ++k) {
                    const Vec3& a = p[k];
                    const Vec3& b = p[(k + 1) % p.size()];
                    const Vec3 u = glm::normalize(b - a);
                    for (size_t l = 0; l < q.size(); ++l) {
                        const auto part = commonPart(a, b, q[l], q[(l + 1) % q.size()]);
                        if (!part)
                            continue;
                        const Vec3 from = a + u * part->first, to = a + u * part->second;
                        shared[size_t(faces[i].face)].push_back({faces[j].face, from, to});
                        shared[size_t(faces[j].face)].push_back({faces[i].face, to, from});
                    }
                }
            }
        }
    }
    return shared;
}

} // namespace regio::solver
