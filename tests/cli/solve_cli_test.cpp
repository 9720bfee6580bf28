// `regio-solve solve` as a user and a script see it: the real executable, its
// options, its JSON report, its progress line and its exit status.
#include "support/command_run.h"
#include "support/sample_scenes.h"
#include "support/small_scenes.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace regio::test;
using nlohmann::json;

namespace {

using Scratch = ScratchDir;

std::string quoted(const std::string& arg) { return shellQuoted(arg); }

// Runs `regio-solve solve ARGS...`.
CommandRun solve(const std::vector<std::string>& args)
{
    std::vector<std::string> all{"solve"};
    all.insert(all.end(), args.begin(), args.end());
    return runRegioSolve(all);
}

const fs::path kData = REGIO_TEST_DATA;

std::set<std::string> faceIdsOfFile(const fs::path& path)
{
    const json scene = json::parse(readText(path));
    std::set<std::string> ids;
    for (const json& object : scene["objects"])
        for (const json& part : object["parts"])
            for (const json& face : part["faces"])
                ids.insert(face["id"].get<std::string>());
    return ids;
}

void expectRgb(const json& value)
{
    ASSERT_TRUE(value.is_array());
    ASSERT_EQ(value.size(), 3u);
    for (const json& c : value)
        EXPECT_TRUE(c.is_number());
}

} // namespace

TEST(SolveCommand, SolvesASampleSceneAndWritesAReportWithEveryRequiredField)
{
    Scratch scratch;
    const fs::path scene = samplePath("two-lights-room");
    const CommandRun run =
        solve({"--iterations", "5", "--hemicube", "60", "--report", (scratch / "r.json").string(), scene.string()});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const json r = json::parse(readText(scratch / "r.json"));
    ASSERT_TRUE(r.is_object());
    EXPECT_EQ(r["scene"], scene.string());
    EXPECT_EQ(r["status"], "solved");
    EXPECT_EQ(r["visibility"], "painter");
    EXPECT_EQ(r["hemicube"], 60);
    EXPECT_EQ(r["lightHemicube"], 120); // the lights' shots twice as fine
    EXPECT_EQ(r["iterations"], 5);
    EXPECT_GT(r["patches"].get<int>(), 0);
    EXPECT_GE(r["elements"].get<int>(), r["patches"].get<int>());
    for (const char* key : {"preprocess", "shoot", "adaptive", "total"})
        EXPECT_GE(r["seconds"][key].get<double>(), 0.0) << key;
    // The sample's own adaptive settings (§5.7), and how many rounds split elements.
    EXPECT_EQ(r["adaptive"]["enabled"], true);
    EXPECT_TRUE(r["adaptive"]["threshold"].is_number());
    EXPECT_TRUE(r["adaptive"]["minEdge"].is_number());
    EXPECT_TRUE(r["adaptive"]["anchoring"].is_boolean());
    EXPECT_GE(r["adaptive"]["rounds"].get<int>(), 0);
    for (const char* key : {"emitted", "absorbed", "unshot", "escaped"})
        expectRgb(r["energy"][key]);
    EXPECT_EQ(r["bsp"]["regions"], 3);
    EXPECT_GT(r["bsp"]["inputFaces"].get<int>(), 0);
    EXPECT_GE(r["bsp"]["fragments"].get<int>(), r["bsp"]["inputFaces"].get<int>());
    EXPECT_EQ(r["bsp"]["perRegion"].size(), 3u);
    // Every face of the file, once, with its area and mean radiosity.
    std::set<std::string> reported;
    for (const json& f : r["faces"]) {
        reported.insert(f["id"].get<std::string>());
        EXPECT_GE(f["area"].get<double>(), 0.0);
        expectRgb(f["radiosity"]);
    }
    EXPECT_EQ(reported, faceIdsOfFile(scene));
    EXPECT_EQ(r["faces"].size(), reported.size());
}

TEST(SolveCommand, EnergyInTheReportBalancesPerChannel)
{
    Scratch scratch;
    const fs::path scene = scratch.write("small.json", kSmallScene);
    const CommandRun run = solve({"--iterations", "3", "--report", (scratch / "r.json").string(), scene.string()});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const json e = json::parse(readText(scratch / "r.json"))["energy"];
    // The lamp: 1 m^2 at (10, 8, 6) W/m^2.
    EXPECT_NEAR(e["emitted"][0].get<double>(), 10.0, 1e-9);
    for (size_t c = 0; c < 3; ++c) {
        const double sum =
            e["absorbed"][c].get<double>() + e["unshot"][c].get<double>() + e["escaped"][c].get<double>();
        EXPECT_NEAR(sum, e["emitted"][c].get<double>(), 1e-6 * e["emitted"][c].get<double>());
    }
}

