// `regio-solve solve --out-dir`: many scenes solved unattended, as a script
// running a batch sees it: the files in the directory, the summary, the
// exit status, the JSON progress lines, a rerun that solves nothing twice,
// and a batch stopped by SIGTERM that loses nothing and resumes.
#include "support/command_run.h"
#include "support/sample_scenes.h"
#include "support/small_scenes.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <csignal>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace regio::test;
using nlohmann::json;

namespace {

// Valid JSON, but a face refers to a material that does not exist.
const char* const kBrokenScene = R"({ "format": "regio-scene", "version": 1,
  "materials": [ { "id": "grey", "reflectance": [0.5, 0.5, 0.5], "emission": [0, 0, 0] } ],
  "objects": [ { "id": "floor", "parts": [ { "id": "floor.panel", "material": "gold",
      "vertices": [[0,0,0], [0,0,1], [1,0,1], [1,0,0]],
      "faces": [ { "id": "floor.up", "loop": [0, 1, 2, 3] } ] } ] } ]
})";

CommandRun solve(const std::vector<std::string>& args)
{
    std::vector<std::string> all{"solve"};
    all.insert(all.end(), args.begin(), args.end());
    return runRegioSolve(all);
}

json report(const fs::path& path) { return json::parse(readText(path)); }

std::set<std::string> filesIn(const fs::path& dir)
{
    std::set<std::string> names;
    for (const fs::directory_entry& entry : fs::directory_iterator(dir))
        names.insert(entry.path().filename().string());
    return names;
}

std::vector<json> jsonLines(const std::string& text)
{
    std::vector<json> lines;
    size_t start = 0;
    while (start < text.size()) {
        const size_t end = text.find('\n', start);
        const std::string line = text.substr(start, end == std::string::npos ? std::string::npos : end - start);
        if (!line.empty())
            lines.push_back(json::parse(line));
        if (end == std::string::npos)
            break;
        start = end + 1;
    }
    return lines;
}

// regio-solve running in the background, its standard output read line by
// line through a pipe, so a test can act at a given point of a batch.
class Background {
public:
    explicit Background(const std::vector<std::string>& args, const fs::path& errFile)
    {
        int fds[2];
        if (::pipe(fds) != 0)
            throw std::runtime_error("pipe");
        m_pid = ::fork();
        if (m_pid == 0) {
            ::dup2(fds[1], STDOUT_FILENO);
            const int err = ::open(errFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
            ::dup2(err, STDERR_FILENO);
            ::close(fds[0]);
            execRegioSolve(args);
        }
        ::close(fds[1]);
        m_out = ::fdopen(fds[0], "r");
    }
    ~Background()
    {
        if (m_pid > 0 && !m_waited) {
            ::kill(m_pid, SIGKILL);
            wait();
        }
        if (m_out)
            std::fclose(m_out);
    }
    // The next line of standard output, or nothing at its end.
    std::optional<std::string> line()
    {
        char buffer[4096];
        if (!std::fgets(buffer, sizeof buffer, m_out))
            return std::nullopt;
        return std::string(buffer);
    }
    void signal(int number) { ::kill(m_pid, number); }
    // The exit status as a shell reports it.
    int wait()
    {
        while (line()) {
        }
        int status = 0;
        ::waitpid(m_pid, &status, 0);
        m_waited = true;
        return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    }

private:
    pid_t m_pid = -1;
    std::FILE* m_out = nullptr;
    bool m_waited = false;
};

} // namespace

