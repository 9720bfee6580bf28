// Exact energy bookkeeping, as the solver reports it: emitted = absorbed +
// unshot + escaped (what leaves an open scene), per channel, after any number
// of shots, open or closed scene.
#include "solver/solver.h"
#include "support/solver_test_scenes.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace regio;
using namespace regio::solver;
using regio::model::Rgb;

namespace {

void expectBalanced(const SolverStats& s)
{
    for (int c = 0; c < 3; ++c) {
        const double emitted = s.energy.emitted[c];
        const double sum = s.energy.absorbed[c] + s.energy.unshot[c] + s.energy.escaped[c];
        EXPECT_NEAR(sum, emitted, 1e-6 * emitted) << "channel " << c << " after " << s.iterations << " shots";
        EXPECT_GE(s.energy.absorbed[c], 0.0);
        // Overrelaxed shots leave some unshot power negative, never the magnitude.
        EXPECT_GE(s.energy.unshotMagnitude[c], std::abs(s.energy.unshot[c]) * (1.0 - 1e-12));
        EXPECT_GE(s.energy.escaped[c], -1e-9 * emitted);
    }
}

// An open scene: a floor, a table-like box and two lamps of different colour, no walls.
model::Scene openScene()
{
    model::Scene scene;
    test::addMaterial(scene, "floor", {0.5, 0.4, 0.3});
    test::addMaterial(scene, "box", {0.2, 0.7, 0.4});
    test::addMaterial(scene, "warm", {0.3, 0.3, 0.3}, {10.0, 6.0, 2.0});
    test::addMaterial(scene, "cold", {0.1, 0.1, 0.1}, {1.0, 3.0, 9.0});
    test::addPolygon(scene, "floor", {{0, 0, 0}, {0, 0, 4}, {4, 0, 4}, {4, 0, 0}}, "floor");
    test::addBox(scene, "box", {1, 0, 1}, {2, 0.8, 2.5}, "box");
    test::addPolygon(scene, "lamp1", {{0.5, 2, 0.5}, {1.5, 2, 0.5}, {1.5, 2, 1.5}, {0.5, 2, 1.5}}, "warm");
    test::addPolygon(scene, "lamp2", {{2.5, 1.5, 2.5}, {3.0, 1.5, 2.5}, {3.0, 1.5, 3.0}, {2.5, 1.5, 3.0}}, "cold");
    return scene;
}

std::unique_ptr<Solver> make(const model::Scene& scene, model::Visibility mode, double overrelaxation = 1.2)
{
    SolverOptions options;
    options.overrelaxation = overrelaxation;
    options.hemicube = 64;
    options.visibility = mode;
    options.patchSize = 0.5;
    // A fixed mesh: the closed room's bound is float rounding only (with
    // subdivision: adaptive_solver_test.cpp).
    options.adaptive = false;
    auto built = Solver::create(scene, options);
    EXPECT_TRUE(built.ok());
    return std::move(*built);
}

} // namespace

TEST(Energy, BalanceHoldsPerChannelBeforeAndAfterEveryShotInAnOpenScene)
{
    for (model::Visibility mode : {model::Visibility::Painter, model::Visibility::ZBuffer}) {
        auto solver = make(openScene(), mode);
        ASSERT_TRUE(solver);
        expectBalanced(solver->stats());
        for (int i = 0; i < 60; ++i) {
            solver->step(1);
            expectBalanced(solver->stats());
        }
        solver->step(300);
        expectBalanced(solver->stats());
        // Light leaves an open scene.
        EXPECT_GT(solver->stats().energy.escaped.r, 0.1 * solver->stats().energy.emitted.r);
    }
}

TEST(Energy, ClassicProgressiveRefinementNeverLeavesUnshotPowerNegative)
{
    auto solver = make(openScene(), model::Visibility::Painter, 1.0);
    ASSERT_TRUE(solver);
    for (int i = 0; i < 100; ++i) {
        solver->step(1);
        const SolverStats s = solver->stats();
        expectBalanced(s);
        EXPECT_EQ(s.energy.unshot, s.energy.unshotMagnitude);
        for (const Rgb& u : solver->shooting().unshotRadiosity())
            ASSERT_TRUE(u.r >= 0.0 && u.g >= 0.0 && u.b >= 0.0);
    }
}

TEST(Energy, EmittedPowerIsExitanceTimesArea)
{
    auto solver = make(openScene(), model::Visibility::Painter);
    ASSERT_TRUE(solver);
    // lamp1: 1 m^2 at (10, 6, 2); lamp2: 0.25 m^2 at (1, 3, 9).
    const Rgb emitted = solver->stats().energy.emitted;
    EXPECT_NEAR(emitted.r, 10.25, 1e-9);
    EXPECT_NEAR(emitted.g, 6.75, 1e-9);
    EXPECT_NEAR(emitted.b, 4.25, 1e-9);
    EXPECT_EQ(solver->stats().energy.unshot, emitted);
}

TEST(Energy, NothingEscapesAClosedRoom)
{
    model::Scene scene;
    test::addMaterial(scene, "wall", {0.5, 0.6, 0.7});
    test::addMaterial(scene, "lamp", {0.5, 0.5, 0.5}, {5.0, 5.0, 5.0});
    test::addBox(scene, "room", {0, 0, 0}, {3, 2.5, 4}, "wall", true);
    test::addBox(scene, "block", {1, 0, 1}, {2, 1, 2}, "wall");
    test::addPolygon(scene, "lamp", {{1, 2.4, 1}, {2, 2.4, 1}, {2, 2.4, 2}, {1, 2.4, 2}}, "lamp");
    auto solver = make(scene, model::Visibility::Painter);
    ASSERT_TRUE(solver);
    solver->step(200);
    const SolverStats s = solver->stats();
    expectBalanced(s);
    // Only float rounding of the delta form factors is lost (and nothing
    // reaches a back face inside a closed room).
    for (int c = 0; c < 3; ++c)
        EXPECT_LT(s.energy.escaped[c], 1e-5 * s.energy.emitted[c]);
}
