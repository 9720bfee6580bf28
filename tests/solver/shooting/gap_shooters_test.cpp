// Patches that shoot out of a narrow gap (solver/shooting/gap_shooters.h): a
// ceiling patch over a lamp hung 2 cm below the ceiling renders its hemicube
// from 16 points, and what it sends through the slit reaches the walls as a
// ray-cast reference says, not in one band along their top.
#include "solver/shooting/gap_shooters.h"

#include "solver/shooting/near_field.h"
#include "solver/shooting/shooting.h"
#include "support/prepared_scenes.h"
#include "support/solver_test_scenes.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace regio;
using namespace regio::solver;
using model::Vec3;

namespace {

constexpr double kCeiling = 2.5;
constexpr Vec3 kPanelMin{1.0, 2.44, 1.5}, kPanelMax{2.0, 2.48, 2.5};

// A room 5 x 2.5 x 4 with a lamp panel 1 m square and 4 cm thick whose top
// is 2 cm under the ceiling; 0.5 m patches, each cut into 16 elements so
// that the walls' top 12.5 cm are a row of their own.
model::Scene lampUnderCeiling()
{
    model::Scene scene;
    test::addMaterial(scene, "wall", Rgb{0.7});
    test::addMaterial(scene, "lamp", Rgb{0.8}, Rgb{12.0});
    test::addBox(scene, "room", {0, 0, 0}, {5, kCeiling, 4}, "wall", true);
    test::addBox(scene, "panel", kPanelMin, kPanelMax, "lamp");
    scene.solver.patchSize = 0.5;
    scene.solver.elementsPerPatch = 16;
    return scene;
}

std::array<Vec3, 3> cornersOf(const PreparedScene& s, const std::array<int, 3>& v)
{
    return {s.vertices[size_t(v[0])], s.vertices[size_t(v[1])], s.vertices[size_t(v[2])]};
}

// The k x k equal triangles' centroids of a triangle (the midpoint rule).
std::vector<Vec3> subCentroids(const std::array<Vec3, 3>& t, int k)
{
    std::vector<Vec3> points;
    for (int i = 0; i < k; ++i)
        for (int j = 0; i + j < k; ++j)
            for (int up = 0; up < (i + j + 1 < k ? 2 : 1); ++up) {
                const double u = (i + (up ? 2.0 : 1.0) / 3.0) / k, v = (j + (up ? 2.0 : 1.0) / 3.0) / k;
                points.push_back(t[0] + u * (t[1] - t[0]) + v * (t[2] - t[0]));
            }
    return points;
}

// Whether the segment a-b passes through the panel (a slab test: the room
// is convex, so the panel is the only thing between the ceiling and a wall).
bool panelBlocks(const Vec3& a, const Vec3& b)
{
    double t0 = 0.0, t1 = 1.0;
    for (int axis = 0; axis < 3; ++axis) {
        const double d = b[axis] - a[axis];
        if (std::abs(d) < 1e-15) {
            if (a[axis] < kPanelMin[axis] || a[axis] > kPanelMax[axis])
                return false;
            continue;
        }
        double lo = (kPanelMin[axis] - a[axis]) / d, hi = (kPanelMax[axis] - a[axis]) / d;
        if (lo > hi)
            std::swap(lo, hi);
        t0 = std::max(t0, lo);
        t1 = std::min(t1, hi);
        if (t0 > t1)
            return false;
    }
    return true;
}

// The ceiling patch nearest above the panel's centre.
int patchOverThePanel(const PreparedScene& s)
{
    int best = -1;
    double bestDistance = 1e9;
    const Vec3 centre{1.5, kCeiling, 2.0};
    for (size_t p = 0; p < s.patches.size(); ++p)
        if (s.faces[size_t(s.patches[p].properties)].id == "room.body.py")
            if (const double d = glm::distance(s.patches[p].centroid, centre); d < bestDistance) {
                bestDistance = d;
                best = int(p);
            }
    return best;
}

} // namespace

