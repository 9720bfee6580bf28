// The solver's speed: the time to a converged answer, a shot's cost as the
// scene and the hemicube grow, and the preparation of a large scene.
//
// Time to a converged answer, what a user waits for. Each case solves a scene
// from scratch until the unshot power falls below 0.1 % of the emitted (no
// iteration limit), and reports the seconds of shooting plus refinement
// (preparation apart), the shots, and the shots that rendered a hemicube (the
// others reused the form factors kept from an earlier shot of the same patch).
//
//   cornell/T/C/W    the Cornell box sample with its own settings (adaptive on)
//   two_lights/T/C/W the two-light sample with its own settings (adaptive on)
//   furnished/T/C/W  a generated furnished room (tests/support/furnished_room.h,
//                    seed 1, 11 objects, automatic regions) meshed to about
//                    20 000 elements (the patch size from a coarse mesh's
//                    count), fixed mesh, hemicube 150
//
// T is the hemicube threads (0 = every core), C the form-factor row budget in
// MiB (0 = render every shot), W = 1 for overrelaxed shots (the default,
// shooting.h), 0 for classic progressive refinement: T=1, C=0, W=0 is how
// the solver ran before any of them existed. The answer is the same for every
// T and C (tests/solver/shooting/shot_reuse_test.cpp) and within 0.5 % per
// face for either W (shooting_test.cpp). T=1, C=0, W=0 runs once (it is
// slow), the others three times.
//
// A shot's cost at scale: a generated warehouse (the furnished-room generator,
// seed 7, one object per thousand elements, at least 10, on a floor that grows
// with them: 1000 objects on 40 m x 40 m; automatic regions) meshed to about
// 10 000, 100 000 and 1 000 000 elements, fixed mesh, 100 shots:
//
//   scale/E/N/T/R    E thousand elements, hemicube N, T threads, R = 1 for
//                    automatic regions, 0 for one BSP tree (no region culling)
//
// with the milliseconds per shot, the regions culled per shot and the peak
// resident memory of the process so far (run one case alone to read its own:
// --benchmark_filter). Rows are kept as in a solve (1 GiB), but 100 shots
// of distinct patches render every one.
//
//   preview_frame    the frame of the 100 000-element warehouse: smooth
//                    alone (output/vertex_radiosity.h), the shading built
//                    once per mesh, and a frame (vertex values summed from
//                    the element radiosity, the lit mesh copied), ten
//                    frames; beside it the same with the lights' direct
//                    part exact (output/exact_direct.h), what the outputs
//                    and the editor draw, and its build again for the
//                    screen with the direct part of every place known
//                    (what the editor pays after a refinement round)
//
//   prepare          the regional tree, BSP trees and meshing of a scene of
//                    about 100 000 faces (the generator with 7300 objects on
//                    a 130 m floor, automatic regions, patch size 1 m, one
//                    element per patch)
//
// Three repetitions each (one for the largest); the machine's load shows in
// the spread, so read the medians the summary prints. Not a test: timings are
// never pass/fail.
#include "output/exact_direct.h"
#include "output/vertex_radiosity.h"
#include "solver/solver.h"
#include "support/furnished_room.h"
#include "support/sample_scenes.h"

#include <benchmark/benchmark.h>

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

using namespace regio;
using namespace regio::solver;

