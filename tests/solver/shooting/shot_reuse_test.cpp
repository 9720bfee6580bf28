// How shots run changes no result: a shot that reuses the kept form factors
// of its patch's earlier shot, and a hemicube rendered on several threads,
// give the radiosity and the energy books of rendering every shot on one
// thread, to the last bit. And the arena the kept rows live in.
#include "solver/shooting/row_arena.h"
#include "solver/solver.h"
#include "support/sample_scenes.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <numeric>
#include <set>
#include <vector>

using namespace regio;
using namespace regio::solver;

namespace {

struct SolveOutcome {
    std::vector<Rgb> radiosity;
    EnergyBalance energy;
    int iterations = 0;
    int renderedShots = 0;
    int distinctShooters = 0;
    std::size_t cacheBytes = 0;
    int elements = 0;
};

SolveOutcome solve(const std::string& sample, SolverOptions options, int shots)
{
    auto built = Solver::create(test::loadSample(sample), options);
    EXPECT_TRUE(built.ok());
    SolveOutcome run;
    if (!built.ok())
        return run;
    Solver& solver = **built;
    std::set<int> shooters;
    for (int i = 0; i < shots; ++i) {
        if (solver.step(1) != 1)
            break;
        shooters.insert(solver.shooting().lastShooter());
    }
    run.radiosity = solver.shooting().radiosity();
    run.energy = solver.stats().energy;
    run.iterations = solver.stats().iterations;
    run.renderedShots = solver.stats().renderedShots;
    run.distinctShooters = static_cast<int>(shooters.size());
    run.cacheBytes = solver.shooting().formFactorCacheBytes();
    run.elements = solver.stats().elements;
    return run;
}

void expectSameResult(const SolveOutcome& a, const SolveOutcome& b)
{
    ASSERT_EQ(a.iterations, b.iterations);
    ASSERT_EQ(a.radiosity.size(), b.radiosity.size());
    for (size_t j = 0; j < a.radiosity.size(); ++j)
        ASSERT_EQ(a.radiosity[j], b.radiosity[j]) << "element " << j;
    EXPECT_EQ(a.energy.absorbed, b.energy.absorbed);
    EXPECT_EQ(a.energy.escaped, b.energy.escaped);
    EXPECT_EQ(a.energy.unshot, b.energy.unshot);
}

SolverOptions fixedMesh(int hemicube)
{
    SolverOptions o;
    o.hemicube = hemicube;
    o.adaptive = false;
    o.threads = 1;
    return o;
}

} // namespace

TEST(ShotReuse, KeptRowsGiveTheResultOfRenderingEveryShot)
{
    SolverOptions rendering = fixedMesh(64);
    rendering.formFactorCacheBytes = 0;
    const SolveOutcome everyShot = solve("cornell-box", rendering, 1500);
    const SolveOutcome reusing = solve("cornell-box", fixedMesh(64), 1500);
    expectSameResult(everyShot, reusing);
    EXPECT_EQ(everyShot.renderedShots, everyShot.iterations);
    EXPECT_EQ(everyShot.cacheBytes, 0u);
    // Each patch rendered once: every later shot of it reused its row.
    EXPECT_EQ(reusing.renderedShots, reusing.distinctShooters);
    EXPECT_LT(reusing.renderedShots, reusing.iterations / 2);
    EXPECT_GT(reusing.cacheBytes, 0u);
}

TEST(ShotReuse, ABudgetTooSmallForEveryRowKeepsWhatFitsAndTheSameResult)
{
    SolverOptions small = fixedMesh(64);
    small.formFactorCacheBytes = 64 * 1024;
    const SolveOutcome everyRow = solve("cornell-box", fixedMesh(64), 1500);
    const SolveOutcome someRows = solve("cornell-box", small, 1500);
    expectSameResult(everyRow, someRows);
    EXPECT_LE(someRows.cacheBytes, small.formFactorCacheBytes);
    EXPECT_GT(someRows.cacheBytes, 0u);
    EXPECT_GT(someRows.renderedShots, everyRow.renderedShots);
    EXPECT_LT(someRows.renderedShots, someRows.iterations);
}

TEST(ShotReuse, RowsAreDroppedWhenAdaptiveSubdivisionChangesTheMesh)
{
    // The sample's own settings subdivide (§5.7) in the first few hundred
    // shots; a smaller hemicube keeps it quick.
    SolverOptions o;
    o.hemicube = 48;
    o.threads = 1;
    SolverOptions rendering = o;
    rendering.formFactorCacheBytes = 0;
    const SolveOutcome everyShot = solve("cornell-box", rendering, 1500);
    const SolveOutcome reusing = solve("cornell-box", o, 1500);
    ASSERT_GT(reusing.elements, 552 * 4) << "the mesh was expected to grow";
    expectSameResult(everyShot, reusing);
    EXPECT_LT(reusing.renderedShots, reusing.iterations / 2);
}

