// The refinement schedule of the solver (solver/shooting/adaptive_refinement.h): when
// a round is due, how far a round may grow the mesh, which elements go first,
// and that a cancelled round resumes to the very mesh an uninterrupted one
// makes.
#include "solver/prepare/prepare.h"
#include "solver/shooting/adaptive_refinement.h"
#include "solver/shooting/shooting.h"

#include "support/adaptive_scenes.h"

#include <gtest/gtest.h>

#include <atomic>

namespace regio::solver {
namespace {

// The box under the lamp, prepared, after the lamp's first shot.
struct Shot {
    PreparedScene scene;
    std::unique_ptr<Shooting> shooting;
    model::AdaptiveSettings settings;

    explicit Shot(double threshold = 0.3, double minEdge = 0.04)
    {
        model::Scene s = test::boxUnderLamp();
        s.solver.adaptive.threshold = threshold;
        s.solver.adaptive.minEdge = minEdge;
        settings = s.solver.adaptive;
        model::Result<solver::PreparedScene> prepared = prepareScene(s);
        scene = std::move(*prepared);
        shooting = std::make_unique<Shooting>(scene, 64, model::Visibility::Painter);
        shooting->shoot();
    }
    int elements() const { return int(scene.elements.size()); }
};

AdaptiveRefinement::Outcome runOnce(AdaptiveRefinement& r, const Shot& shot)
{
    return r.runRound(shot.shooting->radiosity(), shot.shooting->unshotRadiosity(), nullptr);
}

TEST(AdaptiveRefinement, ARoundIsDueAfterAnEmittersShotAndEveryIntervalthShotOnly)
{
    const Shot shot;
    AdaptiveRefinement r(shot.scene, shot.settings);
    EXPECT_FALSE(r.roundDue());
    r.noteShot(3, false);
    EXPECT_FALSE(r.roundDue());
    r.noteShot(4, true);
    EXPECT_TRUE(r.roundDue());
    runOnce(r, shot);
    EXPECT_FALSE(r.roundDue());
    r.noteShot(15, false);
    EXPECT_FALSE(r.roundDue());
    r.noteShot(16, false);
    EXPECT_TRUE(r.roundDue());
}

TEST(AdaptiveRefinement, ARoundSplitsWhereTheCriterionHoldsAndHandsOverTheActiveScene)
{
    const Shot shot;
    AdaptiveRefinement r(shot.scene, shot.settings);
    r.noteShot(1, true);
    ASSERT_EQ(runOnce(r, shot), AdaptiveRefinement::Outcome::Refined);
    EXPECT_EQ(r.rounds(), 1);
    const ActiveScene active = r.takeActiveScene();
    EXPECT_GT(active.scene.elements.size(), shot.scene.elements.size());
    EXPECT_EQ(active.radiosity.size(), active.scene.elements.size());
    EXPECT_EQ(active.unshot.size(), active.scene.elements.size());
    // The power still to shoot is the same: new elements carry their parent's.
    Rgb before{0.0}, after{0.0};
    for (size_t e = 0; e < shot.scene.elements.size(); ++e)
        before += shot.shooting->unshotRadiosity()[e] * shot.scene.elements[e].area;
    for (size_t e = 0; e < active.scene.elements.size(); ++e)
        after += active.unshot[e] * active.scene.elements[e].area;
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(after[c], before[c], 1e-12 * before[c]);
}

TEST(AdaptiveRefinement, ASettledMeshEndsTheRoundWithoutChange)
{
    const Shot shot(/*threshold*/ 10.0); // no neighbour differs by more than 1000 %
    AdaptiveRefinement r(shot.scene, shot.settings);
    r.noteShot(1, true);
    EXPECT_EQ(runOnce(r, shot), AdaptiveRefinement::Outcome::Settled);
    EXPECT_EQ(r.rounds(), 0);
}

TEST(AdaptiveRefinement, WithABudgetForOneSplitTheElementOfSharpestContrastIsSplit)
{
    const Shot shot(/*threshold*/ 0.0, /*minEdge*/ 0.01);
    RefinementPolicy policy;
    policy.sliceSize = 1;
    policy.maxRounds = 1;
    policy.growthLimit = (shot.elements() + 1.0) / shot.elements();
    AdaptiveRefinement r(shot.scene, shot.settings, policy);
    r.noteShot(1, true);
    ASSERT_EQ(runOnce(r, shot), AdaptiveRefinement::Outcome::Refined);

    // The sharpest element by the criterion, measured on a mesh of its own.
    PreparedScene copy = shot.scene;
    AdaptiveMesh reference(copy, shot.shooting->radiosity(), shot.shooting->unshotRadiosity());
    int sharpest = -1;
    double best = -1.0;
    for (int e = 0; e < shot.elements(); ++e) {
        const double c = reference.contrast(e, reference.radiosity());
        if (c > best) {
            best = c;
            sharpest = e;
        }
    }
    ASSERT_GE(sharpest, 0);
    EXPECT_FALSE(r.mesh().isActive(sharpest)) << "the element of contrast " << best << " was not split";
    // One split (with the grading splits it needs), no more.
    int splits = 0;
    for (int e = 0; e < shot.elements(); ++e)
        splits += r.mesh().isActive(e) ? 0 : 1;
    EXPECT_GE(splits, 1);
    EXPECT_LE(splits, 4);
}

TEST(AdaptiveRefinement, EachRoundGrowsTheMeshOnlyByItsShareOfTheBudget)
{
    const Shot shot(/*threshold*/ 0.0, /*minEdge*/ 0.005);
    RefinementPolicy policy;
    policy.maxRounds = 4;
    policy.growthLimit = 3.0;
    policy.sliceSize = 8;
    AdaptiveRefinement r(shot.scene, shot.settings, policy);
    const int initial = shot.elements();
    // A slice may overshoot: each of its splits can bring grading splits.
    const int slack = 3 * policy.sliceSize * 8;
    std::vector<Rgb> radiosity = shot.shooting->radiosity();
    std::vector<Rgb> unshot = shot.shooting->unshotRadiosity();
    for (int round = 1; round <= policy.maxRounds + 2; ++round) {
        r.noteShot(round, true);
        const auto outcome = r.runRound(radiosity, unshot, nullptr);
        if (outcome == AdaptiveRefinement::Outcome::Refined) {
            ActiveScene active = r.takeActiveScene();
            radiosity = active.radiosity;
            unshot = active.unshot;
        }
        const int allowed = initial + (2 * initial * std::min(round, policy.maxRounds)) / policy.maxRounds;
        EXPECT_LE(int(radiosity.size()), allowed + slack) << "round " << round;
        if (round <= policy.maxRounds) {
            EXPECT_GE(int(radiosity.size()), allowed - slack) << "round " << round << " left budget unused";
        }
    }
    EXPECT_EQ(r.rounds(), policy.maxRounds) << "no round after the last allowed one";
    EXPECT_LE(int(radiosity.size()), r.elementLimit() + slack);
}

TEST(AdaptiveRefinement, ACancelledRoundResumesToTheMeshAnUninterruptedRoundMakes)
{
    const Shot shot(/*threshold*/ 0.05, /*minEdge*/ 0.005);
    RefinementPolicy policy;
    policy.sliceSize = 1;
    policy.selectSliceSize = 16;
    policy.growthLimit = 16.0;
    policy.maxRounds = 1;

    AdaptiveRefinement straight(shot.scene, shot.settings, policy);
    straight.noteShot(1, true);
    ASSERT_EQ(runOnce(straight, shot), AdaptiveRefinement::Outcome::Refined);
    const ActiveScene expected = straight.takeActiveScene();

    AdaptiveRefinement interrupted(shot.scene, shot.settings, policy);
    interrupted.noteShot(1, true);
    // A cancel flag that stays set: every call does one slice and stops.
    const std::atomic<bool> cancel{true};
    AdaptiveRefinement::Outcome outcome =
        interrupted.runRound(shot.shooting->radiosity(), shot.shooting->unshotRadiosity(), &cancel);
    int cancellations = 0;
    while (outcome == AdaptiveRefinement::Outcome::Cancelled && cancellations < 100000) {
        ++cancellations;
        EXPECT_TRUE(interrupted.roundDue()) << "an interrupted round is still due";
        // The arrays passed on resumption are ignored (no shot happened since).
        outcome = interrupted.runRound({}, {}, &cancel);
    }
    ASSERT_EQ(outcome, AdaptiveRefinement::Outcome::Refined);
    EXPECT_GT(cancellations, 10) << "the round was interrupted in its selection and its splits";
    EXPECT_FALSE(interrupted.roundDue());
    const ActiveScene got = interrupted.takeActiveScene();
    ASSERT_EQ(got.scene.elements.size(), expected.scene.elements.size());
    EXPECT_EQ(got.scene.vertices, expected.scene.vertices);
    EXPECT_EQ(got.sourceElement, expected.sourceElement);
    EXPECT_EQ(got.radiosity, expected.radiosity);
    EXPECT_EQ(got.unshot, expected.unshot);
}

} // namespace
} // namespace regio::solver
