// Suggested BSP root orders (§5.3, Thibault and Naylor 1987): the order the
// greedy heuristic proposes is reproduced exactly by the solver's builder,
// names only faces of its region, and splits no more than scene order.
#include "solver/authoring/bsp_suggest.h"

#include "model/edit/edit_regions.h"
#include "model/geometry/primitives.h"
#include "model/geometry/region_clip.h"
#include "model/validation/validation.h"
#include "solver/prepare/bsp_tree.h"
#include "support/furnished_room.h"
#include "support/sample_scenes.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <set>
#include <unordered_map>

using namespace regio;
using namespace regio::solver;

namespace {

// A scene with one region holding all of `scene`: its single BSP tree, with
// an order the author can edit (scene order to start with).
model::Scene oneRegion(model::Scene scene, std::vector<std::string> order = {})
{
    PrepareOptions options;
    options.regions = RegionsMode::None;
    model::Result<PreparedScene> prepared = prepareBsp(scene, options);
    EXPECT_TRUE(prepared.ok());
    model::Region region;
    region.id = "all";
    region.min = prepared->bounds.min - model::Vec3(0.01);
    region.max = prepared->bounds.max + model::Vec3(0.01);
    region.bspOrder = std::move(order);
    scene.regions = {region};
    return scene;
}

BspFigures regionFigures(const model::Scene& scene, const std::string& regionId)
{
    model::Result<SceneBspFigures> result = computeBspFigures(scene);
    EXPECT_TRUE(result.ok());
    if (!result.ok())
        return {};
    const int r = result->regionIndex(regionId);
    EXPECT_GE(r, 0) << regionId;
    return r >= 0 ? result->regions[size_t(r)].figures : BspFigures{};
}

model::Scene applied(model::Scene scene, const BspOrderSuggestion& suggestion)
{
    EXPECT_TRUE(model::setBspOrder(scene, suggestion.regionId, suggestion.order));
    return scene;
}

void expectNoBspOrderProblems(const model::Scene& scene)
{
    for (const model::Diagnostic& d : model::validateScene(scene))
        EXPECT_EQ(d.pointer.find("/bspOrder"), std::string::npos) << d.pointer << ": " << d.message;
}

// A box A under a plate B that overhangs it on both sides: in scene order A's
// side faces come first and their planes cut B.
model::Scene boxUnderPlate()
{
    model::Scene scene;
    scene.materials.push_back({"white", "", {0.5, 0.5, 0.5}, {1, 1, 1}});
    scene.objects.push_back({"a", "", {*model::makeBox("a.body", {0, 0, 0}, {1, 1, 1}, "white")}});
    scene.objects.push_back({"b", "", {*model::makeBox("b.plate", {-1, 2, 0}, {2, 2.1, 1}, "white")}});
    return scene;
}

} // namespace

// The cells the suggestion starts from (prepareBspInput) rebuild the trees of
// the whole preparation (prepareScene) exactly.
TEST(BspSuggest, TheCellsOfTheBspStageRebuildTheSolversTreesExactly)
{
    for (const model::Scene& scene : {test::loadSample("two-lights-room"), oneRegion(test::furnishedRoom(3, 40))}) {
        model::Result<PreparedScene> prepared = prepareScene(scene);
        ASSERT_TRUE(prepared.ok());
        const PreparedScene& s = *prepared;
        model::Result<BspInput> input = prepareBspInput(scene);
        ASSERT_TRUE(input.ok());
        std::vector<std::vector<FacePolygon>>& cells = input->cells;
        ASSERT_EQ(cells.size(), s.regions.size());

        std::unordered_map<std::string, int> faceIndex;
        for (size_t i = 0; i < s.faces.size(); ++i)
            faceIndex.emplace(s.faces[i].id, int(i));
        for (size_t r = 0; r < cells.size(); ++r) {
            EXPECT_EQ(int(cells[r].size()), s.regions[r].stats.inputFaces);
            // The builder's ranks as prepareScene computes them.
            const std::vector<std::string>& order = scene.regions[r].bspOrder;
            std::vector<int> rank(s.faces.size());
            for (size_t i = 0; i < rank.size(); ++i)
                rank[i] = int(order.size() + i);
            for (size_t i = order.size(); i-- > 0;)
                rank[size_t(faceIndex.at(order[i]))] = int(i);
            PreparedScene scratch;
            scratch.properties = s.properties;
            scratch.regions = s.regions;
            buildRegionBsp(scratch, int(r), cells[r], rank);
            EXPECT_EQ(figuresOf(scratch.regions[r].stats), figuresOf(s.regions[r].stats)) << s.regions[r].id;
        }
    }
}