TEST(SolveCommand, OptionsOverrideTheScenesSettingsAndShowInTheReport)
{
    Scratch scratch;
    const fs::path scene = samplePath("two-lights-room");
    const CommandRun run = solve({"--iterations=2", "--hemicube=41", "--visibility", "zbuffer", "--regions", "none",
                                  "--quiet", "--report", (scratch / "r.json").string(), scene.string()});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const json r = json::parse(readText(scratch / "r.json"));
    EXPECT_EQ(r["visibility"], "zbuffer");
    EXPECT_EQ(r["regions"], "none");
    EXPECT_EQ(r["hemicube"], 42); // odd resolutions round up to even
    EXPECT_EQ(r["lightHemicube"], 84);
    EXPECT_EQ(r["iterations"], 2);
    EXPECT_EQ(r["bsp"]["regions"], 1);
}

TEST(SolveCommand, IterationsMeansExactlyThatManyShotsWhateverTheScenesConvergenceSetting)
{
    Scratch scratch;
    std::string text = kSmallScene;
    const std::string loose = "\"convergence\": 0.99";
    text.replace(text.find("\"convergence\": 0.001"), std::string("\"convergence\": 0.001").size(), loose);
    const fs::path scene = scratch.write("loose.json", text);
    // The scene's own setting stops after the first shots (the lamp's unshot
    // patches and what the first shots sent back fall under 99 %)...
    CommandRun run = solve({"--report", (scratch / "a.json").string(), scene.string()});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    json r = json::parse(readText(scratch / "a.json"));
    EXPECT_EQ(r["stop"], "converged");
    EXPECT_LT(r["iterations"], 3);
    // ... but --iterations 3 shoots three times.
    run = solve({"--iterations", "3", "--report", (scratch / "b.json").string(), scene.string()});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    r = json::parse(readText(scratch / "b.json"));
    EXPECT_EQ(r["stop"], "maxIterations");
    EXPECT_EQ(r["iterations"], 3);
}

TEST(SolveCommand, ConvergenceStopsTheSolveEarly)
{
    Scratch scratch;
    const fs::path scene = samplePath("two-lights-room");
    const CommandRun run =
        solve({"--hemicube", "40", "--convergence", "0.6", "--report", (scratch / "r.json").string(), scene.string()});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const json r = json::parse(readText(scratch / "r.json"));
    EXPECT_EQ(r["stop"], "converged");
    EXPECT_LT(r["unshotRatio"].get<double>(), 0.6);
    EXPECT_LT(r["iterations"].get<int>(), 500);
}

TEST(SolveCommand, SeveralScenesGiveAnArrayOfReports)
{
    Scratch scratch;
    const fs::path small = scratch.write("small.json", kSmallScene);
    const CommandRun run = solve({"--iterations", "2", "--quiet", "--report", (scratch / "r.json").string(),
                                  small.string(), samplePath("cornell-box").string()});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const json r = json::parse(readText(scratch / "r.json"));
    ASSERT_TRUE(r.is_array());
    ASSERT_EQ(r.size(), 2u);
    EXPECT_EQ(r[0]["scene"], small.string());
    EXPECT_EQ(r[1]["scene"], samplePath("cornell-box").string());
}

TEST(SolveCommand, ReportDashWritesTheJsonToStandardOutput)
{
    Scratch scratch;
    const fs::path scene = scratch.write("small.json", kSmallScene);
    const CommandRun run = solve({"--iterations", "1", "--report", "-", scene.string()});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const json r = json::parse(run.out); // nothing else on standard output
    EXPECT_EQ(r["iterations"], 1);
}

