// The lights' direct contribution at a point (solver/picture/direct_light.h):
// the closed form where nothing stands between, exact halves where a board
// hides half of a light, and a brute-force integration over the light, with
// its own ray test, where a block casts a penumbra.
#include "solver/picture/direct_light.h"

#include "solver/shooting/near_field.h"

#include "support/closed_forms.h"
#include "support/prepared_scenes.h"
#include "support/solver_test_scenes.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>

using namespace regio;
using namespace regio::solver;
using model::Vec3;

using test::cornerFormFactor;

namespace {

// A 4 x 4 floor facing up, a square light [x0, x1] x [z0, z1] at height h
// facing down (emission 1, 2, 3), reflectance 0.5 everywhere.
model::Scene lampOverFloor(double x0, double x1, double z0, double z1, double h)
{
    model::Scene scene;
    test::addMaterial(scene, "grey", {0.5, 0.5, 0.5});
    test::addMaterial(scene, "lamp", {0.5, 0.5, 0.5}, {1.0, 2.0, 3.0});
    test::addPolygon(scene, "floor", {{-2, 0, -2}, {-2, 0, 2}, {2, 0, 2}, {2, 0, -2}}, "grey");
    test::addPolygon(scene, "lamp", {{x0, h, z0}, {x1, h, z0}, {x1, h, z1}, {x0, h, z1}}, "lamp");
    return scene;
}

// Does the segment from a to b pass through the open box (slab test)?
bool segmentHitsBox(const Vec3& a, const Vec3& b, const Vec3& lo, const Vec3& hi)
{
    double t0 = 1e-9, t1 = 1.0 - 1e-9;
    for (int k = 0; k < 3; ++k) {
        const double d = b[k] - a[k];
        if (std::abs(d) < 1e-15) {
            if (a[k] <= lo[k] || a[k] >= hi[k])
                return false;
            continue;
        }
        double ta = (lo[k] - a[k]) / d, tb = (hi[k] - a[k]) / d;
        if (ta > tb)
            std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
    }
    return t0 < t1;
}

// F from a floor point (facing up) to the horizontal light rectangle, by the
// midpoint rule on an n x n grid, with the block [lo, hi] in the way.
double bruteForce(const Vec3& x, double x0, double x1, double z0, double z1, double h, const Vec3& lo, const Vec3& hi,
                  int n)
{
    const double dx = (x1 - x0) / n, dz = (z1 - z0) / n;
    double sum = 0.0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const Vec3 y(x0 + (i + 0.5) * dx, h, z0 + (j + 0.5) * dz);
            if (segmentHitsBox(x, y, lo, hi))
                continue;
            const Vec3 d = y - x;
            const double r2 = glm::dot(d, d);
            sum += d.y * d.y / (std::numbers::pi * r2 * r2) * dx * dz; // cos at both ends = d.y / r
        }
    return sum;
}

} // namespace

TEST(DirectLight, UnderACornerOfAnUnhiddenLightItIsTheClosedFormTimesTheEmission)
{
    const PreparedScene s = test::prepared(lampOverFloor(0.0, 0.6, 0.0, 0.4, 1.5));
    const DirectLight direct(s);
    ASSERT_TRUE(direct.any());
    const int floor = int(test::faceNamed(s, "floor.face"));
    const double f = cornerFormFactor(0.6, 0.4, 1.5);
    EXPECT_NEAR(direct.visibleFactor(floor, {0, 0, 0}, int(test::faceNamed(s, "lamp.face"))), f, 1e-12);
    const model::Rgb e = direct.irradiance(floor, {0, 0, 0});
    EXPECT_NEAR(e.x, 1.0 * f, 1e-12);
    EXPECT_NEAR(e.y, 2.0 * f, 1e-12);
    EXPECT_NEAR(e.z, 3.0 * f, 1e-12);
    EXPECT_NEAR(direct.radiosity(floor, {0, 0, 0}).z, 0.5 * 3.0 * f, 1e-12);
}

TEST(DirectLight, ARoundLampOfMoreCornersThanTheContourFormulaTakesCountsThemAll)
{
    // A 40-gon of radius 0.5 at height 1 over the origin: the sum of its 40
    // triangles from the centre, each within the contour formula's corners.
    model::Scene scene = lampOverFloor(0.0, 0.1, 0.0, 0.1, 1.0);
    std::vector<Vec3> round;
    for (int k = 0; k < 40; ++k) {
        const double angle = 2.0 * std::numbers::pi * k / 40.0; // counter-clockwise in x, z: facing down
        round.push_back({0.5 * std::cos(angle), 1.0, 0.5 * std::sin(angle)});
    }
    scene.objects.pop_back();
    test::addPolygon(scene, "lamp", round, "lamp");
    const PreparedScene s = test::prepared(scene);
    const DirectLight direct(s);
    const Vec3 x(0.1, 0.0, -0.05), up(0, 1, 0);
    double expected = 0.0;
    for (size_t k = 0; k < round.size(); ++k)
        expected += pointToPolygonFormFactor(x, up, {Vec3(0, 1, 0), round[k], round[(k + 1) % round.size()]});
    EXPECT_NEAR(direct.visibleFactor(int(test::faceNamed(s, "floor.face")), x, int(test::faceNamed(s, "lamp.face"))),
                expected, 1e-12);
    // Near a disk's: R^2 / (h^2 + R^2) under its centre.
    EXPECT_NEAR(
        direct.visibleFactor(int(test::faceNamed(s, "floor.face")), {0, 0, 0}, int(test::faceNamed(s, "lamp.face"))),
        0.25 / 1.25, 0.01 * 0.2);
}