TEST(BatchCommand, ThreeScenesOneBrokenGiveTwoSolvedScenesAClearErrorAndExitOne)
{
    ScratchDir scratch;
    scratch.write("one.json", kSmallScene);
    scratch.write("two.json", kSmallScene);
    scratch.write("broken.json", kBrokenScene);
    const fs::path out = scratch / "out";
    const std::vector<std::string> args{"--out-dir",
                                        out.string(),
                                        "--format",
                                        "glb,ply,png",
                                        "--size",
                                        "64x48",
                                        (scratch / "one.json").string(),
                                        (scratch / "broken.json").string(),
                                        (scratch / "two.json").string()};
    const CommandRun first = solve(args);
    ASSERT_TRUE(first.exited) << first.err;
    EXPECT_EQ(first.exitCode, 1) << first.err;
    for (const char* name : {"one", "two"}) {
        const json r = report(out / (std::string(name) + ".report.json"));
        EXPECT_EQ(r["status"], "solved");
        EXPECT_EQ(r["stop"], "converged");
        EXPECT_EQ(r["batch"]["sceneSha256"].get<std::string>().size(), 64u);
        for (const char* extension : {".glb", ".ply", ".png"})
            EXPECT_GT(fs::file_size(out / (std::string(name) + extension)), 100u) << name << extension;
    }
    // The broken scene: its report says why, and no outputs.
    const json broken = report(out / "broken.report.json");
    EXPECT_EQ(broken["status"], "invalid");
    ASSERT_FALSE(broken["errors"].empty());
    EXPECT_NE(broken["errors"][0].get<std::string>().find("broken.json"), std::string::npos);
    EXPECT_NE(broken["errors"][0].get<std::string>().find("gold"), std::string::npos);
    EXPECT_EQ(filesIn(out),
              (std::set<std::string>{"one.report.json", "one.glb", "one.ply", "one.png", "two.report.json", "two.glb",
                                     "two.ply", "two.png", "broken.report.json"}));
    // The summary table: a row per scene, the error under the broken one.
    EXPECT_NE(first.out.find("3 scenes: 2 solved, 0 skipped, 1 failed"), std::string::npos) << first.out;
    EXPECT_NE(first.out.find("broken.json"), std::string::npos) << first.out;
    EXPECT_NE(first.err.find("broken.json"), std::string::npos) << first.err;

    // Again: nothing is solved twice, the files stay as they are.
    const auto modified = fs::last_write_time(out / "one.glb");
    const CommandRun again = solve(args);
    EXPECT_EQ(again.exitCode, 1) << again.err;
    EXPECT_NE(again.out.find("3 scenes: 0 solved, 2 skipped, 1 failed"), std::string::npos) << again.out;
    EXPECT_EQ(fs::last_write_time(out / "one.glb"), modified);

    // --force: every scene again.
    std::vector<std::string> forced = args;
    forced.insert(forced.begin(), "--force");
    const CommandRun force = solve(forced);
    EXPECT_EQ(force.exitCode, 1) << force.err;
    EXPECT_NE(force.out.find("3 scenes: 2 solved, 0 skipped, 1 failed"), std::string::npos) << force.out;
}

TEST(BatchCommand, ASceneIsSolvedAgainWhenItsContentOrAResultOptionChangesAndNotForThreadsOrJobs)
{
    ScratchDir scratch;
    const fs::path scene = scratch.write("room.json", kSmallScene);
    const fs::path out = scratch / "out";
    const auto run = [&](std::vector<std::string> extra) {
        std::vector<std::string> args{"--out-dir", out.string(), scene.string()};
        args.insert(args.begin(), extra.begin(), extra.end());
        return solve(args);
    };
    const auto solved = [](const CommandRun& r) { return r.out.find("1 solved") != std::string::npos; };
    EXPECT_TRUE(solved(run({})));
    EXPECT_FALSE(solved(run({"--threads", "1", "--jobs", "1"})));
    EXPECT_TRUE(solved(run({"--hemicube", "60"})));
    EXPECT_FALSE(solved(run({"--hemicube", "60"})));
    // A missing output is made.
    EXPECT_TRUE(solved(run({"--hemicube", "60", "--format", "ply"})));
    fs::remove(out / "room.ply");
    EXPECT_TRUE(solved(run({"--hemicube", "60", "--format", "ply"})));
    // New content: one more byte of white space is another scene.
    scratch.write("room.json", std::string(kSmallScene) + "\n");
    EXPECT_TRUE(solved(run({"--hemicube", "60", "--format", "ply"})));
}

TEST(BatchCommand, JsonProgressGivesEverySceneEventAndEachPercentOfWorkOnStandardOutput)
{
    ScratchDir scratch;
    scratch.write("one.json", kSmallScene);
    scratch.write("broken.json", kBrokenScene);
    const CommandRun run = solve({"--out-dir", (scratch / "out").string(), "--progress", "json", "--jobs", "2",
                                  (scratch / "one.json").string(), (scratch / "broken.json").string()});
    EXPECT_EQ(run.exitCode, 1) << run.err;
    const std::vector<json> lines = jsonLines(run.out);
    ASSERT_FALSE(lines.empty()) << run.out;
    std::map<std::string, std::vector<std::string>> events;
    int lastPercent = -1;
    double lastElapsed = 0.0;
    for (const json& line : lines) {
        ASSERT_TRUE(line.contains("event") && line.contains("elapsed")) << line;
        EXPECT_GE(line["elapsed"].get<double>(), lastElapsed);
        lastElapsed = line["elapsed"].get<double>();
        if (line["event"] == "summary")
            continue;
        events[line["scene"].get<std::string>()].push_back(line["event"].get<std::string>());
        if (line["event"] == "progress") {
            EXPECT_EQ(line["phase"], "shoot");
            EXPECT_GT(line["percent"].get<int>(), lastPercent);
            EXPECT_LE(line["percent"].get<int>(), 100);
            lastPercent = line["percent"].get<int>();
            EXPECT_GE(line["unshot"].get<double>(), 0.0);
            EXPECT_GE(line["iteration"].get<int>(), 1);
        }
    }
    EXPECT_EQ(lastPercent, 100);
    EXPECT_EQ(events["one"].front(), "start");
    EXPECT_EQ(events["one"].back(), "solved");
    EXPECT_EQ(events["broken"].front(), "start");
    EXPECT_EQ(events["broken"].back(), "failed");
    EXPECT_EQ(lines.back()["event"], "summary");
    EXPECT_EQ(lines.back()["solved"], 1);
    EXPECT_EQ(lines.back()["failed"], 1);
    // People's summary goes to standard error, out of the tools' way.
    EXPECT_NE(run.err.find("2 scenes: 1 solved"), std::string::npos) << run.err;
}

