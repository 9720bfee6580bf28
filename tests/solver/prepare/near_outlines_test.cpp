// A face hanging just in front of another cuts it along its outline
// (solver/prepare/near_outlines.h), and the elements along that outline are
// split before the first shot (solver/shooting/adaptive_refinement.h).
#include "solver/prepare/near_outlines.h"

#include "solver/shooting/adaptive_refinement.h"
#include "solver/shooting/contact_lines.h"

#include "support/prepared_scenes.h"
#include "support/solver_test_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

using namespace regio;
using namespace regio::solver;
using model::Vec3;

namespace {

// The lamp's footprint on the ceiling, off the patch grid.
constexpr double kX0 = 0.93, kX1 = 1.87, kZ0 = 1.17, kZ1 = 2.11;

// A closed 3 x 2.5 x 3 m room with 0.5 m patches and a lamp 4 cm thick whose
// top hangs `gap` under the ceiling.
model::Scene roomWithLampUnderCeiling(double gap)
{
    model::Scene scene;
    test::addMaterial(scene, "wall", Rgb{0.7});
    test::addMaterial(scene, "lamp", Rgb{0.8}, Rgb{12.0});
    test::addBox(scene, "room", {0, 0, 0}, {3, 2.5, 3}, "wall", true);
    test::addBox(scene, "lamp", {kX0, 2.46 - gap, kZ0}, {kX1, 2.5 - gap, kZ1}, "lamp");
    scene.solver.patchSize = 0.5;
    return scene;
}

// How many of the face's patches have corners both inside and outside the
// lamp's footprint (more than a millimetre from its outline).
int patchesAcrossTheOutline(const PreparedScene& s, const std::string& face)
{
    const InputFace& f = s.faces[test::faceNamed(s, face)];
    int across = 0;
    for (int p = f.firstPatch; p < f.firstPatch + f.patchCount; ++p) {
        bool inside = false, outside = false;
        for (int v : s.patches[size_t(p)].vertices) {
            const Vec3& x = s.vertices[size_t(v)];
            const double inward = std::min({x.x - kX0, kX1 - x.x, x.z - kZ0, kZ1 - x.z});
            inside = inside || inward > 1e-3;
            outside = outside || inward < -1e-3;
        }
        across += inside && outside ? 1 : 0;
    }
    return across;
}

} // namespace

TEST(NearOutlines, ACeilingIsCutAlongTheOutlineOfALampHangingJustUnderIt)
{
    // 2 cm under the ceiling, a 25th of a patch: no patch of the ceiling
    // straddles the lamp's outline.
    const PreparedScene near = test::prepared(roomWithLampUnderCeiling(0.02));
    EXPECT_EQ(patchesAcrossTheOutline(near, "room.body.py"), 0);
    // 30 cm under it, beyond a tenth of a patch: the ceiling is meshed as if
    // the lamp were not there, and patches do straddle the outline.
    const PreparedScene far = test::prepared(roomWithLampUnderCeiling(0.3));
    EXPECT_GT(patchesAcrossTheOutline(far, "room.body.py"), 0);
    // A panel that does not glow leaves the gap dark, and the ceiling is
    // cut all the same: the light falls off across the outline from outside
    // (a dark ring around the panel on a ceiling that is not).
    model::Scene dark = roomWithLampUnderCeiling(0.02);
    dark.objects.back().parts.front().material = "wall";
    const PreparedScene unlit = test::prepared(dark);
    EXPECT_EQ(patchesAcrossTheOutline(unlit, "room.body.py"), 0);
}

TEST(NearOutlines, OnlyTheCeilingIsCutAndOnlyAlongTheLampsTop)
{
    // The lamp's sides stand at right angles to the ceiling and its bottom
    // turns its back on it: the ceiling's cuts are the top's four edges, and
    // the floor, 2.4 m away, has none.
    const PreparedScene near = test::prepared(roomWithLampUnderCeiling(0.02));
    const PreparedScene far = test::prepared(roomWithLampUnderCeiling(0.3));
    EXPECT_EQ(near.faces[test::faceNamed(near, "room.body.ny")].patchCount,
              far.faces[test::faceNamed(far, "room.body.ny")].patchCount);
    EXPECT_GT(near.faces[test::faceNamed(near, "room.body.py")].patchCount,
              far.faces[test::faceNamed(far, "room.body.py")].patchCount);
    // The lamp's top is cut along nothing: the ceiling's outline lies
    // outside it.
    EXPECT_EQ(near.faces[test::faceNamed(near, "lamp.body.py")].patchCount,
              far.faces[test::faceNamed(far, "lamp.body.py")].patchCount);
}