TEST(DirectLight, ALightSeesNothingBehindItAndItsOwnFaceGetsNothingFromIt)
{
    const PreparedScene s = test::prepared(lampOverFloor(-0.5, 0.5, -0.5, 0.5, 1.0));
    const DirectLight direct(s);
    const int lamp = int(test::faceNamed(s, "lamp.face"));
    // Above the lamp, behind its emitting side: the floor face's plane is
    // used for the normal, but the point lies behind the light.
    EXPECT_EQ(direct.visibleFactor(int(test::faceNamed(s, "floor.face")), {0, 2, 0}, lamp), 0.0);
    EXPECT_EQ(direct.irradiance(lamp, {0, 1, 0}), model::Rgb(0.0));
}

TEST(DirectLight, ABoardThatHidesHalfOfTheLightLeavesExactlyHalf)
{
    // Seen from the origin, a board at half the lamp's height over x in
    // [0, 0.5] hides the lamp's half x > 0; by symmetry that is half.
    model::Scene scene = lampOverFloor(-0.5, 0.5, -0.5, 0.5, 1.0);
    test::addPolygon(scene, "board", {{0, 0.5, -1}, {0, 0.5, 1}, {0.5, 0.5, 1}, {0.5, 0.5, -1}}, "grey");
    const PreparedScene s = test::prepared(scene);
    const DirectLight direct(s);
    const int floor = int(test::faceNamed(s, "floor.face")), lamp = int(test::faceNamed(s, "lamp.face"));
    const double whole = 4.0 * cornerFormFactor(0.5, 0.5, 1.0);
    EXPECT_NEAR(direct.visibleFactor(floor, {0, 0, 0}, lamp), 0.5 * whole, 1e-12);
    // Under the board's middle the board hides the lamp's x > -0.25: what
    // is left is a strip 0.5 to 0.75 beside the point, 1 deep.
    const double strip = 2.0 * (cornerFormFactor(0.75, 0.5, 1.0) - cornerFormFactor(0.5, 0.5, 1.0));
    EXPECT_NEAR(direct.visibleFactor(floor, {0.25, 0, 0}, lamp), strip, 1e-12);
}

TEST(DirectLight, InABlocksPenumbraItMatchesAnIntegrationOverTheLightWithItsOwnRays)
{
    // A block standing on the floor under the side of the lamp: points in
    // its umbra, its penumbra (at its foot and away from it, in the wedge
    // beside a corner) and in full light.
    const double x0 = -0.2, x1 = 0.2, z0 = -0.15, z1 = 0.15, h = 1.0;
    model::Scene scene = lampOverFloor(x0, x1, z0, z1, h);
    const Vec3 lo(0.1, 0.0, 0.05), hi(0.4, 0.5, 0.35);
    test::addBox(scene, "block", lo, hi, "grey");
    const PreparedScene s = test::prepared(scene);
    const DirectLight direct(s);
    const int floor = int(test::faceNamed(s, "floor.face")), lamp = int(test::faceNamed(s, "lamp.face"));
    // The lamp's corners cast the top corner (0.4, 0.5, 0.35) at (0.6, 0.55)
    // to (1.0, 0.85): points across that band, in the umbra behind it, at
    // the block's foot and in full light.
    int inPenumbra = 0;
    for (const Vec3& x :
         {Vec3(0.6, 0, 0.6), Vec3(0.7, 0, 0.45), Vec3(0.8, 0, 0.7), Vec3(0.5, 0, 0.5), Vec3(0.9, 0, 0.2),
          Vec3(0.45, 0, 0.4), Vec3(0.65, 0, 0.9), Vec3(0.45, 0, 0.2), Vec3(0.41, 0, 0.2), Vec3(-0.3, 0, 0.1)}) {
        // The midpoint rule's steps along the shadow's slanted edges are
        // worth a few 1e-4 of the light at 800 x 800.
        const double whole = bruteForce(x, x0, x1, z0, z1, h, lo, lo, 200);
        const double got = direct.visibleFactor(floor, x, lamp);
        EXPECT_NEAR(got, bruteForce(x, x0, x1, z0, z1, h, lo, hi, 800), 1e-3 * whole) << x.x << " " << x.z;
        if (got > 0.02 * whole && got < 0.98 * whole)
            ++inPenumbra;
    }
    EXPECT_GE(inPenumbra, 4);
    // The block's own top, with nothing above it, sees all of the lamp:
    // its own faces do not hide it.
    const int top = int(test::faceNamed(s, "block.body.py"));
    const Vec3 onTop(0.15, 0.5, 0.1);
    EXPECT_NEAR(direct.visibleFactor(top, onTop, lamp),
                pointToPolygonFormFactor(onTop, {0, 1, 0}, s.faces[size_t(lamp)].polygon), 1e-12);
}
