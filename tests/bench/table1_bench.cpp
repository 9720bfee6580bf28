// The paper's Table 1 (§7): the two-light test scene meshed to about 5930
// elements, 100 shooting iterations at hemicube resolutions 150^2, 300^2 and
// 600^2; here in painter and z-buffer modes. Prints seconds per 100
// iterations and how many times faster than the SGI R4000 of the paper
// (31.23 s / 52.05 s / 121.34 s) each run was.
//
// Every repetition starts from a fresh solver (the same 100 shooters); the
// preparation (regional tree, BSP trees, meshing) is not timed. Use
// --benchmark_repetitions=N for medians (default 5 here).
#include "model/scene_json.h"
#include "model/validation.h"
#include "solver/prepare.h"
#include "solver/solver.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

using namespace regio;
using namespace regio::solver;

namespace {

constexpr int kPaperElements = 5930;
constexpr int kIterations = 100;

struct Setup {
    model::Scene scene;
    double patchSize = 0.5;
    int elementsPerPatch = 4;
    int elements = 0;
};

int elementCount(const model::Scene& scene, double patchSize, int elementsPerPatch)
{
    PrepareOptions options;
    options.patchSize = patchSize;
    options.elementsPerPatch = elementsPerPatch;
    const PrepareResult r = prepareScene(scene, options);
    return r.scene ? static_cast<int>(r.scene->elements.size()) : 0;
}

// The element/patch ratio and patch size whose mesh comes closest to the
// paper's element count.
const Setup& setup()
{
    static const Setup s = [] {
        Setup s;
        const std::string path = std::string(REGIO_SOURCE_DIR) + "/resources/scenes/two-lights-room.json";
        model::SceneReadResult read = model::loadSceneFile(path);
        if (!read.scene || model::hasErrors(model::validateScene(*read.scene))) {
            std::fprintf(stderr, "cannot use %s\n", path.c_str());
            std::exit(2);
        }
        s.scene = *read.scene;
        // The mesher makes k x k elements per patch, so the ratios tried are
        // squares; the patch size is scanned in 1 % steps (element counts jump
        // with the BSP splits, bisection would miss the closest).
        int best = 0;
        for (int ratio : {1, 4, 9, 16})
            for (double size = 0.15; size < 2.0; size *= 1.01) {
                const int n = elementCount(s.scene, size, ratio);
                if (std::abs(n - kPaperElements) < std::abs(best - kPaperElements)) {
                    best = n;
                    s.patchSize = size;
                    s.elementsPerPatch = ratio;
                }
            }
        s.elements = best;
        std::printf("two-lights-room: patchSize %.4f m, %d elements per patch -> %d elements (paper: %d)\n",
                    s.patchSize, s.elementsPerPatch, s.elements, kPaperElements);
        return s;
    }();
    return s;
}

double paperSeconds(int resolution)
{
    switch (resolution) {
    case 150: return 31.23;
    case 300: return 52.05;
    case 600: return 121.34;
    }
    return 0.0;
}

void table1(benchmark::State& state, VisibilityMode mode)
{
    const Setup& s = setup();
    const int resolution = static_cast<int>(state.range(0));
    for (auto _ : state) {
        state.PauseTiming();
        SolverOptions options;
        options.hemicube = resolution;
        options.patchSize = s.patchSize;
        options.elementsPerPatch = s.elementsPerPatch;
        options.visibility = mode;
        auto built = Solver::create(s.scene, options);
        if (!built.solver) {
            state.SkipWithError("the scene could not be prepared");
            return;
        }
        state.ResumeTiming();
        const int done = built.solver->step(kIterations);
        benchmark::DoNotOptimize(done);
        if (done != kIterations)
            state.SkipWithError("fewer than 100 shooters");
    }
    state.counters["elements"] = s.elements;
    // Seconds per 100 iterations equal seconds per benchmark iteration here.
    state.counters["s_per_100"] = benchmark::Counter(1.0, benchmark::Counter::kIsIterationInvariantRate |
                                                              benchmark::Counter::kInvert);
    state.counters["x_paper"] = benchmark::Counter(paperSeconds(resolution), benchmark::Counter::kIsIterationInvariantRate);
}

void painter(benchmark::State& state) { table1(state, VisibilityMode::Painter); }
void zbuffer(benchmark::State& state) { table1(state, VisibilityMode::ZBuffer); }

} // namespace

BENCHMARK(painter)->Arg(150)->Arg(300)->Arg(600)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1)->Repetitions(5);
BENCHMARK(zbuffer)->Arg(150)->Arg(300)->Arg(600)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1)->Repetitions(5);

int main(int argc, char** argv)
{
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv))
        return 1;
    setup();
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
