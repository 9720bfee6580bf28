#include "solver/shooting/coplanar_partners.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <map>

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
    double lo = 0.0, hi = 0.0; // along x
    int face = -1;
    model::Box3 box; // to pass over faces that cannot touch before their edges are compared
};

// The boxes meet or touch (within the distance tolerance).
bool touch(const model::Box3& a, const model::Box3& b)
{
    for (int axis = 0; axis < 3; ++axis)
        if (a.min[axis] > b.max[axis] + model::kDistanceEpsilon || b.min[axis] > a.max[axis] + model::kDistanceEpsilon)
            return false;
    return true;
}

} // namespace

double collinearOverlap(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d)
{
    const Vec3 ab = b - a;
    const double length = glm::length(ab);
    if (length <= model::kDistanceEpsilon)
        return 0.0;
    const Vec3 u = ab / length;
    const auto offLine = [&](const Vec3& p) { return glm::length(glm::cross(p - a, u)); };
    if (offLine(c) > model::kDistanceEpsilon || offLine(d) > model::kDistanceEpsilon)
        return 0.0;
    const double tc = glm::dot(c - a, u), td = glm::dot(d - a, u);
    const double lo = std::max(0.0, std::min(tc, td)), hi = std::min(length, std::max(tc, td));
    return hi - lo > model::kDistanceEpsilon ? hi - lo : 0.0;
}

std::vector<std::vector<SharedOutline>> sharedOutlines(const PreparedScene& scene)
{
    std::vector<std::vector<SharedOutline>> shared(scene.faces.size());
    std::map<BucketKey, std::vector<Extent>> buckets;
    for (size_t f = 0; f < scene.faces.size(); ++f) {
        const InputFace& face = scene.faces[f];
        if (face.polygon.size() < 3 || face.elements.empty())
            continue;
        Extent e{face.polygon.front().x, face.polygon.front().x, int(f), {}};
        for (const Vec3& p : face.polygon) {
            e.lo = std::min(e.lo, p.x);
            e.hi = std::max(e.hi, p.x);
            e.box.extend(p);
        }
        buckets[bucketKey(scene.properties[f])].push_back(e);
    }
    for (auto& [key, faces] : buckets) {
        // Sweep along x: only faces whose x ranges meet can touch.
        std::sort(faces.begin(), faces.end(), [](const Extent& x, const Extent& y) { return x.lo < y.lo; });
        for (size_t i = 0; i < faces.size(); ++i) {
            const std::vector<Vec3>& p = scene.faces[size_t(faces[i].face)].polygon;
            for (size_t j = i + 1; j < faces.size() && faces[j].lo <= faces[i].hi + model::kDistanceEpsilon; ++j) {
                if (!touch(faces[i].box, faces[j].box))
                    continue;
                const std::vector<Vec3>& q = scene.faces[size_t(faces[j].face)].polygon;
                for (size_t k = 0; k < p.size(); ++k) {
                    const Vec3& a = p[k];
                    const Vec3& b = p[(k + 1) % p.size()];
                    const Vec3 u = glm::normalize(b - a);
                    for (size_t l = 0; l < q.size(); ++l) {
                        const Vec3& c = q[l];
                        const Vec3& d = q[(l + 1) % q.size()];
                        if (collinearOverlap(a, b, c, d) <= 0.0)
                            continue;
                        // The common part, from a towards b.
                        const double length = glm::length(b - a);
                        const double tc = glm::dot(c - a, u), td = glm::dot(d - a, u);
                        const Vec3 from = a + u * std::max(0.0, std::min(tc, td));
                        const Vec3 to = a + u * std::min(length, std::max(tc, td));
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
