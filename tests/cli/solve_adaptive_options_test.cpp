// `regio-solve solve --adaptive/--threshold/--min-edge/--anchoring`: the
// command-line overrides of the scene's adaptive subdivision settings (§5.7),
// as the report and the mesh it describes show them.
#include "support/command_run.h"
#include "support/sample_scenes.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace regio::test;
using nlohmann::json;

namespace {

const fs::path kTwoLights = samplePath("two-lights-room");

// A lamp above a grey floor; the file's adaptive settings differ from every
// value the tests pass, so an override that does not arrive shows.
const char* const kLampOverFloor = R"({ "format": "regio-scene", "version": 1,
  "materials": [ { "id": "lamp", "reflectance": [0, 0, 0], "emission": [10, 8, 6] },
                 { "id": "grey", "reflectance": [0.5, 0.4, 0.3], "emission": [0, 0, 0] } ],
  "objects": [ { "id": "light", "parts": [ { "id": "light.panel", "material": "lamp",
      "vertices": [[0.4,1,0.4], [0.6,1,0.4], [0.6,1,0.6], [0.4,1,0.6]],
      "faces": [ { "id": "light.down", "loop": [0, 1, 2, 3] } ] } ] },
    { "id": "floor", "parts": [ { "id": "floor.panel", "material": "grey",
      "vertices": [[-2,0,-2], [-2,0,3], [3,0,3], [3,0,-2]],
      "faces": [ { "id": "floor.up", "loop": [0, 1, 2, 3] } ] } ] } ],
  "solver": { "hemicube": 50, "patchSize": 1.0, "elementsPerPatch": 1, "maxIterations": 500, "convergence": 0.001,
              "adaptive": { "enabled": false, "threshold": 0.5, "minEdge": 0.3, "anchoring": true } }
})";

// Runs `regio-solve solve --quiet --report R ARGS... SCENE` and returns the report.
json solveReport(const ScratchDir& scratch, std::vector<std::string> args, const fs::path& scene)
{
    std::vector<std::string> all{"solve", "--quiet", "--report", (scratch / "report.json").string()};
    all.insert(all.end(), args.begin(), args.end());
    all.push_back(scene.string());
    const CommandRun run = runRegioSolve(all);
    EXPECT_EQ(run.exitCode, 0) << run.err;
    const std::string text = readText(scratch / "report.json");
    return text.empty() ? json() : json::parse(text);
}

} // namespace

TEST(SolveAdaptiveOptions, EachOptionOverridesTheScenesSettingInTheReport)
{
    ScratchDir scratch;
    const fs::path scene = scratch.write("lamp.json", kLampOverFloor);
    const json a = solveReport(
        scratch,
        {"--iterations", "2", "--adaptive", "on", "--threshold", "0.125", "--min-edge", "0.0625", "--anchoring", "off"},
        scene)["adaptive"];
    EXPECT_EQ(a["enabled"], true);
    EXPECT_EQ(a["threshold"], 0.125);
    EXPECT_EQ(a["minEdge"], 0.0625);
    EXPECT_EQ(a["anchoring"], false);
}

TEST(SolveAdaptiveOptions, WithoutOptionsTheReportHoldsTheScenesOwnSettings)
{
    ScratchDir scratch;
    const fs::path scene = scratch.write("lamp.json", kLampOverFloor);
    const json a = solveReport(scratch, {"--iterations", "2"}, scene)["adaptive"];
    EXPECT_EQ(a["enabled"], false);
    EXPECT_EQ(a["threshold"], 0.5);
    EXPECT_EQ(a["minEdge"], 0.3);
    EXPECT_EQ(a["anchoring"], true);
    EXPECT_EQ(a["rounds"], 0);
}

TEST(SolveAdaptiveOptions, OptionsAlsoTakeTheirValueAfterAnEqualsSign)
{
    ScratchDir scratch;
    const fs::path scene = scratch.write("lamp.json", kLampOverFloor);
    const json a = solveReport(
        scratch, {"--iterations=2", "--adaptive=on", "--threshold=0.25", "--min-edge=0.5", "--anchoring=off"},
        scene)["adaptive"];
    EXPECT_EQ(a["enabled"], true);
    EXPECT_EQ(a["threshold"], 0.25);
    EXPECT_EQ(a["minEdge"], 0.5);
    EXPECT_EQ(a["anchoring"], false);
}

