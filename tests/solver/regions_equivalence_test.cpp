// Regions change nothing but speed (paper §3, §5.2): the same scene solved
// with its authored regions, with none (one classic BSP tree, the baseline)
// and with automatic regions gives the same radiosity on every input face.
//
// The mesh is made per input face (solver/prepare/meshing.h), so patches and
// elements, and with them the shooters and receivers, are identical in every
// mode; region planes and BSP splits only cut elements into the pieces the
// painter paints (solver/prepare/pieces.h). What remains between the modes is the
// order the painter paints in and the pixels along cut edges, which the
// crack-free cuts keep to rounding, and the shooting order that may differ
// in ties. Every face of non-zero area is compared, however small.
#include "solver/solver.h"
#include "support/sample_scenes.h"
#include "support/solver_test_scenes.h"

#include <gtest/gtest.h>

#include <map>

using namespace regio;
using namespace regio::solver;

namespace {

struct Solution {
    std::map<std::string, FaceResult> faces;
    int regions = 0;
    int patches = 0;
    int elements = 0;
    int lostPieces = 0;
};

Solution solve(const model::Scene& scene, RegionsMode regions)
{
    SolverOptions options;
    options.hemicube = 100;
    options.patchSize = 0.5;
    options.elementsPerPatch = 1;
    options.visibility = model::Visibility::Painter;
    options.regions = regions;
    options.autoRegionPatchThreshold = 100;
    options.maxIterations = 100000;
    options.convergence = 1e-3;
    // The same mesh in every mode: equal patch and element counts are part of
    // the equivalence (adaptive subdivision would follow each mode's noise).
    options.adaptive = false;
    auto built = Solver::create(scene, options);
    EXPECT_TRUE(built.ok()) << (built.diagnostics().empty() ? "" : built.diagnostics()[0].message);
    if (!built.ok())
        return {};
    Solution s;
    s.regions = static_cast<int>((*built)->prepared().regions.size());
    s.patches = static_cast<int>((*built)->prepared().patches.size());
    s.elements = static_cast<int>((*built)->prepared().elements.size());
    s.lostPieces = (*built)->prepared().stats.lostPieces;
    std::atomic<bool> cancel{false};
    EXPECT_EQ((*built)->run({}, cancel), StopReason::Converged);
    for (FaceResult& f : (*built)->faceResults())
        s.faces[f.id] = f;
    return s;
}

// Every face of non-zero area agrees per channel within 0.5 %.
void expectSameFaces(const Solution& a, const Solution& b, const std::string& what)
{
    ASSERT_EQ(a.faces.size(), b.faces.size());
    EXPECT_EQ(a.patches, b.patches) << what << ": the same shooters";
    EXPECT_EQ(a.elements, b.elements) << what << ": the same receivers";
    EXPECT_EQ(a.lostPieces, 0) << what;
    EXPECT_EQ(b.lostPieces, 0) << what;
    int compared = 0;
    for (const auto& [id, fa] : a.faces) {
        if (fa.area <= 0.0)
            continue;
        ++compared;
        const FaceResult& fb = b.faces.at(id);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(fa.radiosity[c], fb.radiosity[c], 0.005 * fb.radiosity[c])
                << what << ": " << id << " channel " << c;
    }
    EXPECT_GT(compared, 0);
}

void expectAllModesAgree(const model::Scene& scene, const std::string& name, int authoredRegions)
{
    const Solution none = solve(scene, RegionsMode::None);
    const Solution authored = solve(scene, RegionsMode::Authored);
    const Solution automatic = solve(scene, RegionsMode::Auto);
    EXPECT_EQ(none.regions, 1);
    EXPECT_EQ(authored.regions, authoredRegions);
    EXPECT_GT(automatic.regions, 1) << "automatic regions cut the scene";
    expectSameFaces(authored, none, name + " authored vs none");
    expectSameFaces(automatic, none, name + " auto vs none");
}

} // namespace

TEST(RegionsEquivalence, TheTwoLightSampleGivesTheSameRadiosityOnEveryFaceInAllThreeRegionModes)
{
    const model::Scene scene = test::loadSample("two-lights-room");
    ASSERT_FALSE(scene.objects.empty());
    ASSERT_GE(scene.regions.size(), 2u);
    expectAllModesAgree(scene, "two-lights-room", static_cast<int>(scene.regions.size()));
}

TEST(RegionsEquivalence, RandomRegionScenesGiveTheSameRadiosityOnEveryFaceInAllThreeRegionModes)
{
    for (unsigned seed : {3u, 11u}) {
        const model::Scene scene = test::randomRegionScene(seed, 2, 2);
        expectAllModesAgree(scene, "random scene " + std::to_string(seed), 4);
    }
}

TEST(RegionsEquivalence, ARoomCutAtTheRegionBordersGivesTheSameSolutionAsOneBspTree)
{
    const model::Scene scene = test::conformingRegionScene();
    const Solution none = solve(scene, RegionsMode::None);
    const Solution authored = solve(scene, RegionsMode::Authored);
    EXPECT_EQ(authored.regions, 4);
    expectSameFaces(authored, none, "conforming scene authored vs none");
}
