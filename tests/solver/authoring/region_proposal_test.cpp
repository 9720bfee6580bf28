// Proposed regions: boxes tiling the scene along planes that pass between the
// parts, each with a suggested BSP order; compared with the solver's
// automatic (patch-count) regions and with the single-BSP baseline.
#include "solver/authoring/region_proposal.h"

#include "model/geometry/primitives.h"
#include "model/geometry/region_clip.h"
#include "model/validation/validation.h"
#include "support/furnished_room.h"
#include "support/sample_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>

using namespace regio;
using namespace regio::solver;

namespace {

Box3 boxOf(const model::Region& region)
{
    Box3 box;
    box.extend(region.min);
    box.extend(region.max);
    return box;
}

double volume(const Box3& box)
{
    const Vec3 s = box.size();
    return s.x * s.y * s.z;
}

PrepareOptions noRegions()
{
    PrepareOptions options;
    options.regions = RegionsMode::None;
    return options;
}

PrepareOptions automaticRegions()
{
    PrepareOptions options;
    options.regions = RegionsMode::Auto;
    return options;
}

Box3 sceneBounds(const model::Scene& scene)
{
    model::Result<PreparedScene> prepared = prepareBsp(scene, noRegions());
    EXPECT_TRUE(prepared.ok());
    return prepared.ok() ? prepared->bounds : Box3{};
}

void expectTiling(const std::vector<model::Region>& regions, const Box3& bounds)
{
    double sum = 0.0;
    for (size_t i = 0; i < regions.size(); ++i) {
        const Box3 box = boxOf(regions[i]);
        sum += volume(box);
        EXPECT_TRUE(bounds.contains(box.min) && bounds.contains(box.max)) << regions[i].id;
        for (size_t j = 0; j < i; ++j)
            EXPECT_FALSE(box.overlapsInterior(boxOf(regions[j]))) << regions[i].id << " / " << regions[j].id;
    }
    // Inside the bounds, pairwise disjoint, and as much volume: they cover it.
    EXPECT_NEAR(sum, volume(bounds), 1e-9 * volume(bounds));
}

SceneBspFigures figuresOk(const model::Scene& scene, RegionsMode mode)
{
    model::Result<SceneBspFigures> result = computeBspFigures(scene, {mode});
    EXPECT_TRUE(result.ok());
    return result.ok() ? *result : SceneBspFigures{};
}

// The scene as one region with the suggested order: the best single BSP.
SceneBspFigures suggestedSingleBsp(const model::Scene& scene)
{
    model::Region all;
    all.id = "all";
    const Box3 bounds = sceneBounds(scene);
    all.min = bounds.min;
    all.max = bounds.max;
    model::Scene one = withRegions(scene, {all});
    auto suggestion = suggestBspOrder(one, "all");
    EXPECT_TRUE(suggestion);
    if (suggestion)
        one.regions[0].bspOrder = suggestion->order;
    return figuresOk(one, RegionsMode::Authored);
}

model::Scene withSuggestedOrders(model::Scene scene)
{
    auto suggestions = suggestBspOrders(scene);
    EXPECT_TRUE(suggestions);
    if (suggestions)
        for (size_t r = 0; r < scene.regions.size(); ++r)
            scene.regions[r].bspOrder = (*suggestions)[r].order;
    return scene;
}

void printRow(const char* scene, const char* setup, const SceneBspFigures& f)
{
    std::printf("| %-18s | %-42s | %7zu | %6d | %9d | %6d | %5d |\n", scene, setup, f.regions.size(), f.regionPieces,
                f.fragments, f.splits, f.maxDepth);
}

} // namespace

// Where the sweep puts its planes (the tests below but the last ones): the
// sweep alone, without the comparison with fewer cuts and one region.
RegionProposalOptions sweepOnly()
{
    RegionProposalOptions options;
    options.neverWorseThanOneRegion = false;
    return options;
}

TEST(RegionProposal, TilesTheSceneBoundsWithTouchingBoxes)
{
    for (const model::Scene& scene : {test::loadSample("two-lights-room"), test::furnishedRoom(1, 100)}) {
        const model::Result<RegionProposal> proposal = proposeRegions(scene, sweepOnly());
        ASSERT_GT(proposal->regions.size(), 1u);
        expectTiling(proposal->regions, sceneBounds(scene));
    }
}

