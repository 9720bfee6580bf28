// Coplanar partner faces (solver/shooting/coplanar_partners.h): faces side by
// side in one plane with one material share pieces of outline, and adaptive
// subdivision compares, interpolates and grades across them
// (solver/shooting/adaptive_subdivision.h).
#include "solver/prepare/prepare.h"
#include "solver/shooting/adaptive_subdivision.h"
#include "solver/shooting/coplanar_partners.h"
#include "solver/shooting/shooting.h"
#include "support/adaptive_mesh_checks.h"
#include "support/sample_scenes.h"
#include "support/solver_test_scenes.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>
#include <string>
#include <vector>

using namespace regio;
using namespace regio::solver;
using model::Vec3;
using test::countTVertices;
using test::preparedFloor;

namespace {

// The criterion's settings for the synthetic fields below (as in
// adaptive_subdivision_test.cpp).
constexpr double kMinEdge = 0.06;
constexpr double kThreshold = 0.25;

} // namespace

TEST(AdaptiveSubdivision, CeilingTilesOfOnePlaneAndMaterialArePartnersAndALampInThemIsNot)
{
    model::Result<PreparedScene> r = prepareScene(test::loadSample("cornell-box"));
    ASSERT_TRUE(r.ok());
    const PreparedScene& s = *r;
    const std::vector<std::vector<SharedOutline>> shared = sharedOutlines(s);
    const auto faceIndex = [&](const std::string& id) {
        for (size_t f = 0; f < s.faces.size(); ++f)
            if (s.faces[f].id == id)
                return int(f);
        return -1;
    };
    const auto partnerIds = [&](const std::string& id) {
        std::set<std::string> out;
        for (const SharedOutline& o : shared[size_t(faceIndex(id))])
            out.insert(s.faces[size_t(o.partner)].id);
        return out;
    };
    EXPECT_EQ(partnerIds("ceiling.tile00"), (std::set<std::string>{"ceiling.tile01", "ceiling.tile10"}));
    EXPECT_EQ(partnerIds("ceiling.tile01"), (std::set<std::string>{"ceiling.tile00", "ceiling.tile02"}));
    EXPECT_TRUE(partnerIds("light.panel.emitter").empty()); // another material
    EXPECT_TRUE(partnerIds("floor.top").empty());
    // The published left wall is not flat: its two triangles are two planes.
    EXPECT_TRUE(partnerIds("left-wall.lower").empty());
}

namespace {

// Two 3 m x 3 m floor faces side by side along x = 3 (one plane, one
// material).
PreparedScene twoFloorsScene()
{
    return preparedFloor({{"west", {{0, 0, 0}, {3, 0, 0}, {3, 3, 0}, {0, 3, 0}}},
                          {"east", {{3, 0, 0}, {6, 0, 0}, {6, 3, 0}, {3, 3, 0}}}});
}

// Refines on the field until nothing is selected.
void refineOn(AdaptiveMesh& mesh, const std::function<Rgb(const Vec3&)>& field)
{
    const auto values = [&] {
        std::vector<Rgb> out;
        for (const Element& e : mesh.scene().elements)
            out.push_back(field(e.centroid));
        return out;
    };
    for (int pass = 0; pass < 12; ++pass) {
        const std::vector<int> selected = mesh.selectBySubdivisionCriterion(values(), kThreshold, kMinEdge);
        if (selected.empty())
            return;
        mesh.subdivide(selected, kMinEdge);
    }
    ADD_FAILURE() << "the subdivision did not settle";
}

// The length of the element's edge on the line x = 3 (0 if none).
double edgeOnSeam(const PreparedScene& s, int element)
{
    const auto& v = s.elements[size_t(element)].vertices;
    for (int k = 0; k < 3; ++k) {
        const Vec3 a = s.vertices[size_t(v[size_t(k)])], b = s.vertices[size_t(v[size_t((k + 1) % 3)])];
        if (std::abs(a.x - 3.0) < 1e-9 && std::abs(b.x - 3.0) < 1e-9)
            return glm::length(b - a);
    }
    return 0.0;
}

} // namespace

TEST(AdaptiveSubdivision, AShadowBorderAlongTheSeamOfTwoCoplanarFacesIsRefinedOnBothSides)
{
    // Dark west of x = 3, lit east of it: each face is even in itself, so only
    // a comparison across the seam sees the border.
    PreparedScene s = twoFloorsScene();
    const auto field = [](const Vec3& p) { return p.x < 3.0 ? Rgb{1.0} : Rgb{10.0}; };
    std::vector<Rgb> radiosity;
    for (const Element& e : s.elements)
        radiosity.push_back(field(e.centroid));
    AdaptiveMesh mesh(s, radiosity, std::vector<Rgb>(s.elements.size(), Rgb{0.0}));
    refineOn(mesh, field);
    int west = 0, east = 0;
    double longest = 0.0;
    for (int e : mesh.activeElements())
        if (const double length = edgeOnSeam(s, e); length > 0.0) {
            (s.elements[size_t(e)].centroid.x < 3.0 ? west : east) += 1;
            longest = std::max(longest, length);
        }
    EXPECT_GT(west, 12);
    EXPECT_GT(east, 12);
    EXPECT_LT(longest, 4.0 * kMinEdge); // refined to near the smallest edge along the seam
    // Children interpolate across the seam too: the west's new elements at the
    // seam lean towards the lit side.
    for (int e : mesh.activeElements())
        if (edgeOnSeam(s, e) > 0.0 && s.elements[size_t(e)].centroid.x < 3.0) {
            EXPECT_GT(luminance(mesh.radiosity()[size_t(e)]), 1.0 + 1e-6);
        }
}

