#include "solver/shooting/penumbrae.h"

#include "solver/prepare/covered_parts.h"
#include "solver/prepare/face_polygon.h"
#include "solver/prepare/shadow_lines.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace regio::solver {

namespace {

// The convex hull of points on a plane (Andrew's monotone chain),
// counter-clockwise around `normal`.
std::vector<Vec3> hullOnPlane(std::vector<Vec3> points, const Vec3& normal)
{
    const Vec3 helper = std::abs(normal.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
    const Vec3 u = glm::normalize(glm::cross(helper, normal));
    const Vec3 v = glm::cross(normal, u);
    std::sort(points.begin(), points.end(), [&](const Vec3& a, const Vec3& b) {
        const double au = glm::dot(a, u), bu = glm::dot(b, u);
        return au < bu || (au == bu && glm::dot(a, v) < glm::dot(b, v));
    });
    const auto turn = [&](const Vec3& o, const Vec3& a, const Vec3& b) {
        return glm::dot(glm::cross(a - o, b - o), normal);
    };
    std::vector<Vec3> hull(2 * points.size());
    size_t k = 0;
    for (size_t i = 0; i < points.size(); ++i) {
        while (k >= 2 && turn(hull[k - 2], hull[k - 1], points[i]) <= 1e-15)
            --k;
        hull[k++] = points[i];
    }
    for (size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
        while (k >= lower && turn(hull[k - 2], hull[k - 1], points[i]) <= 1e-15)
            --k;
        hull[k++] = points[i];
    }
    hull.resize(k > 1 ? k - 1 : k);
    return hull;
}

// The vertices of the solid whose face `cover` stands on the face: those of
// every face of its part.
std::vector<Vec3> solidVertices(const PreparedScene& scene, size_t cover)
{
    std::vector<Vec3> vertices;
    const auto [first, last] = facesOfPart(scene, cover);
    for (size_t h = first; h < last; ++h)
        vertices.insert(vertices.end(), scene.faces[h].polygon.begin(), scene.faces[h].polygon.end());
    return vertices;
}

// The shadows of the solid (its `footprint` on the plane, its `vertices`)
// from each vertex of the light; none when a vertex of the solid is not
// below every vertex of the light (the shadow reaches to infinity).
std::vector<std::vector<Vec3>> shadowsFrom(const std::vector<Vec3>& light, const Plane& plane,
                                           const std::vector<Vec3>& footprint, const std::vector<Vec3>& vertices)
{
    std::vector<std::vector<Vec3>> shadows;
    for (const Vec3& l : light) {
        const double hl = plane.signedDistance(l);
        std::vector<Vec3> points = footprint;
        for (const Vec3& c : vertices) {
            const double hc = plane.signedDistance(c);
            if (hc <= model::kDistanceEpsilon)
                continue; // on the face: the footprint has it
            if (hc >= hl - model::kDistanceEpsilon)
                return {};
            points.push_back(l + (c - l) * (hl / (hl - hc)));
        }
        shadows.push_back(hullOnPlane(std::move(points), plane.normal));
    }
    return shadows;
}

} // namespace

std::vector<Penumbra> penumbrae(const PreparedScene& scene, const PenumbraLimits& limits)
{
    std::vector<Penumbra> result;
    const std::vector<std::vector<size_t>> coversOf = coversOfFaces(scene);
    const std::vector<size_t> lights = lightFaces(scene);
    const double minWidth = ShadowLineLimits{}.solidMinWidth * scene.patchSize;
    for (size_t f = 0; f < scene.faces.size(); ++f) {
        if (scene.faces[f].elements.empty())
            continue;
        const Plane& plane = scene.properties[f].plane;
        for (size_t cover : coversOf[f]) {
            const std::vector<Vec3>& footprint = scene.faces[cover].polygon;
            if (footprintWidth(footprint) < minWidth)
                continue;
            const Vec3 centre = model::polygonCentroid(footprint);
            const std::vector<Vec3> vertices = solidVertices(scene, cover);
            std::vector<Penumbra> found;
            double brightest = 0.0;
            for (size_t light : lights) {
                // A light that turns its back on the solid lights none of it.
                const std::vector<Vec3>& polygon = scene.faces[light].polygon;
                if (glm::dot(scene.properties[light].plane.normal, centre - polygon[0]) <= 0.0)
                    continue;
                Penumbra penumbra;
                penumbra.face = int(f);
                penumbra.weight = directLight(scene, light, centre, plane.normal);
                if (penumbra.weight <= 0.0)
                    continue;
                penumbra.shadows = shadowsFrom(polygon, plane, footprint, vertices);
                if (penumbra.shadows.empty())
                    continue;
                brightest = std::max(brightest, penumbra.weight);
                found.push_back(std::move(penumbra));
            }
            for (Penumbra& penumbra : found) {
                if (penumbra.weight < limits.dimmestShare * brightest)
                    continue;
                for (const std::vector<Vec3>& shadow : penumbra.shadows)
                    for (const Vec3& p : shadow)
                        penumbra.bounds.extend(p);
                result.push_back(std::move(penumbra));
            }
        }
    }
    std::stable_sort(result.begin(), result.end(),
                     [](const Penumbra& a, const Penumbra& b) { return a.weight > b.weight; });
    return result;
}

std::vector<int> elementsInPenumbra(const AdaptiveMesh& mesh, const Penumbra& penumbra)
{
    const PreparedScene& scene = mesh.scene();
    const Vec3& normal = scene.properties[size_t(penumbra.face)].plane.normal;
    const Vec3 margin(model::kDistanceEpsilon);
    std::vector<int> found;
    for (int e : scene.faces[size_t(penumbra.face)].elements) {
        if (!mesh.isActive(e))
            continue;
        const Element& element = scene.elements[size_t(e)];
        const Vec3 points[4] = {scene.vertices[size_t(element.vertices[0])],
                                scene.vertices[size_t(element.vertices[1])],
                                scene.vertices[size_t(element.vertices[2])], element.centroid};
        // Wholly beside the shadows' bounds: in full light.
        model::Box3 box;
        for (const Vec3& p : points)
            box.extend(p);
        if (glm::any(glm::lessThan(box.max, penumbra.bounds.min - margin)) ||
            glm::any(glm::greaterThan(box.min, penumbra.bounds.max + margin)))
            continue;
        bool inSome = false, outOfSome = false;
        for (const std::vector<Vec3>& shadow : penumbra.shadows)
            for (const Vec3& p : points)
                (insideConvex(shadow, normal, p, 0.0) ? inSome : outOfSome) = true;
        if (inSome && outOfSome)
            found.push_back(e);
    }
    std::sort(found.begin(), found.end());
    return found;
}

} // namespace regio::solver