TEST(BspSuggest, TheSolverBuildsExactlyThePredictedTreeFromTheSuggestedOrder)
{
    const model::Scene room = test::loadSample("two-lights-room");
    auto suggestions = suggestBspOrders(room);
    ASSERT_TRUE(suggestions);
    ASSERT_EQ(suggestions->size(), room.regions.size());
    for (const BspOrderSuggestion& s : *suggestions) {
        EXPECT_FALSE(s.order.empty()) << s.regionId;
        EXPECT_EQ(regionFigures(applied(room, s), s.regionId), s.suggested) << s.regionId;
    }

    const model::Scene furnished = oneRegion(test::furnishedRoom(1, 100));
    auto single = suggestBspOrder(furnished, "all");
    ASSERT_TRUE(single);
    EXPECT_EQ(regionFigures(applied(furnished, *single), "all"), single->suggested);
}

TEST(BspSuggest, ReportsTheCurrentOrdersFiguresAsTheSolverBuildsThem)
{
    const model::Scene room = test::loadSample("two-lights-room");
    for (const model::Region& region : room.regions) {
        auto s = suggestBspOrder(room, region.id);
        ASSERT_TRUE(s) << region.id;
        EXPECT_EQ(s->regionId, region.id);
        EXPECT_EQ(s->current, regionFigures(room, region.id));
    }
}

TEST(BspSuggest, GivesNoMoreFragmentsThanSceneOrderOnTheSampleAndTheFurnishedRoom)
{
    // Scene order: empty bspOrders. Printed for the README.
    model::Scene room = test::loadSample("two-lights-room");
    for (model::Region& region : room.regions)
        region.bspOrder.clear();
    auto suggestions = suggestBspOrders(room);
    ASSERT_TRUE(suggestions);
    for (const BspOrderSuggestion& s : *suggestions) {
        std::printf(
            "two-lights-room %-8s scene order: fragments %4d splits %4d depth %3d | suggested: fragments "
            "%4d splits %4d depth %3d\n",
            s.regionId.c_str(), s.current.fragments, s.current.splits, s.current.depth, s.suggested.fragments,
            s.suggested.splits, s.suggested.depth);
        EXPECT_LE(s.suggested.fragments, s.current.fragments) << s.regionId;
    }

    const model::Scene furnished = oneRegion(test::furnishedRoom(1, 100));
    const auto start = std::chrono::steady_clock::now();
    auto single = suggestBspOrder(furnished, "all");
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    ASSERT_TRUE(single);
    std::printf(
        "furnished-room-100 single BSP  scene order: fragments %5d splits %5d depth %3d | suggested: "
        "fragments %5d splits %5d depth %3d  (%.0f ms)\n",
        single->current.fragments, single->current.splits, single->current.depth, single->suggested.fragments,
        single->suggested.splits, single->suggested.depth, ms);
    EXPECT_LE(single->suggested.fragments, single->current.fragments);
}