TEST(GapShooters, AnOpenPatchShootsFromItsCentroid)
{
    const PreparedScene s = test::prepared(lampUnderCeiling());
    for (size_t p = 0; p < s.patches.size(); ++p)
        if (s.faces[size_t(s.patches[p].properties)].id == "room.body.ny") { // the floor, 2.44 m below the panel
            const std::vector<Vec3> points = shooterPoints(s, int(p));
            ASSERT_EQ(points.size(), 1u);
            EXPECT_EQ(points[0], s.patches[p].centroid);
        }
}

TEST(GapShooters, APatchOverALampHungCloseUnderTheCeilingShootsFromSixteenPointsInsideIt)
{
    const PreparedScene s = test::prepared(lampUnderCeiling());
    const int over = patchOverThePanel(s);
    ASSERT_GE(over, 0);
    const Patch& patch = s.patches[size_t(over)];
    const std::vector<Vec3> points = shooterPoints(s, over);
    ASSERT_EQ(points.size(), size_t(kGapShooterSplits * kGapShooterSplits));

    // Each inside the patch's triangle, and together they stand for it: their
    // mean is its centroid.
    const std::array<Vec3, 3> t = cornersOf(s, patch.vertices);
    const Vec3 n = glm::cross(t[1] - t[0], t[2] - t[0]);
    Vec3 mean{0.0};
    for (const Vec3& x : points) {
        for (int i = 0; i < 3; ++i)
            EXPECT_GT(glm::dot(glm::cross(t[size_t((i + 1) % 3)] - t[size_t(i)], x - t[size_t(i)]), n), 0.0);
        mean += x / double(points.size());
    }
    EXPECT_NEAR(glm::distance(mean, patch.centroid), 0.0, 1e-12);

    // The patch's 16 elements each speak through the one point inside it.
    ASSERT_EQ(patch.elementCount, 16);
    const std::vector<double> w = pointWeights(s, over, points);
    ASSERT_EQ(w.size(), size_t(patch.elementCount) * points.size());
    std::vector<int> owners(points.size(), 0);
    for (size_t e = 0; e < size_t(patch.elementCount); ++e)
        for (size_t q = 0; q < points.size(); ++q)
            if (w[e * points.size() + q] != 0.0) {
                EXPECT_EQ(w[e * points.size() + q], 1.0);
                ++owners[q];
            }
    for (int held : owners)
        EXPECT_EQ(held, 1);
}

TEST(GapShooters, AnElementSmallerThanThePointsAreApartSpeaksThroughTheNearestAndABigOneThroughAllInside)
{
    // The same patch at 4 elements (each holds 4 points) and at 64 (48 of
    // them hold none): every element's weights sum to 1.
    for (int perPatch : {4, 64}) {
        model::Scene scene = lampUnderCeiling();
        scene.solver.elementsPerPatch = perPatch;
        const PreparedScene s = test::prepared(scene);
        const int over = patchOverThePanel(s);
        ASSERT_GE(over, 0);
        const Patch& patch = s.patches[size_t(over)];
        ASSERT_EQ(patch.elementCount, perPatch);
        const std::vector<Vec3> points = shooterPoints(s, over);
        const std::vector<double> w = pointWeights(s, over, points);
        for (size_t e = 0; e < size_t(perPatch); ++e) {
            double sum = 0.0;
            int used = 0;
            for (size_t q = 0; q < points.size(); ++q) {
                sum += w[e * points.size() + q];
                used += w[e * points.size() + q] != 0.0 ? 1 : 0;
            }
            EXPECT_NEAR(sum, 1.0, 1e-12);
            EXPECT_EQ(used, perPatch == 4 ? 4 : 1);
        }
    }
}

