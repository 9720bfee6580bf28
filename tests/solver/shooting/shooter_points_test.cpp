// Patches that shoot from several points (solver/shooting/shooter_points.h):
// a ceiling patch over a lamp hung 2 cm below the ceiling renders its
// hemicube from 16 points, and what it sends through the slit reaches the
// walls as a ray-cast reference says, not in one band along their top; a
// wall patch behind a table's leg does too, and what it sends past the leg
// reaches the leg behind it and the first leg's sides as rays say.
#include "solver/shooting/shooter_points.h"

#include "solver/prepare/facing_faces.h"
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
#include <map>
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

// Whether the segment a-b passes through the box lo-hi (a slab test).
bool boxBlocks(const Vec3& a, const Vec3& b, const Vec3& boxMin, const Vec3& boxMax)
{
    double t0 = 0.0, t1 = 1.0;
    for (int axis = 0; axis < 3; ++axis) {
        const double d = b[axis] - a[axis];
        if (std::abs(d) < 1e-15) {
            if (a[axis] < boxMin[axis] || a[axis] > boxMax[axis])
                return false;
            continue;
        }
        double lo = (boxMin[axis] - a[axis]) / d, hi = (boxMax[axis] - a[axis]) / d;
        if (lo > hi)
            std::swap(lo, hi);
        t0 = std::max(t0, lo);
        t1 = std::min(t1, hi);
        if (t0 > t1)
            return false;
    }
    return true;
}

// Whether the segment a-b passes through the panel (the room is convex, so
// the panel is the only thing between the ceiling and a wall).
bool panelBlocks(const Vec3& a, const Vec3& b) { return boxBlocks(a, b, kPanelMin, kPanelMax); }

// The patch of face `id` whose centroid is nearest to `at`.
int patchNearest(const PreparedScene& s, const std::string& id, const Vec3& at)
{
    int best = -1;
    double bestDistance = 1e9;
    for (size_t p = 0; p < s.patches.size(); ++p)
        if (s.faces[size_t(s.patches[p].properties)].id == id)
            if (const double d = glm::distance(s.patches[p].centroid, at); d < bestDistance) {
                bestDistance = d;
                best = int(p);
            }
    return best;
}

// A room 5 x 2.5 x 4 of 0.5 m patches, 4 elements each, and the wall z = 0
// patch whose centroid is nearest to (2.5, 0.75, 0): the room alone.
model::Scene wallRoom()
{
    model::Scene scene;
    test::addMaterial(scene, "wall", Rgb{0.7});
    test::addMaterial(scene, "wood", Rgb{0.5});
    test::addBox(scene, "room", {0, 0, 0}, {5, kCeiling, 4}, "wall", true);
    scene.solver.patchSize = 0.5;
    scene.solver.elementsPerPatch = 4;
    return scene;
}
const std::string kWall = "room.body.nz";

// The centroid of that wall's patch nearest to (2.5, 0.75): the meshing of
// the wall is the same whatever stands in front of it.
Vec3 wallPatchCentroid()
{
    const PreparedScene s = test::prepared(wallRoom());
    return s.patches[size_t(patchNearest(s, kWall, {2.5, 0.75, 0.0}))].centroid;
}

// Two legs 6 cm square and 1.5 m tall in line with that patch's centroid:
// the front one 0.33 m in front of the wall, the back one 0.9 m.
struct Legs {
    Vec3 frontMin, frontMax, backMin, backMax;
};
Legs legsBehind(const Vec3& c)
{
    return {{c.x - 0.03, 0.0, 0.33}, {c.x + 0.03, 1.5, 0.39}, {c.x - 0.03, 0.0, 0.9}, {c.x + 0.03, 1.5, 0.96}};
}

// The form factors of `patch` shooting alone (its elements' unshot
// radiosity 1, everything else's 0) at hemicube 150; empty if it did not.
std::vector<double> rowOfAlone(const PreparedScene& s, int patch)
{
    ShootingOptions options;
    options.overrelaxation = 1.0;
    Shooting shooting(s, 150, model::Visibility::Painter, options);
    std::vector<Rgb> unshot(s.elements.size(), Rgb{0.0});
    const Patch& p = s.patches[size_t(patch)];
    for (int e = p.firstElement; e < p.firstElement + p.elementCount; ++e)
        unshot[size_t(e)] = Rgb{1.0};
    shooting.replaceElementState(shooting.radiosity(), unshot);
    if (shooting.selectShooter() != patch || shooting.shoot() != ShotResult::Shot)
        return {};
    return shooting.lastFormFactors();
}

// The ceiling patch nearest above the panel's centre.
int patchOverThePanel(const PreparedScene& s) { return patchNearest(s, "room.body.py", {1.5, kCeiling, 2.0}); }

} // namespace

TEST(ShooterPoints, AnOpenPatchShootsFromItsCentroid)
{
    const PreparedScene s = test::prepared(lampUnderCeiling());
    for (size_t p = 0; p < s.patches.size(); ++p)
        if (s.faces[size_t(s.patches[p].properties)].id == "room.body.ny") { // the floor, 2.44 m below the panel
            const std::vector<Vec3> points = shooterPoints(s, int(p));
            ASSERT_EQ(points.size(), 1u);
            EXPECT_EQ(points[0], s.patches[p].centroid);
        }
}

