// HemicubeRenderer: the five faces split between threads paint the item
// buffer one thread paints, pixel for pixel, in both visibility modes.
#include "solver/prepare/prepare.h"
#include "solver/visibility/hemicube_renderer.h"
#include "support/furnished_room.h"
#include "support/sample_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>

using namespace regio;
using namespace regio::solver;

namespace {

PreparedScene prepare(const model::Scene& scene, RegionsMode regions = RegionsMode::Authored)
{
    PrepareOptions options;
    options.regions = regions;
    model::Result<PreparedScene> r = prepareScene(scene, options);
    EXPECT_TRUE(r.ok());
    return r.ok() ? std::move(*r) : PreparedScene{};
}

// Renders every `stride`-th patch with 1, 2 and 3 threads and compares the
// whole item buffers and the statistics.
void expectSameForAnyThreadCount(const PreparedScene& p, model::Visibility mode, int resolution, size_t stride)
{
    const Hemicube h(resolution);
    HemicubeRenderer one(p, h, mode, 1);
    HemicubeRenderer two(p, h, mode, 2);
    HemicubeRenderer three(p, h, mode, 3);
    ASSERT_EQ(one.threads(), 1);
    ASSERT_EQ(two.threads(), 2);
    ASSERT_EQ(three.threads(), 3);
    ItemBuffer a = one.makeBuffer(), b = two.makeBuffer(), c = three.makeBuffer();
    int compared = 0;
    for (size_t i = 0; i < p.patches.size(); i += stride) {
        const ShooterFrame frame = shooterFrameOfPatch(p, static_cast<int>(i));
        ASSERT_TRUE(one.render(frame, a));
        ASSERT_TRUE(two.render(frame, b));
        ASSERT_TRUE(three.render(frame, c));
        ASSERT_TRUE(std::ranges::equal(a.all(), b.all())) << "patch " << i;
        ASSERT_TRUE(std::ranges::equal(a.all(), c.all())) << "patch " << i;
        ++compared;
    }
    EXPECT_GT(compared, 5);
    EXPECT_EQ(one.stats().elementsVisited, two.stats().elementsVisited);
    EXPECT_EQ(one.stats().elementsRasterised, three.stats().elementsRasterised);
    EXPECT_EQ(one.stats().regionsCulled, three.stats().regionsCulled);
}

} // namespace

TEST(HemicubeRenderer, PaintsTheSampleRoomAsOneThreadDoesInBothModes)
{
    const PreparedScene p = prepare(test::loadSample("two-lights-room"));
    expectSameForAnyThreadCount(p, model::Visibility::Painter, 100, 7);
    expectSameForAnyThreadCount(p, model::Visibility::ZBuffer, 100, 7);
}

TEST(HemicubeRenderer, PaintsAFurnishedRoomWithManyRegionsAsOneThreadDoes)
{
    const PreparedScene p = prepare(test::furnishedRoom(12, 20), RegionsMode::Auto);
    ASSERT_GT(p.regions.size(), 1u);
    expectSameForAnyThreadCount(p, model::Visibility::Painter, 64, p.patches.size() / 12);
}

TEST(HemicubeRenderer, AskingForMoreThreadsThanFaceGroupsUsesThree)
{
    const PreparedScene p = prepare(test::loadSample("cornell-box"));
    const Hemicube h(32);
    EXPECT_EQ(HemicubeRenderer(p, h, model::Visibility::Painter, 8).threads(), 3);
    EXPECT_GE(HemicubeRenderer(p, h, model::Visibility::Painter, 0).threads(), 1);
    EXPECT_EQ(resolveThreadCount(5), 5);
    EXPECT_GE(resolveThreadCount(0), 1);
}

TEST(HemicubeRenderer, ACancelledRenderReportsItOnEveryThreadCount)
{
    const PreparedScene p = prepare(test::loadSample("two-lights-room"));
    const Hemicube h(64);
    const std::atomic<bool> cancel{true};
    for (int threads : {1, 2, 3}) {
        HemicubeRenderer r(p, h, model::Visibility::Painter, threads);
        ItemBuffer b = r.makeBuffer();
        EXPECT_FALSE(r.render(shooterFrameOfPatch(p, 0), b, &cancel)) << threads << " threads";
        // And it renders again afterwards.
        EXPECT_TRUE(r.render(shooterFrameOfPatch(p, 0), b));
    }
}
