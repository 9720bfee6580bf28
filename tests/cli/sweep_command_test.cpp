// `regio-solve sweep`: a parameter study as one command, seen through the
// files it writes and the batch it runs.
#include "support/command_run.h"
#include "support/small_scenes.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace regio::test;
using nlohmann::json;

namespace {

CommandRun sweep(const std::vector<std::string>& args)
{
    std::vector<std::string> all{"sweep"};
    all.insert(all.end(), args.begin(), args.end());
    return runRegioSolve(all);
}

json scene(const fs::path& path) { return json::parse(readText(path)); }

} // namespace

TEST(SweepCommand, WritesEveryCombinationOfTheValuesWithATableOfThem)
{
    ScratchDir scratch;
    const fs::path file = scratch.write("room.json", kSmallScene);
    const fs::path out = scratch / "study";
    const CommandRun run = sweep({file.string(), "--set", "solver.hemicube=60,100,150", "--set",
                                  "materials.grey.reflectance=0.25,[0.7,0.6,0.5]", "--out-dir", out.string()});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("6 variants"), std::string::npos) << run.out;
    // The last --set varies fastest, as in nested loops.
    const std::vector<std::pair<int, json>> expected{{60, {0.25, 0.25, 0.25}},  {60, {0.7, 0.6, 0.5}},
                                                     {100, {0.25, 0.25, 0.25}}, {100, {0.7, 0.6, 0.5}},
                                                     {150, {0.25, 0.25, 0.25}}, {150, {0.7, 0.6, 0.5}}};
    for (size_t i = 0; i < expected.size(); ++i) {
        const json variant = scene(out / ("room-00" + std::to_string(i + 1) + ".json"));
        EXPECT_EQ(variant["solver"]["hemicube"], expected[i].first) << i;
        EXPECT_EQ(variant["materials"][1]["id"], "grey");
        EXPECT_EQ(variant["materials"][1]["reflectance"], expected[i].second) << i;
        // Everything else as the original has it.
        json rest = variant;
        json original = json::parse(kSmallScene);
        rest["solver"].erase("hemicube");
        original["solver"].erase("hemicube");
        rest["materials"][1].erase("reflectance");
        original["materials"][1].erase("reflectance");
        EXPECT_EQ(rest, original);
    }
    EXPECT_FALSE(fs::exists(out / "room-007.json"));
    EXPECT_EQ(readText(out / "room.sweep.csv"),
              "scene,solver.hemicube,materials.grey.reflectance\n"
              "room-001.json,60,\"[0.25,0.25,0.25]\"\n"
              "room-002.json,60,\"[0.7,0.6,0.5]\"\n"
              "room-003.json,100,\"[0.25,0.25,0.25]\"\n"
              "room-004.json,100,\"[0.7,0.6,0.5]\"\n"
              "room-005.json,150,\"[0.25,0.25,0.25]\"\n"
              "room-006.json,150,\"[0.7,0.6,0.5]\"\n");
}

TEST(SweepCommand, PathsReachIntoListsByIdsThatHoldDotsOrByIndexAndAddValuesTheFileLeavesOut)
{
    ScratchDir scratch;
    const fs::path file = scratch.write("room.json", kSmallScene);
    const fs::path out = scratch / "study";
    const CommandRun run = sweep({file.string(), "--out-dir", out.string(), "--set",
                                  "objects.light.parts.light.panel.faces.0.id=down,bulb", "--set",
                                  "solver.adaptive.enabled=true", "--set", "solver.visibility=zbuffer"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const json first = scene(out / "room-001.json");
    EXPECT_EQ(first["objects"][0]["parts"][0]["faces"][0]["id"], "down");
    EXPECT_EQ(scene(out / "room-002.json")["objects"][0]["parts"][0]["faces"][0]["id"], "bulb");
    EXPECT_EQ(first["solver"]["visibility"], "zbuffer");
    // "adaptive" is not in the file: it is added.
    EXPECT_EQ(first["solver"]["adaptive"], json({{"enabled", true}}));
}

TEST(SweepCommand, SolvesTheVariantsIntoItsDirectoryAndAgainSolvesNothingTwice)
{
    ScratchDir scratch;
    const fs::path file = scratch.write("room.json", kSmallScene);
    const fs::path out = scratch / "study";
    const std::vector<std::string> args{
        file.string(), "--set", "solver.hemicube=40,80", "--out-dir", out.string(), "--solve", "--format", "ply",
        "--jobs",      "2"};
    const CommandRun run = sweep(args);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("2 scenes: 2 solved"), std::string::npos) << run.out;
    for (const auto& [name, hemicube] : {std::pair{"room-001", 40}, std::pair{"room-002", 80}}) {
        const json report = json::parse(readText(out / (std::string(name) + ".report.json")));
        EXPECT_EQ(report["status"], "solved");
        EXPECT_EQ(report["hemicube"], hemicube);
        EXPECT_TRUE(fs::exists(out / (std::string(name) + ".ply")));
    }
    const CommandRun again = sweep(args);
    ASSERT_EQ(again.exitCode, 0) << again.err;
    EXPECT_NE(again.out.find("2 scenes: 0 solved, 2 skipped"), std::string::npos) << again.out;
}

TEST(SweepCommand, WritesNoVariantWhenOneIsNotAValidSceneAndSaysWhichValueItWas)
{
    ScratchDir scratch;
    const fs::path file = scratch.write("room.json", kSmallScene);
    const fs::path out = scratch / "study";
    const CommandRun run =
        sweep({file.string(), "--set", "solver.hemicube=100,7", "--out-dir", out.string(), "--solve"});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_NE(run.err.find("room-002.json (solver.hemicube=7)"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("/solver/hemicube"), std::string::npos) << run.err;
    EXPECT_FALSE(fs::exists(out));
}

TEST(SweepCommand, AKeyTheSceneFormatDoesNotKnowIsAnErrorNotAWarning)
{
    ScratchDir scratch;
    const fs::path file = scratch.write("room.json", kSmallScene);
    const fs::path out = scratch / "study";
    const CommandRun run = sweep({file.string(), "--set", "solver.hemicub=60", "--out-dir", out.string()});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_NE(run.err.find("/solver/hemicub: error: unknown key"), std::string::npos) << run.err;
    EXPECT_FALSE(fs::exists(out));
}

TEST(SweepCommand, RefusesBadArgumentsWithAMessage)
{
    ScratchDir scratch;
    const std::string file = scratch.write("room.json", kSmallScene).string();
    const std::string out = (scratch / "study").string();
    const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
        {{file, "--out-dir", out}, "no --set given"},
        {{file, "--set", "solver.hemicube=60"}, "--out-dir is needed"},
        {{file, "--set", "solver.hemicube", "--out-dir", out}, "expects PATH=VALUES"},
        {{file, "--set", "solver.hemicube=60,,80", "--out-dir", out}, "has an empty value"},
        {{file, "--set", "materials.gold.reflectance=0.5", "--out-dir", out}, "no entry of id or index 'gold'"},
        {{file, "--set", "solver.hemicube.x=1", "--out-dir", out}, "is a value"},
        {{file, file, "--set", "solver.hemicube=60", "--out-dir", out}, "one scene at a time"},
        {{(scratch / "missing.json").string(), "--set", "solver.hemicube=60", "--out-dir", out}, "cannot open"},
    };
    for (const auto& [args, message] : cases) {
        const CommandRun run = sweep(args);
        EXPECT_EQ(run.exitCode, 2) << message;
        EXPECT_NE(run.err.find(message), std::string::npos) << message << ": " << run.err;
    }
    EXPECT_FALSE(fs::exists(out));
}
