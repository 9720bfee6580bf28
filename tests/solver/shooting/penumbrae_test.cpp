// The penumbrae of solids standing on a face (solver/shooting/penumbrae.h),
// whose elements the refinement splits before the first shot
// (solver/shooting/adaptive_refinement.h). The closed room's block,
// [1, 2] x [0, 1] x [1, 2], stands under a lamp of the same square at
// height 2.4: from a lamp corner, the block's top corners fall on the floor
// 2.4 / 1.4 times as far from it as they are, so each corner's shadow is a
// square 1 + 1/1.4 * 1 = 1.714 m wide, and together they reach from 0.286 to
// 2.714 m on both axes; the umbra is the block's footprint.
#include "solver/shooting/penumbrae.h"

#include "solver/shooting/adaptive_refinement.h"

#include "support/adaptive_scenes.h"
#include "support/prepared_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace regio;
using namespace regio::solver;
using model::Vec3;

namespace {

constexpr double kReach = 2.4 / 1.4; // how far a lamp corner's shadow reaches past the block, per metre of it
constexpr double kOuterLo = 2.0 - kReach, kOuterHi = 1.0 + kReach;

AdaptiveMesh meshOf(PreparedScene& scene)
{
    const std::vector<Rgb> zero(scene.elements.size(), Rgb{0.0});
    return AdaptiveMesh(scene, zero, zero);
}

// A second lamp of the near one's size at the far end of the room, with its
// own emission.
void addFarLamp(model::Scene& scene, double emission)
{
    test::addMaterial(scene, "far-lamp", Rgb{0.5}, Rgb{emission});
    test::addPolygon(scene, "far-lamp", {{1, 2.4, 2.9}, {2, 2.4, 2.9}, {2, 2.4, 3.9}, {1, 2.4, 3.9}}, "far-lamp");
}

// Where an element's corners and centroid lie against the square
// [lo, hi]^2 on the floor: all strictly inside, all strictly outside, or
// neither (on its outline: not judged).
enum class Side { Inside, Outside, Across };
Side sideOf(const PreparedScene& s, int e, double lo, double hi)
{
    const Element& element = s.elements[size_t(e)];
    const Vec3 points[4] = {s.vertices[size_t(element.vertices[0])], s.vertices[size_t(element.vertices[1])],
                            s.vertices[size_t(element.vertices[2])], element.centroid};
    int inside = 0, outside = 0;
    for (const Vec3& p : points) {
        const double eps = 1e-6;
        if (p.x > lo + eps && p.x < hi - eps && p.z > lo + eps && p.z < hi - eps)
            ++inside;
        else if (p.x < lo - eps || p.x > hi + eps || p.z < lo - eps || p.z > hi + eps)
            ++outside;
    }
    return inside == 4 ? Side::Inside : outside == 4 ? Side::Outside : Side::Across;
}

} // namespace

TEST(Penumbrae, ABlockUnderASquareLampCastsOneShadowFromEachLampCorner)
{
    PreparedScene s = test::prepared(test::closedRoom());
    const std::vector<Penumbra> found = penumbrae(s);
    ASSERT_EQ(found.size(), 1u) << "the block on the floor, under the one lamp";
    const Penumbra& penumbra = found[0];
    EXPECT_EQ(size_t(penumbra.face), test::faceNamed(s, "room.body.ny"));
    ASSERT_EQ(penumbra.shadows.size(), 4u);
    for (const std::vector<Vec3>& shadow : penumbra.shadows) {
        EXPECT_NEAR(model::polygonArea(shadow), kReach * kReach, 1e-9);
        for (const Vec3& p : shadow)
            EXPECT_NEAR(p.y, 0.0, 1e-12);
    }
    EXPECT_NEAR(penumbra.bounds.min.x, kOuterLo, 1e-9);
    EXPECT_NEAR(penumbra.bounds.min.z, kOuterLo, 1e-9);
    EXPECT_NEAR(penumbra.bounds.max.x, kOuterHi, 1e-9);
    EXPECT_NEAR(penumbra.bounds.max.z, kOuterHi, 1e-9);
    // Direct light at the footprint's centre, 2.4 m below the lamp's centre.
    EXPECT_NEAR(penumbra.weight, 5.0 * 1.0 / (std::numbers::pi * 2.4 * 2.4), 1e-9);
}