TEST(RegionProposal, WithGapsOnlyPlacesItsPlanesBetweenPartsSoOnlyTheRoomShellIsCut)
{
    const model::Scene scene = test::furnishedRoom(1, 100);
    RegionProposalOptions gapsOnly;
    gapsOnly.cutParts = false;
    const model::Result<RegionProposal> proposal = proposeRegions(scene, gapsOnly);
    EXPECT_EQ(proposal->straddlingParts, (std::vector<std::string>{"room.shell"}));
    const model::Scene proposed = withRegions(scene, proposal->regions);
    for (const model::Object& object : proposed.objects)
        for (const model::Part& part : object.parts)
            if (part.id != "room.shell") {
                EXPECT_FALSE(model::partStraddlesRegions(proposed, part)) << part.id;
            }
}

TEST(RegionProposal, GivesAValidSceneWhoseOnlyWarningsAreTheCutPartsAndClippingThemClearsThem)
{
    const model::Scene scene = test::furnishedRoom(1, 100);
    const model::Result<RegionProposal> proposal = proposeRegions(scene);
    ASSERT_FALSE(proposal->straddlingParts.empty());
    EXPECT_EQ(proposal->straddlingParts.front(), "room.shell");
    model::Scene proposed = withRegions(scene, proposal->regions);
    for (const model::Diagnostic& d : model::validateScene(proposed)) {
        EXPECT_FALSE(d.isError()) << d.pointer << ": " << d.message;
        EXPECT_NE(d.message.find("straddles"), std::string::npos) << d.message;
        ASSERT_GE(d.idPath.size(), 2u);
        EXPECT_EQ(std::count(proposal->straddlingParts.begin(), proposal->straddlingParts.end(), d.idPath[1]), 1)
            << d.message;
    }
    for (const std::string& part : proposal->straddlingParts) {
        auto clip = model::clipPartToRegions(proposed, part);
        ASSERT_TRUE(clip) << part << ": " << clip.error().message;
        if (part == "room.shell") {
            EXPECT_EQ(clip->pieces.size(), proposal->regions.size()) << "one piece of the shell per region";
        }
    }
    // Left: no errors, no straddling part. The room's pieces are open shells
    // now (validation warns about open parts that are not flat panels).
    for (const model::Diagnostic& d : model::validateScene(proposed)) {
        EXPECT_FALSE(d.isError()) << d.pointer << ": " << d.message;
        EXPECT_EQ(d.message.find("straddles"), std::string::npos) << d.message;
        EXPECT_EQ(d.message.find("outside every region"), std::string::npos) << d.message;
        if (d.message.find("open shell") != std::string::npos) {
            EXPECT_NE(d.message.find("room.shell-"), std::string::npos) << d.message;
        }
    }
}

TEST(RegionProposal, GivesEachRegionTheSuggestedOrderAndTheSolversFigures)
{
    const model::Scene scene = test::loadSample("two-lights-room");
    const model::Result<RegionProposal> proposal = proposeRegions(scene);
    ASSERT_TRUE(proposal.ok());
    EXPECT_TRUE(proposal.diagnostics().empty());
    const model::Scene proposed = withRegions(scene, proposal->regions);
    auto suggestions = suggestBspOrders(withRegions(scene, [&] {
        std::vector<model::Region> bare = proposal->regions;
        for (model::Region& r : bare)
            r.bspOrder.clear();
        return bare;
    }()));
    ASSERT_TRUE(suggestions);
    for (size_t r = 0; r < proposal->regions.size(); ++r) {
        EXPECT_EQ(proposal->regions[r].bspOrder, (*suggestions)[r].order) << proposal->regions[r].id;
        EXPECT_EQ(proposal->figures.regions[r].figures, (*suggestions)[r].suggested) << proposal->regions[r].id;
    }
    const SceneBspFigures figures = figuresOk(proposed, RegionsMode::Authored);
    EXPECT_EQ(figures.fragments, proposal->figures.fragments);
    EXPECT_EQ(figures.maxDepth, proposal->figures.maxDepth);
}

TEST(RegionProposal, CanLeaveTheOrdersEmpty)
{
    RegionProposalOptions options;
    options.suggestOrders = false;
    const model::Result<RegionProposal> proposal = proposeRegions(test::loadSample("two-lights-room"), options);
    ASSERT_FALSE(proposal->regions.empty());
    for (const model::Region& region : proposal->regions)
        EXPECT_TRUE(region.bspOrder.empty());
}

