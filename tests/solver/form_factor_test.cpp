// Form factors against known answers (opposed unit squares 1 apart: 0.19982;
// unit squares sharing an edge at 90 degrees: 0.20004; the opposed squares
// with a slab halfway: 0.09808), measured through the solver's own result:
// one emitter, a receiver of reflectance rho, no other reflection:
// B_receiver = rho * E * F * A_emitter / A_receiver.
#include "solver/solver.h"
#include "support/solver_test_scenes.h"

#include <gtest/gtest.h>

using namespace regio;
using namespace regio::solver;
using regio::model::Vec3;

namespace {

constexpr double kRho = 0.5;

// Emitter and receiver are unit squares; the emitter absorbs everything so
// that only its own light reaches the receiver.
double measuredFormFactor(const model::Scene& scene, int hemicube, double patchSize,
                          model::Visibility mode = model::Visibility::Painter)
{
    SolverOptions options;
    options.hemicube = hemicube;
    options.patchSize = patchSize;
    options.elementsPerPatch = 1;
    options.adaptive = false; // form factors of the mesh as meshed
    options.maxIterations = 100000;
    options.convergence = 1e-9;
    options.visibility = mode;
    auto built = Solver::create(scene, options);
    EXPECT_TRUE(built.ok()) << (built.diagnostics().empty() ? "" : built.diagnostics()[0].message);
    if (!built.ok())
        return -1.0;
    std::atomic<bool> cancel{false};
    (*built)->run({}, cancel);
    for (const FaceResult& f : (*built)->faceResults())
        if (f.id == "receiver.face")
            return f.radiosity.g / kRho;
    ADD_FAILURE() << "no receiver face";
    return -1.0;
}

model::Scene emitterAndReceiver(const std::vector<Vec3>& receiver)
{
    model::Scene scene;
    test::addMaterial(scene, "light", {0.0, 0.0, 0.0}, {1.0, 1.0, 1.0});
    test::addMaterial(scene, "grey", {kRho, kRho, kRho});
    // Emitter: z = 0, facing +z.
    test::addPolygon(scene, "emitter", {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, "light");
    test::addPolygon(scene, "receiver", receiver, "grey");
    return scene;
}

} // namespace

TEST(FormFactor, ParallelOpposedUnitSquaresOneApartExchange0_19982)
{
    // Receiver at z = 1 facing -z.
    const auto scene = emitterAndReceiver({{0, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 0, 1}});
    const double f = measuredFormFactor(scene, 150, 0.1);
    EXPECT_NEAR(f, 0.19982, 0.01 * 0.19982);
}

TEST(FormFactor, PerpendicularUnitSquaresSharingAnEdgeExchange0_20004)
{
    // Receiver in the plane x = 0, facing +x, sharing the emitter's edge on the y axis.
    const auto scene = emitterAndReceiver({{0, 0, 0}, {0, 1, 0}, {0, 1, 1}, {0, 0, 1}});
    const double f = measuredFormFactor(scene, 150, 0.05);
    EXPECT_NEAR(f, 0.20004, 0.01 * 0.20004);
}

TEST(FormFactor, ZBufferGivesTheSameParallelSquaresFormFactor)
{
    const auto scene = emitterAndReceiver({{0, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 0, 1}});
    EXPECT_NEAR(measuredFormFactor(scene, 150, 0.1, model::Visibility::ZBuffer), 0.19982, 0.01 * 0.19982);
}

TEST(FormFactor, OneHemicubeAtTheCentreOfALargePatchShowsTheProximityError)
{
    // One shooter for the whole emitter: the point-to-area factor 0.2395,
    // not 0.1998 (Baum et al. 1989). This is why shooting patches must be small.
    const auto scene = emitterAndReceiver({{0, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 0, 1}});
    SolverOptions options;
    options.hemicube = 300;
    options.patchSize = 5.0; // the unit square stays two triangles
    options.elementsPerPatch = 1;
    options.adaptive = false; // form factors of the mesh as meshed
    auto built = Solver::create(scene, options);
    ASSERT_TRUE(built.ok());
    ASSERT_EQ((*built)->prepared().patches.size(), 4u); // two squares, two triangles each
    (*built)->step(2);                                  // both emitter triangles, each from its own centroid
    double received = 0.0;
    for (const FaceResult& f : (*built)->faceResults())
        if (f.id == "receiver.face")
            received = f.radiosity.g / kRho;
    // Triangle centroids sit off the square's centre: the single-point estimate
    // is between the centre value 0.2395 and the true 0.1998, far above the latter.
    EXPECT_GT(received, 0.21);
}

TEST(FormFactor, SlabHalfwayBetweenParallelSquaresCutsTheExchangeTo0_09808)
{
    // A 0.5 x 0.5 x 0.02 slab centred between the squares: 0.09808 (Monte
    // Carlo against the real slab; a flat plate in its place gives 0.0995).
    auto scene = emitterAndReceiver({{0, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 0, 1}});
    test::addMaterial(scene, "black", {0.0, 0.0, 0.0});
    test::addBox(scene, "slab", {0.25, 0.25, 0.49}, {0.75, 0.75, 0.51}, "black");
    const double f = measuredFormFactor(scene, 300, 0.1);
    EXPECT_NEAR(f, 0.09808, 0.01 * 0.09808);
}