TEST(Penumbrae, ALampThatFacesAwayOrHangsBelowTheBlocksTopCastsNone)
{
    model::Scene up = test::closedRoom();
    up.objects.back().parts[0].faces[0].loop = {3, 2, 1, 0}; // the lamp turned to the ceiling
    EXPECT_TRUE(penumbrae(test::prepared(up)).empty());

    model::Scene low = test::closedRoom();
    for (Vec3& v : low.objects.back().parts[0].vertices)
        v.y = 0.9; // below the block's top: its shadow has no end
    EXPECT_TRUE(penumbrae(test::prepared(low)).empty());
}

TEST(Penumbrae, OnlyTheLightsThatSendTheSolidAQuarterOfWhatTheBrightestSendsCount)
{
    // The far lamp sends the footprint's centre (2.4 / 3.06)^2 / 9.37 of its
    // emission over pi, the near one 1 / 5.76: 0.38 times as much for the
    // same emission.
    model::Scene dim = test::closedRoom();
    addFarLamp(dim, 2.5);
    EXPECT_EQ(penumbrae(test::prepared(dim)).size(), 1u);

    model::Scene bright = test::closedRoom();
    addFarLamp(bright, 7.5);
    const std::vector<Penumbra> both = penumbrae(test::prepared(bright));
    ASSERT_EQ(both.size(), 2u);
    EXPECT_GT(both[0].weight, both[1].weight) << "brightest first";
    EXPECT_NEAR(both[0].bounds.max.z, kOuterHi, 1e-9) << "the lamp above the block";
}

TEST(Penumbrae, TheElementsOfTheBandAndNoOthers)
{
    // Every floor point between the outer square and the footprint lies in
    // some corner's shadow and outside another's.
    PreparedScene s = test::prepared(test::closedRoom());
    const AdaptiveMesh mesh = meshOf(s);
    const std::vector<int> found = elementsInPenumbra(mesh, penumbrae(s).at(0));
    int inside = 0, outside = 0;
    for (int e : s.faces[test::faceNamed(s, "room.body.ny")].elements) {
        const bool listed = std::binary_search(found.begin(), found.end(), e);
        switch (sideOf(s, e, kOuterLo, kOuterHi)) {
        case Side::Inside:
            EXPECT_TRUE(listed) << e;
            ++inside;
            break;
        case Side::Outside:
            EXPECT_FALSE(listed) << e;
            ++outside;
            break;
        case Side::Across: break;
        }
    }
    EXPECT_GT(inside, 10);
    EXPECT_GT(outside, 10);
    const std::vector<int>& floor = s.faces[test::faceNamed(s, "room.body.ny")].elements;
    for (int e : found)
        EXPECT_NE(std::find(floor.begin(), floor.end(), e), floor.end()) << e;
}

