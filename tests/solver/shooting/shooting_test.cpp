// Progressive shooting (paper §5.6; Cohen et al. 1988) and the solver API
// around it: shooter choice, the radiosity update, stopping, back faces,
// snapshots while solving and cancellation.
#include "solver/prepare/prepare.h"
#include "solver/solver.h"
#include "support/sample_scenes.h"
#include "support/solver_test_scenes.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <thread>

using namespace regio;
using namespace regio::solver;
using regio::model::Rgb;

namespace {

// A floor with a box, a white lamp of 1 m^2 and a brighter-per-area lamp of
// 0.25 m^2: the large one carries more power.
model::Scene twoLamps()
{
    model::Scene scene;
    test::addMaterial(scene, "floor", {0.5, 0.4, 0.3});
    test::addMaterial(scene, "big", {0.2, 0.2, 0.2}, {1.0, 1.0, 1.0});
    test::addMaterial(scene, "small", {0.2, 0.2, 0.2}, {3.0, 3.0, 3.0});
    test::addPolygon(scene, "floor", {{0, 0, 0}, {0, 0, 4}, {4, 0, 4}, {4, 0, 0}}, "floor");
    test::addBox(scene, "box", {1, 0, 1}, {2, 0.8, 2.5}, "floor");
    // Both lamps clear of the box's planes, so no BSP split cuts them.
    test::addPolygon(scene, "big", {{2.5, 2, 0.2}, {3.5, 2, 0.2}, {3.5, 2, 1.2}, {2.5, 2, 1.2}}, "big");
    test::addPolygon(scene, "small", {{2.5, 2, 2.7}, {3.0, 2, 2.7}, {3.0, 2, 3.2}, {2.5, 2, 3.2}}, "small");
    return scene;
}

std::unique_ptr<Solver> make(const model::Scene& scene, SolverOptions options = {})
{
    if (!options.hemicube)
        options.hemicube = 64;
    if (!options.patchSize)
        options.patchSize = 2.0; // each lamp stays two triangle patches
    if (!options.adaptive)
        options.adaptive = false; // shooting on a fixed mesh (adaptive_solver_test.cpp has the rest)
    auto built = Solver::create(scene, options);
    EXPECT_TRUE(built.ok()) << (built.diagnostics().empty() ? "" : built.diagnostics()[0].message);
    return std::move(*built);
}

// A hemicube so fine that one shot takes far longer than a cancel may: the
// render itself must notice the flag.
std::unique_ptr<Solver> slowShooter()
{
    SolverOptions options;
    options.hemicube = 2000;
    options.patchSize = 0.25;
    options.maxIterations = 100000;
    options.convergence = 0.0;
    return make(test::randomRegionScene(9), options);
}

struct CancelledRun {
    StopReason stop = StopReason::None;
    double secondsToStop = 0.0; // from the cancel request to run() returning
};

// Runs `solver` on a worker thread and cancels it `after` the run started.
CancelledRun cancelAfter(Solver& solver, std::chrono::milliseconds after)
{
    std::atomic<bool> cancel{false};
    std::atomic<bool> started{false};
    CancelledRun result;
    std::chrono::steady_clock::time_point stopped;
    std::thread worker([&] {
        started = true;
        result.stop = solver.run({}, cancel);
        stopped = std::chrono::steady_clock::now();
    });
    while (!started)
        std::this_thread::yield();
    std::this_thread::sleep_for(after);
    const auto requested = std::chrono::steady_clock::now();
    cancel = true;
    worker.join();
    result.secondsToStop = std::chrono::duration<double>(stopped - requested).count();
    return result;
}

std::string faceOfPatch(const PreparedScene& p, int patch)
{
    return p.faces[static_cast<size_t>(p.patches[static_cast<size_t>(patch)].properties)].id;
}

} // namespace