namespace {

constexpr double kConvergence = 0.001;
constexpr int kFurnishedElements = 20000;

struct Case {
    model::Scene scene;
    SolverOptions options; // without threads and budget
};

int elementCount(const model::Scene& scene, const SolverOptions& options)
{
    const model::SolverSettings s = resolveSettings(scene.solver, options);
    model::Result<PreparedScene> r = prepareScene(scene, prepareOptionsFor(s, options.autoRegionPatchThreshold));
    return r.ok() ? static_cast<int>(r->elements.size()) : 0;
}

SolverOptions untilConverged()
{
    SolverOptions o;
    o.maxIterations = 100000000;
    o.convergence = kConvergence;
    return o;
}

const Case& sample(const std::string& name)
{
    static std::map<std::string, Case> cases;
    auto it = cases.find(name);
    if (it == cases.end())
        it = cases.emplace(name, Case{test::loadSample(name), untilConverged()}).first;
    return it->second;
}

const Case& furnished()
{
    static const Case c = [] {
        Case f{test::furnishedRoom(1, 11), untilConverged()};
        f.options.adaptive = false;
        f.options.hemicube = 150;
        f.options.elementsPerPatch = 4;
        f.options.regions = model::RegionsMode::Auto;
        // The element count grows as 1 / patchSize^2: one coarse preparation
        // gives the patch size, a second the count it makes.
        f.options.patchSize = 0.5;
        const int coarse = elementCount(f.scene, f.options);
        const double bestSize = 0.5 * std::sqrt(double(coarse) / kFurnishedElements);
        f.options.patchSize = bestSize;
        const int best = elementCount(f.scene, f.options);
        std::printf("furnished room: patch size %.4f m -> %d elements\n", bestSize, best);
        return f;
    }();
    return c;
}

struct Figures {
    double seconds = 0.0;
    double prepare = 0.0;
    double shots = 0.0;
    double rendered = 0.0;
    double elements = 0.0;
};

std::map<std::string, std::vector<Figures>>& measured()
{
    static std::map<std::string, std::vector<Figures>> m;
    return m;
}

void converge(benchmark::State& state, const Case& c, const char* name)
{
    SolverOptions options = c.options;
    options.threads = static_cast<int>(state.range(0));
    options.formFactorCacheBytes = static_cast<std::size_t>(state.range(1)) << 20;
    options.overrelaxation = state.range(2) ? kDefaultOverrelaxation : 1.0;
    Figures fig;
    for (auto _ : state) {
        auto built = Solver::create(c.scene, options);
        if (!built.ok()) {
            state.SkipWithError("the scene could not be prepared");
            return;
        }
        Solver& solver = **built;
        const std::atomic<bool> cancel{false};
        const StopReason stop = solver.run({}, cancel);
        const SolverStats s = solver.stats();
        if (stop != StopReason::Converged) {
            state.SkipWithError("the solve did not converge");
            return;
        }
        fig = {s.shootSeconds + s.adaptiveSeconds, s.preprocessSeconds, double(s.iterations), double(s.renderedShots),
               double(s.elements)};
        state.SetIterationTime(fig.seconds);
    }
    const std::string key = std::string(name) + " threads " + std::to_string(state.range(0)) + ", rows " +
                            std::to_string(state.range(1)) + " MiB, " + (state.range(2) ? "overrelaxed" : "classic");
    measured()[key].push_back(fig);
    state.counters["shots"] = fig.shots;
    state.counters["rendered"] = fig.rendered;
    state.counters["elements"] = fig.elements;
    state.counters["prepare_s"] = fig.prepare;
}

double peakMegabytes()
{
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_maxrss) / 1024.0; // ru_maxrss is in KiB on Linux
}

// The warehouse for about `elements` elements: one object per thousand
// elements (at least 10) on a floor that grows with them (1000 objects on
// 40 m x 40 m), so a scene of a million elements has a thousand objects in
// many regions, and a small one is not all object faces at their coarsest.
const model::Scene& warehouse(int elements)
{
    static std::map<int, model::Scene> scenes;
    auto it = scenes.find(elements);
    if (it == scenes.end()) {
        const int objects = std::max(10, elements / 1000);
        const double side = 40.0 * std::sqrt(objects / 1000.0);
        it = scenes.emplace(elements, test::furnishedRoom(7, objects, {side, 3.0, side})).first;
    }
    return it->second;
}

// Meshed to about `elements` elements: the count grows as 1 / patchSize^2,
// so a coarse preparation gives the patch size, and a second corrects it.
SolverOptions warehouseOptions(int elements, bool regions)
{
    static std::map<int, double> patchSizes;
    SolverOptions o;
    o.adaptive = false;
    o.elementsPerPatch = 4;
    o.regions = regions ? model::RegionsMode::Auto : model::RegionsMode::None;
    auto it = patchSizes.find(elements);
    if (it == patchSizes.end()) {
        SolverOptions coarse = o;
        coarse.regions = model::RegionsMode::Auto;
        coarse.patchSize = 1.0;
        const int n = elementCount(warehouse(elements), coarse);
        // Small faces keep their one patch: correct the estimate once.
        coarse.patchSize = std::sqrt(double(n) / elements);
        const int m = elementCount(warehouse(elements), coarse);
        it = patchSizes.emplace(elements, *coarse.patchSize * std::sqrt(double(m) / elements)).first;
    }
    o.patchSize = it->second;
    return o;
}