TEST(SolveAdaptiveOptions, AdaptiveOnRefinesTheSampleBetweenShots)
{
    ScratchDir scratch;
    // No shot, no round: the initial mesh of the sample.
    const int initial = solveReport(scratch, {"--iterations", "0", "--hemicube", "60"}, kTwoLights)["elements"];
    const json r = solveReport(scratch, {"--iterations", "20", "--hemicube", "60", "--adaptive", "on"}, kTwoLights);
    EXPECT_GE(r["adaptive"]["rounds"].get<int>(), 1);
    EXPECT_GT(r["elements"].get<int>(), initial);
    EXPECT_GT(r["seconds"]["adaptive"].get<double>(), 0.0);
}

TEST(SolveAdaptiveOptions, AdaptiveOffKeepsTheInitialMeshAndDoesNoRound)
{
    ScratchDir scratch;
    // With adaptive subdivision on, even the mesh of the first shot is finer
    // along the lamps' and furniture's feet (contact lines): compare with the
    // prepared mesh.
    const int initial =
        solveReport(scratch, {"--iterations", "0", "--hemicube", "60", "--adaptive", "off"}, kTwoLights)["elements"];
    const json r = solveReport(scratch, {"--iterations", "20", "--hemicube", "60", "--adaptive", "off"}, kTwoLights);
    EXPECT_EQ(r["adaptive"]["enabled"], false);
    EXPECT_EQ(r["adaptive"]["rounds"], 0);
    EXPECT_EQ(r["adaptive"]["contactElements"], 0);
    EXPECT_EQ(r["adaptive"]["penumbraElements"], 0);
    EXPECT_EQ(r["elements"].get<int>(), initial);
    EXPECT_EQ(r["seconds"]["adaptive"].get<double>(), 0.0);
}

TEST(SolveAdaptiveOptions, AThresholdOfOneSplitsNothing)
{
    // The contrast is relative to the brighter neighbour, so it never exceeds 1.
    ScratchDir scratch;
    const int initial = solveReport(scratch, {"--iterations", "0", "--hemicube", "60"}, kTwoLights)["elements"];
    const json r = solveReport(
        scratch, {"--iterations", "20", "--hemicube", "60", "--adaptive", "on", "--threshold", "1"}, kTwoLights);
    EXPECT_EQ(r["adaptive"]["rounds"], 0);
    EXPECT_EQ(r["elements"].get<int>(), initial);
}

TEST(SolveAdaptiveOptions, AMinimumEdgeLongerThanEveryElementSplitsNothing)
{
    ScratchDir scratch;
    // Not even along contact lines: the prepared mesh, as with adaptive off.
    const int initial =
        solveReport(scratch, {"--iterations", "0", "--hemicube", "60", "--adaptive", "off"}, kTwoLights)["elements"];
    const json r = solveReport(
        scratch, {"--iterations", "20", "--hemicube", "60", "--adaptive", "on", "--min-edge", "50"}, kTwoLights);
    EXPECT_EQ(r["adaptive"]["rounds"], 0);
    EXPECT_EQ(r["adaptive"]["contactElements"], 0);
    EXPECT_EQ(r["adaptive"]["penumbraElements"], 0);
    EXPECT_EQ(r["elements"].get<int>(), initial);
}

TEST(SolveAdaptiveOptions, TheSplitsAlongContactLinesAndInPenumbraeAreCountedBeforeTheFirstShot)
{
    ScratchDir scratch;
    const int prepared =
        solveReport(scratch, {"--iterations", "0", "--hemicube", "60", "--adaptive", "off"}, kTwoLights)["elements"];
    const json r = solveReport(scratch, {"--iterations", "0", "--hemicube", "60", "--adaptive", "on"}, kTwoLights);
    EXPECT_EQ(r["adaptive"]["rounds"], 0);
    EXPECT_GT(r["adaptive"]["contactElements"].get<int>(), 0);
    EXPECT_GT(r["adaptive"]["penumbraElements"].get<int>(), 0);
    EXPECT_EQ(r["elements"].get<int>(),
              prepared + r["adaptive"]["contactElements"].get<int>() + r["adaptive"]["penumbraElements"].get<int>());
}