TEST(SolveCommand, ShowsAProgressLineOnStandardErrorUnlessQuiet)
{
    Scratch scratch;
    const fs::path scene = scratch.write("small.json", kSmallScene);
    const CommandRun loud = solve({"--iterations", "3", scene.string()});
    ASSERT_EQ(loud.exitCode, 0);
    EXPECT_NE(loud.err.find('\r'), std::string::npos);
    EXPECT_NE(loud.err.find("iteration 3/3"), std::string::npos) << loud.err;
    EXPECT_NE(loud.out.find("3 iterations"), std::string::npos) << loud.out;

    const CommandRun quiet = solve({"--iterations", "3", "--quiet", scene.string()});
    ASSERT_EQ(quiet.exitCode, 0);
    EXPECT_EQ(quiet.err, "");
    EXPECT_EQ(quiet.out, "");
}

TEST(SolveCommand, RefusesToSolveASceneWithValidationErrorsAndExitsOne)
{
    Scratch scratch;
    const fs::path bad = kData / "bad" / "non-convex-face.json";
    const CommandRun run = solve({"--iterations", "1", "--report", (scratch / "r.json").string(), bad.string()});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_NE(run.err.find("not convex"), std::string::npos) << run.err;
    const json r = json::parse(readText(scratch / "r.json"));
    EXPECT_EQ(r["status"], "invalid");
    EXPECT_FALSE(r.contains("faces"));
}

TEST(SolveCommand, ASceneTooBigForTheMachineIsRefusedBeforeItIsPreparedAndExitsOne)
{
    Scratch scratch;
    json scene = json::parse(readText(samplePath("cornell-box")));
    scene["solver"]["patchSize"] = 0.0005; // half a millimetre: two thirds of a billion elements
    const fs::path file = scratch.write("too-fine.json", scene.dump());
    const CommandRun run = solve({"--report", (scratch / "r.json").string(), file.string()});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_NE(run.err.find("/solver/patchSize: error: the mesh would have about 676 million elements, beyond the "
                           "limit of 20 million: raise the patch size"),
              std::string::npos)
        << run.err;
    const json r = json::parse(readText(scratch / "r.json"));
    EXPECT_NE(r["status"], "solved");
    EXPECT_FALSE(r.contains("faces"));
}

TEST(SolveCommand, ASceneNeedingMoreMemoryThanTheProcessMayTakeIsRefusedWithBothFigures)
{
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
    GTEST_SKIP() << "a sanitizer's shadow memory does not fit under an address-space limit";
#endif
    Scratch scratch;
    json scene = json::parse(readText(samplePath("cornell-box")));
    scene["solver"]["patchSize"] = 0.004; // 10.6 million elements once refined: some 22 GB
    const fs::path file = scratch.write("fine.json", scene.dump());
    // 2 GB of address space for the process, as `ulimit -v` or a batch
    // system's memory limit would allow it.
    const CommandRun run = runRegioSolve({"solve", "--quiet", file.string()}, {}, "/dev/null", "ulimit -v 2000000");
    EXPECT_EQ(run.exitCode, 1) << run.err;
    EXPECT_NE(run.err.find("/solver/patchSize: error: the solve would need about "), std::string::npos) << run.err;
    EXPECT_NE(run.err.find(" GB of memory (10.6 million elements), more than the 2.0 GB available"), std::string::npos)
        << run.err;
}

TEST(SolveCommand, AnUnreadableFileExitsTwo)
{
    const CommandRun run = solve({"/nonexistent/scene.json"});
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_NE(run.err.find("/nonexistent/scene.json"), std::string::npos);
}

TEST(SolveCommand, AMixOfGoodAndBadScenesSolvesTheGoodOnesAndReportsTheWorstExitCode)
{
    Scratch scratch;
    const fs::path small = scratch.write("small.json", kSmallScene);
    const CommandRun run = solve({"--iterations", "1", "--quiet", "--report", (scratch / "r.json").string(),
                                  (kData / "bad" / "unknown-material.json").string(), small.string()});
    EXPECT_EQ(run.exitCode, 1);
    const json r = json::parse(readText(scratch / "r.json"));
    ASSERT_EQ(r.size(), 2u);
    EXPECT_EQ(r[0]["status"], "invalid");
    EXPECT_EQ(r[1]["status"], "solved");
}