TEST(Penumbrae, TheRefinementSplitsTheBandTwiceBeforeTheFirstShotOnTopOfItsBudget)
{
    const model::Scene scene = test::closedRoomRefined();
    PreparedScene s = test::prepared(scene);
    const int initial = int(s.elements.size());
    // The band is a quarter of the room's floor: its share of the budget is
    // enough for the first pass, not the second.
    RefinementPolicy policy;
    policy.contactPasses = 0;
    {
        AdaptiveRefinement r(s, scene.solver.adaptive, policy);
        ASSERT_GT(r.splitBeforeFirstShot(), 0);
        const int band = int(elementsInPenumbra(meshOf(s), penumbrae(s).at(0)).size());
        EXPECT_GE(r.penumbraElements(), 3 * band);
        EXPECT_LE(r.penumbraElements(), int(policy.penumbraShare * (policy.growthLimit - 1.0) * initial));
    }
    // With the whole growth budget for it, twice.
    policy.penumbraShare = 1.0;
    AdaptiveRefinement r(s, scene.solver.adaptive, policy);
    const int limit = r.elementLimit();
    const int splits = r.splitBeforeFirstShot();
    ASSERT_GT(splits, 0);
    EXPECT_EQ(r.contactElements(), 0);
    EXPECT_EQ(r.penumbraElements(), 3 * splits);
    EXPECT_EQ(r.elementLimit(), limit + 3 * splits);
    const ActiveScene active = r.takeActiveScene();
    EXPECT_EQ(int(active.scene.elements.size()), initial + 3 * splits);
    // The floor's elements that were wholly inside the band are split
    // twice, into sixteen; those wholly outside it, away from the grading,
    // not at all.
    int fine = 0, kept = 0;
    for (int e : s.faces[test::faceNamed(s, "room.body.ny")].elements) {
        const double area = s.elements[size_t(e)].area;
        if (sideOf(s, e, kOuterLo, kOuterHi) == Side::Inside) {
            const std::vector<ElementLevel>& levels = r.mesh().hierarchy();
            EXPECT_FALSE(levels[size_t(e)].active()) << e;
            for (int child : levels[size_t(e)].children) {
                ASSERT_GE(child, 0);
                ASSERT_FALSE(levels[size_t(child)].active()) << child;
                const int grandchild = levels[size_t(child)].children[0];
                EXPECT_NEAR(r.mesh().scene().elements[size_t(grandchild)].area, area / 16.0, 1e-12);
            }
            ++fine;
        } else if (sideOf(s, e, kOuterLo - 0.5, kOuterHi + 0.5) == Side::Outside) {
            EXPECT_TRUE(r.mesh().isActive(e)) << e;
            ++kept;
        }
    }
    EXPECT_GT(fine, 30);
    EXPECT_GT(kept, 10);
    for (size_t e = 0; e < active.scene.elements.size(); ++e) {
        const Rgb emission = active.scene.properties[size_t(active.scene.elements[e].properties)].emission;
        EXPECT_EQ(active.radiosity[e], emission);
        EXPECT_EQ(active.unshot[e], emission);
    }
}

TEST(Penumbrae, TheRefinementTakesTheBrightestLightsBandsFirstAndNoneThatDoesNotFit)
{
    model::Scene scene = test::closedRoomRefined();
    addFarLamp(scene, 7.5);
    PreparedScene s = test::prepared(scene);
    const std::vector<Penumbra> bands = penumbrae(s);
    ASSERT_EQ(bands.size(), 2u);
    const AdaptiveMesh before = meshOf(s);
    const std::vector<int> nearBand = elementsInPenumbra(before, bands[0]);
    const std::vector<int> farBand = elementsInPenumbra(before, bands[1]);
    std::vector<int> farOnly;
    std::set_difference(farBand.begin(), farBand.end(), nearBand.begin(), nearBand.end(), std::back_inserter(farOnly));
    ASSERT_FALSE(farOnly.empty());

    // A budget of the near lamp's band, once: the far lamp's does not fit.
    RefinementPolicy policy;
    policy.contactPasses = 0;
    policy.penumbraPasses = 1;
    policy.penumbraShare =
        (3.0 * double(nearBand.size()) + 1.5) / ((policy.growthLimit - 1.0) * double(s.elements.size()));
    AdaptiveRefinement r(s, scene.solver.adaptive, policy);
    ASSERT_GT(r.splitBeforeFirstShot(), 0);
    for (int e : nearBand)
        EXPECT_FALSE(r.mesh().isActive(e)) << e;
    EXPECT_TRUE(std::any_of(farOnly.begin(), farOnly.end(), [&](int e) { return r.mesh().isActive(e); }));

    // No budget: no band.
    policy.penumbraShare = 0.0;
    AdaptiveRefinement none(s, scene.solver.adaptive, policy);
    EXPECT_EQ(none.splitBeforeFirstShot(), 0);
    EXPECT_EQ(none.penumbraElements(), 0);
}
