// What adaptive subdivision (§5.7) costs on the two-light sample with its own
// settings (hemicube, mesh, adaptive threshold and minEdge):
//
//   full_solve/0 and /1  a solve of exactly 500 shots (maxIterations, set below)
//                        with adaptive subdivision off and on: seconds (shots
//                        plus refinement rounds; preparation not timed) and
//                        the element count at the end;
//   rounds               the refinement rounds of such a solve taken apart
//                        through the public pieces the Solver is made of
//                        (Shooting, AdaptiveRefinement): the seconds a round
//                        spends choosing and splitting elements, and the
//                        seconds of the hand-over of the grown mesh to the
//                        shooter (AdaptiveRefinement::takeActiveScene, moving
//                        the scene into place, Shooting::replaceElementState).
//                        The Solver also copies the grown mesh for snapshots
//                        (SolutionMesh) in its hand-over; that copy is private
//                        to it and not in these figures.
//
// Three repetitions each; the machine's load shows in the spread, so read the
// medians the summary prints. Not a test: timings are never pass/fail.
#include "model/io/scene_json.h"
#include "model/validation/validation.h"
#include "solver/prepare/prepare.h"
#include "solver/shooting/adaptive_refinement.h"
#include "solver/shooting/shooting.h"
#include "solver/solver.h"
#include "support/sample_scenes.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

using namespace regio;
using namespace regio::solver;

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

const model::Scene& scene()
{
    static const model::Scene s = [] {
        const std::string path = regio::test::samplePath("two-lights-room").string();
        model::Result<model::Scene> read = model::loadSceneFile(path);
        if (!read.ok() || model::hasErrors(model::validateScene(*read))) {
            std::fprintf(stderr, "cannot use %s\n", path.c_str());
            std::exit(2);
        }
        // 500 shots, the sample's limit when docs/performance.md's figures
        // were first taken (it converges at about 6900 now and has 10000).
        model::Scene scene = std::move(*read);
        scene.solver.maxIterations = 500;
        return scene;
    }();
    return s;
}

// Every repetition's figures by name, for the summary of medians.
std::map<std::string, std::vector<double>>& measured()
{
    static std::map<std::string, std::vector<double>> m;
    return m;
}

// The rounds of the last repetition of `rounds`: elements after the round,
// seconds splitting, seconds handing over.
struct RoundFigures {
    int elements = 0;
    double splitSeconds = 0.0;
    double handOverSeconds = 0.0;
};
std::vector<RoundFigures>& lastRounds()
{
    static std::vector<RoundFigures> r;
    return r;
}