TEST(Shooting, ThePatchWithTheMostUnshotPowerShootsFirst)
{
    auto solver = make(twoLamps());
    ASSERT_TRUE(solver);
    const Shooting& s = solver->shooting();
    int big = 0, small = 0;
    for (size_t i = 0; i < solver->prepared().patches.size(); ++i) {
        big += faceOfPatch(solver->prepared(), static_cast<int>(i)) == "big.face";
        small += faceOfPatch(solver->prepared(), static_cast<int>(i)) == "small.face";
    }
    // Lights are cut at a quarter of the patch size (solver/prepare/meshing.h):
    // 1 W over 8 patches of the big lamp, 0.75 W over 2 of the small one.
    ASSERT_EQ(big, 8);
    ASSERT_EQ(small, 2);
    // 0.375 W per patch of the small lamp against 0.125 W for the big one.
    EXPECT_EQ(faceOfPatch(solver->prepared(), s.selectShooter()), "small.face");
    solver->step(2);
    EXPECT_EQ(faceOfPatch(solver->prepared(), s.selectShooter()), "big.face");
}

TEST(Shooting, UnshotPowerIsJudgedByLuminance)
{
    model::Scene scene;
    test::addMaterial(scene, "floor", {0.5, 0.5, 0.5});
    test::addMaterial(scene, "blue", {0.0, 0.0, 0.0}, {0.0, 0.0, 5.0});  // luminance 0.36
    test::addMaterial(scene, "green", {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}); // luminance 0.72
    test::addPolygon(scene, "floor", {{0, 0, 0}, {0, 0, 4}, {4, 0, 4}, {4, 0, 0}}, "floor");
    test::addPolygon(scene, "blue", {{0.5, 2, 0.5}, {1.5, 2, 0.5}, {1.5, 2, 1.5}, {0.5, 2, 1.5}}, "blue");
    test::addPolygon(scene, "green", {{2.5, 2, 2.5}, {3.5, 2, 2.5}, {3.5, 2, 3.5}, {2.5, 2, 3.5}}, "green");
    auto solver = make(scene);
    ASSERT_TRUE(solver);
    EXPECT_EQ(faceOfPatch(solver->prepared(), solver->shooting().selectShooter()), "green.face");
}

// dB_j = rho_j w dB_i F_ij A_i / A_j, and the shooter keeps (1 - w) dB_i
// unshot: w = 1 (classic progressive refinement) and the default w.
// A lamp's first shot: every receiver gains rho_j B_i F_ij A_i / A_j. Lights
// shoot exactly what they hold whatever the overrelaxation (an overshoot
// would only leave each of their patches a debt to take back, shooting.h).
TEST(Shooting, ReceiversGainReflectanceTimesShotRadiosityTimesFormFactorTimesAreaRatio)
{
    for (double w : {1.0, kDefaultOverrelaxation}) {
        SCOPED_TRACE(w);
        SolverOptions options;
        options.overrelaxation = w;
        auto solver = make(twoLamps(), options);
        ASSERT_TRUE(solver);
        const PreparedScene& p = solver->prepared();
        const Shooting& s = solver->shooting();
        const int shooter = s.selectShooter();
        const Patch& patch = p.patches[static_cast<size_t>(shooter)];
        const Rgb emission = p.properties[static_cast<size_t>(patch.properties)].emission;
        solver->step(1);
        ASSERT_EQ(s.lastShooter(), shooter);
        const std::vector<double> factors = s.lastFormFactors();
        int receivers = 0;
        for (size_t j = 0; j < p.elements.size(); ++j) {
            const Element& e = p.elements[j];
            const Properties& props = p.properties[static_cast<size_t>(e.properties)];
            const double f = factors[j];
            receivers += f > 0.0;
            const Rgb expected = props.reflectance * emission * f * patch.area / e.area;
            const Rgb gained = s.radiosity()[j] - props.emission;
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(gained[c], expected[c], 1e-12);
        }
        EXPECT_GT(receivers, 10);
        for (int e = patch.firstElement; e < patch.firstElement + patch.elementCount; ++e)
            for (int c = 0; c < 3; ++c)
                EXPECT_EQ(s.unshotRadiosity()[static_cast<size_t>(e)][c], 0.0);
    }
}

