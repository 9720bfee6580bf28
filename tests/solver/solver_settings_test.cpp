// The solver runs with the scene's own settings unless the caller overrides
// them (regio-solve flags, the editor's dry run): one resolution,
// solver/settings.h.
#include "solver/solver.h"
#include "support/solver_test_scenes.h"

#include <gtest/gtest.h>

namespace regio::solver {
namespace {

model::Scene twoRegionRoom()
{
    model::Scene scene;
    test::addMaterial(scene, "white", Rgb{0.5});
    test::addBox(scene, "room", Vec3{0.0}, Vec3{4.0, 2.0, 2.0}, "white", true);
    test::addRegion(scene, "west", Vec3{-0.1}, Vec3{2.0, 2.1, 2.1});
    test::addRegion(scene, "east", Vec3{2.0, -0.1, -0.1}, Vec3{4.1, 2.1, 2.1});
    return scene;
}

TEST(SolverSettings, TheScenesVisibilityAndRegionsModeAreUsedWhenNotOverridden)
{
    model::Scene scene = twoRegionRoom();
    scene.solver.visibility = model::Visibility::ZBuffer;
    scene.solver.regions = model::RegionsMode::None;
    auto built = Solver::create(scene);
    ASSERT_TRUE(built.ok());
    EXPECT_EQ((*built)->settings().visibility, model::Visibility::ZBuffer);
    EXPECT_EQ((*built)->settings().regions, RegionsMode::None);
    EXPECT_EQ((*built)->prepared().regions.size(), 1u);
}

TEST(SolverSettings, OptionsOverrideTheScenesVisibilityAndRegionsMode)
{
    model::Scene scene = twoRegionRoom();
    scene.solver.visibility = model::Visibility::ZBuffer;
    scene.solver.regions = model::RegionsMode::None;
    SolverOptions options;
    options.visibility = model::Visibility::Painter;
    options.regions = RegionsMode::Authored;
    auto built = Solver::create(scene, options);
    ASSERT_TRUE(built.ok());
    EXPECT_EQ((*built)->settings().visibility, model::Visibility::Painter);
    EXPECT_EQ((*built)->settings().regions, RegionsMode::Authored);
    EXPECT_EQ((*built)->prepared().regions.size(), 2u);
}

TEST(SolverSettings, ResolvingTakesTheScenesValuesAndAppliesEveryOverride)
{
    model::SolverSettings scene;
    scene.hemicube = 200;
    scene.adaptive.threshold = 0.2;
    EXPECT_EQ(resolveSettings(scene), scene);

    SettingsOverrides o;
    o.hemicube = 300;
    o.maxIterations = 7;
    o.convergence = 0.01;
    o.patchSize = 0.25;
    o.elementsPerPatch = 9;
    o.visibility = model::Visibility::ZBuffer;
    o.regions = model::RegionsMode::Auto;
    o.adaptive = false;
    o.adaptiveThreshold = 0.5;
    o.adaptiveMinEdge = 0.1;
    o.adaptiveAnchoring = false;
    const model::SolverSettings r = resolveSettings(scene, o);
    EXPECT_EQ(r.hemicube, 300);
    EXPECT_EQ(r.maxIterations, 7);
    EXPECT_EQ(r.convergence, 0.01);
    EXPECT_EQ(r.patchSize, 0.25);
    EXPECT_EQ(r.elementsPerPatch, 9);
    EXPECT_EQ(r.visibility, model::Visibility::ZBuffer);
    EXPECT_EQ(r.regions, model::RegionsMode::Auto);
    EXPECT_FALSE(r.adaptive.enabled);
    EXPECT_EQ(r.adaptive.threshold, 0.5);
    EXPECT_EQ(r.adaptive.minEdge, 0.1);
    EXPECT_FALSE(r.adaptive.anchoring);
}

TEST(SolverSettings, WhatTheSolverCannotRunWithIsRefusedAtTheSetting)
{
    EXPECT_TRUE(checkRunnable(model::SolverSettings{}).ok());
    auto refusedAt = [](auto breakIt) {
        model::SolverSettings s;
        breakIt(s);
        const model::Check check = checkRunnable(s);
        return check.ok() ? std::string("accepted") : check.error().pointer;
    };
    EXPECT_EQ(refusedAt([](model::SolverSettings& s) { s.hemicube = 1; }), "/solver/hemicube");
    EXPECT_EQ(refusedAt([](model::SolverSettings& s) { s.patchSize = 0.0; }), "/solver/patchSize");
    EXPECT_EQ(refusedAt([](model::SolverSettings& s) { s.elementsPerPatch = 0; }), "/solver/elementsPerPatch");
    EXPECT_EQ(refusedAt([](model::SolverSettings& s) { s.adaptive.minEdge = -1.0; }), "/solver/adaptive/minEdge");
    EXPECT_EQ(refusedAt([](model::SolverSettings& s) { s.adaptive.threshold = -0.1; }), "/solver/adaptive/threshold");
    // Subdivision settings matter only when subdivision is on.
    EXPECT_EQ(refusedAt([](model::SolverSettings& s) {
                  s.adaptive.enabled = false;
                  s.adaptive.minEdge = -1.0;
              }),
              "accepted");
}

TEST(SolverSettings, TheSolverRunsWithTheResolvedSettings)
{
    model::Scene scene = twoRegionRoom();
    SolverOptions options;
    options.hemicube = 64;
    options.adaptive = false;
    auto built = Solver::create(scene, options);
    ASSERT_TRUE(built.ok());
    EXPECT_EQ((*built)->settings(), resolveSettings(scene.solver, options));
}

} // namespace
} // namespace regio::solver