TEST(RegionProposal, KeepsASmallSceneInOneRegion)
{
    model::Scene scene;
    scene.materials.push_back({"white", "", {0.5, 0.5, 0.5}, {1, 1, 1}});
    scene.objects.push_back({"a", "", {*model::makeBox("a.body", {0, 0, 0}, {1, 1, 1}, "white")}});
    scene.objects.push_back({"b", "", {*model::makeBox("b.body", {2, 0, 0}, {3, 1, 1}, "white")}});
    const model::Result<RegionProposal> proposal = proposeRegions(scene);
    ASSERT_EQ(proposal->regions.size(), 1u);
    EXPECT_EQ(proposal->regions[0].id, "region-1");
    expectTiling(proposal->regions, sceneBounds(scene));

    RegionProposalOptions fine = sweepOnly();
    fine.patchThreshold = 1;
    const model::Result<RegionProposal> split = proposeRegions(scene, fine);
    ASSERT_EQ(split->regions.size(), 2u) << "the gap between the boxes is the only plane";
    EXPECT_GT(split->regions[0].max.x, 1.0);
    EXPECT_LT(split->regions[0].max.x, 2.0);
    EXPECT_TRUE(split->straddlingParts.empty());
}

TEST(RegionProposal, GivesAFlatSceneRegionsWithAThickness)
{
    model::Scene scene;
    scene.materials.push_back({"white", "", {0.5, 0.5, 0.5}, {1, 1, 1}});
    model::Part floor;
    floor.id = "floor.panel";
    floor.material = "white";
    floor.vertices = {{0, 0, 0}, {0, 0, 2}, {3, 0, 2}, {3, 0, 0}};
    floor.faces = {{"floor.panel.top", {0, 1, 2, 3}, ""}};
    scene.objects.push_back({"floor", "", {floor}});
    const model::Result<RegionProposal> proposal = proposeRegions(scene);
    ASSERT_EQ(proposal->regions.size(), 1u);
    EXPECT_LT(proposal->regions[0].min.y, 0.0);
    EXPECT_GT(proposal->regions[0].max.y, 0.0);
    EXPECT_FALSE(model::hasErrors(model::validateScene(withRegions(scene, proposal->regions))));
}

TEST(RegionProposal, SplitsAlongTheOnlyAxisThatHasAGap)
{
    // Two slabs overlapping in x and y; only z separates them (0.2 .. 0.3).
    model::Scene scene;
    scene.materials.push_back({"white", "", {0.5, 0.5, 0.5}, {1, 1, 1}});
    scene.objects.push_back({"slabs",
                             "",
                             {*model::makeBox("slabs.a", {0, 0, 0}, {3, 1, 0.2}, "white"),
                              *model::makeBox("slabs.b", {1, 0, 0.3}, {4, 1, 0.5}, "white")}});
    RegionProposalOptions fine = sweepOnly();
    fine.patchThreshold = 1;
    const model::Result<RegionProposal> proposal = proposeRegions(scene, fine);
    ASSERT_EQ(proposal->regions.size(), 2u);
    EXPECT_NEAR(proposal->regions[0].max.z, 0.25, 1e-12);
    EXPECT_TRUE(proposal->straddlingParts.empty());
}

TEST(RegionProposal, KeepsPartsThatNoPlaneSeparatesTogether)
{
    // A pinwheel of four blocks (seen from above): every axis-aligned plane
    // between two of them cuts a third. With gaps only, the group stays whole
    // however fine the threshold; allowed to cut, the proposal crosses as few
    // blocks as it can and names them.
    model::Scene scene;
    scene.materials.push_back({"white", "", {0.5, 0.5, 0.5}, {1, 1, 1}});
    scene.objects.push_back({"pinwheel",
                             "",
                             {*model::makeBox("pinwheel.a", {0, 0, 0}, {1.95, 1, 0.95}, "white"),
                              *model::makeBox("pinwheel.b", {2.05, 0, 0}, {3, 1, 1.95}, "white"),
                              *model::makeBox("pinwheel.c", {1.05, 0, 2.05}, {3, 1, 3}, "white"),
                              *model::makeBox("pinwheel.d", {0, 0, 1.05}, {0.95, 1, 3}, "white")}});
    RegionProposalOptions fine = sweepOnly();
    fine.patchThreshold = 1;
    fine.cutParts = false;
    const model::Result<RegionProposal> whole = proposeRegions(scene, fine);
    EXPECT_EQ(whole->regions.size(), 1u);
    EXPECT_TRUE(whole->straddlingParts.empty());

    fine.cutParts = true;
    const model::Result<RegionProposal> cut = proposeRegions(scene, fine);
    EXPECT_GT(cut->regions.size(), 1u);
    ASSERT_FALSE(cut->straddlingParts.empty());
    EXPECT_LT(cut->straddlingParts.size(), 4u) << "a plane through the middle crosses two blocks, not all four";
    expectTiling(cut->regions, sceneBounds(scene));
}