// Patches that do not emit overshoot: a shot sends w times their unshot
// radiosity and leaves (1 - w) of it, negative, for a later shot to take back.
TEST(Shooting, APatchThatDoesNotEmitShootsWTimesItsUnshotRadiosity)
{
    auto solver = make(twoLamps());
    ASSERT_TRUE(solver);
    const PreparedScene& p = solver->prepared();
    const Shooting& s = solver->shooting();
    const auto emits = [&](int patch) {
        return p.properties[static_cast<size_t>(p.patches[static_cast<size_t>(patch)].properties)].emission != Rgb{0.0};
    };
    while (emits(s.selectShooter()))
        ASSERT_EQ(solver->step(1), 1);
    const Patch& patch = p.patches[static_cast<size_t>(s.selectShooter())];
    const std::vector<Rgb> before = s.unshotRadiosity();
    solver->step(1);
    for (int e = patch.firstElement; e < patch.firstElement + patch.elementCount; ++e)
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(s.unshotRadiosity()[static_cast<size_t>(e)][c],
                        (1.0 - kDefaultOverrelaxation) * before[static_cast<size_t>(e)][c], 1e-12);
}

TEST(Shooting, PatchUnshotPowerIsTheAreaWeightedSumOfItsElements)
{
    SolverOptions options;
    options.patchSize = 0.5;
    options.elementsPerPatch = 4;
    auto solver = make(twoLamps(), options);
    ASSERT_TRUE(solver);
    solver->step(25);
    const PreparedScene& p = solver->prepared();
    const Shooting& s = solver->shooting();
    for (size_t i = 0; i < p.patches.size(); ++i) {
        const Patch& patch = p.patches[i];
        Rgb sum{0.0};
        for (int e = patch.firstElement; e < patch.firstElement + patch.elementCount; ++e)
            sum += s.unshotRadiosity()[static_cast<size_t>(e)] * p.elements[static_cast<size_t>(e)].area;
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(s.patchUnshotPower()[i][c], sum[c], 1e-12 + 1e-9 * std::abs(sum[c]));
    }
}

// The lights' shots render a hemicube twice as fine (at most 1024, never
// coarser than the scene's); the other shots keep the scene's.
TEST(Shooting, TheLightsShootWithAHemicubeTwiceAsFine)
{
    EXPECT_EQ(lightHemicubeResolution(200), 400);
    EXPECT_EQ(lightHemicubeResolution(3), 8) << "the scene's resolution rounded up to even first";
    EXPECT_EQ(lightHemicubeResolution(600), kLightHemicubeMaxResolution);
    EXPECT_EQ(lightHemicubeResolution(2000), 2000);

    const model::Scene scene = twoLamps();
    PrepareOptions options;
    options.patchSize = 0.5;
    const model::Result<PreparedScene> prepared = prepareScene(scene, options);
    ASSERT_TRUE(prepared.ok());
    const PreparedScene& p = *prepared;
    const auto emits = [&](int patch) {
        return p.properties[static_cast<size_t>(p.patches[static_cast<size_t>(patch)].properties)].emits();
    };
    ShootingOptions coarse;
    coarse.finerLightHemicubes = false;
    Shooting finer(p, 32, model::Visibility::Painter);
    Shooting at32(p, 32, model::Visibility::Painter, coarse);
    Shooting at64(p, 64, model::Visibility::Painter, coarse);
    EXPECT_EQ(finer.hemicubeResolution(), 32);
    EXPECT_EQ(finer.lightHemicubeResolution(), 64);
    EXPECT_EQ(at32.lightHemicubeResolution(), 32);

    // A light's shot: the factors of a 64 hemicube, to the last bit.
    ASSERT_TRUE(emits(finer.selectShooter()));
    for (Shooting* s : {&finer, &at32, &at64})
        ASSERT_EQ(s->shoot(), ShotResult::Shot);
    ASSERT_EQ(finer.lastShooter(), at64.lastShooter());
    EXPECT_EQ(finer.lastFormFactors(), at64.lastFormFactors());
    EXPECT_NE(finer.lastFormFactors(), at32.lastFormFactors());

    // Once the lights have shot, a reflector's shot: the scene's 32.
    while (emits(finer.selectShooter()))
        ASSERT_EQ(finer.shoot(), ShotResult::Shot);
    ASSERT_EQ(finer.shoot(), ShotResult::Shot);
    const int reflector = finer.lastShooter();
    Shooting plain(p, 32, model::Visibility::Painter, coarse);
    std::vector<Rgb> unshot(p.elements.size(), Rgb{0.0});
    const Patch& patch = p.patches[static_cast<size_t>(reflector)];
    for (int e = patch.firstElement; e < patch.firstElement + patch.elementCount; ++e)
        unshot[static_cast<size_t>(e)] = Rgb{1.0};
    plain.replaceElementState(plain.radiosity(), unshot);
    ASSERT_EQ(plain.shoot(), ShotResult::Shot);
    ASSERT_EQ(plain.lastShooter(), reflector);
    EXPECT_EQ(finer.lastFormFactors(), plain.lastFormFactors());
}

