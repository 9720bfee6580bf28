#include "editor/viewport/overlay_lines.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace regio::editor {

void LineList::add(const model::Vec3& a, const model::Vec3& b, const glm::vec4& colour)
{
    for (const model::Vec3& p : {a, b}) {
        m_vertices.insert(m_vertices.end(), {float(p.x), float(p.y), float(p.z)});
        m_vertices.insert(m_vertices.end(), {colour.r, colour.g, colour.b, colour.a});
    }
}

void LineList::addTriangle(const model::Vec3& a, const model::Vec3& b, const model::Vec3& c, const glm::vec4& colour)
{
    for (const model::Vec3& p : {a, b, c}) {
        m_vertices.insert(m_vertices.end(), {float(p.x), float(p.y), float(p.z)});
        m_vertices.insert(m_vertices.end(), {colour.r, colour.g, colour.b, colour.a});
    }
}

void LineList::addTriangle(const model::Vec3& a, const model::Vec3& b, const model::Vec3& c, const glm::vec4& colourA,
                           const glm::vec4& colourB, const glm::vec4& colourC)
{
    const model::Vec3* points[3] = {&a, &b, &c};
    const glm::vec4* colours[3] = {&colourA, &colourB, &colourC};
    for (int i = 0; i < 3; ++i) {
        const model::Vec3& p = *points[i];
        const glm::vec4& colour = *colours[i];
        m_vertices.insert(m_vertices.end(), {float(p.x), float(p.y), float(p.z)});
        m_vertices.insert(m_vertices.end(), {colour.r, colour.g, colour.b, colour.a});
    }
}

void LineList::addBox(const model::Vec3& lo, const model::Vec3& hi, const glm::vec4& colour)
{
    auto corner = [&](int i) { return model::Vec3(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z); };
    for (int i = 0; i < 8; ++i)
        for (int bit : {1, 2, 4})
            if (!(i & bit))
                add(corner(i), corner(i | bit), colour);
}

void LineList::addCircle(const model::Vec3& centre, const model::Vec3& axis, double radius, const glm::vec4& colour,
                         int segments)
{
    const model::Vec3 n = glm::normalize(axis);
    const model::Vec3 helper = std::abs(n.y) < 0.9 ? model::Vec3(0, 1, 0) : model::Vec3(1, 0, 0);
    const model::Vec3 u = glm::normalize(glm::cross(n, helper));
    const model::Vec3 v = glm::cross(n, u);
    for (int i = 0; i < segments; ++i) {
        const double a0 = 2.0 * M_PI * i / segments, a1 = 2.0 * M_PI * (i + 1) / segments;
        add(centre + radius * (std::cos(a0) * u + std::sin(a0) * v),
            centre + radius * (std::cos(a1) * u + std::sin(a1) * v), colour);
    }
}

LineList buildGrid(double spacing, double extent)
{
    LineList lines;
    if (!(spacing > 0.0))
        return lines;
    const int major = 10;
    // Whole major cells, and never so many lines that the grid turns grey.
    int half = int(std::ceil(extent / (spacing * major))) * major;
    half = std::clamp(half, major, 2000);
    const double e = half * spacing;
    const glm::vec4 minor(0.5f, 0.5f, 0.55f, 0.25f), majorColour(0.6f, 0.6f, 0.65f, 0.5f);
    for (int i = -half; i <= half; ++i) {
        const double c = i * spacing;
        const bool isMajor = i % major == 0;
        const glm::vec4 zLine = i == 0 ? glm::vec4(0.3f, 0.45f, 1.0f, 0.9f) : (isMajor ? majorColour : minor);
        const glm::vec4 xLine = i == 0 ? glm::vec4(1.0f, 0.3f, 0.3f, 0.9f) : (isMajor ? majorColour : minor);
        lines.add({c, 0.0, -e}, {c, 0.0, e}, zLine); // along z, at x = c
        lines.add({-e, 0.0, c}, {e, 0.0, c}, xLine); // along x, at z = c
    }
    return lines;
}

LineList buildRegionBoxes(const model::Scene& scene, const std::vector<std::string>& selected)
{
    LineList lines;
    for (const model::Region& region : scene.regions) {
        const bool isSelected = std::find(selected.begin(), selected.end(), region.id) != selected.end();
        lines.addBox(region.min, region.max,
                     isSelected ? glm::vec4(1.0f, 0.85f, 0.2f, 1.0f) : glm::vec4(0.2f, 0.8f, 0.9f, 0.6f));
    }
    return lines;
}

} // namespace regio::editor
