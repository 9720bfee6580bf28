// `regio-solve` as a user and a script see it: the real executable, its
// output and its exit status, on the sample scenes, on every broken file of
// the test data and on hostile input.
#include "support/command_run.h"
#include "support/sample_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <random>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace regio::test;

namespace {

std::vector<std::string> linesOf(const std::string& text)
{
    std::vector<std::string> lines;
    std::stringstream in(text);
    for (std::string line; std::getline(in, line);)
        lines.push_back(line);
    return lines;
}

bool hasLineStartingWith(const std::string& text, const std::string& prefix, const std::string& containing = {})
{
    for (const std::string& line : linesOf(text))
        if (line.rfind(prefix, 0) == 0 && line.find(containing) != std::string::npos)
            return true;
    return false;
}

std::vector<fs::path> jsonFilesIn(const fs::path& dir)
{
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(dir))
        if (entry.path().extension() == ".json")
            files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

const fs::path kDataDir = REGIO_TEST_DATA;

const char* const kValidScene = R"({ "format": "regio-scene", "version": 1,
  "materials": [ { "id": "lamp", "reflectance": [0.5, 0.5, 0.5], "emission": [10, 10, 10] } ],
  "objects": [ { "id": "panel", "parts": [ { "id": "panel.quad", "material": "lamp",
      "vertices": [[0,0,0], [0,0,1], [1,0,1], [1,0,0]],
      "faces": [ { "id": "panel.top", "loop": [0, 1, 2, 3] } ] } ] } ]
})";

} // namespace

// ----------------------------------------------------- the command line

TEST(RegioSolve, HelpListsTheCommandsAndExitsZero)
{
    for (const char* flag : {"--help", "-h", "help"}) {
        const CommandRun run = runRegioSolve({flag});
        EXPECT_EQ(run.exitCode, 0) << flag;
        EXPECT_NE(run.out.find("Usage: regio-solve COMMAND"), std::string::npos) << run.out;
        EXPECT_NE(run.out.find("\n  check "), std::string::npos) << run.out;
        EXPECT_NE(run.out.find("\n  solve "), std::string::npos) << run.out;
        EXPECT_TRUE(run.err.empty()) << run.err;
    }
}

TEST(RegioSolve, VersionNamesTheProgramAndTheSceneFormatItReads)
{
    const CommandRun run = runRegioSolve({"--version"});
    EXPECT_EQ(run.exitCode, 0);
    EXPECT_EQ(run.out.rfind("regio-solve ", 0), 0u) << run.out;
    EXPECT_NE(run.out.find("regio-scene version 1"), std::string::npos) << run.out;
}

TEST(RegioSolve, NoCommandPrintsTheUsageToStandardErrorAndExitsTwo)
{
    const CommandRun run = runRegioSolve({});
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_TRUE(run.out.empty());
    EXPECT_NE(run.err.find("Usage: regio-solve COMMAND"), std::string::npos) << run.err;
}

TEST(RegioSolve, AnUnknownCommandExitsTwoAndSaysWhichOne)
{
    const CommandRun run = runRegioSolve({"frobnicate", "scene.json"});
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_NE(run.err.find("unknown command 'frobnicate'"), std::string::npos) << run.err;
}

