// A scene too big for the machine is refused before its preparation
// (solver/resource_estimate.h): the estimate follows the real mesh, and
// Solver::create says what the scene would need instead of running out of
// memory.
#include "solver/resource_estimate.h"
#include "solver/solver.h"
#include "support/sample_scenes.h"

#include <gtest/gtest.h>

#include <chrono>

namespace regio::solver {
namespace {

// Where memory matters, at fine meshes. (At coarse ones the BSP fragments
// and the small faces' own patches count for more than area: the Cornell
// box at 0.5 m has 91 patches, the estimate says 34.)
TEST(ResourceEstimate, FollowsTheRealMeshOfTheSamplesWithinAFactorOfTwo)
{
    for (const char* name : {"cornell-box", "two-lights-room"})
        for (const double patchSize : {0.1, 0.04}) {
            model::Scene scene = test::loadSample(name);
            scene.solver.patchSize = patchSize;
            scene.solver.adaptive.enabled = false;
            const ResourceEstimate e = estimateResources(scene, scene.solver, 1, 0);
            auto built = Solver::create(scene, {});
            ASSERT_TRUE(built.ok()) << name;
            const double patches = double((*built)->prepared().patches.size());
            const double elements = double((*built)->prepared().elements.size());
            EXPECT_GT(e.patches, 0.5 * patches) << name << " at " << patchSize;
            EXPECT_LT(e.patches, 2.0 * patches) << name << " at " << patchSize;
            EXPECT_GT(e.elements, 0.5 * elements) << name << " at " << patchSize;
            EXPECT_LT(e.elements, 2.0 * elements) << name << " at " << patchSize;
            EXPECT_EQ(e.maxElements, e.elements) << "no adaptive subdivision, no growth";
        }
}

TEST(ResourceEstimate, CountsAdaptiveGrowthTheHemicubeAndTheCache)
{
    model::Scene scene = test::loadSample("cornell-box");
    scene.solver.adaptive.enabled = true;
    scene.solver.hemicube = 1000;
    const ResourceEstimate e = estimateResources(scene, scene.solver, 1, 64u << 20);
    EXPECT_GT(e.maxElements, 4.0 * e.elements) << "the growth budget and the penumbrae's splits";
    EXPECT_DOUBLE_EQ(e.meshBytes, e.maxElements * kBytesPerElement);
    EXPECT_GE(e.hemicubeBytes, 3.0 * 1000 * 1000 * 4); // ids of the top face and four half sides, at least
    EXPECT_EQ(e.cacheBytes, double(64u << 20));
    EXPECT_DOUBLE_EQ(e.totalBytes(), e.meshBytes + e.hemicubeBytes + e.cacheBytes);
    EXPECT_GT(estimateResources(scene, scene.solver, 2, 0).hemicubeBytes, e.hemicubeBytes) << "a painter per thread";
}

// Adaptive subdivision grows the mesh up to four times, and the splits in
// the solids' penumbrae before the first shot come on top: the estimate's
// growth covers both, as the solver counts them.
TEST(ResourceEstimate, CoversTheAdaptiveGrowthAndThePenumbraeOfTheSamples)
{
    for (const char* name : {"cornell-box", "two-lights-room"}) {
        const model::Scene scene = test::loadSample(name);
        ASSERT_TRUE(scene.solver.adaptive.enabled) << name;
        const ResourceEstimate e = estimateResources(scene, scene.solver, 1, 0);
        auto built = Solver::create(scene, {});
        ASSERT_TRUE(built.ok()) << name;
        const SolverStats stats = (*built)->stats();
        ASSERT_GT(stats.penumbraElements, 0) << name << ": the sample has penumbrae to split";
        const double initial = double(stats.elements - stats.contactElements - stats.penumbraElements);
        const double reachable = 4.0 * initial + double(stats.penumbraElements);
        EXPECT_GE(e.maxElements / e.elements, reachable / initial) << name;
    }
}

TEST(ResourceEstimate, APatchSizeInTheWrongUnitIsRefusedAtOnceNamingTheSetting)
{
    model::Scene scene = test::loadSample("cornell-box");
    scene.solver.patchSize = 0.0001; // 0.1 mm: 10^9 patches
    const auto start = std::chrono::steady_clock::now();
    auto built = Solver::create(scene, {});
    ASSERT_FALSE(built.ok());
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5)) << "refused before preparation";
    const model::Diagnostic& d = built.error();
    EXPECT_EQ(d.pointer, "/solver/patchSize");
    EXPECT_NE(d.message.find("beyond the limit of 20 million"), std::string::npos) << d.message;
    EXPECT_NE(d.message.find("raise the patch size"), std::string::npos) << d.message;
}

TEST(ResourceEstimate, ASceneNeedingMoreMemoryThanIsFreeIsRefusedWithBothFigures)
{
    model::Scene scene = test::loadSample("cornell-box");
    const ResourceEstimate e = estimateResources(scene, scene.solver, 1, 0);
    EXPECT_TRUE(checkResources(e, 0).ok()) << "unknown free memory: not checked";
    EXPECT_TRUE(checkResources(e, std::uint64_t(e.totalBytes()) + 1).ok());
    const model::Check refused = checkResources(e, std::uint64_t(e.totalBytes() / 2));
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.error().pointer, "/solver/patchSize");
    EXPECT_NE(refused.error().message.find("of memory"), std::string::npos) << refused.error().message;
    EXPECT_NE(refused.error().message.find("available (free memory"), std::string::npos) << refused.error().message;
}

TEST(ResourceEstimate, TheFreeMemoryIsReadFromTheSystem)
{
    const std::uint64_t free = availableMemoryBytes();
    EXPECT_GT(free, std::uint64_t{16} << 20) << "a machine that runs the tests has more than 16 MB free";
}

} // namespace
} // namespace regio::solver