struct ScaleFigures {
    int threads = 0; // the hemicube threads the solver used
    double msPerShot = 0.0;
    double elements = 0.0;
    double regions = 0.0;
    double culledPerShot = 0.0;
    double peakMiB = 0.0;
};
std::map<std::string, std::vector<ScaleFigures>>& scaleMeasured()
{
    static std::map<std::string, std::vector<ScaleFigures>> m;
    return m;
}

void scale(benchmark::State& state)
{
    const int elements = static_cast<int>(state.range(0)) * 1000;
    SolverOptions options = warehouseOptions(elements, state.range(4) != 0);
    options.hemicube = static_cast<int>(state.range(1));
    options.threads = static_cast<int>(state.range(2));
    constexpr int kShots = 100;
    ScaleFigures fig;
    for (auto _ : state) {
        auto built = Solver::create(warehouse(elements), options);
        if (!built.ok()) {
            state.SkipWithError("the scene could not be prepared");
            return;
        }
        Solver& solver = **built;
        if (solver.step(kShots) != kShots) {
            state.SkipWithError("fewer than 100 shooters");
            return;
        }
        const SolverStats s = solver.stats();
        state.SetIterationTime(s.shootSeconds);
        fig.msPerShot = 1000.0 * s.shootSeconds / kShots;
        fig.elements = s.elements;
        fig.regions = static_cast<double>(solver.prepared().regions.size());
        fig.culledPerShot = double(solver.shooting().visibilityStats().regionsCulled) / s.renderedShots;
        fig.peakMiB = peakMegabytes();
        fig.threads = solver.shooting().threads();
    }
    char key[128];
    std::snprintf(key, sizeof key, "%7d elements, %3d^2, %d threads, %s", int(fig.elements), int(state.range(1)),
                  fig.threads, state.range(4) ? "auto regions" : "one BSP");
    scaleMeasured()[key].push_back(fig);
    state.counters["ms_per_shot"] = fig.msPerShot;
    state.counters["elements"] = fig.elements;
    state.counters["regions"] = fig.regions;
    state.counters["culled_per_shot"] = fig.culledPerShot;
    state.counters["peak_MiB"] = fig.peakMiB;
}

std::vector<double>& prepareMeasured()
{
    static std::vector<double> m;
    return m;
}

void prepare(benchmark::State& state)
{
    static const model::Scene big = test::furnishedRoom(11, 7300, {130.0, 3.0, 130.0});
    PrepareOptions options;
    options.regions = model::RegionsMode::Auto;
    options.patchSize = 1.0;
    options.elementsPerPatch = 1;
    size_t faces = 0, elements = 0, regions = 0;
    for (auto _ : state) {
        const auto start = std::chrono::steady_clock::now();
        model::Result<PreparedScene> r = prepareScene(big, options);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (!r.ok()) {
            state.SkipWithError("the scene could not be prepared");
            return;
        }
        state.SetIterationTime(seconds);
        prepareMeasured().push_back(seconds);
        faces = r->faces.size();
        elements = r->elements.size();
        regions = r->regions.size();
    }
    state.counters["faces"] = double(faces);
    state.counters["elements"] = double(elements);
    state.counters["regions"] = double(regions);
}

struct FrameFigures {
    double buildMs = 0.0;
    double frameMs = 0.0;
    double cachedBuildMs = 0.0; // rebuilt with the direct part known at every place
    double smoothBuildMs = 0.0; // the smooth shading alone
    double smoothFrameMs = 0.0;
    double elements = 0.0;
};
std::vector<FrameFigures>& frameMeasured()
{
    static std::vector<FrameFigures> m;
    return m;
}