TEST(SolveCommand, BadOptionsAreUsageErrorsThatExitTwo)
{
    const std::string scene = samplePath("cornell-box").string();
    for (const std::vector<std::string>& args :
         std::vector<std::vector<std::string>>{{"--hemicube", "1", scene},
                                               {"--hemicube", "abc", scene},
                                               {"--hemicube", "100000", scene},
                                               {"--iterations", "-3", scene},
                                               {"--convergence", "nan", scene},
                                               {"--visibility", "raytrace", scene},
                                               {"--regions", "some", scene},
                                               {"--threads", "0", scene},
                                               {"--threads", "two", scene},
                                               {"--cache-mb", "-1", scene},
                                               {"--report"},
                                               {"--frobnicate", scene},
                                               {}}) {
        const CommandRun run = solve(args);
        EXPECT_EQ(run.exitCode, 2) << (args.empty() ? "no arguments" : args[0]);
        EXPECT_NE(run.err.find("regio-solve solve:"), std::string::npos) << run.err;
    }
}

TEST(SolveCommand, HelpDescribesEveryOption)
{
    const CommandRun run = solve({"--help"});
    EXPECT_EQ(run.exitCode, 0);
    for (const char* option :
         {"--hemicube", "--iterations", "--convergence", "--visibility", "--regions", "--adaptive", "--threshold",
          "--min-edge", "--anchoring", "--report", "--quiet", "--threads", "--cache-mb"})
        EXPECT_NE(run.out.find(option), std::string::npos) << option;
}

TEST(SolveCommand, ThreadsAndKeptFormFactorsChangeNoNumberOfTheReport)
{
    Scratch scratch;
    const std::string scene = samplePath("cornell-box").string();
    auto report = [&](const std::vector<std::string>& how, const std::string& name) {
        std::vector<std::string> args{"--iterations", "400", "--hemicube", "64", "--adaptive", "off", "--quiet"};
        args.insert(args.end(), how.begin(), how.end());
        args.insert(args.end(), {"--report", (scratch / name).string(), scene});
        const CommandRun run = solve(args);
        EXPECT_EQ(run.exitCode, 0) << run.err;
        json r = json::parse(readText(scratch / name));
        r.erase("seconds");
        return r;
    };
    json plain = report({"--threads", "1", "--cache-mb", "0"}, "plain.json");
    json fast = report({"--threads", "3", "--cache-mb", "64"}, "fast.json");
    EXPECT_EQ(plain["threads"], 1);
    EXPECT_EQ(fast["threads"], 3);
    EXPECT_EQ(plain["renderedShots"], 400);
    EXPECT_LT(fast["renderedShots"].get<int>(), 400);
    for (json* r : {&plain, &fast}) {
        r->erase("threads");
        r->erase("renderedShots");
    }
    EXPECT_EQ(plain, fast);
}

TEST(SolveCommand, InterruptStopsTheSolveAndStillWritesTheReport)
{
    Scratch scratch;
    const fs::path scene = samplePath("two-lights-room");
    const std::string command = quoted(REGIO_SOLVE_EXE) +
                                " solve --quiet --iterations 1000000 --hemicube 600 --report " +
                                quoted((scratch / "r.json").string()) + " " + quoted(scene.string()) +
                                " </dev/null >/dev/null 2>&1 & pid=$!; sleep 1; kill -INT $pid; wait $pid; echo $? > " +
                                quoted((scratch / "code").string());
    ASSERT_EQ(std::system(command.c_str()), 0);
    EXPECT_EQ(readText(scratch / "code"), "130\n");
    const json r = json::parse(readText(scratch / "r.json"));
    EXPECT_EQ(r["status"], "interrupted");
    EXPECT_EQ(r["stop"], "cancelled");
    EXPECT_LT(r["iterations"].get<int>(), 1000000);
}

TEST(SolveOutputs, WritesTheLitModelAndThePictureOfTheSolvedScene)
{
    Scratch scratch;
    const fs::path scene = scratch.write("small.json", kSmallScene);
    const fs::path model = scratch / "lit.ply";
    const fs::path image = scratch / "lit.png";
    const CommandRun run = solve({"--quiet", "--iterations", "5", "--out", model.string(), "--image", image.string(),
                                  "--size", "64x48", scene.string()});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const std::string ply = readText(model);
    EXPECT_EQ(ply.rfind("ply\nformat binary_little_endian 1.0\n", 0), 0u);
    EXPECT_NE(ply.find("property float radiosity_r"), std::string::npos);
    const std::string png = readText(image);
    ASSERT_GT(png.size(), 8u);
    EXPECT_EQ(png.substr(1, 3), "PNG");
    // The IHDR chunk holds the size asked for, big-endian.
    auto be32 = [&](size_t at) {
        return (unsigned(uint8_t(png[at])) << 24) | (unsigned(uint8_t(png[at + 1])) << 16) |
               (unsigned(uint8_t(png[at + 2])) << 8) | unsigned(uint8_t(png[at + 3]));
    };
    EXPECT_EQ(be32(16), 64u);
    EXPECT_EQ(be32(20), 48u);
}

