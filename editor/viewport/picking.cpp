#include "editor/viewport/picking.h"

#include "model/geometry/geometry.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <limits>

namespace regio::editor {

namespace {

// Inside test for a convex polygon: the point is on the inner side of every
// edge, seen along the polygon's normal (edges run counter-clockwise).
bool insideConvex(const std::vector<model::Vec3>& loop, const model::Vec3& normal, const model::Vec3& p)
{
    const double eps = 1e-9;
    for (size_t i = 0; i < loop.size(); ++i) {
        const model::Vec3& a = loop[i];
        const model::Vec3& b = loop[(i + 1) % loop.size()];
        if (glm::dot(glm::cross(b - a, p - a), normal) < -eps * glm::length(b - a))
            return false;
    }
    return true;
}

} // namespace

std::optional<PickHit> pickFace(const model::Scene& scene, const Ray& ray, bool ignoreBackFaces)
{
    std::optional<PickHit> best;
    double bestT = std::numeric_limits<double>::infinity();
    for (const model::Object& object : scene.objects) {
        for (const model::Part& part : object.parts) {
            for (const model::Face& face : part.faces) {
                bool validLoop = face.loop.size() >= 3;
                for (int i : face.loop)
                    validLoop = validLoop && i >= 0 && i < int(part.vertices.size());
                if (!validLoop)
                    continue;
                const std::vector<model::Vec3> loop = model::loopPositions(part.vertices, face.loop);
                const model::Vec3 n = model::polygonNormal(loop);
                if (glm::length(n) < 0.5)
                    continue; // degenerate
                const double denom = glm::dot(n, ray.direction);
                if (std::abs(denom) < 1e-12)
                    continue; // ray parallel to the face
                const bool back = denom > 0.0;
                if (back && ignoreBackFaces)
                    continue;
                const double t = glm::dot(n, loop[0] - ray.origin) / denom;
                if (!(t > 0.0) || t >= bestT)
                    continue;
                const model::Vec3 p = ray.origin + t * ray.direction;
                if (!insideConvex(loop, n, p))
                    continue;
                bestT = t;
                best = PickHit{object.id, part.id, face.id, p, n, t, back};
            }
        }
    }
    return best;
}

std::optional<model::Vec3> intersectGround(const Ray& ray, double height)
{
    if (std::abs(ray.direction.y) < 1e-12)
        return std::nullopt;
    const double t = (height - ray.origin.y) / ray.direction.y;
    if (!(t > 0.0))
        return std::nullopt;
    return ray.origin + t * ray.direction;
}

} // namespace regio::editor
