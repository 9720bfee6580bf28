// The hemicube of a shooting patch is turned about the patch's normal by an
// angle that follows from where the patch lies (shooterFrameOfPatch): a thin
// face seen edge-on from a light then takes its share of the light whatever
// pixels it happens to cover from each of the light's patches.
#include "solver/shooting/near_field.h"
#include "solver/visibility/visibility.h"
#include "support/prepared_scenes.h"
#include "support/solver_test_scenes.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <vector>

using namespace regio;
using namespace regio::solver;

namespace {

// A lamp 1 m square facing down, 2.5 m up, and 1 m off to its side a board's
// front edge 1.2 m long and 3 cm high, facing the lamp: seen from the lamp
// almost along its plane, half a pixel high on a 100-pixel hemicube. Open:
// nothing else. Patches of 0.5 m: the lamp is cut into 8 x 8 patches.
model::Scene lampAndThinEdge(const Vec3& lampOffset = Vec3{0.0})
{
    model::Scene scene;
    test::addMaterial(scene, "wood", Rgb{0.5});
    test::addMaterial(scene, "lamp", Rgb{0.0}, Rgb{10.0});
    const Vec3 o = lampOffset;
    test::addPolygon(
        scene, "lamp",
        {o + Vec3{-0.5, 2.5, -0.5}, o + Vec3{0.5, 2.5, -0.5}, o + Vec3{0.5, 2.5, 0.5}, o + Vec3{-0.5, 2.5, 0.5}},
        "lamp");
    test::addPolygon(scene, "edge", {{0.6, 0.72, 1.0}, {-0.6, 0.72, 1.0}, {-0.6, 0.75, 1.0}, {0.6, 0.75, 1.0}}, "wood");
    scene.solver.patchSize = 0.5;
    scene.solver.hemicube = 100;
    return scene;
}

// F(lamp -> edge) as the hemicubes of the lamp's patches see it, each patch
// in the frame `frameOf` gives it.
double hemicubeFactor(const PreparedScene& s, const std::function<ShooterFrame(int)>& frameOf)
{
    const size_t lamp = test::faceNamed(s, "lamp.face"), edge = test::faceNamed(s, "edge.face");
    const Hemicube hemicube(100);
    Visibility visibility(s, hemicube, model::Visibility::Painter);
    ItemBuffer buffer = visibility.makeBuffer();
    std::vector<double> perItem;
    double factor = 0.0, area = 0.0;
    for (size_t p = 0; p < s.patches.size(); ++p) {
        if (size_t(s.patches[p].properties) != lamp)
            continue;
        EXPECT_TRUE(visibility.render(frameOf(int(p)), buffer));
        perItem.assign(s.elements.size() + kFirstElementItem, 0.0);
        buffer.accumulate(hemicube, perItem);
        for (size_t e = 0; e < s.elements.size(); ++e)
            if (size_t(s.elements[e].properties) == edge)
                factor += perItem[e + kFirstElementItem] * s.patches[p].area;
        area += s.patches[p].area;
    }
    return factor / area;
}

// The exact F(lamp -> edge): the point-to-polygon factor averaged over a
// 100 x 100 grid on the lamp.
double exactFactor(const Vec3& lampOffset = Vec3{0.0})
{
    const std::vector<Vec3> edge{{0.6, 0.72, 1.0}, {-0.6, 0.72, 1.0}, {-0.6, 0.75, 1.0}, {0.6, 0.75, 1.0}};
    constexpr int n = 100;
    double sum = 0.0;
    for (int i = 0; i < n; ++i)
        for (int k = 0; k < n; ++k) {
            const Vec3 x = lampOffset + Vec3{-0.5 + (i + 0.5) / n, 2.5, -0.5 + (k + 0.5) / n};
            sum += pointToPolygonFormFactor(x, {0.0, -1.0, 0.0}, edge);
        }
    return sum / (n * n);
}

// The frame the hemicube had before it was turned: along the patch's first edge.
ShooterFrame frameAlongFirstEdge(const PreparedScene& s, int patch)
{
    const Patch& p = s.patches[size_t(patch)];
    const Vec3& a = s.vertices[size_t(p.vertices[0])];
    const Vec3& b = s.vertices[size_t(p.vertices[1])];
    return ShooterFrame::make(p.centroid, s.properties[size_t(p.properties)].plane.normal, b - a);
}

} // namespace

