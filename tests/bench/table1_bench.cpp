// The paper's Table 1 (§7): the two-light test scene meshed to about 5930
// elements, 100 shooting iterations at hemicube resolutions 150^2, 300^2 and
// 600^2; here in painter and z-buffer modes, on one thread and on every core
// (the render split between threads by paint order or by faces, whichever
// the renderer finds faster: hemicube_renderer.h). Prints
// seconds per 100 iterations and how many times faster than the SGI R4000 of
// the paper (31.23 s / 52.05 s / 121.34 s) each run was, then a summary table
// of the medians.
//
// Every repetition starts from a fresh solver (the same 100 shooters, so
// shots that reuse kept form factors are as many as in a solve); the
// preparation (regional tree, BSP trees, meshing) is not timed. Five
// repetitions each; the machine's load shows in the spread, so read medians.
// Not a test: timings are never pass/fail.
#include "model/io/scene_json.h"
#include "model/validation/validation.h"
#include "solver/prepare/prepare.h"
#include "solver/solver.h"
#include "support/sample_scenes.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

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
    const model::Result<PreparedScene> r = prepareScene(scene, options);
    return r.ok() ? static_cast<int>(r->elements.size()) : 0;
}

// The element/patch ratio and patch size whose mesh comes closest to the
// paper's element count.
const Setup& setup()
{
    static const Setup instance = [] {
        Setup s;
        const std::string path = regio::test::samplePath("two-lights-room").string();
        model::Result<model::Scene> read = model::loadSceneFile(path);
        if (!read.ok() || model::hasErrors(model::validateScene(*read))) {
            std::fprintf(stderr, "cannot use %s\n", path.c_str());
            std::exit(2);
        }
        s.scene = *read;
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
    return instance;
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

// Seconds per 100 iterations of every repetition, per (mode, resolution),
// for the summary table printed at the end.
// Keyed by (mode, resolution, threads).
using Key = std::tuple<std::string, int, int>;
std::map<Key, std::vector<double>>& measured()
{
    static std::map<Key, std::vector<double>> m;
    return m;
}
// The split the renderer kept, per key (the last repetition's).
std::map<Key, std::string>& splits()
{
    static std::map<Key, std::string> m;
    return m;
}

void table1(benchmark::State& state, model::Visibility mode)
{
    const Setup& s = setup();
    const int resolution = static_cast<int>(state.range(0));
    double seconds = 0.0;
    std::string split;
    for (auto _ : state) {
        SolverOptions options;
        options.hemicube = resolution;
        options.patchSize = s.patchSize;
        options.elementsPerPatch = s.elementsPerPatch;
        options.visibility = mode;
        options.threads = static_cast<int>(state.range(1));
        // Table 1 is about the hemicube on a fixed mesh of about 5930 elements:
        // the scene's adaptive subdivision (on in the sample) would grow the
        // mesh between shots and time the refinement too (adaptive_bench does).
        options.adaptive = false;
        // The paper's progressive refinement: the shooters of Table 1, each
        // shot sending what its patch has (overrelaxation would shoot some
        // patches again sooner, and reuse their rows).
        options.overrelaxation = 1.0;
        auto built = Solver::create(s.scene, options);
        if (!built.ok()) {
            state.SkipWithError("the scene could not be prepared");
            return;
        }
        const auto start = std::chrono::steady_clock::now();
        const int done = (*built)->step(kIterations);
        seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        state.SetIterationTime(seconds);
        const Shooting& shooting = (*built)->shooting();
        split = shooting.threads() == 1 ? "-" : shooting.renderSplit() == RenderSplit::Order ? "order" : "faces";
        if (done != kIterations) {
            state.SkipWithError("fewer than 100 shooters");
            return;
        }
    }
    const Key key{model::visibilityName(mode), resolution, resolveThreadCount(static_cast<int>(state.range(1)))};
    measured()[key].push_back(seconds);
    splits()[key] = split;
    state.counters["elements"] = s.elements;
    state.counters["s_per_100"] = seconds;
    state.counters["paper_over_ours"] = paperSeconds(resolution) / seconds;
}

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

void painter(benchmark::State& state) { table1(state, model::Visibility::Painter); }
void zbuffer(benchmark::State& state) { table1(state, model::Visibility::ZBuffer); }

} // namespace

// One iteration = 100 shots from a fresh solver; the solver's construction
// (scene preparation) is outside the manually timed region.
BENCHMARK(painter)
    ->ArgNames({"hemicube", "threads"})
    ->ArgsProduct({{150, 300, 600}, {1, 0}})
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->Iterations(1)
    ->Repetitions(5);
BENCHMARK(zbuffer)
    ->ArgNames({"hemicube", "threads"})
    ->ArgsProduct({{150, 300, 600}, {1, 0}})
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->Iterations(1)
    ->Repetitions(5);

int main(int argc, char** argv)
{
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv))
        return 1;
    setup();
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();

    std::printf("\nTable 1, %d elements, seconds per %d iterations (medians):\n", setup().elements, kIterations);
    std::printf("%-10s %8s %8s %6s %10s %10s %16s\n", "mode", "hemicube", "threads", "split", "ours [s]", "paper [s]",
                "paper / ours");
    for (const auto& [key, runs] : measured()) {
        const auto& [mode, resolution, threads] = key;
        const double m = median(runs);
        std::printf("%-10s %8d %8d %6s %10.3f %10.2f %16.0f   (%zu runs)\n", mode.c_str(), resolution,
                    std::min(threads, HemicubeRenderer::kMaxThreads), splits()[key].c_str(), m,
                    paperSeconds(resolution), paperSeconds(resolution) / m, runs.size());
    }
    return 0;
}