TEST(SolveOutputs, RefusesAnUnknownModelFormatBeforeSolving)
{
    Scratch scratch;
    const fs::path scene = scratch.write("small.json", kSmallScene);
    const CommandRun run = solve({"--out", (scratch / "lit.stl").string(), scene.string()});
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_NE(run.err.find("--out expects a .gltf, .glb, .ply or .obj file"), std::string::npos) << run.err;
    EXPECT_FALSE(fs::exists(scratch / "lit.stl"));
}

TEST(SolveOutputs, TakeOneSceneAtATime)
{
    Scratch scratch;
    const fs::path scene = scratch.write("small.json", kSmallScene);
    const CommandRun run = solve({"--image", (scratch / "a.png").string(), scene.string(), scene.string()});
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_NE(run.err.find("one scene at a time"), std::string::npos) << run.err;
}

TEST(SolveOutputs, RefusesABadPictureSize)
{
    Scratch scratch;
    const fs::path scene = scratch.write("small.json", kSmallScene);
    const CommandRun run = solve({"--image", (scratch / "a.png").string(), "--size", "0x10", scene.string()});
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_NE(run.err.find("--size expects"), std::string::npos) << run.err;
}

// The guide's table of report fields ("The report of one scene is one JSON
// object", docs/reference.md) names every field a report has, and the keys of its
// objects.
TEST(SolveCommand, TheGuideDocumentsEveryFieldOfTheReport)
{
    const std::string readme = readText(fs::path(REGIO_SOURCE_DIR) / "docs" / "reference.md");
    const size_t start = readme.find("The report of one scene is one JSON object");
    ASSERT_NE(start, std::string::npos) << "the guide's report section moved";
    // Rows of the table: backticked names in the first column, and in the
    // whole row (an object's keys are listed beside it).
    std::map<std::string, std::set<std::string>> rows;
    std::istringstream lines(readme.substr(start));
    std::string line;
    bool inTable = false;
    while (std::getline(lines, line)) {
        if (line.rfind("|", 0) != 0) {
            if (inTable)
                break;
            continue;
        }
        inTable = true;
        const size_t secondBar = line.find('|', 1);
        std::set<std::string> names, all;
        for (size_t at = line.find('`'); at != std::string::npos; at = line.find('`', at + 1)) {
            const size_t end = line.find('`', at + 1);
            if (end == std::string::npos)
                break;
            const std::string name = line.substr(at + 1, end - at - 1);
            (at < secondBar ? names : all).insert(name);
            at = end;
        }
        for (const std::string& n : names)
            rows[n] = all;
    }
    ASSERT_FALSE(rows.empty());

    Scratch scratch;
    const CommandRun run = solve({"--iterations", "2", "--hemicube", "40", "--quiet", "--report",
                                  (scratch / "r.json").string(), samplePath("two-lights-room").string()});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const json r = json::parse(readText(scratch / "r.json"));
    for (const auto& [key, value] : r.items()) {
        ASSERT_TRUE(rows.count(key)) << "the guide does not document '" << key << "'";
        if (value.is_object()) {
            for (const auto& [inner, unused] : value.items()) {
                EXPECT_TRUE(rows[key].count(inner)) << "the guide does not document '" << key << "." << inner << "'";
            }
        }
    }
}

// A new user's first solve of a sample ends converged, not at its iteration
// limit with light left to shoot.
TEST(SampleScenes, ConvergeWithinTheirOwnLimits)
{
    for (const char* name : {"cornell-box", "two-lights-room"}) {
        Scratch scratch;
        const CommandRun run = solve({"--quiet", "--report", (scratch / "r.json").string(), samplePath(name).string()});
        ASSERT_EQ(run.exitCode, 0) << run.err;
        const json r = json::parse(readText(scratch / "r.json"));
        EXPECT_EQ(r["stop"], "converged") << name << ": " << r["iterations"] << " of " << r["maxIterations"]
                                          << " iterations, unshot " << r["unshotRatio"];
        EXPECT_LT(r["iterations"].get<int>(), r["maxIterations"].get<int>() * 9 / 10)
            << name << ": converged too close to its limit";
    }
}