TEST(TurnedHemicube, AThinFaceSeenEdgeOnFromALightTakesItsExactShareOverTheLightsPatches)
{
    const PreparedScene s = test::prepared(lampAndThinEdge());
    const double exact = exactFactor();
    ASSERT_GT(exact, 1e-4);
    const double turned = hemicubeFactor(s, [&](int p) { return shooterFrameOfPatch(s, p); });
    const double alongEdges = hemicubeFactor(s, [&](int p) { return frameAlongFirstEdge(s, p); });
    std::printf("F(lamp -> edge): exact %.6f, turned hemicubes %+.2f %%, along the patches' edges %+.2f %%\n", exact,
                100.0 * (turned / exact - 1.0), 100.0 * (alongEdges / exact - 1.0));
    // Half a pixel high from every patch: along the edges every patch of a
    // row of the lamp sees the edge in the same phase, and the rows' phases
    // do not average out.
    EXPECT_NEAR(turned, exact, 0.03 * exact);
    EXPECT_GT(std::abs(alongEdges / exact - 1.0), 0.1);
}

TEST(TurnedHemicube, MovingTheLightByAHairChangesWhatTheThinFaceTakesByAHair)
{
    // A model file stores coordinates as 32-bit floats: 1e-7 m off.
    const Vec3 hair{1e-7, -1e-7, 1e-7};
    const PreparedScene a = test::prepared(lampAndThinEdge());
    const PreparedScene b = test::prepared(lampAndThinEdge(hair));
    const double fa = hemicubeFactor(a, [&](int p) { return shooterFrameOfPatch(a, p); });
    const double fb = hemicubeFactor(b, [&](int p) { return shooterFrameOfPatch(b, p); });
    EXPECT_NEAR(fb, fa, 0.001 * fa);
}

TEST(TurnedHemicube, TheTurnFollowsWhereThePatchLiesNotItsCorners)
{
    // The lamp's loop started at another corner: patches with the same
    // centroid have the same frame, whichever corner comes first.
    model::Scene rotated = lampAndThinEdge();
    std::vector<int>& loop = rotated.objects[0].parts[0].faces[0].loop;
    std::rotate(loop.begin(), loop.begin() + 1, loop.end());
    const PreparedScene a = test::prepared(lampAndThinEdge());
    const PreparedScene b = test::prepared(rotated);
    int matched = 0, otherFirstEdge = 0;
    std::vector<double> angles;
    for (size_t p = 0; p < a.patches.size(); ++p) {
        const ShooterFrame fa = shooterFrameOfPatch(a, int(p));
        for (size_t q = 0; q < b.patches.size(); ++q)
            if (glm::length(b.patches[q].centroid - a.patches[p].centroid) < 1e-12) {
                const ShooterFrame fb = shooterFrameOfPatch(b, int(q));
                EXPECT_LT(glm::length(fb.u - fa.u), 1e-9);
                EXPECT_LT(glm::length(fb.v - fa.v), 1e-9);
                ++matched;
                otherFirstEdge +=
                    glm::length(frameAlongFirstEdge(b, int(q)).u - frameAlongFirstEdge(a, int(p)).u) > 1e-6;
            }
        if (size_t(a.patches[p].properties) == test::faceNamed(a, "lamp.face"))
            angles.push_back(std::atan2(fa.u.z, fa.u.x));
    }
    // The strips start elsewhere too, so not every patch has a twin; of those
    // that have, many start at another corner.
    EXPECT_GT(matched, 32);
    EXPECT_GT(otherFirstEdge, 8);
    // The lamp's patches are turned as if at random: few pairs of them within
    // a degree of each other's turn (1 in 180 at random; along the patches'
    // edges, every pair of patches alike).
    const size_t n = angles.size();
    ASSERT_GE(n, 64u);
    size_t alike = 0;
    for (size_t i = 0; i < n; ++i)
        for (size_t j = i + 1; j < n; ++j)
            alike += std::abs(std::remainder(angles[i] - angles[j], 2.0 * std::numbers::pi)) < std::numbers::pi / 180.0;
    EXPECT_LT(alike, n * (n - 1) / 2 / 60) << alike << " of " << n * (n - 1) / 2 << " pairs";
}
