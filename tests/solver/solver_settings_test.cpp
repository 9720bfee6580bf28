// The solver runs with the scene's own settings unless the caller overrides
// them (regio-solve flags, the editor's dry run).
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
    ASSERT_TRUE(built.solver);
    EXPECT_EQ(built.solver->settings().visibility, VisibilityMode::ZBuffer);
    EXPECT_EQ(built.solver->settings().regions, RegionsMode::None);
    EXPECT_EQ(built.solver->prepared().regions.size(), 1u);
}

TEST(SolverSettings, OptionsOverrideTheScenesVisibilityAndRegionsMode)
{
    model::Scene scene = twoRegionRoom();
    scene.solver.visibility = model::Visibility::ZBuffer;
    scene.solver.regions = model::RegionsMode::None;
    SolverOptions options;
    options.visibility = VisibilityMode::Painter;
    options.regions = RegionsMode::Authored;
    auto built = Solver::create(scene, options);
    ASSERT_TRUE(built.solver);
    EXPECT_EQ(built.solver->settings().visibility, VisibilityMode::Painter);
    EXPECT_EQ(built.solver->settings().regions, RegionsMode::Authored);
    EXPECT_EQ(built.solver->prepared().regions.size(), 2u);
}

} // namespace
} // namespace regio::solver
