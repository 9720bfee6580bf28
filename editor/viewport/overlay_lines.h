#pragma once
// Coloured line lists for the viewport's overlays (grid, region boxes, gizmo,
// clip plane): xyz rgba per vertex, two vertices per segment (or three per
// triangle for the filled overlays).
#include "model/geometry/geometry.h"
#include "model/scene.h"

#include <glm/vec4.hpp>

#include <vector>

namespace regio::editor {

class LineList {
public:
    void add(const model::Vec3& a, const model::Vec3& b, const glm::vec4& colour);
    void addBox(const model::Vec3& min, const model::Vec3& max, const glm::vec4& colour);
    // Three vertices of a filled triangle (for LineLists drawn as triangles).
    void addTriangle(const model::Vec3& a, const model::Vec3& b, const model::Vec3& c, const glm::vec4& colour);
    // The same with a colour per vertex (Gouraud-shaded layers).
    void addTriangle(const model::Vec3& a, const model::Vec3& b, const model::Vec3& c, const glm::vec4& colourA,
                     const glm::vec4& colourB, const glm::vec4& colourC);
    void reserve(size_t vertexCount) { m_vertices.reserve(vertexCount * 7); }
    void addCircle(const model::Vec3& centre, const model::Vec3& axis, double radius, const glm::vec4& colour,
                   int segments = 48);
    void append(const LineList& other)
    {
        m_vertices.insert(m_vertices.end(), other.m_vertices.begin(), other.m_vertices.end());
    }
    const std::vector<float>& vertices() const { return m_vertices; }
    bool empty() const { return m_vertices.empty(); }
    void clear() { m_vertices.clear(); }

private:
    std::vector<float> m_vertices;
};

// The ground grid on y = 0: minor lines every `spacing`, major ones every
// ten, the x axis red and the z axis blue, out to at least `extent`.
LineList buildGrid(double spacing, double extent);

// Region boxes; the selected ones brighter.
LineList buildRegionBoxes(const model::Scene& scene, const std::vector<std::string>& selected);

} // namespace regio::editor
