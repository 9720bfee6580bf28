// HemicubeRenderer: stretches of the paint order painted on several threads
// and merged make the item buffer one thread paints, pixel for pixel, in both
// visibility modes.
#include "solver/prepare/prepare.h"
#include "solver/visibility/hemicube_renderer.h"
#include "support/adaptive_scenes.h"
#include "support/furnished_room.h"
#include "support/prepared_scenes.h"
#include "support/sample_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <utility>
#include <vector>

using namespace regio;
using namespace regio::solver;

namespace {

// Renders every `stride`-th patch with 1, 2, 3 and 5 threads, split either
// way, and compares the whole item buffers and the statistics.
void expectSameForAnyThreadCount(const PreparedScene& p, model::Visibility mode, int resolution, size_t stride)
{
    const Hemicube h(resolution);
    for (auto [threads, split] :
         {std::pair{2, RenderSplit::Order}, std::pair{3, RenderSplit::Order}, std::pair{5, RenderSplit::Order},
          std::pair{2, RenderSplit::Faces}, std::pair{3, RenderSplit::Faces}, std::pair{5, RenderSplit::Faces}}) {
        SCOPED_TRACE(split == RenderSplit::Order ? "order split" : "face split");
        HemicubeRenderer one(p, h, mode, 1);
        HemicubeRenderer many(p, h, mode, threads);
        many.forceSplit(split);
        ASSERT_EQ(one.threads(), 1);
        ASSERT_EQ(many.threads(), threads);
        ItemBuffer a = one.makeBuffer(), b = many.makeBuffer();
        int compared = 0;
        for (size_t i = 0; i < p.patches.size(); i += stride) {
            const ShooterFrame frame = shooterFrameOfPatch(p, static_cast<int>(i));
            ASSERT_TRUE(one.render(frame, a));
            ASSERT_TRUE(many.render(frame, b));
            ASSERT_TRUE(std::ranges::equal(a.all(), b.all())) << "patch " << i << ", " << threads << " threads";
            ++compared;
        }
        EXPECT_GT(compared, 5);
        EXPECT_EQ(one.stats().elementsVisited, many.stats().elementsVisited);
        EXPECT_EQ(one.stats().elementsRasterised, many.stats().elementsRasterised);
        EXPECT_EQ(one.stats().regionsCulled, many.stats().regionsCulled);
    }
}

} // namespace

TEST(HemicubeRenderer, PaintsTheSampleRoomAsOneThreadDoesInBothModes)
{
    const PreparedScene p = test::prepared(test::loadSample("two-lights-room"));
    expectSameForAnyThreadCount(p, model::Visibility::Painter, 100, 7);
    expectSameForAnyThreadCount(p, model::Visibility::ZBuffer, 100, 7);
}

TEST(HemicubeRenderer, PaintsAFurnishedRoomWithManyRegionsAsOneThreadDoes)
{
    const PreparedScene p = test::prepared(test::furnishedRoom(12, 20), RegionsMode::Auto);
    ASSERT_GT(p.regions.size(), 1u);
    expectSameForAnyThreadCount(p, model::Visibility::Painter, 64, p.patches.size() / 12);
}

TEST(HemicubeRenderer, PaintsAsOneThreadDoesWhenThreadsOutnumberThePieces)
{
    PrepareOptions options;
    options.patchSize = 100.0; // one patch and one element per face
    options.elementsPerPatch = 1;
    model::Scene scene;
    test::addMaterial(scene, "wall", {0.5, 0.6, 0.7});
    test::addBox(scene, "room", {0, 0, 0}, {3, 2.5, 4}, "wall", true);
    test::addBox(scene, "shelf", {1, 1, 1}, {2, 1.2, 2}, "wall"); // floating: no contact points
    const PreparedScene p = test::prepared(scene, options);
    ASSERT_LT(p.pieces.size(), 5u * HemicubeRenderer::kMaxThreads);
    const Hemicube h(32);
    HemicubeRenderer one(p, h, model::Visibility::Painter, 1);
    HemicubeRenderer many(p, h, model::Visibility::Painter, HemicubeRenderer::kMaxThreads);
    ItemBuffer a = one.makeBuffer(), b = many.makeBuffer();
    for (size_t i = 0; i < p.patches.size(); ++i) {
        ASSERT_TRUE(one.render(shooterFrameOfPatch(p, static_cast<int>(i)), a));
        ASSERT_TRUE(many.render(shooterFrameOfPatch(p, static_cast<int>(i)), b));
        ASSERT_TRUE(std::ranges::equal(a.all(), b.all())) << "patch " << i;
    }
}