TEST(Shooting, ReplacingTheElementStateRecomputesPatchPowersForAGrownMesh)
{
    // Adaptive subdivision (§5.7) hands over new per-element arrays; the patch
    // powers that choose the next shooter must follow them.
    const model::Scene scene = twoLamps();
    const model::Result<PreparedScene> prepared = prepareScene(scene, {});
    ASSERT_TRUE(prepared.ok());
    const PreparedScene& p = *prepared;
    Shooting shooting(p, 32, model::Visibility::Painter);
    shooting.shoot();
    std::vector<Rgb> radiosity = shooting.radiosity();
    std::vector<Rgb> unshot(p.elements.size(), Rgb{0.0});
    // All unshot light on the floor's first element only.
    size_t floorElement = 0;
    while (p.faces[static_cast<size_t>(p.elements[floorElement].properties)].id != "floor.face")
        ++floorElement;
    unshot[floorElement] = Rgb{2.0, 2.0, 2.0};
    shooting.replaceElementState(radiosity, unshot);
    EXPECT_EQ(shooting.selectShooter(), p.elements[floorElement].patch);
    const double power = 2.0 * p.elements[floorElement].area;
    EXPECT_NEAR(shooting.energy().unshot.g, power, 1e-12);
    EXPECT_NEAR(shooting.patchUnshotPower()[static_cast<size_t>(p.elements[floorElement].patch)].g, power, 1e-12);
    EXPECT_EQ(shooting.radiosity(), radiosity);
}

TEST(Shooting, StepShootsExactlyTheRequestedNumberOfTimes)
{
    SolverOptions options;
    options.maxIterations = 3; // step ignores the run limits
    options.convergence = 0.9;
    auto solver = make(twoLamps(), options);
    ASSERT_TRUE(solver);
    EXPECT_EQ(solver->step(7), 7);
    EXPECT_EQ(solver->stats().iterations, 7);
}

TEST(Shooting, RunStopsAtMaxIterations)
{
    SolverOptions options;
    options.maxIterations = 12;
    options.convergence = 0.0;
    auto solver = make(twoLamps(), options);
    ASSERT_TRUE(solver);
    std::atomic<bool> cancel{false};
    int calls = 0;
    EXPECT_EQ(solver->run([&](const SolverStats&) { ++calls; }, cancel), StopReason::MaxIterations);
    EXPECT_EQ(solver->stats().iterations, 12);
    EXPECT_EQ(calls, 12);
    EXPECT_EQ(solver->stats().stop, StopReason::MaxIterations);
}

TEST(Shooting, RunStopsWhenUnshotOverEmittedFallsBelowTheConvergenceThreshold)
{
    SolverOptions options;
    options.maxIterations = 100000;
    options.convergence = 0.01;
    auto solver = make(twoLamps(), options);
    ASSERT_TRUE(solver);
    std::atomic<bool> cancel{false};
    EXPECT_EQ(solver->run({}, cancel), StopReason::Converged);
    const SolverStats s = solver->stats();
    EXPECT_LT(s.unshotRatio, 0.01);
    for (int c = 0; c < 3; ++c)
        EXPECT_LT(s.energy.unshot[c], 0.01 * s.energy.emitted[c]);
    // One shot fewer was not enough.
    EXPECT_GT(s.iterations, 4);
}