TEST(SolveAdaptiveOptions, BadValuesAreUsageErrorsNamingTheOption)
{
    const std::string scene = kTwoLights.string();
    struct Case {
        std::vector<std::string> args;
        std::string option;
    };
    for (const Case& c : std::vector<Case>{{{"--adaptive", "yes", scene}, "--adaptive"},
                                           {{"--adaptive", "", scene}, "--adaptive"},
                                           {{"--adaptive"}, "--adaptive"},
                                           {{"--anchoring", "true", scene}, "--anchoring"},
                                           {{"--anchoring=1", scene}, "--anchoring"},
                                           {{"--threshold", "-0.1", scene}, "--threshold"},
                                           {{"--threshold", "abc", scene}, "--threshold"},
                                           {{"--threshold", "nan", scene}, "--threshold"},
                                           {{"--threshold", "0.1x", scene}, "--threshold"},
                                           {{"--min-edge", "0", scene}, "--min-edge"},
                                           {{"--min-edge", "-0.02", scene}, "--min-edge"},
                                           {{"--min-edge", "inf", scene}, "--min-edge"},
                                           {{"--min-edge", "2cm", scene}, "--min-edge"}}) {
        std::vector<std::string> all{"solve"};
        all.insert(all.end(), c.args.begin(), c.args.end());
        const CommandRun run = runRegioSolve(all);
        const std::string what = c.args[0] + (c.args.size() > 1 ? " " + c.args[1] : "");
        EXPECT_EQ(run.exitCode, 2) << what;
        EXPECT_NE(run.err.find("regio-solve solve: " + c.option), std::string::npos) << what << ": " << run.err;
        EXPECT_EQ(run.out, "") << what; // refused before anything was solved
    }
}

TEST(SolveAdaptiveOptions, TheSummaryLineCountsTheRounds)
{
    const CommandRun run =
        runRegioSolve({"solve", "--iterations", "20", "--hemicube", "60", "--adaptive", "on", kTwoLights.string()});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("adaptive round"), std::string::npos) << run.out;
    const CommandRun off =
        runRegioSolve({"solve", "--iterations", "2", "--hemicube", "60", "--adaptive", "off", kTwoLights.string()});
    ASSERT_EQ(off.exitCode, 0) << off.err;
    EXPECT_EQ(off.out.find("adaptive"), std::string::npos) << off.out;
}

TEST(SolveAdaptiveOptions, TuningASubdivisionThatIsOffIsSolvedWithAWarning)
{
    ScratchDir scratch;
    const fs::path scene = scratch.write("lamp.json", kLampOverFloor); // adaptive.enabled = false
    const CommandRun run = runRegioSolve(
        {"solve", "--quiet", "--iterations", "1", "--threshold", "0.2", "--min-edge", "0.1", scene.string()});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.err.find("warning: --threshold, --min-edge have no effect"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("--adaptive on turns it on"), std::string::npos) << run.err;

    const CommandRun off = runRegioSolve(
        {"solve", "--quiet", "--iterations", "1", "--adaptive", "off", "--anchoring", "off", kTwoLights.string()});
    ASSERT_EQ(off.exitCode, 0) << off.err;
    EXPECT_NE(off.err.find("warning: --anchoring has no effect"), std::string::npos) << off.err;
    EXPECT_EQ(off.err.find("turns it on"), std::string::npos) << off.err;

    const CommandRun on = runRegioSolve(
        {"solve", "--quiet", "--iterations", "1", "--adaptive", "on", "--threshold", "0.2", scene.string()});
    ASSERT_EQ(on.exitCode, 0) << on.err;
    EXPECT_EQ(on.err, "");
}

TEST(SolveAdaptiveOptions, TheReportsEnergyBooksBalanceWithSubdivisionOn)
{
    ScratchDir scratch;
    const json r = solveReport(scratch, {"--iterations", "20", "--hemicube", "60", "--adaptive", "on"}, kTwoLights);
    ASSERT_GE(r["adaptive"]["rounds"].get<int>(), 1);
    const json& e = r["energy"];
    for (size_t c = 0; c < 3; ++c) {
        const double emitted = e["emitted"][c].get<double>();
        const double sum =
            e["absorbed"][c].get<double>() + e["unshot"][c].get<double>() + e["escaped"][c].get<double>();
        EXPECT_NEAR(sum, emitted, 1e-9 * emitted) << "channel " << c;
    }
}