void previewFrame(benchmark::State& state)
{
    const model::Scene& scene = warehouse(100000);
    const SolverOptions options = warehouseOptions(100000, true);
    const model::SolverSettings settings = resolveSettings(scene.solver, options);
    model::Result<PreparedScene> prepared = prepareScene(scene, prepareOptionsFor(settings));
    if (!prepared.ok()) {
        state.SkipWithError("the scene could not be prepared");
        return;
    }
    // Some radiosity per element: the values do not change the cost.
    std::vector<model::Rgb> radiosity(prepared->elements.size());
    for (size_t e = 0; e < radiosity.size(); ++e)
        radiosity[e] = model::Rgb(1.0 + 0.001 * double(e % 997));
    FrameFigures fig;
    fig.elements = double(prepared->elements.size());
    using Clock = std::chrono::steady_clock;
    constexpr int kFrames = 10;
    const auto milliseconds = [](Clock::time_point a, Clock::time_point b) {
        return 1000.0 * std::chrono::duration<double>(b - a).count();
    };
    for (auto _ : state) {
        const auto smoothStart = Clock::now();
        const output::SmoothShading smooth(*prepared);
        const auto smoothBuilt = Clock::now();
        for (int f = 0; f < kFrames; ++f) {
            radiosity[size_t(f)] *= 1.01; // a new solution each frame
            const output::LitMesh mesh = smooth.litMesh(radiosity);
            benchmark::DoNotOptimize(mesh.radiosity.data());
        }
        output::DirectCache cache;
        const auto start = Clock::now();
        const output::ExactDirectShading shading(*prepared, {}, &cache);
        const auto built = Clock::now();
        // What the preview pays for a mesh whose places it has all seen
        // (cut for the screen: no search for corners a file's reader welds).
        const output::ExactDirectShading again(*prepared, {}, &cache, output::CutFor::Screen);
        const auto rebuilt = Clock::now();
        fig.cachedBuildMs = milliseconds(built, rebuilt);
        for (int f = 0; f < kFrames; ++f) {
            radiosity[size_t(f)] *= 1.01;
            const output::LitMesh mesh = shading.litMesh(radiosity);
            benchmark::DoNotOptimize(mesh.radiosity.data());
        }
        const auto done = Clock::now();
        fig.frameMs = milliseconds(rebuilt, done) / kFrames;
        fig.smoothBuildMs = milliseconds(smoothStart, smoothBuilt);
        fig.smoothFrameMs = milliseconds(smoothBuilt, start) / kFrames;
        fig.buildMs = milliseconds(start, built);
        state.SetIterationTime(std::chrono::duration<double>(done - start).count());
    }
    frameMeasured().push_back(fig);
    state.counters["elements"] = fig.elements;
    state.counters["build_ms"] = fig.buildMs;
    state.counters["frame_ms"] = fig.frameMs;
    state.counters["cached_build_ms"] = fig.cachedBuildMs;
    state.counters["smooth_build_ms"] = fig.smoothBuildMs;
    state.counters["smooth_frame_ms"] = fig.smoothFrameMs;
}

void cornell(benchmark::State& state) { converge(state, sample("cornell-box"), "cornell-box"); }
void twoLights(benchmark::State& state) { converge(state, sample("two-lights-room"), "two-lights-room"); }
void furnishedRoom(benchmark::State& state) { converge(state, furnished(), "furnished room"); }

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n == 0 ? 0.0 : n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

} // namespace

// T=1, C=0, W=0 (how the solver ran before threads, kept rows and
// overrelaxation) once: it is slow.
#define REGIO_CONVERGE(fn, name)                                                                                       \
    BENCHMARK(fn)                                                                                                      \
        ->Name(name)                                                                                                   \
        ->ArgNames({"threads", "rows_mib", "overrelax"})                                                               \
        ->Args({1, 0, 0})                                                                                              \
        ->Unit(benchmark::kMillisecond)                                                                                \
        ->UseManualTime()                                                                                              \
        ->Iterations(1)                                                                                                \
        ->Repetitions(1);                                                                                              \
    BENCHMARK(fn)                                                                                                      \
        ->Name(name)                                                                                                   \
        ->ArgNames({"threads", "rows_mib", "overrelax"})                                                               \
        ->Args({0, 1024, 0})                                                                                           \
        ->Args({1, 1024, 1})                                                                                           \
        ->Args({0, 1024, 1})                                                                                           \
        ->Unit(benchmark::kMillisecond)                                                                                \
        ->UseManualTime()                                                                                              \
        ->Iterations(1)                                                                                                \
        ->Repetitions(3)