TEST(GapShooters, WhatACeilingPatchSendsThroughTheSlitReachesTheWallsAsRaysSay)
{
    // The ceiling patch over the panel centre shoots alone: its row of form
    // factors against the ray-cast reference (the contour formula over 64
    // points of the patch, each times the fraction of 16 rays to the element
    // that miss the panel). Its elements at the panel's rim send a quarter
    // of their light through the slit, far down the walls; shot from its
    // centre alone, where the slit is a thin row of pixels at the horizon,
    // the walls' top row took 14 times the reference and the rest nothing.
    const PreparedScene s = test::prepared(lampUnderCeiling());
    const int over = patchOverThePanel(s);
    ASSERT_GE(over, 0);
    const Patch& patch = s.patches[size_t(over)];
    ShootingOptions options;
    options.overrelaxation = 1.0;
    Shooting shooting(s, 150, model::Visibility::Painter, options);
    std::vector<Rgb> unshot(s.elements.size(), Rgb{0.0});
    for (int e = patch.firstElement; e < patch.firstElement + patch.elementCount; ++e)
        unshot[size_t(e)] = Rgb{1.0};
    shooting.replaceElementState(shooting.radiosity(), unshot);
    ASSERT_EQ(shooting.selectShooter(), over);
    ASSERT_EQ(shooting.shoot(), ShotResult::Shot);
    const std::vector<double> factors = shooting.lastFormFactors();

    const std::vector<Vec3> from = subCentroids(cornersOf(s, patch.vertices), 8);
    const Vec3 down{0.0, -1.0, 0.0};
    const double top = kCeiling - 0.125;
    double solverTop = 0.0, solverBelow = 0.0, referenceTop = 0.0, referenceBelow = 0.0;
    for (size_t e = 0; e < s.elements.size(); ++e) {
        const std::string& id = s.faces[size_t(s.elements[e].properties)].id;
        if (id == "room.body.py" || id == "room.body.ny" || id.rfind("panel", 0) == 0)
            continue;
        const std::array<Vec3, 3> t = cornersOf(s, s.elements[e].vertices);
        const std::vector<Vec3> to = subCentroids(t, 4);
        double f = 0.0;
        for (const Vec3& x : from) {
            int open = 0;
            for (const Vec3& y : to)
                open += panelBlocks(x, y) ? 0 : 1;
            if (open > 0)
                f +=
                    pointToPolygonFormFactor(x, down, std::vector<Vec3>(t.begin(), t.end())) * open / double(to.size());
        }
        f /= double(from.size());
        const bool inTop = s.elements[e].centroid.y > top;
        (inTop ? referenceTop : referenceBelow) += f;
        (inTop ? solverTop : solverBelow) += factors[e];
    }
    std::printf("walls' top 12.5 cm: solver %.5f reference %.5f; below: solver %.5f reference %.5f\n", solverTop,
                referenceTop, solverBelow, referenceBelow);
    ASSERT_GT(referenceBelow, 0.2 * referenceTop) << "the premise: the slit lights the walls far down";
    EXPECT_NEAR(solverTop, referenceTop, 0.15 * referenceTop);
    EXPECT_NEAR(solverBelow, referenceBelow, 0.15 * referenceBelow);
}

TEST(GapShooters, TheBooksStayExact)
{
    // A whole solve of the room, every ceiling patch over the panel shooting
    // from its 16 points: emitted = absorbed + unshot + escaped.
    model::Scene scene = lampUnderCeiling();
    scene.solver.elementsPerPatch = 4;
    const PreparedScene s = test::prepared(scene);
    Shooting shooting(s, 64, model::Visibility::Painter);
    int gapShots = 0;
    while (shooting.unshotRatio() > 0.05) {
        ASSERT_EQ(shooting.shoot(), ShotResult::Shot);
        gapShots += shooterPoints(s, shooting.lastShooter()).size() > 1 ? 1 : 0;
    }
    ASSERT_GT(gapShots, 0) << "the premise: patches over the panel shot";
    const EnergyBalance books = shooting.energy();
    const Rgb sum = books.absorbed + books.unshot + books.escaped;
    EXPECT_NEAR(sum.r, books.emitted.r, 1e-9 * books.emitted.r);
    EXPECT_GT(books.absorbed.r, 0.9 * books.emitted.r);
}