TEST(RegionProposal, IgnoresTheScenesOwnRegionsAndPicksFreshIds)
{
    model::Scene scene = test::loadSample("two-lights-room");
    model::Scene bare = scene;
    bare.regions.clear();
    const model::Result<RegionProposal> a = proposeRegions(scene), b = proposeRegions(bare);
    ASSERT_EQ(a->regions.size(), b->regions.size());
    for (size_t r = 0; r < a->regions.size(); ++r)
        EXPECT_EQ(a->regions[r], b->regions[r]);

    scene.materials.push_back({"region-1", "", {0.5, 0.5, 0.5}, {0, 0, 0}});
    const model::Result<RegionProposal> renamed = proposeRegions(scene);
    EXPECT_EQ(renamed->regions[0].id, "region-1-2");
}

TEST(RegionProposal, ReportsTheProblemsOfASceneThatCannotBePrepared)
{
    model::Scene scene = test::loadSample("two-lights-room");
    scene.objects[0].parts[0].material = "nothing";
    scene.objects[0].parts[0].faces[0].material = "";
    const model::Result<RegionProposal> proposal = proposeRegions(scene);
    EXPECT_FALSE(proposal.ok());
    EXPECT_TRUE(model::hasErrors(proposal.diagnostics()));
}

TEST(RegionProposal, AuthoredProposedAndAutomaticRegionsBeatOneBspAndSuggestedOrdersBeatSceneOrder)
{
    // The numbers of the README table: fragments are what the hemicube paints.
    std::printf("| %-18s | %-42s | %7s | %6s | %9s | %6s | %5s |\n", "scene", "regions and BSP order", "regions",
                "pieces", "fragments", "splits", "depth");
    std::printf("|%s|%s|%s|%s|%s|%s|%s|\n", std::string(20, '-').c_str(), std::string(44, '-').c_str(),
                std::string(9, '-').c_str(), std::string(8, '-').c_str(), std::string(11, '-').c_str(),
                std::string(8, '-').c_str(), std::string(7, '-').c_str());
    struct Case {
        const char* name;
        model::Scene scene;
    };
    for (const Case& c : {Case{"two-lights-room", test::loadSample("two-lights-room")},
                          Case{"furnished-room-100", test::furnishedRoom(1, 100)}}) {
        SCOPED_TRACE(c.name);
        auto row = [&](const char* setup, const SceneBspFigures& f) { printRow(c.name, setup, f); };
        model::Scene sceneOrder = c.scene;
        for (model::Region& region : sceneOrder.regions)
            region.bspOrder.clear();

        // One BSP tree over everything: RegionsMode::None, the baseline.
        const SceneBspFigures single = figuresOk(sceneOrder, RegionsMode::None);
        row("single BSP, scene order", single);
        const SceneBspFigures baseline = figuresOk(c.scene, RegionsMode::None);
        if (!c.scene.regions.empty())
            row("single BSP, authored orders one after another", baseline);
        const SceneBspFigures singleSuggested = suggestedSingleBsp(c.scene);
        row("single BSP, suggested order", singleSuggested);
        EXPECT_LE(singleSuggested.fragments, single.fragments);

        if (!c.scene.regions.empty()) {
            const SceneBspFigures authoredSceneOrder = figuresOk(sceneOrder, RegionsMode::Authored);
            const SceneBspFigures authored = figuresOk(c.scene, RegionsMode::Authored);
            const SceneBspFigures authoredSuggested = figuresOk(withSuggestedOrders(c.scene), RegionsMode::Authored);
            row("authored regions, scene order", authoredSceneOrder);
            row("authored regions, authored orders", authored);
            row("authored regions, suggested orders", authoredSuggested);
            EXPECT_LT(authored.fragments, single.fragments);
            EXPECT_LT(authored.fragments, baseline.fragments);
            EXPECT_LE(authoredSuggested.fragments, authoredSceneOrder.fragments);
        }

        RegionProposalOptions gapsOnly;
        gapsOnly.cutParts = false;
        const model::Result<RegionProposal> gaps = proposeRegions(c.scene, gapsOnly);
        ASSERT_TRUE(gaps.ok());
        row("proposed, gaps only, suggested orders", gaps->figures);
        EXPECT_LT(gaps->figures.fragments, single.fragments);

        const model::Result<RegionProposal> proposal = proposeRegions(c.scene);
        ASSERT_TRUE(proposal.ok());
        const SceneBspFigures proposalSceneOrder = figuresOk(withRegions(c.scene,
                                                                         [&] {
                                                                             std::vector<model::Region> bare =
                                                                                 proposal->regions;
                                                                             for (model::Region& r : bare)
                                                                                 r.bspOrder.clear();
                                                                             return bare;
                                                                         }()),
                                                             RegionsMode::Authored);
        row("proposed, scene order", proposalSceneOrder);
        row("proposed, suggested orders", proposal->figures);
        EXPECT_LT(proposal->figures.fragments, single.fragments);
        // The sample is small enough for one tree with a good order to split
        // nothing; there regions only add the pieces of the clipped panels.
        if (c.scene.regions.empty()) {
            EXPECT_LT(proposal->figures.fragments, singleSuggested.fragments);
        }
        EXPECT_LE(proposal->figures.fragments, proposalSceneOrder.fragments);

        model::Scene clipped = withRegions(c.scene, proposal->regions);
        for (const std::string& part : proposal->straddlingParts)
            ASSERT_TRUE(model::clipPartToRegions(clipped, part)) << part;
        row("proposed, cut parts clipped, suggested orders",
            figuresOk(withSuggestedOrders(clipped), RegionsMode::Authored));
        std::printf("|   (%zu parts cut by the proposal, %zu without cutParts)\n", proposal->straddlingParts.size(),
                    gaps->straddlingParts.size());

        const SceneBspFigures automatic = figuresOk(sceneOrder, RegionsMode::Auto);
        row("automatic (patch count), scene order", automatic);
        model::Result<PreparedScene> autoPrepared = prepareBsp(sceneOrder, automaticRegions());
        ASSERT_TRUE(autoPrepared.ok());
        std::vector<model::Region> autoRegions;
        for (const Region& region : autoPrepared->regions) {
            model::Region r;
            r.id = region.id;
            r.min = region.box.min;
            r.max = region.box.max;
            autoRegions.push_back(r);
        }
        const SceneBspFigures automaticSuggested =
            figuresOk(withSuggestedOrders(withRegions(c.scene, autoRegions)), RegionsMode::Authored);
        row("automatic (patch count), suggested orders", automaticSuggested);
        EXPECT_LE(automaticSuggested.fragments, automatic.fragments);
        if (c.scene.regions.empty()) { // the sample is too small: clipping at 7 boxes adds more than it saves
            EXPECT_LT(automatic.fragments, single.fragments);
        }
    }
}