TEST(ShooterPoints, APatchOverALampHungCloseUnderTheCeilingShootsFromSixteenPointsInsideIt)
{
    const PreparedScene s = test::prepared(lampUnderCeiling());
    const int over = patchOverThePanel(s);
    ASSERT_GE(over, 0);
    const Patch& patch = s.patches[size_t(over)];
    const std::vector<Vec3> points = shooterPoints(s, over);
    ASSERT_EQ(points.size(), size_t(kShooterSplits * kShooterSplits));

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

TEST(ShooterPoints, OnlyTheCeilingsPatchesOverTheLampAreInTheGapThoseBesideItShootFromTheirCentroids)
{
    // The ceiling is cut along the lamp's outline (near_outlines.h), so each
    // of its patches lies over the lamp or beside it. Those beside it within
    // the gap ratio see the room, not a slit: they shoot from their
    // centroids, as the rest of the ceiling does.
    const PreparedScene s = test::prepared(lampUnderCeiling());
    const size_t panelTop = test::faceNamed(s, "panel.body.py");
    int over = 0, besideClose = 0;
    for (size_t p = 0; p < s.patches.size(); ++p) {
        if (s.faces[size_t(s.patches[p].properties)].id != "room.body.py")
            continue;
        const std::array<Vec3, 3> t = cornersOf(s, s.patches[p].vertices);
        const Vec3& c = s.patches[p].centroid;
        const bool isOver = c.x > kPanelMin.x && c.x < kPanelMax.x && c.z > kPanelMin.z && c.z < kPanelMax.z;
        double longest = 0.0;
        for (int i = 0; i < 3; ++i)
            longest = std::max(longest, glm::distance(t[size_t(i)], t[size_t((i + 1) % 3)]));
        const bool close = polygonGap(t, s.faces[panelTop].polygon) * kGapShooterRatio < longest;
        if (isOver) {
            ++over;
            EXPECT_EQ(shooterKind(s, int(p)), ShooterKind::InGap) << p;
            EXPECT_EQ(gapFace(s, int(p)), int(panelTop)) << p;
        } else if (close) {
            ++besideClose;
            EXPECT_EQ(shooterKind(s, int(p)), ShooterKind::Centre) << p;
            EXPECT_EQ(shooterPoints(s, int(p)).size(), 1u) << p;
        }
    }
    EXPECT_GT(over, 0);
    EXPECT_GT(besideClose, 0) << "patches along the outline, within the gap ratio";
}

TEST(ShooterPoints, APatchOverAPanelThatDoesNotGlowShootsFromFourPoints)
{
    // Over a lamp whose top glows the patch shoots from 16 points; over a
    // panel that does not, the gap is dark and four points do as well.
    model::Scene scene = lampUnderCeiling();
    scene.objects.back().parts.front().material = "wall";
    const PreparedScene s = test::prepared(scene);
    const int over = patchOverThePanel(s);
    ASSERT_GE(over, 0);
    ASSERT_EQ(shooterKind(s, over), ShooterKind::InGap);
    const std::vector<Vec3> points = shooterPoints(s, over);
    ASSERT_EQ(points.size(), size_t(kDarkGapShooterSplits * kDarkGapShooterSplits));
    // The centroids of the patch's four equal triangles: inside it, their
    // mean its centroid.
    const std::array<Vec3, 3> t = cornersOf(s, s.patches[size_t(over)].vertices);
    const std::vector<Vec3> expected = subCentroids(t, kDarkGapShooterSplits);
    ASSERT_EQ(expected.size(), points.size());
    Vec3 mean{0.0};
    for (size_t q = 0; q < points.size(); ++q) {
        EXPECT_NEAR(glm::distance(points[q], expected[q]), 0.0, 1e-12) << q;
        mean += points[q] / double(points.size());
    }
    EXPECT_NEAR(glm::distance(mean, s.patches[size_t(over)].centroid), 0.0, 1e-12);
    // Its four elements each speak through one point (pointWeights).
    const std::vector<double> w = pointWeights(s, over, points);
    for (size_t e = 0; e < size_t(s.patches[size_t(over)].elementCount); ++e) {
        double sum = 0.0;
        for (size_t q = 0; q < points.size(); ++q)
            sum += w[e * points.size() + q];
        EXPECT_NEAR(sum, 1.0, 1e-12) << e;
    }
}

TEST(ShooterPoints, AnElementSmallerThanThePointsAreApartSpeaksThroughTheNearestAndABigOneThroughAllInside)
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

TEST(ShooterPoints, WhatACeilingPatchSendsThroughTheSlitReachesTheWallsAsRaysSay)
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
    const std::vector<double> factors = rowOfAlone(s, over);
    ASSERT_FALSE(factors.empty());

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

TEST(ShooterPoints, TheBooksStayExact)
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

TEST(ShooterPoints, AWallPatchBehindANarrowFaceShootsFromSixteenPointsBehindAWideOrCoveredOneFromItsCentroid)
{
    const Vec3 c = wallPatchCentroid();
    // A shelf board 20 cm wide and 3 cm thick, its end 0.23 m in front of
    // the wall (3 cm across: narrow), and a slab 1 m wide behind it, 0.2 m
    // in front of the wall (wide), against which the board's end rests.
    const Vec3 boardMin{c.x - 0.1, c.y - 0.015, 0.23}, boardMax{c.x + 0.1, c.y + 0.015, 0.63};
    const Vec3 slabMin{c.x - 0.5, 0.0, 0.2}, slabMax{c.x + 0.5, 1.5, 0.23};
    const auto pointsOf = [&](bool board, bool slab) {
        model::Scene scene = wallRoom();
        if (board)
            test::addBox(scene, "board", boardMin, boardMax, "wood");
        if (slab)
            test::addBox(scene, "slab", slabMin, slabMax, "wood");
        const PreparedScene s = test::prepared(scene);
        return shooterPoints(s, patchNearest(s, kWall, c)).size();
    };
    EXPECT_EQ(pointsOf(true, false), size_t(kShooterSplits * kShooterSplits)) << "the board's end alone";
    EXPECT_EQ(pointsOf(false, true), 1u) << "the slab alone";
    EXPECT_EQ(pointsOf(true, true), 1u) << "the board's end, covered by the slab, hides nothing";
    EXPECT_EQ(pointsOf(false, false), 1u) << "nothing in front";
    EXPECT_NEAR(polygonWidth(std::vector<Vec3>{{0, 0, 0}, {0.2, 0, 0}, {0.2, 0.03, 0}, {0, 0.03, 0}}), 0.03, 1e-15);
}

TEST(ShooterPoints, WhatAWallPatchSendsPastALegReachesTheLegBehindAndTheLegsSidesAsRaysSay)
{
    // The wall patch behind two legs in line shoots alone: its factors to
    // the back leg's face towards the wall and to the front leg's sides
    // against the ray-cast reference (the contour formula over 64 points
    // of the patch, each times the fraction of 16 rays to the element that
    // miss both legs): -3.6 % and -1.0 % here. From its centre alone the
    // patch sent neither anything: the front leg hid the back leg's face
    // whole, and the centre lies between the planes of the front leg's
    // sides, which most of the patch sees.
    const Vec3 c = wallPatchCentroid();
    const Legs legs = legsBehind(c);
    model::Scene scene = wallRoom();
    test::addBox(scene, "front", legs.frontMin, legs.frontMax, "wood");
    test::addBox(scene, "back", legs.backMin, legs.backMax, "wood");
    const PreparedScene s = test::prepared(scene);
    const int shooter = patchNearest(s, kWall, c);
    ASSERT_GE(shooter, 0);
    ASSERT_EQ(shooterPoints(s, shooter).size(), size_t(kShooterSplits * kShooterSplits));
    const Patch& patch = s.patches[size_t(shooter)];
    ASSERT_TRUE(boxBlocks(patch.centroid, {c.x, c.y, legs.backMin.z}, legs.frontMin, legs.frontMax))
        << "the premise: the front leg hides the back leg's face from the patch's centre";

    const std::vector<double> factors = rowOfAlone(s, shooter);
    ASSERT_FALSE(factors.empty());

    const std::vector<Vec3> from = subCentroids(cornersOf(s, patch.vertices), 8);
    const Vec3 normal{0.0, 0.0, 1.0};
    std::map<std::string, std::pair<double, double>> sums; // solver, reference
    for (size_t e = 0; e < s.elements.size(); ++e) {
        const std::string& id = s.faces[size_t(s.elements[e].properties)].id;
        if (id != "back.body.nz" && id != "front.body.nx" && id != "front.body.px")
            continue;
        const std::array<Vec3, 3> t = cornersOf(s, s.elements[e].vertices);
        std::vector<Vec3> to = subCentroids(t, 4);
        for (Vec3& y : to)
            y += s.elements[e].normal * 1e-6;
        double f = 0.0;
        for (const Vec3& x : from) {
            int open = 0;
            for (const Vec3& y : to)
                open += boxBlocks(x, y, legs.frontMin, legs.frontMax) || boxBlocks(x, y, legs.backMin, legs.backMax)
                            ? 0
                            : 1;
            if (open > 0)
                f += pointToPolygonFormFactor(x, normal, std::vector<Vec3>(t.begin(), t.end())) * open /
                     double(to.size());
        }
        const std::string group = id == "back.body.nz" ? "the back leg's face" : "the front leg's sides";
        sums[group].first += factors[e];
        sums[group].second += f / double(from.size());
    }
    ASSERT_EQ(sums.size(), 2u);
    for (const auto& [group, pair] : sums) {
        const auto [solver, reference] = pair;
        std::printf("%s: solver %.6f reference %.6f (%+.2f %%)\n", group.c_str(), solver, reference,
                    100.0 * (solver - reference) / reference);
        ASSERT_GT(reference, 0.0);
        EXPECT_NEAR(solver, reference, 0.05 * reference) << group;
    }
}