TEST(BspSuggest, ChoosesRootsThatSplitNothingWhenTheSceneAllowsIt)
{
    const model::Scene scene = oneRegion(boxUnderPlate());
    auto s = suggestBspOrder(scene, "all");
    ASSERT_TRUE(s);
    EXPECT_GT(s->current.splits, 0) << "scene order starts with a side of the box, whose plane cuts the plate";
    EXPECT_EQ(s->suggested.splits, 0);
    EXPECT_EQ(s->suggested.fragments, 12);
    EXPECT_EQ(regionFigures(applied(scene, *s), "all"), s->suggested);
}

TEST(BspSuggest, ListsOnlyFacesInsideTheRegionAndLeavesOutsidersToSceneOrder)
{
    // Box "c" lies outside the only region; it still lands in that region's
    // cell, but its faces may not be named in the region's order.
    model::Scene scene = boxUnderPlate();
    scene.objects.push_back({"c", "", {*model::makeBox("c.body", {4, 0, 0}, {5, 1, 1}, "white")}});
    model::Region region;
    region.id = "left";
    region.min = {-1.5, -0.5, -0.5};
    region.max = {2.5, 2.5, 1.5};
    scene.regions = {region};

    auto s = suggestBspOrder(scene, "left");
    ASSERT_TRUE(s);
    EXPECT_EQ(s->suggested.inputFaces, 18);
    for (const std::string& id : s->order)
        EXPECT_EQ(id.rfind("c.", 0), std::string::npos) << id;
    const model::Scene withOrder = applied(scene, *s);
    expectNoBspOrderProblems(withOrder);
    EXPECT_EQ(regionFigures(withOrder, "left"), s->suggested);
}

TEST(BspSuggest, NamesEveryFaceOnceAndOnlyFacesOfItsRegion)
{
    const model::Scene room = test::loadSample("two-lights-room");
    auto suggestions = suggestBspOrders(room);
    ASSERT_TRUE(suggestions);
    model::Scene withOrders = room;
    for (const BspOrderSuggestion& s : *suggestions) {
        std::set<std::string> seen(s.order.begin(), s.order.end());
        EXPECT_EQ(seen.size(), s.order.size()) << s.regionId;
        withOrders = applied(withOrders, s);
    }
    expectNoBspOrderProblems(withOrders);
}

TEST(BspSuggest, IsDeterministic)
{
    const model::Scene scene = oneRegion(test::furnishedRoom(5, 30));
    auto a = suggestBspOrder(scene, "all");
    auto b = suggestBspOrder(scene, "all");
    ASSERT_TRUE(a && b);
    EXPECT_EQ(a->order, b->order);
    EXPECT_EQ(a->suggested, b->suggested);
}

TEST(BspSuggest, SamplesCandidatesInLargeSubtreesAndStillPredictsExactly)
{
    SuggestOptions options;
    options.exhaustiveLimit = 10;
    options.sampleSize = 4;
    const model::Scene scene = oneRegion(test::furnishedRoom(2, 25));
    auto s = suggestBspOrder(scene, "all", options);
    ASSERT_TRUE(s);
    EXPECT_EQ(regionFigures(applied(scene, *s), "all"), s->suggested);
}

TEST(BspSuggest, RefusesAnUnknownRegionAndHasNothingToSuggestWithoutRegions)
{
    const model::Scene room = test::loadSample("two-lights-room");
    auto unknown = suggestBspOrder(room, "attic");
    ASSERT_FALSE(unknown);
    EXPECT_NE(unknown.error().message.find("attic"), std::string::npos);

    model::Scene bare = room;
    bare.regions.clear();
    auto none = suggestBspOrders(bare);
    ASSERT_TRUE(none);
    EXPECT_TRUE(none->empty());
}

TEST(BspSuggest, RefusesASceneThatCannotBePrepared)
{
    model::Scene room = test::loadSample("two-lights-room");
    room.objects[0].parts[0].faces[0].material = "no-such-material";
    auto s = suggestBspOrder(room, "west");
    ASSERT_FALSE(s);
    EXPECT_NE(s.error().message.find("material"), std::string::npos);
}