TEST(AdaptiveSubdivision, CoplanarFacesGradeEachOtherTwoToOneAcrossTheirSeam)
{
    for (const bool anchoring : {true, false}) {
        SCOPED_TRACE(anchoring ? "anchoring" : "no anchoring");
        // A shadow border inside the west face, 0.2 m from the seam.
        PreparedScene s = twoFloorsScene();
        const auto field = [](const Vec3& p) { return p.x < 2.8 ? Rgb{1.0} : Rgb{10.0}; };
        std::vector<Rgb> radiosity;
        for (const Element& e : s.elements)
            radiosity.push_back(field(e.centroid));
        AdaptiveMesh mesh(s, radiosity, std::vector<Rgb>(s.elements.size(), Rgb{0.0}), anchoring);
        refineOn(mesh, field);
        double finestEast = 1e300, worstRatio = 0.0;
        for (int e : mesh.activeElements()) {
            const double length = edgeOnSeam(s, e);
            if (length <= 0.0)
                continue;
            const std::vector<int> across = mesh.partners(e);
            EXPECT_FALSE(across.empty()) << "element " << e;
            for (int n : across) {
                EXPECT_NE(s.elements[size_t(n)].centroid.x < 3.0, s.elements[size_t(e)].centroid.x < 3.0);
                worstRatio = std::max(worstRatio, edgeOnSeam(s, n) / length);
            }
            if (s.elements[size_t(e)].centroid.x > 3.0)
                finestEast = std::min(finestEast, length);
        }
        if (anchoring) {
            EXPECT_LE(worstRatio, 2.0 + 1e-9);
            EXPECT_LT(finestEast, 0.5); // the east face was split for the grading alone
        } else {
            EXPECT_GT(worstRatio, 2.0 + 1e-9); // what the grading is for
        }
        if (anchoring) { // each face's own output stays conforming
            EXPECT_EQ(countTVertices(s, mesh.outputTriangles()), 0);
        }
    }
}

TEST(AdaptiveSubdivision, AFaceBesideTwoSmallerOnesSharesAPieceOfItsOutlineWithEach)
{
    // West 2 m x 2 m; east of it two 1 m x 1 m faces, one above the other; a
    // fourth face in another plane, and a fifth of another material.
    model::Scene scene;
    test::addMaterial(scene, "grey", Rgb{0.5});
    test::addMaterial(scene, "red", Rgb{0.6, 0.1, 0.1});
    test::addPolygon(scene, "west", {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}}, "grey");
    test::addPolygon(scene, "south-east", {{2, 0, 0}, {3, 0, 0}, {3, 1, 0}, {2, 1, 0}}, "grey");
    test::addPolygon(scene, "north-east", {{2, 1, 0}, {3, 1, 0}, {3, 2, 0}, {2, 2, 0}}, "grey");
    test::addPolygon(scene, "raised", {{-1, 0, 0.5}, {0, 0, 0.5}, {0, 2, 0.5}, {-1, 2, 0.5}}, "grey");
    test::addPolygon(scene, "rug", {{0, 2, 0}, {2, 2, 0}, {2, 3, 0}, {0, 3, 0}}, "red");
    scene.solver.patchSize = 0.5;
    model::Result<PreparedScene> r = prepareScene(scene);
    ASSERT_TRUE(r.ok());
    const std::vector<std::vector<SharedOutline>> shared = sharedOutlines(*r);
    ASSERT_EQ(shared.size(), 5u);
    ASSERT_EQ(shared[0].size(), 2u);
    double length = 0.0;
    for (const SharedOutline& o : shared[0]) {
        EXPECT_TRUE(o.partner == 1 || o.partner == 2);
        EXPECT_NEAR(o.a.x, 2.0, 1e-12);
        EXPECT_NEAR(o.b.x, 2.0, 1e-12);
        length += glm::length(o.b - o.a);
    }
    EXPECT_NEAR(length, 2.0, 1e-12);
    EXPECT_EQ(shared[1].size(), 2u); // the west face and its northern neighbour
    EXPECT_EQ(shared[2].size(), 2u);
    EXPECT_TRUE(shared[3].empty()); // another plane
    EXPECT_TRUE(shared[4].empty()); // another material

    EXPECT_NEAR(collinearOverlap({0, 0, 0}, {2, 0, 0}, {1, 0, 0}, {5, 0, 0}), 1.0, 1e-12);
    EXPECT_EQ(collinearOverlap({0, 0, 0}, {2, 0, 0}, {2, 0, 0}, {5, 0, 0}), 0.0);       // only a point
    EXPECT_EQ(collinearOverlap({0, 0, 0}, {2, 0, 0}, {0, 1e-3, 0}, {2, 1e-3, 0}), 0.0); // parallel
}