double median(std::vector<double> v)
{
    if (v.empty())
        return 0.0;
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

void fullSolve(benchmark::State& state)
{
    const bool adaptive = state.range(0) != 0;
    const std::string name = adaptive ? "on" : "off";
    for (auto _ : state) {
        SolverOptions options;
        options.adaptive = adaptive; // the rest is the scene's own settings
        auto built = Solver::create(scene(), options);
        if (!built.ok()) {
            state.SkipWithError("the scene could not be prepared");
            return;
        }
        Solver& s = **built;
        // Exactly maxIterations shots (step() ignores the convergence test), so
        // both runs shoot equally often.
        const auto start = Clock::now();
        const int done = s.step(s.settings().maxIterations);
        const double seconds = secondsSince(start);
        state.SetIterationTime(seconds);
        const SolverStats st = s.stats();
        measured()[name + " seconds"].push_back(seconds);
        measured()[name + " shoot seconds"].push_back(st.shootSeconds);
        measured()[name + " adaptive seconds"].push_back(st.adaptiveSeconds);
        measured()[name + " elements"].push_back(st.elements);
        measured()[name + " rounds"].push_back(st.adaptiveRounds);
        measured()[name + " shots"].push_back(done);
        state.counters["shots"] = done;
        state.counters["elements"] = st.elements;
        state.counters["rounds"] = st.adaptiveRounds;
        state.counters["adaptive_s"] = st.adaptiveSeconds;
    }
}

// The Solver's loop (solver.cpp: step() and refineIfDue()) spelled out with
// the public pieces, timing each round's two halves.
void rounds(benchmark::State& state)
{
    const model::Scene& sc = scene();
    for (auto _ : state) {
        model::Result<PreparedScene> prepared = prepareScene(sc, PrepareOptions{});
        if (!prepared.ok()) {
            state.SkipWithError("the scene could not be prepared");
            return;
        }
        PreparedScene active = std::move(*prepared);
        const int initial = static_cast<int>(active.elements.size());
        AdaptiveRefinement refinement(active, sc.solver.adaptive);
        Shooting shooting(active, sc.solver.hemicube, model::Visibility::Painter);
        const RefinementPolicy policy;
        double splitSeconds = 0.0, handOverSeconds = 0.0, firstHandOver = -1.0, lastHandOver = 0.0;
        int lastElements = initial;
        lastRounds().clear();
        for (int shot = 0; shot < sc.solver.maxIterations && refinement.rounds() < policy.maxRounds; ++shot) {
            if (refinement.roundDue()) {
                const auto splitStart = Clock::now();
                const AdaptiveRefinement::Outcome outcome =
                    refinement.runRound(shooting.radiosity(), shooting.unshotRadiosity(), nullptr);
                const double split = secondsSince(splitStart);
                splitSeconds += split;
                if (outcome == AdaptiveRefinement::Outcome::Refined) {
                    const auto handOverStart = Clock::now();
                    ActiveScene grown = refinement.takeActiveScene();
                    active = std::move(grown.scene); // in place: the shooter refers to it
                    shooting.replaceElementState(std::move(grown.radiosity), std::move(grown.unshot));
                    lastHandOver = secondsSince(handOverStart);
                    handOverSeconds += lastHandOver;
                    if (firstHandOver < 0.0)
                        firstHandOver = lastHandOver;
                    lastElements = static_cast<int>(active.elements.size());
                    lastRounds().push_back({lastElements, split, lastHandOver});
                }
            }
            if (shooting.shoot() != ShotResult::Shot)
                break;
            const Patch& shooter = active.patches[static_cast<size_t>(shooting.lastShooter())];
            refinement.noteShot(shooting.iterations(),
                                active.properties[static_cast<size_t>(shooter.properties)].emits());
        }
        state.SetIterationTime(splitSeconds + handOverSeconds);
        const int n = refinement.rounds();
        measured()["rounds"].push_back(n);
        measured()["round split seconds (all rounds)"].push_back(splitSeconds);
        measured()["hand-over seconds (all rounds)"].push_back(handOverSeconds);
        measured()["hand-over seconds, first round"].push_back(std::max(firstHandOver, 0.0));
        measured()["hand-over seconds, last round"].push_back(lastHandOver);
        measured()["elements initial"].push_back(initial);
        measured()["elements after last round"].push_back(lastElements);
        state.counters["rounds"] = n;
        state.counters["handover_s"] = handOverSeconds;
        state.counters["split_s"] = splitSeconds;
        state.counters["elements"] = lastElements;
    }
}

} // namespace

BENCHMARK(fullSolve)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseManualTime()->Iterations(1)->Repetitions(3);
BENCHMARK(rounds)->Unit(benchmark::kMillisecond)->UseManualTime()->Iterations(1)->Repetitions(3);

int main(int argc, char** argv)
{
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv))
        return 1;
    scene();
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();

    std::printf("\nAdaptive subdivision on two-lights-room (hemicube %d, %d shots), medians:\n",
                scene().solver.hemicube, scene().solver.maxIterations);
    for (const auto& [name, values] : measured())
        std::printf("  %-36s %12.4f   (%zu runs)\n", name.c_str(), median(values), values.size());
    const auto& m = measured();
    if (m.count("on seconds") && m.count("off seconds")) {
        std::printf("  on / off: seconds %.2f, elements %.2f\n",
                    median(m.at("on seconds")) / median(m.at("off seconds")),
                    median(m.at("on elements")) / median(m.at("off elements")));
    }
    if (m.count("on adaptive seconds") && m.count("round split seconds (all rounds)")) {
        // The Solver's adaptive seconds hold the splitting, its hand-over and
        // the copy of the grown mesh for snapshots: what is not splitting is
        // the Solver's whole hand-over (medians of different runs: a guide).
        std::printf("  Solver hand-over incl. its snapshot mesh, all rounds (on adaptive - split): %.4f\n",
                    median(m.at("on adaptive seconds")) - median(m.at("round split seconds (all rounds)")));
    }
    if (!lastRounds().empty()) {
        std::printf("\nRounds of the last repetition:\n%6s %10s %12s %14s\n", "round", "elements", "split [ms]",
                    "hand-over [ms]");
        for (size_t k = 0; k < lastRounds().size(); ++k)
            std::printf("%6zu %10d %12.2f %14.2f\n", k + 1, lastRounds()[k].elements,
                        1e3 * lastRounds()[k].splitSeconds, 1e3 * lastRounds()[k].handOverSeconds);
    }
    return 0;
}
