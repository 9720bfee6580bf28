// The furnace, a known answer: a closed box whose every face has
// reflectance rho and emission E reaches B = E / (1 - rho) everywhere,
// whatever the mesh, once the shooting has converged.
#include "solver/solver.h"
#include "support/solver_test_scenes.h"

#include <gtest/gtest.h>

using namespace regio;
using namespace regio::solver;
using regio::model::Rgb;

namespace {

model::Scene furnace(Rgb rho, Rgb emission)
{
    model::Scene scene;
    test::addMaterial(scene, "furnace", rho, emission);
    test::addBox(scene, "box", {0, 0, 0}, {1.0, 0.8, 1.3}, "furnace", /*inward=*/true);
    return scene;
}

void expectFurnaceAnswer(const model::Scene& scene, Rgb rho, Rgb emission, model::Visibility mode)
{
    SolverOptions options;
    options.hemicube = 100;
    options.patchSize = 0.25;
    options.elementsPerPatch = 4;
    options.maxIterations = 100000;
    options.convergence = 1e-4;
    options.visibility = mode;
    auto built = Solver::create(scene, options);
    ASSERT_TRUE(built.ok());
    std::atomic<bool> cancel{false};
    EXPECT_EQ((*built)->run({}, cancel), StopReason::Converged);
    const std::vector<FaceResult> faces = (*built)->faceResults();
    ASSERT_EQ(faces.size(), 6u);
    for (const FaceResult& f : faces)
        for (int c = 0; c < 3; ++c) {
            const double expected = emission[c] / (1.0 - rho[c]);
            EXPECT_NEAR(f.radiosity[c], expected, 0.01 * expected) << f.id << " channel " << c;
        }
}

} // namespace

TEST(Furnace, UniformBoxReachesEmissionOverOneMinusReflectanceOnEveryFace)
{
    const Rgb rho{0.6, 0.6, 0.6}, e{1.0, 1.0, 1.0};
    expectFurnaceAnswer(furnace(rho, e), rho, e, model::Visibility::Painter);
}

TEST(Furnace, HoldsPerChannelWhenReflectanceDiffersByChannel)
{
    const Rgb rho{0.8, 0.5, 0.2}, e{2.0, 1.0, 3.0};
    expectFurnaceAnswer(furnace(rho, e), rho, e, model::Visibility::Painter);
}

TEST(Furnace, HoldsWithTheZBufferToo)
{
    const Rgb rho{0.7, 0.4, 0.3}, e{1.0, 2.0, 1.0};
    expectFurnaceAnswer(furnace(rho, e), rho, e, model::Visibility::ZBuffer);
}

TEST(Furnace, TheAmbientTermGivesTheAnswerBeforeTheFirstShot)
{
    // Cohen et al. 1988: with uniform rho the ambient estimate is exact at the
    // start, E + rho * E / (1 - rho) = E / (1 - rho).
    const Rgb rho{0.8, 0.5, 0.2}, e{2.0, 1.0, 3.0};
    auto built = Solver::create(furnace(rho, e), {});
    ASSERT_TRUE(built.ok());
    const SolutionSnapshot s = (*built)->snapshot();
    ASSERT_FALSE(s.radiosity.empty());
    for (size_t i = 0; i < s.radiosity.size(); ++i)
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(s.displayRadiosity(i)[c], e[c] / (1.0 - rho[c]), 1e-9);
}
