// The scene file format: what the reader accepts, what it refuses and where
// it says the problem is, and the canonical text the writer produces.
#include "model/io/scene_json.h"
#include "model/limits.h"

#include "support/broken_file_table.h"
#include "support/sample_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>

using namespace regio::model;
namespace fs = std::filesystem;

namespace {

std::string readText(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::stringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
}

std::string validPath(const std::string& name) { return std::string(REGIO_TEST_DATA) + "/valid/" + name; }

std::vector<fs::path> jsonFilesIn(const fs::path& dir)
{
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(dir))
        if (entry.path().extension() == ".json")
            files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

// A version number of 16 million digits.
std::string hugeNumberScene()
{
    return "{\"format\": \"regio-scene\", \"version\": " + std::string(16'000'000, '9') + "}";
}

// A string that opens and never closes, 64 MiB on.
std::string unterminatedHugeString() { return "{\n  \"format\": \"" + std::string(64u << 20, 'a'); }

double secondsToParse(const std::string& text)
{
    const auto start = std::chrono::steady_clock::now();
    (void)parseScene(text); // only its time counts here
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string describe(const Diagnostics& diagnostics)
{
    std::string out;
    for (const Diagnostic& d : diagnostics)
        out += (d.isError() ? "error " : "warning ") + std::to_string(d.line) + ":" + std::to_string(d.column) + " " +
               d.pointer + ": " + d.message + "\n";
    return out;
}

// A well-formed scene text with one replaceable spot, for rules not worth a file.
std::string sceneWith(const std::string& materialExtra, const std::string& loop = "[0, 1, 2, 3]",
                      const std::string& tail = "")
{
    return R"({ "format": "regio-scene", "version": 1,
  "materials": [ { "id": "white", "reflectance": [0.5, 0.5, 0.5])" +
           materialExtra + R"( } ],
  "objects": [ { "id": "floor", "parts": [ { "id": "floor.slab", "material": "white",
      "vertices": [[0,0,0], [0,0,1], [1,0,1], [1,0,0]],
      "faces": [ { "id": "floor.top", "loop": )" +
           loop + R"( } ] } ] } ])" + tail + "\n}\n";
}

const Diagnostic* findAt(const Diagnostics& diagnostics, const std::string& pointer)
{
    for (const Diagnostic& d : diagnostics)
        if (d.pointer == pointer)
            return &d;
    return nullptr;
}

} // namespace

// ---------------------------------------------------------------- reading

TEST(SceneJsonRead, AMinimalFileReadsWithDefaultSolverSettingsAndNoCamera)
{
    const Result<Scene> read = parseScene(readText(validPath("minimal.json")));
    ASSERT_TRUE(read.ok()) << describe(read.diagnostics());
    EXPECT_TRUE(read.diagnostics().empty()) << describe(read.diagnostics());
    EXPECT_TRUE(read->materials.empty());
    EXPECT_TRUE(read->objects.empty());
    EXPECT_TRUE(read->regions.empty());
    EXPECT_EQ(read->solver, SolverSettings{});
    EXPECT_FALSE(read->camera);
}

TEST(SceneJsonRead, EveryFieldOfTheFormatIsRead)
{
    const Result<Scene> read = parseScene(readText(validPath("full.json")));
    ASSERT_TRUE(read.ok()) << describe(read.diagnostics());
    EXPECT_TRUE(read.diagnostics().empty()) << describe(read.diagnostics());
    const Scene& scene = *read;

    ASSERT_EQ(scene.materials.size(), 3u);
    EXPECT_EQ(scene.materials[0].id, "white");
    EXPECT_EQ(scene.materials[0].name, "Matte white");
    EXPECT_EQ(scene.materials[0].reflectance, Rgb(0.73, 0.71, 0.68));
    EXPECT_EQ(scene.materials[2].emission, Rgb(17.5, 12.25, 4.0));

    ASSERT_EQ(scene.objects.size(), 3u);
    const Object& box = scene.objects[1];
    EXPECT_EQ(box.id, "box");
    EXPECT_EQ(box.name, "Red box");
    ASSERT_EQ(box.parts.size(), 1u);
    const Part& cube = box.parts[0];
    EXPECT_EQ(cube.id, "box.cube");
    EXPECT_EQ(cube.name, "Cube");
    EXPECT_EQ(cube.material, "red");
    ASSERT_EQ(cube.vertices.size(), 8u);
    EXPECT_EQ(cube.vertices[6], Vec3(1.0, 0.5, 1.0));
    ASSERT_EQ(cube.faces.size(), 6u);
    EXPECT_EQ(cube.faces[0].id, "box.bottom");
    EXPECT_EQ(cube.faces[0].material, "white");
    EXPECT_EQ(cube.faces[1].material, "");
    EXPECT_EQ(cube.faces[1].loop, (std::vector<int>{3, 7, 6, 2}));

    ASSERT_EQ(scene.regions.size(), 1u);
    EXPECT_EQ(scene.regions[0].name, "Whole room");
    EXPECT_EQ(scene.regions[0].min, Vec3(-1.0, -0.5, -1.0));
    EXPECT_EQ(scene.regions[0].max, Vec3(3.0, 3.0, 3.0));
    EXPECT_EQ(scene.regions[0].bspOrder, (std::vector<std::string>{"floor.top", "box.top", "light.emitter"}));

    EXPECT_EQ(scene.solver.hemicube, 300);
    EXPECT_EQ(scene.solver.patchSize, 0.25);
    EXPECT_EQ(scene.solver.elementsPerPatch, 16);
    EXPECT_FALSE(scene.solver.adaptive.enabled);
    EXPECT_EQ(scene.solver.adaptive.threshold, 0.1);
    EXPECT_EQ(scene.solver.adaptive.minEdge, 0.05);
    EXPECT_FALSE(scene.solver.adaptive.anchoring);
    EXPECT_EQ(scene.solver.maxIterations, 1200);
    EXPECT_EQ(scene.solver.convergence, 0.0005);
    EXPECT_EQ(scene.solver.visibility, Visibility::ZBuffer);
    EXPECT_EQ(scene.solver.regions, RegionsMode::None);

    ASSERT_TRUE(scene.camera);
    EXPECT_EQ(scene.camera->position, Vec3(1.0, 1.5, -4.0));
    EXPECT_EQ(scene.camera->target, Vec3(0.75, 0.5, 0.75));
    EXPECT_EQ(scene.camera->up, Vec3(0.0, 1.0, 0.0));
    EXPECT_EQ(scene.camera->fovY, 50.0);
}

TEST(SceneJsonRead, KeyOrderAndLayoutDoNotMatter)
{
    const Result<Scene> canonical = parseScene(readText(validPath("full.json")));
    const Result<Scene> compact = parseScene(readText(validPath("compact-any-key-order.json")));
    ASSERT_TRUE(canonical.ok() && compact.ok()) << describe(compact.diagnostics());
    EXPECT_EQ(*canonical, *compact);
}

TEST(SceneJsonRead, MissingOptionalKeysTakeTheirDefaults)
{
    const Result<Scene> read = parseScene(sceneWith("", "[0, 1, 2, 3]", R"(, "solver": { "hemicube": 64 })"));
    ASSERT_TRUE(read.ok()) << describe(read.diagnostics());
    EXPECT_EQ(read->materials[0].emission, Rgb(0.0));
    EXPECT_EQ(read->materials[0].name, "");
    EXPECT_TRUE(read->regions.empty());
    SolverSettings expected;
    expected.hemicube = 64;
    EXPECT_EQ(read->solver, expected);
}

TEST(SceneJsonRead, AnIntegerWrittenWithAZeroFractionCountsAsAnInteger)
{
    const Result<Scene> read = parseScene(sceneWith("", "[0.0, 1, 2e0, 3.0]"));
    ASSERT_TRUE(read.ok()) << describe(read.diagnostics());
    EXPECT_EQ(read->objects[0].parts[0].faces[0].loop, (std::vector<int>{0, 1, 2, 3}));
}

TEST(SceneJsonRead, UnknownKeysAreWarningsAndTheSceneStillLoads)
{
    const Result<Scene> read = parseScene(sceneWith(R"(, "gloss": 0.3)", "[0, 1, 2, 3]", R"(, "lights": [])"));
    ASSERT_TRUE(read.ok()) << describe(read.diagnostics());
    ASSERT_EQ(read.diagnostics().size(), 2u) << describe(read.diagnostics());
    const Diagnostic* gloss = findAt(read.diagnostics(), "/materials/0/gloss");
    ASSERT_NE(gloss, nullptr) << describe(read.diagnostics());
    EXPECT_FALSE(gloss->isError());
    EXPECT_EQ(gloss->message, "unknown key \"gloss\" is ignored and will not be saved");
    EXPECT_EQ(gloss->idPath, std::vector<std::string>{"white"});
    const Diagnostic* lights = findAt(read.diagnostics(), "/lights");
    ASSERT_NE(lights, nullptr) << describe(read.diagnostics());
    EXPECT_FALSE(lights->isError());
}

TEST(SceneJsonRead, PointersEscapeSlashAndTildeInKeys)
{
    const Result<Scene> read = parseScene(sceneWith(R"(, "a/b~c": 1)"));
    ASSERT_TRUE(read.ok());
    EXPECT_NE(findAt(read.diagnostics(), "/materials/0/a~1b~0c"), nullptr) << describe(read.diagnostics());
}

TEST(SceneJsonRead, AllProblemsOfAFileAreReportedInOnePass)
{
    const Result<Scene> read = parseScene(sceneWith(R"(, "emission": [-1, 0, 0], "name": 3)", "[0, 1, 2, 9]",
                                                    R"(, "solver": { "hemicube": 3, "patchSize": -1 })"));
    EXPECT_FALSE(read.ok());
    EXPECT_NE(findAt(read.diagnostics(), "/materials/0/emission/0"), nullptr);
    EXPECT_NE(findAt(read.diagnostics(), "/materials/0/name"), nullptr);
    EXPECT_NE(findAt(read.diagnostics(), "/objects/0/parts/0/faces/0/loop/3"), nullptr);
    EXPECT_NE(findAt(read.diagnostics(), "/solver/hemicube"), nullptr);
    EXPECT_NE(findAt(read.diagnostics(), "/solver/patchSize"), nullptr);
    EXPECT_EQ(read.diagnostics().size(), 5u) << describe(read.diagnostics());
}

TEST(SceneJsonRead, DiagnosticsNameTheIdsOfTheEnclosingElements)
{
    const Result<Scene> read = parseScene(sceneWith("", "[0, 1, 2, 9]"));
    ASSERT_EQ(read.diagnostics().size(), 1u) << describe(read.diagnostics());
    EXPECT_EQ(read.diagnostics()[0].idPath, (std::vector<std::string>{"floor", "floor.slab", "floor.top"}));
}

TEST(SceneJsonRead, ANewerVersionIsRefusedWithAClearMessage)
{
    const Result<Scene> read = parseScene(R"({"format": "regio-scene", "version": 2})");
    EXPECT_FALSE(read.ok());
    ASSERT_EQ(read.diagnostics().size(), 1u);
    EXPECT_EQ(read.diagnostics()[0].pointer, "/version");
    EXPECT_EQ(read.diagnostics()[0].message,
              "scene format version 2 is newer than this Regio supports (1); update Regio");
}

TEST(SceneJsonRead, AVersionBeyondAnyIntegerTypeIsStillNewer)
{
    const Result<Scene> read = parseScene(R"({"format": "regio-scene", "version": 100000000000000000000000})");
    ASSERT_EQ(read.diagnostics().size(), 1u);
    EXPECT_NE(read.diagnostics()[0].message.find("is newer than this Regio supports"), std::string::npos)
        << read.diagnostics()[0].message;
}

TEST(SceneJsonRead, AFileOfAnotherFormatIsNotReadFurther)
{
    const Result<Scene> read = parseScene(R"({"format": "gltf", "materials": 5})");
    ASSERT_EQ(read.diagnostics().size(), 1u) << describe(read.diagnostics());
    EXPECT_EQ(read.diagnostics()[0].pointer, "/format");
}

// ------------------------------------------------------ the broken files

class BrokenFileTest : public testing::TestWithParam<regio::test::BrokenFile> { };

TEST_P(BrokenFileTest, IsRejectedWhereTheTableSays)
{
    const regio::test::BrokenFile& expected = GetParam();
    const std::string text = readText(regio::test::brokenDataDir() + "/" + expected.name);
    const Result<Scene> read = parseScene(text);
    EXPECT_FALSE(read.ok());
    ASSERT_TRUE(hasErrors(read.diagnostics()));
    bool found = false;
    for (const Diagnostic& d : read.diagnostics()) {
        found = found || (d.isError() && d.pointer == expected.pointer && d.line == expected.line &&
                          d.column == expected.column && d.message.find(expected.message) != std::string::npos);
    }
    EXPECT_TRUE(found) << "expected " << expected.line << ":" << expected.column << " " << expected.pointer << ": ..."
                       << expected.message << "...\ngot:\n"
                       << describe(read.diagnostics());
}

namespace {

// Files whose flaw is semantic (stage "validation") read fine here; the CLI
// test checks them through validateScene.
std::vector<regio::test::BrokenFile> formatBrokenFiles()
{
    std::vector<regio::test::BrokenFile> files;
    for (const auto& file : regio::test::loadBrokenFileTable())
        if (file.stage == "format")
            files.push_back(file);
    return files;
}

} // namespace

INSTANTIATE_TEST_SUITE_P(TestData, BrokenFileTest, testing::ValuesIn(formatBrokenFiles()),
                         [](const testing::TestParamInfo<regio::test::BrokenFile>& test) {
                             std::string name = test.param.name;
                             for (char& c : name)
                                 if (!std::isalnum(static_cast<unsigned char>(c)))
                                     c = '_';
                             return name;
                         });

TEST(SceneJsonBrokenFiles, EveryFileOfTheCatalogueIsListedInATable)
{
    const auto table = regio::test::loadBrokenFileTable();
    EXPECT_GE(table.size(), 40u);
    for (const auto& entry : fs::directory_iterator(regio::test::brokenDataDir())) {
        const std::string name = entry.path().filename().string();
        if (name.ends_with(".tsv") || name == "README.md")
            continue;
        const std::vector<std::string> listed = regio::test::catalogueFileNames();
        EXPECT_NE(std::find(listed.begin(), listed.end(), name), listed.end())
            << name << " has no row in format.tsv or validation.tsv";
    }
    for (const auto& row : table)
        EXPECT_TRUE(fs::exists(regio::test::brokenDataDir() + "/" + row.name)) << row.name;
}

// ------------------------------------------------- hostile input, syntax

TEST(SceneJsonSyntax, ColumnsCountCharactersNotBytes)
{
    // "é" and "日" are 2 and 3 bytes; the stray "x" is the 14th character.
    const Result<Scene> read = parseScene("{\"é日\": 1,\n  \"ab\": 2 x}");
    ASSERT_EQ(read.diagnostics().size(), 1u);
    EXPECT_EQ(read.diagnostics()[0].line, 2);
    EXPECT_EQ(read.diagnostics()[0].column, 11);
    const Result<Scene> first = parseScene("[\"é日\" x]");
    ASSERT_EQ(first.diagnostics().size(), 1u);
    EXPECT_EQ(first.diagnostics()[0].line, 1);
    EXPECT_EQ(first.diagnostics()[0].column, 7);
}

TEST(SceneJsonSyntax, AByteOrderMarkIsAcceptedAndNotCountedAsAColumn)
{
    const Result<Scene> good = parseScene("\xEF\xBB\xBF" + sceneWith(""));
    EXPECT_TRUE(good.ok()) << describe(good.diagnostics());
    const Result<Scene> bad = parseScene("\xEF\xBB\xBF{x");
    ASSERT_EQ(bad.diagnostics().size(), 1u);
    EXPECT_EQ(bad.diagnostics()[0].column, 2);
}

TEST(SceneJsonSyntax, ASyntaxErrorNamesTheValueBeingRead)
{
    const Result<Scene> read = parseScene(R"({"materials": [{"id": "a"}, {"reflectance": [0.5, 0.5 0.5]}]})");
    ASSERT_EQ(read.diagnostics().size(), 1u);
    EXPECT_EQ(read.diagnostics()[0].pointer, "/materials/1/reflectance/2");
    EXPECT_EQ(read.diagnostics()[0].column, 55); // the unexpected third number
}

TEST(SceneJsonSyntax, NestingDeeperThanTheLimitIsRefusedBeforeParsing)
{
    for (const char* open : {"[", "{\"a\":"}) {
        std::string text;
        for (int i = 0; i < 1'000'000; ++i)
            text += open;
        const Result<Scene> read = parseScene(text);
        ASSERT_EQ(read.diagnostics().size(), 1u);
        EXPECT_NE(read.diagnostics()[0].message.find("nested deeper than 64 levels"), std::string::npos)
            << read.diagnostics()[0].message;
        EXPECT_EQ(read.diagnostics()[0].line, 1);
        EXPECT_GT(read.diagnostics()[0].column, 64);
    }
}

TEST(SceneJsonSyntax, NestingUpToTheLimitIsOrdinaryJson)
{
    const std::string text = std::string(64, '[') + std::string(64, ']');
    const Result<Scene> read = parseScene(text);
    ASSERT_EQ(read.diagnostics().size(), 1u);
    EXPECT_NE(read.diagnostics()[0].message.find("not a Regio scene"), std::string::npos);
}

TEST(SceneJsonSyntax, BracketsInsideStringsAreNotNesting)
{
    const std::string brackets(1000, '[');
    const Result<Scene> read = parseScene(sceneWith(R"(, "name": ")" + brackets + R"(\"[[")"));
    ASSERT_TRUE(read.ok()) << describe(read.diagnostics());
    EXPECT_EQ(read->materials[0].name, brackets + "\"[[");
}

TEST(SceneJsonSyntax, AHugeNumberIsRefusedAtItsPosition)
{
    const Result<Scene> read = parseScene(hugeNumberScene());
    ASSERT_EQ(read.diagnostics().size(), 1u);
    EXPECT_NE(read.diagnostics()[0].message.find("number longer than 1000 characters"), std::string::npos);
    EXPECT_EQ(read.diagnostics()[0].line, 1);
    EXPECT_EQ(read.diagnostics()[0].column, 38);
}

TEST(SceneJsonSyntax, AnUnterminatedHugeStringIsRefusedAtItsOpeningQuote)
{
    const Result<Scene> read = parseScene(unterminatedHugeString());
    ASSERT_EQ(read.diagnostics().size(), 1u);
    EXPECT_EQ(read.diagnostics()[0].message, "string longer than 1 MiB (a missing closing quote?)");
    EXPECT_EQ(read.diagnostics()[0].line, 2);
    EXPECT_EQ(read.diagnostics()[0].column, 13);
}

TEST(SceneJsonSyntax, StringsUpToTheLimitAreRead)
{
    const std::string name(1000000, 'n');
    const Result<Scene> read = parseScene(sceneWith(R"(, "name": ")" + name + "\""));
    ASSERT_TRUE(read.ok()) << describe(read.diagnostics());
    EXPECT_EQ(read->materials[0].name, name);
}

TEST(SceneJsonSyntax, AGiganticRunOfWhiteSpaceIsRefused)
{
    const Result<Scene> read = parseScene("{" + std::string(3u << 20, ' ') + "x");
    ASSERT_EQ(read.diagnostics().size(), 1u);
    EXPECT_EQ(read.diagnostics()[0].message, "more than 1 MiB of white space in a row");
    EXPECT_EQ(read.diagnostics()[0].column, 2);
}

TEST(SceneJsonSyntax, MoreValuesThanAnySceneNeedsAreRefusedBeforeTheyFillMemory)
{
    const std::string text = "[" + std::string((64u << 20) + 1, ',');
    const Result<Scene> read = parseScene(text);
    ASSERT_EQ(read.diagnostics().size(), 1u);
    EXPECT_NE(read.diagnostics()[0].message.find("values (more than a scene of a million faces needs)"),
              std::string::npos)
        << read.diagnostics()[0].message;
}

TEST(SceneJsonSyntax, ANumberBeyondTheRangeOfADoubleIsAnErrorNotInfinity)
{
    for (const char* number : {"1e999", "-1e400", "123456789e999999999"}) {
        const Result<Scene> read = parseScene(sceneWith(R"(, "emission": [0, )" + std::string(number) + ", 0]"));
        EXPECT_FALSE(read.ok());
        ASSERT_EQ(read.diagnostics().size(), 1u) << number;
        EXPECT_EQ(read.diagnostics()[0].pointer, "/materials/0/emission/1");
        EXPECT_NE(read.diagnostics()[0].message.find("out of range"), std::string::npos);
    }
}

TEST(SceneJsonSyntax, MessagesQuotingTheInputStayPrintable)
{
    std::string text = "{\"format\": \x01\xff\xfe";
    const Result<Scene> read = parseScene(text);
    ASSERT_EQ(read.diagnostics().size(), 1u);
    for (char c : read.diagnostics()[0].message) {
        const auto byte = static_cast<unsigned char>(c);
        EXPECT_TRUE(byte >= 0x20 && byte < 0x7F) << read.diagnostics()[0].message;
    }
}

TEST(SceneJsonSyntax, EveryPrefixOfAValidSceneIsRejectedWithAPosition)
{
    const std::string text = readText(validPath("full.json"));
    for (std::size_t length = 0; length + 2 < text.size(); ++length) {
        const Result<Scene> read = parseScene(std::string_view(text).substr(0, length));
        ASSERT_FALSE(read.ok()) << length;
        ASSERT_EQ(read.diagnostics().size(), 1u) << length;
        EXPECT_GT(read.diagnostics()[0].line, 0) << length;
    }
}

TEST(SceneJsonSyntax, RandomBytesAndMutatedScenesNeverThrow)
{
    std::mt19937 random(20261122);
    const std::string scene = readText(validPath("full.json"));
    for (int round = 0; round < 3000; ++round) {
        std::string text;
        if (round % 2 == 0) {
            text.resize(random() % 512);
            for (char& c : text)
                c = static_cast<char>(random() % 256);
        } else {
            text = scene;
            for (int edits = 1 + static_cast<int>(random() % 4); edits > 0; --edits)
                text[random() % text.size()] = "[]{},:\"0-.e \x00\xff"[random() % 14];
        }
        std::optional<Result<Scene>> read;
        EXPECT_NO_THROW(read.emplace(parseScene(text)));
        EXPECT_TRUE(read && (read->ok() || hasErrors(read->diagnostics())));
    }
}

// ----------------------------------------------------------------- writing

TEST(SceneJsonWrite, CanonicalFilesAreReproducedByteForByte)
{
    for (const char* name : {"full.json", "unicode-names.json", "tricky-numbers.json"}) {
        const std::string text = readText(validPath(name));
        const Result<Scene> read = parseScene(text);
        ASSERT_TRUE(read.ok()) << name << "\n" << describe(read.diagnostics());
        EXPECT_EQ(serializeScene(*read), text) << name;
    }
}

TEST(SceneJsonWrite, SaveLoadSaveIsByteIdenticalForEverySampleAndValidFile)
{
    std::vector<fs::path> files = regio::test::sampleFiles();
    ASSERT_FALSE(files.empty()) << "no sample scenes in resources/scenes";
    for (const fs::path& valid : jsonFilesIn(fs::path(REGIO_TEST_DATA) / "valid"))
        files.push_back(valid);
    for (const fs::path& file : files) {
        const Result<Scene> first = parseScene(readText(file));
        ASSERT_TRUE(first.ok()) << file << "\n" << describe(first.diagnostics());
        const std::string saved = serializeScene(*first);
        const Result<Scene> second = parseScene(saved);
        ASSERT_TRUE(second.ok()) << file << "\n" << describe(second.diagnostics());
        EXPECT_TRUE(second.diagnostics().empty()) << file << "\n" << describe(second.diagnostics());
        EXPECT_EQ(*second, *first) << file;
        EXPECT_EQ(serializeScene(*second), saved) << file;
    }
}

TEST(SceneJsonWrite, EveryDoubleKeepsAllItsBits)
{
    std::mt19937_64 random(7);
    Scene scene;
    Part part;
    part.id = "p";
    for (int i = 0; i < 2000; ++i) {
        Vec3 v;
        for (int c = 0; c < 3; ++c) {
            double d;
            do
                d = std::bit_cast<double>(random());
            while (!std::isfinite(d));
            // Within the coordinate limit, every bit of the mantissa still random.
            v[c] = std::abs(d) > kMaxCoordinate ? std::fmod(d, kMaxCoordinate) : d;
        }
        part.vertices.push_back(v);
    }
    part.vertices.push_back(Vec3(std::numeric_limits<double>::denorm_min(), kMaxCoordinate, -0.0));
    scene.objects.push_back(Object{"o", "", {part}});
    const Result<Scene> read = parseScene(serializeScene(scene));
    ASSERT_TRUE(read.ok()) << describe(read.diagnostics());
    const auto& back = read->objects[0].parts[0].vertices;
    ASSERT_EQ(back.size(), part.vertices.size());
    for (std::size_t i = 0; i < back.size(); ++i)
        for (int c = 0; c < 3; ++c)
            ASSERT_EQ(std::bit_cast<std::uint64_t>(back[i][c]), std::bit_cast<std::uint64_t>(part.vertices[i][c]))
                << i << " " << c;
}

TEST(SceneJsonWrite, TheLayoutIsIndentedByTwoSpacesWithNumbersInlineAndOneFinalNewline)
{
    const std::string text = readText(validPath("full.json"));
    const std::string saved = serializeScene(*parseScene(text));
    ASSERT_GE(saved.size(), 2u);
    EXPECT_EQ(saved.back(), '\n');
    EXPECT_NE(saved[saved.size() - 2], '\n');
    EXPECT_EQ(saved.find('\t'), std::string::npos);
    EXPECT_EQ(saved.rfind("{\n  \"format\": \"regio-scene\",\n  \"version\": 1,\n", 0), 0u);
    EXPECT_NE(saved.find("\n            [1.0, 0.5, 1.0],\n"), std::string::npos);
    EXPECT_NE(saved.find("\n            { \"id\": \"box.top\", \"loop\": [3, 7, 6, 2] },\n"), std::string::npos);
    // No line is longer than the width that flat objects are folded at.
    std::stringstream lines(saved);
    for (std::string line; std::getline(lines, line);)
        EXPECT_LE(line.size(), 100u) << line;
}

TEST(SceneJsonWrite, EmptyOptionalFieldsAreOmitted)
{
    Scene scene;
    scene.materials.push_back(Material{"m", "", Rgb(0.5), Rgb(0.0)});
    Part part{"p", "", "", {Vec3(0), Vec3(1, 0, 0), Vec3(0, 0, 1)}, {Face{"f", {0, 2, 1}, ""}}};
    scene.objects.push_back(Object{"o", "", {part}});
    const std::string text = serializeScene(scene);
    EXPECT_EQ(text.find("\"name\""), std::string::npos) << text;
    EXPECT_EQ(text.find("\"material\""), std::string::npos) << text;
    EXPECT_EQ(text.find("\"camera\""), std::string::npos) << text;
    // Required keys are always written, even when empty.
    EXPECT_NE(text.find("\"regions\": []"), std::string::npos) << text;
    EXPECT_NE(text.find("\"solver\""), std::string::npos) << text;
}

TEST(SceneJsonWrite, WritingIsAPureFunctionOfTheScene)
{
    const Scene scene = *parseScene(readText(validPath("full.json")));
    const Scene copy = scene;
    EXPECT_EQ(serializeScene(scene), serializeScene(copy));
}

// ------------------------------------------------------------------ timing
// Wall-clock bounds (CTest label "timing"): hostile input is refused without
// reading on for long. Where it is refused is checked above.

TEST(SceneJsonSyntaxTiming, AHugeNumberIsRefusedQuickly) { EXPECT_LT(secondsToParse(hugeNumberScene()), 2.0); }

TEST(SceneJsonSyntaxTiming, AnUnterminatedHugeStringIsRefusedQuickly)
{
    EXPECT_LT(secondsToParse(unterminatedHugeString()), 2.0);
}
