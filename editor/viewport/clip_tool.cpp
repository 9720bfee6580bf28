#include "editor/viewport/clip_tool.h"

#include <glm/geometric.hpp>

namespace regio::editor {

std::optional<model::Plane> ClipTool::planeThrough(const model::Vec3& a, const model::Vec3& b, const model::Vec3& c)
{
    const model::Vec3 n = glm::cross(b - a, c - a);
    const double scale = glm::length(b - a) * glm::length(c - a);
    const double length = glm::length(n);
    // Relative test: sin(angle at a) must not vanish.
    if (!(length > 0.0) || !(length > 1e-6 * scale))
        return std::nullopt;
    return model::Plane::fromPointNormal(a, glm::normalize(n));
}

std::optional<model::Plane> ClipTool::addPoint(const model::Vec3& point)
{
    if (!m_active)
        return std::nullopt;
    for (const model::Vec3& p : m_points)
        if (glm::length(p - point) < model::kDistanceEpsilon)
            return std::nullopt; // the same point twice defines nothing new
    m_points.push_back(point);
    if (m_points.size() < 3)
        return std::nullopt;
    auto plane = planeThrough(m_points[0], m_points[1], m_points[2]);
    if (!plane) {
        m_points.pop_back(); // collinear: wait for a better third point
        return std::nullopt;
    }
    m_active = false;
    m_points.clear();
    return plane;
}

LineList ClipTool::lines(double markerSize) const
{
    LineList out;
    const glm::vec4 colour(1.0f, 0.3f, 0.9f, 1.0f);
    for (const model::Vec3& p : m_points) {
        out.add(p - model::Vec3(markerSize, 0, 0), p + model::Vec3(markerSize, 0, 0), colour);
        out.add(p - model::Vec3(0, markerSize, 0), p + model::Vec3(0, markerSize, 0), colour);
        out.add(p - model::Vec3(0, 0, markerSize), p + model::Vec3(0, 0, markerSize), colour);
    }
    for (size_t i = 0; i + 1 < m_points.size(); ++i)
        out.add(m_points[i], m_points[i + 1], colour);
    return out;
}

} // namespace regio::editor