TEST(ShotReuse, AnyThreadCountGivesTheResultOfOneThread)
{
    for (model::Visibility mode : {model::Visibility::Painter, model::Visibility::ZBuffer}) {
        SolverOptions one = fixedMesh(80);
        one.visibility = mode;
        one.formFactorCacheBytes = 0;
        SolverOptions two = one;
        two.threads = 2;
        SolverOptions three = one;
        three.threads = 3;
        const SolveOutcome a = solve("two-lights-room", one, 60);
        expectSameResult(a, solve("two-lights-room", two, 60));
        expectSameResult(a, solve("two-lights-room", three, 60));
    }
}

TEST(RowArena, KeepsCopiesThatStayValidUntilReset)
{
    RowArena arena;
    std::vector<std::uint32_t> elements(1000);
    std::iota(elements.begin(), elements.end(), 7u);
    std::vector<double> factors(1000, 0.25);
    std::vector<std::span<const std::uint32_t>> kept;
    std::vector<std::span<const double>> keptFactors;
    // More rows than one chunk holds: earlier rows must not move.
    for (int row = 0; row < 5000; ++row) {
        kept.push_back(arena.keep(std::span<const std::uint32_t>(elements)));
        keptFactors.push_back(arena.keep(std::span<const double>(factors)));
    }
    elements.assign(elements.size(), 0u); // the arena holds copies
    for (size_t row = 0; row < kept.size(); row += 499) {
        ASSERT_EQ(kept[row].size(), 1000u);
        EXPECT_EQ(kept[row][0], 7u);
        EXPECT_EQ(kept[row][999], 1006u);
        EXPECT_EQ(keptFactors[row][500], 0.25);
        EXPECT_EQ(reinterpret_cast<std::uintptr_t>(keptFactors[row].data()) % alignof(double), 0u);
    }
    EXPECT_TRUE(arena.keep(std::span<const double>()).empty());
}

TEST(RowArena, ResetReusesItsChunksAndARowLargerThanAChunkGetsItsOwn)
{
    RowArena arena;
    const std::vector<double> row(100000, 1.0); // 800 kB
    for (int i = 0; i < 100; ++i)
        arena.keep(std::span<const double>(row));
    const std::size_t held = arena.capacity();
    ASSERT_GE(held, 100u * 800000u);
    // A new mesh: the same rows again take no new memory.
    arena.reset();
    for (int i = 0; i < 100; ++i)
        arena.keep(std::span<const double>(row));
    EXPECT_EQ(arena.capacity(), held);
    // One row of 80 MB, larger than a chunk.
    const std::vector<double> huge(10000000, 2.0);
    const std::span<const double> kept = arena.keep(std::span<const double>(huge));
    EXPECT_EQ(kept.size(), huge.size());
    EXPECT_EQ(kept.back(), 2.0);
    EXPECT_GE(arena.capacity(), held + huge.size() * sizeof(double));
}

TEST(RowArena, ReadiesTheNextChunkAheadButNeverPastItsLimit)
{
    constexpr std::size_t MiB = std::size_t(1) << 20;
    // No limit, no chunk ahead: an arena for rows that are never kept holds nothing.
    EXPECT_EQ(RowArena().capacity(), 0u);

    // Room for three chunks of 32 MiB: the first is made when a row needs
    // it, each next one readied when the one before is half full, and no
    // fourth.
    RowArena arena(96 * MiB);
    EXPECT_EQ(arena.capacity(), 0u);
    std::vector<double> row(125000); // 1 MB
    std::vector<std::span<const double>> kept;
    for (int i = 0; i < 60; ++i) {
        row.assign(row.size(), double(i));
        kept.push_back(arena.keep(std::span<const double>(row)));
        EXPECT_EQ(arena.capacity(), (i < 16 ? 32 : i < 49 ? 64 : 96) * MiB) << "row " << i;
    }
    for (int i = 0; i < 60; ++i) {
        ASSERT_EQ(kept[size_t(i)].size(), row.size());
        EXPECT_EQ(kept[size_t(i)].front(), double(i));
        EXPECT_EQ(kept[size_t(i)].back(), double(i));
    }
    // A row larger than a chunk gets its own and leaves the readied one be.
    const std::vector<double> huge(5000000, 3.0); // 40 MB
    EXPECT_EQ(arena.keep(std::span<const double>(huge)).back(), 3.0);
    EXPECT_EQ(arena.capacity(), 96 * MiB + 40 * MiB);
    // What comes after takes the readied chunk, beyond which none is readied.
    for (int i = 0; i < 30; ++i)
        arena.keep(std::span<const double>(row));
    EXPECT_EQ(arena.capacity(), 96 * MiB + 40 * MiB);
}
