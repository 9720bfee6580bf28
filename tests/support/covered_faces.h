#pragma once
// What the solids of a prepared scene cover, computed for the tests apart from
// the solver's own code (solver/prepare/covered_parts.h): a face is covered
// where the face of a solid lies on it back to back (coplanar, facing the
// other way), and its mesh must leave that part out.
#include "model/geometry/geometry.h"
#include "solver/prepare/prepared_scene.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace regio::test {

// The faces of solids that lie on face f back to back.
inline std::vector<size_t> coversOf(const solver::PreparedScene& s, size_t f)
{
    std::vector<size_t> out;
    const model::Plane& plane = s.properties[f].plane;
    for (size_t g = 0; g < s.faces.size(); ++g) {
        const model::Plane& other = s.properties[g].plane;
        if (g != f && s.properties[g].solid && s.faces[g].polygon.size() >= 3 &&
            glm::dot(plane.normal, other.normal) < -1.0 + 1e-9 && std::abs(plane.d + other.d) < 1e-9)
            out.push_back(g);
    }
    return out;
}

// The part of a convex polygon inside the convex `cover` (coplanar).
inline std::vector<model::Vec3> clippedTo(std::vector<model::Vec3> polygon, const std::vector<model::Vec3>& cover,
                                          const model::Vec3& coverNormal)
{
    for (size_t k = 0; k < cover.size() && polygon.size() >= 3; ++k) {
        const model::Vec3 inward = glm::normalize(glm::cross(coverNormal, cover[(k + 1) % cover.size()] - cover[k]));
        std::vector<model::Vec3> front, back;
        model::splitPolygon(polygon, model::Plane{inward, -glm::dot(inward, cover[k])}, front, back);
        polygon = front;
    }
    return polygon.size() >= 3 ? polygon : std::vector<model::Vec3>{};
}

// The area face f and face g have in common (both convex, coplanar).
inline double commonArea(const solver::PreparedScene& s, size_t f, size_t g)
{
    const std::vector<model::Vec3> common =
        clippedTo(s.faces[f].polygon, s.faces[g].polygon, s.properties[g].plane.normal);
    return common.empty() ? 0.0 : model::polygonArea(common);
}

// The area of face f that no solid covers: the covers' areas on it less the
// areas where two covers overlap (boxes standing into each other; no point
// is under three covers in the scenes of the tests).
inline double uncoveredArea(const solver::PreparedScene& s, size_t f)
{
    double area = s.faces[f].area;
    const std::vector<size_t> covers = coversOf(s, f);
    for (size_t i = 0; i < covers.size(); ++i) {
        const std::vector<model::Vec3> first =
            clippedTo(s.faces[f].polygon, s.faces[covers[i]].polygon, s.properties[covers[i]].plane.normal);
        if (first.empty())
            continue;
        area -= model::polygonArea(first);
        for (size_t j = i + 1; j < covers.size(); ++j) {
            const std::vector<model::Vec3> both =
                clippedTo(first, s.faces[covers[j]].polygon, s.properties[covers[j]].plane.normal);
            if (!both.empty())
                area += model::polygonArea(both);
        }
    }
    return std::max(area, 0.0);
}

// p lies on the outline of face f or of one of its covers.
inline bool onOutlineOrCover(const solver::PreparedScene& s, size_t f, const model::Vec3& p, double eps = 1e-6)
{
    const auto onLoop = [&](const std::vector<model::Vec3>& loop) {
        for (size_t i = 0; i < loop.size(); ++i) {
            const model::Vec3 a = loop[i], ab = loop[(i + 1) % loop.size()] - a;
            const double t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
            if (glm::length(a + ab * t - p) <= eps)
                return true;
        }
        return false;
    };
    if (onLoop(s.faces[f].polygon))
        return true;
    for (size_t g : coversOf(s, f))
        if (onLoop(s.faces[g].polygon))
            return true;
    return false;
}

} // namespace regio::test