TEST(BatchCommand, ABatchStoppedBySigtermKeepsFinishedScenesLeavesNoPartialFileAndResumes)
{
    ScratchDir scratch;
    scratch.write("a.json", kSmallScene);
    fs::copy_file(samplePath("cornell-box"), scratch / "b.json");
    scratch.write("c.json", kSmallScene);
    const fs::path out = scratch / "out";
    const std::vector<std::string> args{"solve",
                                        "--out-dir",
                                        out.string(),
                                        "--format",
                                        "glb,obj",
                                        "--progress",
                                        "json",
                                        "--jobs",
                                        "1",
                                        (scratch / "a.json").string(),
                                        (scratch / "b.json").string(),
                                        (scratch / "c.json").string()};
    {
        Background batch(args, scratch / "err");
        bool signalled = false;
        while (const std::optional<std::string> line = batch.line()) {
            const json event = json::parse(*line);
            if (event["event"] == "progress" && event["scene"] == "b" && event["iteration"].get<int>() >= 5) {
                batch.signal(SIGTERM);
                signalled = true;
                break;
            }
        }
        ASSERT_TRUE(signalled) << readText(scratch / "err");
        EXPECT_EQ(batch.wait(), 128 + SIGTERM) << readText(scratch / "err");
    }
    // a is complete, b says how far it got, c was never started; nothing else.
    EXPECT_EQ(report(out / "a.report.json")["status"], "solved");
    EXPECT_EQ(report(out / "b.report.json")["status"], "interrupted");
    EXPECT_EQ(filesIn(out), (std::set<std::string>{"a.report.json", "a.glb", "a.obj", "a.mtl", "b.report.json"}));
    const std::string err = readText(scratch / "err");
    EXPECT_NE(err.find("interrupted"), std::string::npos) << err;
    EXPECT_NE(err.find("not started"), std::string::npos) << err;

    // The same command again finishes the rest and leaves a alone.
    const auto modified = fs::last_write_time(out / "a.glb");
    std::vector<std::string> rerun(args.begin() + 1, args.end());
    const CommandRun resumed = solve(rerun);
    EXPECT_EQ(resumed.exitCode, 0) << resumed.err;
    EXPECT_NE(resumed.err.find("3 scenes: 2 solved, 1 skipped, 0 failed"), std::string::npos) << resumed.err;
    EXPECT_EQ(fs::last_write_time(out / "a.glb"), modified);
    for (const char* name : {"a", "b", "c"})
        EXPECT_EQ(report(out / (std::string(name) + ".report.json"))["status"], "solved") << name;
}

TEST(BatchCommand, RefusesWhatItCannotDoBeforeSolvingAnything)
{
    ScratchDir scratch;
    const fs::path one = scratch.write("room.json", kSmallScene);
    fs::create_directories(scratch / "other");
    const fs::path two = scratch.write("other/room.json", kSmallScene);
    const std::string out = (scratch / "out").string();
    const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
        {{"--out-dir", out, one.string(), two.string()}, "would both write room.report.json"},
        {{"--out-dir", out, "--format", "glb,jpeg", one.string()}, "--format expects"},
        {{"--out-dir", out, "--jobs", "0", one.string()}, "--jobs expects"},
        {{"--out-dir", out, "--progress", "xml", one.string()}, "--progress expects"},
        {{"--out-dir", out, "--out", (scratch / "x.glb").string(), one.string()}, "--out and --image"},
        {{"--out-dir", out, "-"}, "standard input"},
        {{"--jobs", "2", one.string()}, "work with --out-dir"},
        {{"--format", "glb", one.string()}, "work with --out-dir"},
    };
    for (const auto& [args, message] : cases) {
        const CommandRun run = solve(args);
        EXPECT_EQ(run.exitCode, 2) << message;
        EXPECT_NE(run.err.find(message), std::string::npos) << run.err;
    }
    EXPECT_FALSE(fs::exists(scratch / "out"));
    // A file where the directory should be.
    scratch.write("taken", "");
    const CommandRun taken = solve({"--out-dir", (scratch / "taken").string(), one.string()});
    EXPECT_EQ(taken.exitCode, 2);
    EXPECT_NE(taken.err.find("cannot create the directory"), std::string::npos) << taken.err;
}