TEST(NearOutlines, TheElementsAlongTheOutlineAreSplitBeforeTheFirstShotOnBothSides)
{
    const model::Scene scene = roomWithLampUnderCeiling(0.02);
    PreparedScene s = test::prepared(scene);
    const std::vector<std::vector<std::vector<Vec3>>> outlines = nearOutlines(s);
    const size_t ceiling = test::faceNamed(s, "room.body.py");
    ASSERT_EQ(outlines[ceiling].size(), 1u) << "the lamp's top";
    for (size_t f = 0; f < outlines.size(); ++f) {
        if (f != ceiling) {
            EXPECT_TRUE(outlines[f].empty()) << s.faces[f].id;
        }
    }

    // Before: the ceiling's elements with a corner on the outline, inside it
    // and outside.
    const std::vector<Rgb> zero(s.elements.size(), Rgb{0.0});
    const AdaptiveMesh before(s, zero, zero);
    const std::vector<int> along = elementsOnNearOutlines(before, outlines);
    ASSERT_FALSE(along.empty());
    double coarse = 0.0;
    int inside = 0, outside = 0;
    for (int e : along) {
        const Vec3 c = s.elements[size_t(e)].centroid;
        const bool in = c.x > kX0 && c.x < kX1 && c.z > kZ0 && c.z < kZ1;
        ++(in ? inside : outside);
        coarse = std::max(coarse, s.elements[size_t(e)].area);
    }
    EXPECT_GT(inside, 0);
    EXPECT_GT(outside, 0);

    // Three passes, on top of the growth budget: the elements along the
    // outline are an eighth of the size of the coarsest before.
    RefinementPolicy policy;
    policy.penumbraPasses = 0;
    AdaptiveRefinement r(s, scene.solver.adaptive, policy);
    const int splits = r.splitBeforeFirstShot();
    ASSERT_GT(splits, 0);
    EXPECT_EQ(r.contactElements(), 3 * splits);
    ActiveScene active = r.takeActiveScene();
    const std::vector<Rgb> none(active.scene.elements.size(), Rgb{0.0});
    const AdaptiveMesh after(active.scene, none, none);
    const std::vector<int> fine = elementsOnNearOutlines(after, nearOutlines(active.scene));
    ASSERT_GT(fine.size(), along.size());
    for (int e : fine)
        EXPECT_LE(active.scene.elements[size_t(e)].area, coarse / 64.0 + 1e-12) << e;

    // Without the passes nothing along the outline is split.
    policy.outlinePasses = 0;
    policy.contactPasses = 0;
    AdaptiveRefinement unsplit(s, scene.solver.adaptive, policy);
    EXPECT_EQ(unsplit.splitBeforeFirstShot(), 0);
}

TEST(NearOutlines, AFaceWithMoreThanEightHangingInFrontOfItIsLeftWhole)
{
    // Nine panels 0.3 m square, 2 cm under the ceiling: their lines would
    // run across the whole ceiling. Eight are cut along; the ninth leaves
    // the ceiling whole, as many solids on a floor draw no shadow lines.
    for (const int panels : {8, 9}) {
        model::Scene scene = roomWithLampUnderCeiling(0.3);
        for (int i = 0; i < panels; ++i) {
            const double x = 0.3 + 0.9 * (i % 3), z = 0.3 + 0.9 * (i / 3);
            test::addBox(scene, "panel" + std::to_string(i), {x, 2.44, z}, {x + 0.3, 2.48, z + 0.3}, "lamp");
        }
        const PreparedScene s = test::prepared(scene);
        const std::vector<std::vector<std::vector<Vec3>>> outlines = nearOutlines(s);
        EXPECT_EQ(outlines[test::faceNamed(s, "room.body.py")].size(), panels == 8 ? 8u : 0u) << panels;
    }
}