TEST(Shooting, AnOpenSceneConvergesBecauseEscapedLightIsCounted)
{
    model::Scene scene;
    test::addMaterial(scene, "floor", {0.9, 0.9, 0.9});
    test::addMaterial(scene, "lamp", {0.0, 0.0, 0.0}, {1.0, 1.0, 1.0});
    test::addPolygon(scene, "floor", {{0, 0, 0}, {0, 0, 2}, {2, 0, 2}, {2, 0, 0}}, "floor");
    test::addPolygon(scene, "lamp", {{0.5, 1, 0.5}, {1.5, 1, 0.5}, {1.5, 1, 1.5}, {0.5, 1, 1.5}}, "lamp");
    SolverOptions options;
    options.convergence = 1e-6;
    options.maxIterations = 100000;
    auto solver = make(scene, options);
    ASSERT_TRUE(solver);
    std::atomic<bool> cancel{false};
    EXPECT_EQ(solver->run({}, cancel), StopReason::Converged);
    // The floor faces the lamp's back after one bounce: everything it reflects leaves.
    const SolverStats s = solver->stats();
    EXPECT_GT(s.energy.escaped.g, 0.5 * s.energy.emitted.g);
}

TEST(Shooting, ASceneWithoutEmittersHasNothingToShoot)
{
    model::Scene scene;
    test::addMaterial(scene, "grey", {0.5, 0.5, 0.5});
    test::addBox(scene, "room", {0, 0, 0}, {2, 2, 2}, "grey", true);
    auto solver = make(scene);
    ASSERT_TRUE(solver);
    std::atomic<bool> cancel{false};
    EXPECT_EQ(solver->run({}, cancel), StopReason::Converged); // 0 of 0 W left
    EXPECT_EQ(solver->step(5), 0);
    EXPECT_EQ(solver->stats().stop, StopReason::NothingToShoot);
    EXPECT_EQ(solver->stats().iterations, 0);
}

TEST(Shooting, BackFacesBlockLightFromOutsideAnOpenBox)
{
    // A box without a bottom stands over a small floor patch; its faces point
    // outwards, so from the patch only their backs are visible. A lamp above
    // the box must not light the patch (Appendix A would let it through).
    for (model::Visibility mode : {model::Visibility::Painter, model::Visibility::ZBuffer}) {
        model::Scene scene;
        test::addMaterial(scene, "grey", {0.5, 0.5, 0.5});
        test::addMaterial(scene, "lamp", {0.0, 0.0, 0.0}, {10.0, 10.0, 10.0});
        test::addBox(scene, "cover", {-0.5, 0, -0.5}, {0.5, 1, 0.5}, "grey", false, {"ny"});
        test::addPolygon(scene, "inside", {{-0.1, 0, -0.1}, {-0.1, 0, 0.1}, {0.1, 0, 0.1}, {0.1, 0, -0.1}}, "grey");
        test::addPolygon(scene, "outside", {{1, 0, -0.1}, {1, 0, 0.1}, {1.2, 0, 0.1}, {1.2, 0, -0.1}}, "grey");
        test::addPolygon(scene, "lamp", {{-1, 2, -1}, {1, 2, -1}, {1, 2, 1}, {-1, 2, 1}}, "lamp");
        SolverOptions options;
        options.visibility = mode;
        options.patchSize = 0.25;
        options.maxIterations = 32; // the lamp's patches only
        options.convergence = 0.0;
        auto solver = make(scene, options);
        ASSERT_TRUE(solver);
        std::atomic<bool> cancel{false};
        solver->run({}, cancel);
        for (const FaceResult& f : solver->faceResults()) {
            if (f.id == "inside.face") {
                EXPECT_EQ(f.radiosity, Rgb(0.0)) << model::visibilityName(mode);
            }
            if (f.id == "outside.face") {
                EXPECT_GT(f.radiosity.r, 0.1) << model::visibilityName(mode);
            }
        }
    }
}

TEST(Shooting, TheSolverKeepsNoReferenceToTheSceneItWasBuiltFrom)
{
    std::unique_ptr<Solver> solver;
    {
        const model::Scene scene = twoLamps();
        solver = make(scene);
    }
    ASSERT_TRUE(solver);
    EXPECT_EQ(solver->step(5), 5);
    auto reference = make(twoLamps());
    reference->step(5);
    EXPECT_EQ(solver->snapshot().radiosity, reference->snapshot().radiosity);
}