REGIO_CONVERGE(cornell, "cornell");
REGIO_CONVERGE(twoLights, "two_lights");
REGIO_CONVERGE(furnishedRoom, "furnished");

// Elements (thousands), hemicube, threads, unused, regions.
BENCHMARK(scale)
    ->ArgNames({"kelements", "hemicube", "threads", "_", "regions"})
    ->Args({10, 300, 0, 0, 1})
    ->Args({100, 300, 0, 0, 1})
    ->Args({100, 150, 0, 0, 1})
    ->Args({100, 600, 0, 0, 1})
    ->Args({100, 300, 1, 0, 1})
    ->Args({100, 300, 0, 0, 0})
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->Iterations(1)
    ->Repetitions(3);
BENCHMARK(scale)
    ->ArgNames({"kelements", "hemicube", "threads", "_", "regions"})
    ->Args({1000, 300, 0, 0, 1})
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->Iterations(1)
    ->Repetitions(1);
BENCHMARK(previewFrame)
    ->Name("preview_frame")
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->Iterations(1)
    ->Repetitions(3);
BENCHMARK(prepare)->Unit(benchmark::kMillisecond)->UseManualTime()->Iterations(1)->Repetitions(3);

int main(int argc, char** argv)
{
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv))
        return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    std::printf("\nTo 0.1 %% unshot, medians (seconds = shooting + refinement; preparation apart):\n");
    std::printf("%-62s %9s %9s %9s %9s %9s\n", "case", "seconds", "shots", "rendered", "elements", "prepare");
    for (const auto& [key, runs] : measured()) {
        std::vector<double> seconds, shots, rendered, elements, prepare;
        for (const Figures& f : runs) {
            seconds.push_back(f.seconds);
            shots.push_back(f.shots);
            rendered.push_back(f.rendered);
            elements.push_back(f.elements);
            prepare.push_back(f.prepare);
        }
        std::printf("%-62s %9.3f %9.0f %9.0f %9.0f %9.3f\n", key.c_str(), median(seconds), median(shots),
                    median(rendered), median(elements), median(prepare));
    }
    if (!scaleMeasured().empty()) {
        std::printf("\n100 shots on the warehouse, medians:\n");
        std::printf("%-58s %11s %8s %14s %9s\n", "case", "ms/shot", "regions", "culled/shot", "peak MiB");
        for (const auto& [key, runs] : scaleMeasured()) {
            std::vector<double> ms, culled;
            double regions = 0.0, peak = 0.0;
            for (const ScaleFigures& f : runs) {
                ms.push_back(f.msPerShot);
                culled.push_back(f.culledPerShot);
                regions = f.regions;
                peak = std::max(peak, f.peakMiB);
            }
            std::printf("%-58s %11.2f %8.0f %14.1f %9.0f\n", key.c_str(), median(ms), regions, median(culled), peak);
        }
    }
    if (!frameMeasured().empty()) {
        std::vector<double> build, cached, frame, smoothBuild, smoothFrame;
        for (const FrameFigures& f : frameMeasured()) {
            build.push_back(f.buildMs);
            cached.push_back(f.cachedBuildMs);
            frame.push_back(f.frameMs);
            smoothBuild.push_back(f.smoothBuildMs);
            smoothFrame.push_back(f.smoothFrameMs);
        }
        std::printf(
            "\nThe frame, %.0f elements, medians: smooth alone, shading built in %.1f ms once per mesh, "
            "a frame in %.1f ms (with the direct part exact, as the outputs and the editor draw: %.1f ms and %.1f ms; "
            "built again "
            "for the screen with the direct part known at every place, as the preview after a refinement round: %.1f "
            "ms)\n",
            frameMeasured().front().elements, median(smoothBuild), median(smoothFrame), median(build), median(frame),
            median(cached));
    }
    if (!prepareMeasured().empty())
        std::printf("\nPreparation of the 100 000-face scene, median: %.3f s\n", median(prepareMeasured()));
    return 0;
}
