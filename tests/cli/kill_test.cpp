// Nothing lost: regio-solve killed (SIGKILL, no chance to clean up) at
// random moments while it writes never leaves a corrupted or empty file
// under a target name, and the same command run again finishes the work.
// Every file goes through model::writeFileAtomically, the editor's saves
// included; a sweep writes scenes with it as the editor saves them.
#include "support/command_run.h"
#include "support/sample_scenes.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace regio::test;

namespace {

// Runs regio-solve ARGS and kills it with SIGKILL after `delay`; true if it
// was still running then.
bool runAndKill(const std::vector<std::string>& args, std::chrono::microseconds delay)
{
    const pid_t pid = ::fork();
    if (pid == 0) {
        std::freopen("/dev/null", "w", stdout);
        std::freopen("/dev/null", "w", stderr);
        execRegioSolve(args);
    }
    std::this_thread::sleep_for(delay);
    const bool running = ::kill(pid, SIGKILL) == 0;
    int status = 0;
    ::waitpid(pid, &status, 0);
    return running && WIFSIGNALED(status);
}

// A file under its target name is whole: JSON parses, a GLB's header gives
// its own length, an OBJ ends with a line, a PNG with its IEND chunk.
std::string incompleteness(const fs::path& file)
{
    const std::string bytes = readText(file);
    if (bytes.empty())
        return "empty";
    const std::string ext = file.extension().string();
    if (ext == ".json" && nlohmann::json::parse(bytes, nullptr, false).is_discarded())
        return "not whole JSON";
    if (ext == ".glb") {
        if (bytes.size() < 12)
            return "shorter than a GLB header";
        std::uint32_t length = 0;
        std::memcpy(&length, bytes.data() + 8, 4);
        if (length != bytes.size())
            return "GLB length " + std::to_string(length) + " but " + std::to_string(bytes.size()) + " bytes";
    }
    if ((ext == ".obj" || ext == ".mtl") && bytes.back() != '\n')
        return "cut in a line";
    if (ext == ".png" && (bytes.size() < 12 || bytes.compare(bytes.size() - 8, 4, "IEND") != 0))
        return "no IEND chunk";
    return {};
}

void expectEveryTargetWhole(const fs::path& dir, int kill)
{
    for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
        const std::string name = entry.path().filename().string();
        if (name.find(".tmp-") != std::string::npos)
            continue; // a temporary a kill left; never a target name
        const std::string problem = incompleteness(entry.path());
        EXPECT_TRUE(problem.empty()) << "after kill " << kill << ": " << name << " is " << problem;
    }
}

} // namespace

TEST(NothingLost, ABatchKilledAtRandomMomentsLeavesOnlyWholeFilesAndTheRerunFinishes)
{
    ScratchDir scratch;
    std::vector<std::string> scenes;
    for (int i = 0; i < 4; ++i) {
        const fs::path scene = scratch / ("cornell-" + std::to_string(i) + ".json");
        fs::copy_file(samplePath("cornell-box"), scene);
        scenes.push_back(scene.string());
    }
    const fs::path out = scratch / "out";
    std::vector<std::string> args{"solve",       "-q",     "--out-dir", out.string(),   "--format",
                                  "glb,obj,png", "--size", "320x240",   "--iterations", "40",
                                  "--adaptive",  "off",    "--force"};
    args.insert(args.end(), scenes.begin(), scenes.end());

    // How long an uninterrupted run takes, to spread the kills over it: the
    // shortest of three, since a run timed while the machine was busy with
    // other tests would spread them past the end of the quicker runs after.
    auto span = std::chrono::microseconds::max();
    for (int run = 0; run < 3; ++run) {
        const auto start = std::chrono::steady_clock::now();
        const CommandRun whole = runRegioSolve(args);
        ASSERT_EQ(whole.exitCode, 0) << whole.err;
        span = std::min(
            span, std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now() - start));
    }

    std::mt19937 random(20261202);
    int killed = 0;
    for (int kill = 0; kill < 40; ++kill) {
        const auto delay = std::chrono::microseconds(
            std::uniform_int_distribution<std::int64_t>(1000, std::max<std::int64_t>(2000, span.count()))(random));
        killed += runAndKill(args, delay) ? 1 : 0;
        expectEveryTargetWhole(out, kill);
    }
    EXPECT_GE(killed, 30) << "most runs should have been killed mid-way";

    // The same command without --force: finishes what is missing, and the
    // temporaries the kills left are gone.
    args.erase(std::find(args.begin(), args.end(), "--force"));
    const CommandRun rerun = runRegioSolve(args);
    EXPECT_EQ(rerun.exitCode, 0) << rerun.err;
    for (int i = 0; i < 4; ++i)
        for (const char* ext : {".report.json", ".glb", ".obj", ".mtl", ".png"})
            EXPECT_TRUE(fs::exists(out / ("cornell-" + std::to_string(i) + ext))) << i << ext;
    for (const fs::directory_entry& entry : fs::directory_iterator(out))
        EXPECT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos) << entry.path();
    expectEveryTargetWhole(out, -1);
}

TEST(NothingLost, ScenesWrittenAsTheEditorSavesThemAreWholeWhateverMomentTheWriterIsKilled)
{
    ScratchDir scratch;
    const fs::path out = scratch / "variants";
    std::string hemicubes;
    for (int h = 10; h <= 400; h += 2)
        hemicubes += (hemicubes.empty() ? "" : ",") + std::to_string(h);
    const std::vector<std::string> args{"sweep",     samplePath("two-lights-room").string(),
                                        "--set",     "solver.hemicube=" + hemicubes,
                                        "--out-dir", out.string(),
                                        "-q"};
    std::mt19937 random(7);
    for (int kill = 0; kill < 30; ++kill) {
        runAndKill(args, std::chrono::microseconds(std::uniform_int_distribution<int>(2000, 400000)(random)));
        if (fs::exists(out))
            expectEveryTargetWhole(out, kill);
    }
    const CommandRun rerun = runRegioSolve(args);
    EXPECT_EQ(rerun.exitCode, 0) << rerun.err;
    EXPECT_TRUE(fs::exists(out / "two-lights-room-196.json"));
    expectEveryTargetWhole(out, -1);
}
