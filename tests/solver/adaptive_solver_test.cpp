// Adaptive subdivision (§5.7) driven by the Solver: the mesh grows between
// shots where the gradient is, the energy books stay exact, snapshots stay
// consistent while the mesh changes under a running solve, and the per-face
// answers agree with a uniformly fine mesh.
#include "solver/report.h"
#include "solver/solver.h"
#include "solver_test_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <map>
#include <thread>

namespace regio::solver {
namespace {

// A 3 x 3 m floor, a 0.6 m box standing on it and a small lamp above, off to
// one side so the box casts a shadow across the floor. Open: what leaves the
// scene escapes.
model::Scene boxUnderLamp()
{
    model::Scene scene;
    test::addMaterial(scene, "grey", Rgb{0.5});
    test::addMaterial(scene, "lamp", Rgb{0.0}, Rgb{40.0});
    // Floor facing +y, lamp facing -y (corner order decides the side).
    test::addPolygon(scene, "floor", {{-1.5, 0.0, -1.5}, {-1.5, 0.0, 1.5}, {1.5, 0.0, 1.5}, {1.5, 0.0, -1.5}}, "grey");
    test::addBox(scene, "box", Vec3{-0.3, 0.0, -0.3}, Vec3{0.3, 0.6, 0.3}, "grey", false);
    test::addPolygon(scene, "lamp", {{-1.0, 1.5, -0.2}, {-0.6, 1.5, -0.2}, {-0.6, 1.5, 0.2}, {-1.0, 1.5, 0.2}}, "lamp");
    scene.solver.patchSize = 0.5;
    scene.solver.elementsPerPatch = 4;
    scene.solver.hemicube = 100;
    scene.solver.adaptive.enabled = true;
    scene.solver.adaptive.threshold = 0.3; // above the falloff between neighbours, below a shadow edge
    scene.solver.adaptive.minEdge = 0.04;
    return scene;
}

Vec3 elementCentroid(const SolutionMesh& mesh, size_t e)
{
    const auto& t = mesh.triangles[e];
    return (mesh.vertices[size_t(t[0])] + mesh.vertices[size_t(t[1])] + mesh.vertices[size_t(t[2])]) / 3.0;
}

double luminance(const Rgb& c)
{
    return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
}

int faceIndex(const SolutionMesh& mesh, const std::string& id)
{
    const auto it = std::find(mesh.faceIds.begin(), mesh.faceIds.end(), id);
    return it == mesh.faceIds.end() ? -1 : int(it - mesh.faceIds.begin());
}

TEST(AdaptiveSolver, TheEnergyBalanceHoldsExactlyAfterASolveThatSubdivides)
{
    auto built = Solver::create(boxUnderLamp());
    ASSERT_TRUE(built.solver);
    const int initial = built.solver->stats().elements;
    EXPECT_EQ(built.solver->step(40), 40) << "rounds between shots do not count as shots";
    const SolverStats s = built.solver->stats();
    EXPECT_EQ(s.iterations, 40);
    EXPECT_GT(s.adaptiveRounds, 0);
    EXPECT_GT(s.elements, initial);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(s.energy.absorbed[c] + s.energy.unshot[c] + s.energy.escaped[c], s.energy.emitted[c],
                    1e-9 * s.energy.emitted[c]);
}

TEST(AdaptiveSolver, ElementsMultiplyWhereTheShadowFallsAndTheMeshRevisionChanges)
{
    model::Scene scene = boxUnderLamp();
    scene.solver.adaptive.threshold = 0.5; // only the shadow's edge, not the lamp's falloff
    auto built = Solver::create(scene);
    ASSERT_TRUE(built.solver);
    const SolutionSnapshot before = built.solver->snapshot();
    ASSERT_EQ(built.solver->step(2), 2); // the lamp's shot, a refinement round, one more shot
    const SolutionSnapshot after = built.solver->snapshot();
    EXPECT_GT(after.mesh->revision, before.mesh->revision);
    EXPECT_GT(after.mesh->triangles.size(), before.mesh->triangles.size());
    EXPECT_EQ(after.stats.elements, int(after.mesh->triangles.size()));

    // The lamp is at x < 0: the box's shadow lies on the floor at
    // 0.3 < x < ~1.05, |z| < ~0.5. Compare how the floor's element count grew
    // there and beside it, as far from the lamp but out of the shadow (the
    // same falloff, no shadow edge).
    const int floor = faceIndex(*after.mesh, "floor.face");
    ASSERT_GE(floor, 0);
    const auto count = [floor](const SolutionMesh& mesh, bool inShadow) {
        int n = 0;
        for (size_t e = 0; e < mesh.triangles.size(); ++e) {
            if (mesh.elementFace[e] != floor)
                continue;
            const Vec3 c = elementCentroid(mesh, e);
            if (c.x < 0.3 || c.x > 1.1)
                continue;
            if (inShadow ? std::abs(c.z) < 0.6 : std::abs(c.z) > 0.9)
                ++n;
        }
        return n;
    };
    const double shadowGrowth = double(count(*after.mesh, true)) / count(*before.mesh, true);
    const double besideGrowth = double(count(*after.mesh, false)) / count(*before.mesh, false);
    EXPECT_GT(shadowGrowth, 2.0 * besideGrowth)
        << "by the shadow " << count(*before.mesh, true) << " -> " << count(*after.mesh, true) << " elements, beside it "
        << count(*before.mesh, false) << " -> " << count(*after.mesh, false);
}

TEST(AdaptiveSolver, SnapshotsFromAnotherThreadStayConsistentWhileRunSubdivides)
{
    model::Scene scene = boxUnderLamp();
    scene.solver.maxIterations = 60;
    scene.solver.convergence = 1e-6;
    auto built = Solver::create(scene);
    ASSERT_TRUE(built.solver);
    Solver& solver = *built.solver;
    std::atomic<bool> done{false};
    std::atomic<int> inconsistent{0};
    std::atomic<int> taken{0};
    std::thread reader([&] {
        while (!done.load()) {
            const SolutionSnapshot s = solver.snapshot();
            if (s.mesh->triangles.size() != s.radiosity.size() || s.mesh->elementFace.size() != s.radiosity.size()
                || s.mesh->reflectance.size() != s.radiosity.size())
                ++inconsistent;
            const std::vector<FaceResult> faces = solver.faceResults();
            if (faces.size() != s.mesh->faceIds.size())
                ++inconsistent;
            (void)solver.stats();
            ++taken;
        }
    });
    const std::atomic<bool> cancel{false};
    const StopReason stop = solver.run({}, cancel);
    done = true;
    reader.join();
    EXPECT_EQ(stop, StopReason::MaxIterations);
    EXPECT_GT(taken.load(), 0);
    EXPECT_EQ(inconsistent.load(), 0);
    const SolutionSnapshot last = solver.snapshot();
    EXPECT_GT(last.mesh->revision, 0);
    EXPECT_EQ(last.mesh->triangles.size(), last.radiosity.size());
}

TEST(AdaptiveSolver, PerFaceMeansAgreeWithAUniformlyFineMeshWithinTwoPercent)
{
    model::Scene scene = boxUnderLamp();
    scene.solver.convergence = 1e-4;
    scene.solver.maxIterations = 2000;
    const std::atomic<bool> cancel{false};

    auto adaptive = Solver::create(scene);
    ASSERT_TRUE(adaptive.solver);
    ASSERT_EQ(adaptive.solver->run({}, cancel), StopReason::Converged);
    EXPECT_GT(adaptive.solver->stats().adaptiveRounds, 0);

    SolverOptions fine;
    fine.adaptive = false;
    fine.elementsPerPatch = 64;
    auto uniform = Solver::create(scene, fine);
    ASSERT_TRUE(uniform.solver);
    ASSERT_EQ(uniform.solver->run({}, cancel), StopReason::Converged);

    const std::vector<FaceResult> a = adaptive.solver->faceResults();
    const std::vector<FaceResult> u = uniform.solver->faceResults();
    ASSERT_EQ(a.size(), u.size());
    double brightest = 0.0;
    for (const FaceResult& f : u)
        brightest = std::max(brightest, luminance(f.radiosity));
    int compared = 0;
    for (size_t i = 0; i < a.size(); ++i) {
        ASSERT_EQ(a[i].id, u[i].id);
        // A face in the dark (the box's bottom on the floor) has no mean to compare.
        if (luminance(u[i].radiosity) < 1e-6 * brightest)
            continue;
        ++compared;
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(a[i].radiosity[c], u[i].radiosity[c], 0.02 * u[i].radiosity[c]) << a[i].id;
    }
    EXPECT_EQ(compared, 7); // floor, lamp, box top and four sides (the shadowed one too)
}

TEST(AdaptiveSolver, TheReportGivesTheFinalElementCountAndTheRounds)
{
    auto built = Solver::create(boxUnderLamp());
    ASSERT_TRUE(built.solver);
    const int initial = built.solver->stats().elements;
    built.solver->step(20);
    const nlohmann::json report = solveReport("box under lamp", *built.solver);
    EXPECT_EQ(report["elements"].get<int>(), built.solver->stats().elements);
    EXPECT_GT(report["elements"].get<int>(), initial);
    EXPECT_TRUE(report["adaptive"]["enabled"].get<bool>());
    EXPECT_EQ(report["adaptive"]["rounds"].get<int>(), built.solver->stats().adaptiveRounds);
    EXPECT_GT(report["adaptive"]["rounds"].get<int>(), 0);
}

TEST(AdaptiveSolver, OptionsOverrideTheScenesAdaptiveSettings)
{
    SolverOptions options;
    options.adaptive = false;
    options.adaptiveThreshold = 0.2;
    options.adaptiveMinEdge = 0.1;
    options.adaptiveAnchoring = false;
    auto built = Solver::create(boxUnderLamp(), options);
    ASSERT_TRUE(built.solver);
    const model::AdaptiveSettings& a = built.solver->settings().adaptive;
    EXPECT_FALSE(a.enabled);
    EXPECT_EQ(a.threshold, 0.2);
    EXPECT_EQ(a.minEdge, 0.1);
    EXPECT_FALSE(a.anchoring);
    const int initial = built.solver->stats().elements;
    built.solver->step(5);
    EXPECT_EQ(built.solver->stats().elements, initial);
    EXPECT_EQ(built.solver->snapshot().mesh->revision, 0);
}

} // namespace
} // namespace regio::solver