TEST(RegioSolveCheck, HelpDescribesTheOutputAndTheExitStatus)
{
    const CommandRun run = runRegioSolve({"check", "--help"});
    EXPECT_EQ(run.exitCode, 0);
    EXPECT_NE(run.out.find("FILE: /json/pointer: error|warning: message"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("Exit status"), std::string::npos) << run.out;
}

TEST(RegioSolveCheck, NoFileOrAnUnknownOptionIsAUsageError)
{
    const CommandRun none = runRegioSolve({"check"});
    EXPECT_EQ(none.exitCode, 2);
    EXPECT_NE(none.err.find("no scene file given"), std::string::npos) << none.err;
    const CommandRun option = runRegioSolve({"check", "--frob", (kDataDir / "valid" / "full.json").string()});
    EXPECT_EQ(option.exitCode, 2);
    EXPECT_NE(option.err.find("unknown option '--frob'"), std::string::npos) << option.err;
}

// --------------------------------------------------------- good scenes

TEST(RegioSolveCheck, EverySampleSceneIsAccepted)
{
    const std::vector<fs::path> scenes = sampleFiles();
    ASSERT_FALSE(scenes.empty()) << "no sample scenes in " << samplesFolder();
    for (const fs::path& scene : scenes) {
        const CommandRun run = runRegioSolve({"check", scene.string()});
        EXPECT_EQ(run.exitCode, 0) << scene << "\n" << run.out << run.err;
        EXPECT_TRUE(hasLineStartingWith(run.out, scene.string() + ": ok")) << run.out;
    }
}

TEST(RegioSolveCheck, EveryValidTestFileIsAccepted)
{
    for (const fs::path& file : jsonFilesIn(kDataDir / "valid")) {
        const CommandRun run = runRegioSolve({"check", file.string()});
        EXPECT_EQ(run.exitCode, 0) << file << "\n" << run.out << run.err;
    }
}

TEST(RegioSolveCheck, TheSummaryCountsTheSceneContents)
{
    const CommandRun run = runRegioSolve({"check", "full.json"}, kDataDir / "valid");
    EXPECT_EQ(run.exitCode, 0) << run.out;
    EXPECT_NE(run.out.find("full.json: ok (3 materials, 3 objects, 3 parts, 8 faces, 1 region)"), std::string::npos)
        << run.out;
}

TEST(RegioSolveCheck, WarningsAloneStillExitZero)
{
    ScratchDir dir;
    std::string text = kValidScene;
    text.insert(text.find("\"materials\""), "\"lights\": [], ");
    dir.write("extra-key.json", text);
    const CommandRun run = runRegioSolve({"check", "extra-key.json"}, dir.path());
    EXPECT_EQ(run.exitCode, 0) << run.out;
    EXPECT_TRUE(hasLineStartingWith(run.out, "extra-key.json: /lights: warning: unknown key")) << run.out;
    EXPECT_TRUE(hasLineStartingWith(run.out, "extra-key.json: ok with 1 warning")) << run.out;
}

TEST(RegioSolveCheck, ADashReadsStandardInput)
{
    ScratchDir dir;
    const fs::path scene = dir.write("scene.json", kValidScene);
    const CommandRun run = runRegioSolve({"check", "-"}, {}, scene);
    EXPECT_EQ(run.exitCode, 0) << run.out << run.err;
    EXPECT_TRUE(hasLineStartingWith(run.out, "<stdin>: ok")) << run.out;
}

// ---------------------------------------------------------- bad scenes

// tests/data/bad/check.tsv: the exact output of `regio-solve check -q FILE`
// for every file of the bad-file catalogue, and its exit status.
struct CatalogueFile {
    std::string name;
    int exitCode = 0;
    std::vector<std::string> lines;
};

void PrintTo(const CatalogueFile& file, std::ostream* out) { *out << file.name; }

std::vector<CatalogueFile> loadCheckTable()
{
    std::vector<CatalogueFile> table;
    std::ifstream in(kDataDir / "bad" / "check.tsv");
    for (std::string row; std::getline(in, row);) {
        if (row.empty() || row[0] == '#')
            continue;
        const size_t tab1 = row.find('\t');
        const size_t tab2 = row.find('\t', tab1 + 1);
        const std::string name = row.substr(0, tab1);
        if (table.empty() || table.back().name != name)
            table.push_back({name, std::stoi(row.substr(tab1 + 1, tab2 - tab1 - 1)), {}});
        const std::string line = row.substr(tab2 + 1);
        if (line != "-")
            table.back().lines.push_back(line);
    }
    return table;
}

class CheckCatalogueFile : public testing::TestWithParam<CatalogueFile> { };

TEST_P(CheckCatalogueFile, PrintsExactlyItsDiagnosticsAndExitsAsItShould)
{
    const CatalogueFile& expected = GetParam();
    const CommandRun run = runRegioSolve({"check", "-q", expected.name}, kDataDir / "bad");
    ASSERT_TRUE(run.exited) << "regio-solve crashed on " << expected.name;
    EXPECT_EQ(run.exitCode, expected.exitCode) << run.out << run.err;
    EXPECT_EQ(linesOf(run.out), expected.lines);
    EXPECT_EQ(run.err, "");
}

INSTANTIATE_TEST_SUITE_P(BadFiles, CheckCatalogueFile, testing::ValuesIn(loadCheckTable()),
                         [](const testing::TestParamInfo<CatalogueFile>& test) {
                             std::string name = test.param.name;
                             for (char& c : name)
                                 if (!std::isalnum(static_cast<unsigned char>(c)))
                                     c = '_';
                             return name;
                         });

TEST(RegioSolveCheck, EveryFileOfTheCatalogueHasItsExpectedOutputAndTheCatalogueCoversEveryKindOfFault)
{
    const std::vector<CatalogueFile> table = loadCheckTable();
    std::set<std::string> listed;
    for (const CatalogueFile& file : table)
        listed.insert(file.name);
    size_t files = 0;
    for (const auto& entry : fs::directory_iterator(kDataDir / "bad")) {
        const std::string name = entry.path().filename().string();
        if (name.ends_with(".tsv"))
            continue;
        ++files;
        EXPECT_TRUE(listed.count(name)) << name << " has no rows in check.tsv";
    }
    EXPECT_GE(files, 60u);
    // Every diagnostic about an element with an id names it beside the
    // pointer; syntax errors (FILE:LINE:COLUMN) come before any id is known.
    const std::regex syntaxError(R"(^[^:]+:[0-9]+:[0-9]+: )");
    for (const CatalogueFile& file : table)
        for (const std::string& line : file.lines)
            if (line.find(": /objects/") != std::string::npos && line.find(" (object ") == std::string::npos &&
                line.find(" (part ") == std::string::npos && line.find(" (face ") == std::string::npos &&
                !std::regex_search(line, syntaxError))
                ADD_FAILURE() << "names no object, part or face: " << line;
}

TEST(RegioSolveCheck, AFileClaimingTwoGigabytesIsRefusedBeforeItIsRead)
{
    ScratchDir dir;
    const fs::path huge = dir.path() / "huge.json";
    std::ofstream(huge).put('{');
    fs::resize_file(huge, std::uintmax_t{2} << 30); // sparse: no disk space taken
    const CommandRun run = runRegioSolve({"check", "-q", huge.string()});
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_NE(run.out.find("huge.json: error: file too large"), std::string::npos) << run.out;
}

TEST(RegioSolveCheck, AMissingFileOrADirectoryIsUnreadableAndExitsTwo)
{
    ScratchDir dir;
    const CommandRun missing = runRegioSolve({"check", "no-such-scene.json"}, dir.path());
    EXPECT_EQ(missing.exitCode, 2);
    EXPECT_TRUE(hasLineStartingWith(missing.out, "no-such-scene.json: error: cannot open: No such file"))
        << missing.out;
    const CommandRun directory = runRegioSolve({"check", dir.path().string()});
    EXPECT_EQ(directory.exitCode, 2);
    EXPECT_NE(directory.out.find("is a directory"), std::string::npos) << directory.out;
}

TEST(RegioSolveCheck, TheWorstFileDecidesTheExitStatus)
{
    const std::string good = (kDataDir / "valid" / "full.json").string();
    const std::string bad = (kDataDir / "bad" / "newer-version.json").string();
    EXPECT_EQ(runRegioSolve({"check", good, good}).exitCode, 0);
    EXPECT_EQ(runRegioSolve({"check", good, bad, good}).exitCode, 1);
    const CommandRun all = runRegioSolve({"check", good, bad, "/nonexistent/scene.json"});
    EXPECT_EQ(all.exitCode, 2);
    // Every file is still checked and summarised.
    EXPECT_EQ(linesOf(all.out).size(), 1u + 2u + 2u) << all.out;
}

TEST(RegioSolveCheck, QuietLeavesOnlyTheDiagnostics)
{
    const std::string good = (kDataDir / "valid" / "full.json").string();
    const std::string bad = (kDataDir / "bad" / "hemicube-odd.json").string();
    const CommandRun run = runRegioSolve({"check", "--quiet", good, bad});
    EXPECT_EQ(run.exitCode, 1);
    ASSERT_EQ(linesOf(run.out).size(), 1u) << run.out;
    EXPECT_TRUE(hasLineStartingWith(run.out, bad + ": /solver/hemicube: error: ")) << run.out;
    EXPECT_EQ(runRegioSolve({"check", "-q", good}).out, "");
}

// ------------------------------------------------------- hostile input

TEST(RegioSolveCheck, AHugeNumberIsRefusedWithoutCrashing)
{
    ScratchDir dir;
    // 64 MB of digits: the same path as a 1 GB number, at test-suite cost.
    std::string text = "{\"format\": \"regio-scene\", \"version\": 1, \"materials\": [1";
    text.append(64u << 20, '7');
    text += "], \"objects\": []}";
    dir.write("huge-number.json", text);
    const CommandRun run = runRegioSolve({"check", "huge-number.json"}, dir.path());
    ASSERT_TRUE(run.exited);
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_TRUE(hasLineStartingWith(run.out, "huge-number.json:1:55: error: number longer than"))
        << run.out.substr(0, 500);
}

TEST(RegioSolveCheck, AMillionNestedArraysAreRefusedWithoutCrashing)
{
    ScratchDir dir;
    dir.write("deep.json", std::string(1'000'000, '[') + std::string(1'000'000, ']'));
    const CommandRun run = runRegioSolve({"check", "deep.json"}, dir.path());
    ASSERT_TRUE(run.exited);
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_TRUE(hasLineStartingWith(run.out, "deep.json:1:65: error: ")) << run.out;
}

TEST(RegioSolveCheck, RandomBytesNeverCrashTheCommand)
{
    ScratchDir dir;
    std::mt19937 random(99);
    std::vector<std::string> args{"check", "--quiet"};
    for (int i = 0; i < 40; ++i) {
        std::string bytes(random() % 4096, '\0');
        for (char& c : bytes)
            c = static_cast<char>(random() % 256);
        const std::string name = "random-" + std::to_string(i) + ".bin";
        dir.write(name, bytes);
        args.push_back(name);
    }
    const CommandRun run = runRegioSolve(args, dir.path());
    ASSERT_TRUE(run.exited);
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_EQ(linesOf(run.out).size(), 40u) << run.out;
}

TEST(RegioSolveCheck, ControlCharactersFromTheFileAreEscapedInTheOutput)
{
    ScratchDir dir;
    std::string text = kValidScene;
    text.insert(text.find("\"materials\""), "\"bell\\u0007\": 1, ");
    dir.write("bell.json", text);
    const CommandRun run = runRegioSolve({"check", "bell.json"}, dir.path());
    EXPECT_EQ(run.exitCode, 0) << run.out;
    EXPECT_EQ(run.out.find('\a'), std::string::npos);
    EXPECT_NE(run.out.find("/bell\\x07: warning: unknown key \"bell\\x07\""), std::string::npos) << run.out;
}
