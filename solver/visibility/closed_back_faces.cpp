#include "solver/visibility/closed_back_faces.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <map>
#include <numbers>
#include <utility>

namespace regio::solver {

namespace {
// How far in front of the eye the side is judged: far below any gap between
// two faces of a scene, far above the distance at which faces count as
// touching (model::kDistanceEpsilon).
constexpr double kProbe = 1e-5;

// Signed solid angle of triangle (a, b, c) seen from the origin (Van Oosterom
// and Strackee 1983): positive when the origin lies behind the triangle's
// front (counter-clockwise) side.
double solidAngle(const Vec3& a, const Vec3& b, const Vec3& c)
{
    const double la = glm::length(a), lb = glm::length(b), lc = glm::length(c);
    const double numerator = glm::dot(a, glm::cross(b, c));
    const double denominator = la * lb * lc + glm::dot(a, b) * lc + glm::dot(a, c) * lb + glm::dot(b, c) * la;
    return 2.0 * std::atan2(numerator, denominator);
}
} // namespace

std::vector<ClosedPart> closedParts(const PreparedScene& scene)
{
    std::map<std::pair<int, int>, ClosedPart> byPart; // (object, part)
    std::map<std::pair<int, int>, double> volume;
    for (size_t f = 0; f < scene.faces.size(); ++f) {
        if (!scene.properties[f].solid)
            continue;
        const InputFace& face = scene.faces[f];
        const std::pair<int, int> key{face.object, face.part};
        ClosedPart& part = byPart[key];
        for (const Vec3& p : face.polygon)
            part.bounds.extend(p);
        for (size_t i = 1; i + 1 < face.polygon.size(); ++i) {
            const std::array<Vec3, 3> t{face.polygon[0], face.polygon[i], face.polygon[i + 1]};
            part.triangles.push_back(t);
            volume[key] += glm::dot(t[0], glm::cross(t[1], t[2])) / 6.0; // divergence theorem
        }
    }
    std::vector<ClosedPart> out;
    out.reserve(byPart.size());
    for (auto& [key, part] : byPart)
        if (!part.triangles.empty()) {
            part.inward = volume[key] < 0.0;
            out.push_back(std::move(part));
        }
    return out;
}

double windingNumber(const ClosedPart& part, const Vec3& point)
{
    double sum = 0.0;
    for (const std::array<Vec3, 3>& t : part.triangles)
        sum += solidAngle(t[0] - point, t[1] - point, t[2] - point);
    return sum / (4.0 * std::numbers::pi);
}

bool closedBackFacesHidden(const std::vector<ClosedPart>& parts, const Vec3& eye, const Vec3& normal)
{
    const Vec3 probe = eye + kProbe * normal;
    for (const ClosedPart& part : parts) {
        // Outside the bounds the winding number is 0: outside a solid (its
        // empty side), outside a room (its material side).
        const double w = part.bounds.contains(probe, 0.0) ? windingNumber(part, probe) : 0.0;
        const bool material = part.inward ? w > -0.5 : w > 0.5;
        if (material)
            return false;
    }
    return true;
}

} // namespace regio::solver
