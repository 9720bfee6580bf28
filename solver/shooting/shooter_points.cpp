#include "solver/shooting/shooter_points.h"

#include "solver/prepare/face_polygon.h"
#include "solver/prepare/facing_faces.h"
#include "solver/visibility/item_buffer.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <limits>

namespace regio::solver {

namespace {
// Whether x (in the triangle's plane) lies inside the triangle abc, edges included.
bool inside(const Vec3& x, const Vec3& a, const Vec3& b, const Vec3& c)
{
    const Vec3 n = glm::cross(b - a, c - a);
    return glm::dot(glm::cross(b - a, x - a), n) >= 0.0 && glm::dot(glm::cross(c - b, x - b), n) >= 0.0 &&
           glm::dot(glm::cross(a - c, x - c), n) >= 0.0;
}

// The centroids of the k x k equal triangles of triangle abc: in
// barycentric steps of 1/k, the k(k+1)/2 upright ones and the k(k-1)/2
// turned ones between them.
std::vector<Vec3> splitCentroids(const std::array<Vec3, 3>& corners, int k = kShooterSplits)
{
    const Vec3 a = corners[0], ab = (corners[1] - corners[0]) / double(k), ac = (corners[2] - corners[0]) / double(k);
    std::vector<Vec3> points;
    points.reserve(size_t(k * k));
    for (int i = 0; i < k; ++i)
        for (int j = 0; i + j < k; ++j) {
            points.push_back(a + (double(i) + 1.0 / 3.0) * ab + (double(j) + 1.0 / 3.0) * ac);
            if (i + j + 1 < k)
                points.push_back(a + (double(i) + 2.0 / 3.0) * ab + (double(j) + 2.0 / 3.0) * ac);
        }
    return points;
}

// Whether some of the patch's points lie over `polygon`: inside it seen
// along the patch's normal.
bool lieOver(const std::array<Vec3, 3>& corners, const std::vector<Vec3>& polygon)
{
    const Vec3 normal = glm::normalize(glm::cross(corners[1] - corners[0], corners[2] - corners[0]));
    std::vector<Vec3> dropped;
    dropped.reserve(polygon.size());
    for (const Vec3& q : polygon)
        dropped.push_back(q - normal * glm::dot(normal, q - corners[0]));
    const std::vector<Vec3> points = splitCentroids(corners);
    return std::any_of(points.begin(), points.end(), [&](const Vec3& x) {
        return insideConvex(dropped, normal, x, -model::kDistanceEpsilon) ||
               insideConvex(dropped, -normal, x, -model::kDistanceEpsilon);
    });
}

} // namespace

ShooterSite shooterSite(const PreparedScene& scene, int patch)
{
    const Patch& p = scene.patches[static_cast<size_t>(patch)];
    const auto& facing = scene.faces[static_cast<size_t>(p.properties)].facing;
    if (facing.empty())
        return {ShooterKind::Centre, -1};
    const std::array<Vec3, 3> corners{scene.vertices[size_t(p.vertices[0])], scene.vertices[size_t(p.vertices[1])],
                                      scene.vertices[size_t(p.vertices[2])]};
    double longest = 0.0;
    for (int i = 0; i < 3; ++i)
        longest = std::max(longest, glm::distance(corners[size_t(i)], corners[size_t((i + 1) % 3)]));
    ShooterKind kind = ShooterKind::Centre;
    for (int face : facing) {
        const InputFace& f = scene.faces[static_cast<size_t>(face)];
        if (f.polygon.size() < 3)
            continue;
        const double gap = polygonGap(corners, f.polygon);
        // Only a patch over the face is in the gap; one beside it (the
        // ceiling just outside a lamp's outline) sees the room, not a slit.
        if (gap * kGapShooterRatio < longest && lieOver(corners, f.polygon))
            return {ShooterKind::InGap, face};
        // A face that solids cover whole (a shelf board's end against its
        // side) has no elements and hides nothing.
        if (gap < longest && !f.elements.empty() && polygonWidth(f.polygon) * kNarrowFaceWidth < longest)
            kind = ShooterKind::BehindNarrowFace;
    }
    return {kind, -1};
}

ShooterKind shooterKind(const PreparedScene& scene, int patch) { return shooterSite(scene, patch).kind; }

int gapFace(const PreparedScene& scene, int patch) { return shooterSite(scene, patch).gapFace; }

double polygonWidth(std::span<const Vec3> polygon)
{
    double width = std::numeric_limits<double>::max();
    for (size_t i = 0; i < polygon.size(); ++i) {
        const Vec3 edge = polygon[(i + 1) % polygon.size()] - polygon[i];
        const double length = glm::length(edge);
        if (length <= 0.0)
            continue;
        double farthest = 0.0;
        for (const Vec3& q : polygon)
            farthest = std::max(farthest, glm::length(glm::cross(edge, q - polygon[i])) / length);
        width = std::min(width, farthest);
    }
    return polygon.size() < 3 ? 0.0 : width;
}

std::vector<Vec3> shooterPoints(const PreparedScene& scene, int patch)
{
    return shooterPoints(scene, patch, shooterSite(scene, patch));
}

std::vector<Vec3> shooterPoints(const PreparedScene& scene, int patch, const ShooterSite& site)
{
    const Patch& p = scene.patches[static_cast<size_t>(patch)];
    if (site.kind == ShooterKind::Centre)
        return {p.centroid};
    const std::array<Vec3, 3> corners{scene.vertices[size_t(p.vertices[0])], scene.vertices[size_t(p.vertices[1])],
                                      scene.vertices[size_t(p.vertices[2])]};

    if (site.kind == ShooterKind::InGap && !scene.properties[size_t(p.properties)].emits() &&
        !scene.properties[size_t(site.gapFace)].emits())
        return splitCentroids(corners, kDarkGapShooterSplits);
    return splitCentroids(corners);
}

std::vector<double> pointWeights(const PreparedScene& scene, int patch, std::span<const Vec3> points)
{
    const Patch& p = scene.patches[static_cast<size_t>(patch)];
    const size_t m = points.size(), count = static_cast<size_t>(p.elementCount);
    const auto corner = [&](const Element& e, int i) -> const Vec3& {
        return scene.vertices[size_t(e.vertices[size_t(i)])];
    };
    // Each point to the first element that holds it (the elements tile the patch).
    std::vector<int> owner(m, -1);
    std::vector<int> held(count, 0);
    for (size_t q = 0; q < m; ++q)
        for (size_t s = 0; s < count && owner[q] < 0; ++s) {
            const Element& e = scene.elements[size_t(p.firstElement) + s];
            if (inside(points[q], corner(e, 0), corner(e, 1), corner(e, 2))) {
                owner[q] = int(s);
                ++held[s];
            }
        }
    std::vector<double> w(count * m, 0.0);
    for (size_t q = 0; q < m; ++q)
        if (owner[q] >= 0)
            w[size_t(owner[q]) * m + q] = 1.0 / held[size_t(owner[q])];
    for (size_t s = 0; s < count; ++s) {
        if (held[s] > 0)
            continue;
        const Vec3& centroid = scene.elements[size_t(p.firstElement) + s].centroid;
        size_t nearest = 0;
        double best = std::numeric_limits<double>::max();
        for (size_t q = 0; q < m; ++q)
            if (const double d = glm::distance(points[q], centroid); d < best) {
                best = d;
                nearest = q;
            }
        w[s * m + nearest] = 1.0;
    }
    return w;
}

double seenShare(const PreparedScene& scene, std::uint32_t element, std::span<const Vec3> points,
                 std::span<const double> weights, int shooterElement, const std::vector<std::vector<double>>& perPoint)
{
    const Element& receiver = scene.elements[element];
    const Vec3& onPlane = scene.vertices[size_t(receiver.vertices[0])];
    const size_t m = points.size(), item = size_t(element) + kFirstElementItem;
    double seen = 0.0, inFront = 0.0;
    for (size_t q = 0; q < m; ++q) {
        const double w = weights[size_t(shooterElement) * m + q];
        if (w == 0.0 || glm::dot(receiver.normal, points[q] - onPlane) <= 0.0)
            continue;
        inFront += w;
        if (perPoint[q][item] > 0.0)
            seen += w;
    }
    return inFront > 0.0 ? seen / inFront : 0.0;
}

void splitFarShareByPoints(const PreparedScene& scene, int patch, std::span<const double> w,
                           const std::vector<std::vector<double>>& perPoint,
                           const std::vector<std::uint32_t>& rowElements, const std::vector<NearTerm>& near,
                           std::vector<double>& pointFactors, std::vector<double>& coefficients)
{
    const Patch& p = scene.patches[static_cast<size_t>(patch)];
    const size_t m = perPoint.size(), count = static_cast<size_t>(p.elementCount);
    std::vector<char> isNear(rowElements.size(), 0);
    std::vector<double> nearOf(count, 0.0); // each shooter element's near factors
    for (const NearTerm& t : near) {
        isNear[t.entry] = 1;
        nearOf[size_t(t.shooterElement)] += t.factor;
    }
    // Each point's factors: all of them (what its hemicube saw of every
    // receiver) and those of the far receivers, which it keeps. The row's
    // receivers are every element that some point saw.
    std::vector<double> total(m, 0.0), far(m, 0.0);
    pointFactors.assign(rowElements.size() * m, 0.0);
    for (size_t k = 0; k < rowElements.size(); ++k)
        for (size_t q = 0; q < m; ++q) {
            const double f = perPoint[q][rowElements[k] + kFirstElementItem];
            total[q] += f;
            if (isNear[k])
                continue;
            far[q] += f;
            pointFactors[k * m + q] = f;
        }
    coefficients.assign(count * m, 0.0);
    for (size_t s = 0; s < count; ++s) {
        double totalOf = 0.0, farOf = 0.0;
        for (size_t q = 0; q < m; ++q) {
            totalOf += w[s * m + q] * total[q];
            farOf += w[s * m + q] * far[q];
        }
        if (farOf <= 0.0)
            continue;
        const double scale = std::max(0.0, totalOf - nearOf[s]) / farOf;
        for (size_t q = 0; q < m; ++q)
            coefficients[s * m + q] = w[s * m + q] * scale;
    }
}

} // namespace regio::solver