TEST(Shooting, SnapshotsCanBeTakenFromAnotherThreadWhileSolving)
{
    SolverOptions options;
    options.hemicube = 100;
    options.patchSize = 0.25;
    options.maxIterations = 400;
    options.convergence = 0.0;
    auto solver = make(test::randomRegionScene(5), options);
    ASSERT_TRUE(solver);
    std::atomic<bool> cancel{false};
    std::thread worker([&] { solver->run({}, cancel); });
    int previous = 0, taken = 0;
    while (solver->stats().stop == StopReason::None && taken < 2000) {
        const SolutionSnapshot s = solver->snapshot();
        ASSERT_TRUE(s.mesh);
        ASSERT_EQ(s.radiosity.size(), s.mesh->triangles.size());
        EXPECT_GE(s.stats.iterations, previous);
        previous = s.stats.iterations;
        // Each snapshot is one consistent state: the books balance.
        for (int c = 0; c < 3; ++c) {
            const double sum = s.stats.energy.absorbed[c] + s.stats.energy.unshot[c] + s.stats.energy.escaped[c];
            EXPECT_NEAR(sum, s.stats.energy.emitted[c], 1e-6 * s.stats.energy.emitted[c]);
        }
        ++taken;
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    worker.join();
    EXPECT_GT(taken, 1);
    EXPECT_EQ(solver->stats().iterations, 400);
}

TEST(Shooting, RunStopsWhenCancelledInTheMiddleOfAShot)
{
    auto solver = slowShooter();
    ASSERT_TRUE(solver);
    const CancelledRun run = cancelAfter(*solver, std::chrono::milliseconds(150));
    EXPECT_EQ(run.stop, StopReason::Cancelled);
    // A cancelled shot leaves no half-applied state behind.
    const SolverStats s = solver->stats();
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(s.energy.absorbed[c] + s.energy.unshot[c] + s.energy.escaped[c], s.energy.emitted[c],
                    1e-6 * s.energy.emitted[c]);
}

// Wall-clock bound (CTest label "timing"): Stop in the editor must feel
// immediate, also in the middle of a long shot.
TEST(ShootingTiming, RunHonoursCancelWithinOneHundredMilliseconds)
{
    auto solver = slowShooter();
    ASSERT_TRUE(solver);
    EXPECT_LT(cancelAfter(*solver, std::chrono::milliseconds(150)).secondsToStop, 0.1);
}

// Overrelaxation changes the path, not the answer: the Cornell box solved to
// 0.05 % unshot with and without it agrees within 0.5 % on every face
// (measured 0.17 %; at 0.1 % unshot the two differ by what is left unshot,
// up to 0.52 % on the short block's dark side), and gets there in fewer
// shots.
TEST(Shooting, OverrelaxationReachesTheSameAnswerInFewerShots)
{
    const model::Scene scene = test::loadSample("cornell-box");
    std::vector<FaceResult> results[2];
    int shots[2] = {0, 0};
    for (int k = 0; k < 2; ++k) {
        SolverOptions options;
        options.overrelaxation = k == 0 ? 1.0 : kDefaultOverrelaxation;
        options.adaptive = false; // both on the same mesh
        options.hemicube = 100;
        options.maxIterations = 1000000;
        options.convergence = 0.0005;
        auto built = Solver::create(scene, options);
        ASSERT_TRUE(built.ok());
        const std::atomic<bool> cancel{false};
        ASSERT_EQ((*built)->run({}, cancel), StopReason::Converged);
        results[k] = (*built)->faceResults();
        shots[k] = (*built)->stats().iterations;
    }
    EXPECT_LT(shots[1], shots[0] * 3 / 4) << shots[1] << " against " << shots[0];
    ASSERT_EQ(results[0].size(), results[1].size());
    for (size_t i = 0; i < results[0].size(); ++i)
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(results[1][i].radiosity[c], results[0][i].radiosity[c],
                        0.005 * results[0][i].radiosity[c] + 1e-12)
                << results[0][i].id << " channel " << c;
}