TEST(RegionProposal, NeverCostsMoreFragmentsThanOneRegionWithItsSuggestedOrder)
{
    // The two-light room: the sweep's planes cost fragments that one region
    // with its suggested order does not, so the one region is proposed. The
    // furnished room: its 37 regions pay, and stay.
    const model::Scene room = test::loadSample("two-lights-room");
    const model::Result<RegionProposal> swept = proposeRegions(room, sweepOnly());
    const model::Result<RegionProposal> chosen = proposeRegions(room);
    ASSERT_TRUE(swept);
    ASSERT_TRUE(chosen);
    EXPECT_GT(swept->figures.fragments, chosen->figures.fragments) << "the sweep alone costs more here";
    EXPECT_EQ(chosen->regions.size(), 1u);
    EXPECT_EQ(chosen->figures.fragments, chosen->singleRegionFragments);
    expectTiling(chosen->regions, sceneBounds(room));

    const model::Scene furnished = test::furnishedRoom(1, 100);
    const model::Result<RegionProposal> kept = proposeRegions(furnished);
    ASSERT_TRUE(kept);
    EXPECT_GT(kept->regions.size(), 1u);
    EXPECT_LT(kept->figures.fragments, kept->singleRegionFragments);
    std::printf(
        "two-light room: sweep %d fragments, chosen %d (%zu region); furnished room: %d regions, %d fragments "
        "against %d for one region\n",
        swept->figures.fragments, chosen->figures.fragments, chosen->regions.size(), int(kept->regions.size()),
        kept->figures.fragments, kept->singleRegionFragments);
}
