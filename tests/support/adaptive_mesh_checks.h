#pragma once
// Meshes and checks the tests of adaptive subdivision share
// (tests/solver/shooting/adaptive_subdivision_test.cpp and
// coplanar_partners_test.cpp): grey floors meshed coarsely, the shortest edge
// of an element, and the T-vertices left in an output.
#include "solver/prepare/prepare.h"
#include "solver/shooting/adaptive_subdivision.h"
#include "support/solver_test_scenes.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace regio::test {

// Grey floor faces (id, polygon), 1 m patches of 4 elements (element legs
// ~0.5 m).
inline solver::PreparedScene preparedFloor(const std::vector<std::pair<std::string, std::vector<Vec3>>>& faces)
{
    model::Scene scene;
    addMaterial(scene, "grey", Rgb{0.5});
    for (const auto& [id, polygon] : faces)
        addPolygon(scene, id, polygon, "grey");
    scene.solver.patchSize = 1.0;
    scene.solver.elementsPerPatch = 4;
    model::Result<solver::PreparedScene> r = solver::prepareScene(scene);
    EXPECT_TRUE(r.ok());
    return r.ok() ? std::move(*r) : solver::PreparedScene{};
}

inline double shortestEdge(const solver::PreparedScene& s, const solver::Element& e)
{
    double m = 1e300;
    for (int k = 0; k < 3; ++k)
        m = std::min(m, glm::length(s.vertices[size_t(e.vertices[size_t(k)])] -
                                    s.vertices[size_t(e.vertices[size_t((k + 1) % 3)])]));
    return m;
}

inline bool strictlyInside(const Vec3& p, const Vec3& a, const Vec3& b)
{
    const Vec3 ab = b - a;
    const double t = glm::dot(p - a, ab) / glm::dot(ab, ab);
    if (t <= 1e-9 || t >= 1.0 - 1e-9)
        return false;
    return glm::length(a + t * ab - p) < 1e-9;
}

// Output vertices lying inside an edge of another output triangle of the same face.
inline int countTVertices(const solver::PreparedScene& s, const std::vector<solver::OutputTriangle>& triangles)
{
    std::map<int, std::set<int>> verticesOfFace;
    for (const solver::OutputTriangle& t : triangles)
        for (int v : t.vertices)
            verticesOfFace[s.elements[size_t(t.element)].properties].insert(v);
    int count = 0;
    for (const solver::OutputTriangle& t : triangles) {
        const int face = s.elements[size_t(t.element)].properties;
        for (int k = 0; k < 3; ++k) {
            const Vec3 a = s.vertices[size_t(t.vertices[size_t(k)])],
                       b = s.vertices[size_t(t.vertices[size_t((k + 1) % 3)])];
            for (int v : verticesOfFace[face])
                if (strictlyInside(s.vertices[size_t(v)], a, b))
                    ++count;
        }
    }
    return count;
}

} // namespace regio::test