TEST(HemicubeRenderer, TimesBothSplitsAlternatelyThenKeepsOne)
{
    const PreparedScene p = test::prepared(test::loadSample("two-lights-room"));
    const Hemicube h(64);
    HemicubeRenderer r(p, h, model::Visibility::Painter, 2);
    ItemBuffer b = r.makeBuffer();
    size_t order = 0, faces = 0;
    for (int i = 0; i < 2 * static_cast<int>(HemicubeRenderer::kTimedShots); ++i) {
        (r.split() == RenderSplit::Order ? order : faces) += 1;
        ASSERT_TRUE(r.render(shooterFrameOfPatch(p, i), b));
    }
    EXPECT_EQ(order, HemicubeRenderer::kTimedShots);
    EXPECT_EQ(faces, HemicubeRenderer::kTimedShots);
    const RenderSplit kept = r.split();
    for (int i = 0; i < 4; ++i) {
        ASSERT_TRUE(r.render(shooterFrameOfPatch(p, i), b));
        EXPECT_EQ(r.split(), kept);
    }
}

TEST(HemicubeRenderer, UsesAtMostItsMostThreads)
{
    const PreparedScene p = test::prepared(test::loadSample("cornell-box"));
    const Hemicube h(32);
    EXPECT_EQ(HemicubeRenderer(p, h, model::Visibility::Painter, 64).threads(), HemicubeRenderer::kMaxThreads);
    EXPECT_GE(HemicubeRenderer(p, h, model::Visibility::Painter, 0).threads(), 1);
    EXPECT_EQ(resolveThreadCount(5), 5);
    EXPECT_GE(resolveThreadCount(0), 1);
}

TEST(HemicubeRenderer, ACancelledRenderReportsItOnEveryThreadCount)
{
    const PreparedScene p = test::prepared(test::loadSample("two-lights-room"));
    const Hemicube h(64);
    const std::atomic<bool> cancel{true};
    for (int threads : {1, 2, 5}) {
        HemicubeRenderer r(p, h, model::Visibility::Painter, threads);
        r.forceSplit(threads == 5 ? RenderSplit::Faces : RenderSplit::Order);
        ItemBuffer b = r.makeBuffer();
        EXPECT_FALSE(r.render(shooterFrameOfPatch(p, 0), b, &cancel)) << threads << " threads";
        // And it renders again afterwards.
        EXPECT_TRUE(r.render(shooterFrameOfPatch(p, 0), b));
    }
}

TEST(HemicubeRenderer, RunsOtherWorkOnItsThreadsEveryIndexOnce)
{
    const PreparedScene p = test::prepared(test::loadSample("cornell-box"));
    const Hemicube h(32);
    for (int threads : {1, 2, 5}) {
        HemicubeRenderer r(p, h, model::Visibility::Painter, threads);
        for (size_t count : {size_t(0), size_t(1), size_t(3), size_t(1000)}) {
            std::vector<std::atomic<int>> seen(count);
            r.parallelFor(count, [&](size_t begin, size_t end) {
                for (size_t i = begin; i < end; ++i)
                    seen[i].fetch_add(1);
            });
            EXPECT_TRUE(std::ranges::all_of(seen, [](const std::atomic<int>& n) { return n.load() == 1; }))
                << count << " indices on " << threads << " threads";
        }
        // And it renders afterwards.
        ItemBuffer b = r.makeBuffer();
        EXPECT_TRUE(r.render(shooterFrameOfPatch(p, 0), b));
    }
}
