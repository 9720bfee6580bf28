// Scene files on disk: loading reports unreadable files as diagnostics, and
// saving is atomic - whatever goes wrong, the previous file stays intact and
// no temporary file is left behind.
#include "model/io/scene_json.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

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

class ScratchDir {
public:
    ScratchDir()
    {
        static std::atomic<int> counter{0};
        m_path = fs::temp_directory_path() /
                 ("regio-file-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
        fs::create_directories(m_path);
    }
    ~ScratchDir()
    {
        std::error_code ec;
        fs::permissions(m_path, fs::perms::owner_all, fs::perm_options::add, ec);
        fs::remove_all(m_path, ec);
    }
    const fs::path& path() const { return m_path; }
    fs::path operator/(const std::string& name) const { return m_path / name; }
    // Every entry of the directory, to prove no temporary file was left.
    std::vector<std::string> entries() const
    {
        std::vector<std::string> names;
        for (const auto& entry : fs::directory_iterator(m_path))
            names.push_back(entry.path().filename().string());
        std::sort(names.begin(), names.end());
        return names;
    }

private:
    fs::path m_path;
};

Scene sampleScene()
{
    const Result<Scene> read = loadSceneFile(std::string(REGIO_TEST_DATA) + "/valid/full.json");
    EXPECT_TRUE(read.ok());
    return read.ok() ? *read : Scene{};
}

Scene otherScene()
{
    Scene scene = sampleScene();
    scene.materials[0].name = "Changed";
    scene.solver.hemicube = 64;
    return scene;
}

const std::string kOldText = "the user's previous scene file\n";

} // namespace

// ----------------------------------------------------------------- loading

TEST(SceneFileLoad, ReadsAFileAsParseSceneReadsItsText)
{
    const std::string path = std::string(REGIO_TEST_DATA) + "/valid/full.json";
    const Result<Scene> fromFile = loadSceneFile(path);
    const Result<Scene> fromText = parseScene(readText(path));
    ASSERT_TRUE(fromFile.ok() && fromText.ok());
    EXPECT_EQ(*fromFile, *fromText);
    EXPECT_TRUE(fromFile.diagnostics().empty());
}

TEST(SceneFileLoad, AMissingFileIsOneErrorWithTheSystemsReason)
{
    ScratchDir dir;
    const Result<Scene> read = loadSceneFile((dir / "absent.json").string());
    EXPECT_FALSE(read.ok());
    ASSERT_EQ(read.diagnostics().size(), 1u);
    EXPECT_TRUE(read.diagnostics()[0].isError());
    EXPECT_EQ(read.diagnostics()[0].message, "cannot open: No such file or directory");
    EXPECT_EQ(read.diagnostics()[0].pointer, "");
}

TEST(SceneFileLoad, ADirectoryIsRefused)
{
    ScratchDir dir;
    const Result<Scene> read = loadSceneFile(dir.path().string());
    EXPECT_FALSE(read.ok());
    ASSERT_EQ(read.diagnostics().size(), 1u);
    EXPECT_EQ(read.diagnostics()[0].message, "is a directory, not a scene file");
}

TEST(SceneFileLoad, SyntaxErrorsKeepTheirPositionAndNoPathPrefix)
{
    const Result<Scene> read = loadSceneFile(std::string(REGIO_TEST_DATA) + "/bad/malformed-json.json");
    ASSERT_EQ(read.diagnostics().size(), 1u);
    EXPECT_EQ(read.diagnostics()[0].line, 6);
    EXPECT_EQ(read.diagnostics()[0].column, 21);
    EXPECT_EQ(read.diagnostics()[0].message.find("malformed-json"), std::string::npos);
}

// ------------------------------------------------------------------ saving

TEST(SceneFileSave, WritesTheCanonicalTextAndNothingElse)
{
    ScratchDir dir;
    const Scene scene = sampleScene();
    const std::string path = (dir / "scene.json").string();
    EXPECT_TRUE(saveSceneFile(scene, path));
    EXPECT_EQ(readText(path), serializeScene(scene));
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"scene.json"});
    const Result<Scene> back = loadSceneFile(path);
    ASSERT_TRUE(back.ok());
    EXPECT_EQ(*back, scene);
}

TEST(SceneFileSave, ReplacesAnExistingFileWhole)
{
    ScratchDir dir;
    const std::string path = (dir / "scene.json").string();
    std::ofstream(path) << std::string(100000, 'x');
    EXPECT_TRUE(saveSceneFile(otherScene(), path));
    EXPECT_EQ(readText(path), serializeScene(otherScene()));
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"scene.json"});
}

TEST(SceneFileSave, SaveLoadSaveGivesTheSameBytes)
{
    ScratchDir dir;
    const std::string first = (dir / "first.json").string();
    const std::string second = (dir / "second.json").string();
    ASSERT_TRUE(saveSceneFile(sampleScene(), first));
    const Result<Scene> read = loadSceneFile(first);
    ASSERT_TRUE(read.ok());
    ASSERT_TRUE(saveSceneFile(*read, second));
    EXPECT_EQ(readText(first), readText(second));
}

TEST(SceneFileSave, KeepsThePermissionsOfTheFileItReplaces)
{
    ScratchDir dir;
    const fs::path path = dir / "private.json";
    std::ofstream(path) << kOldText;
    ::chmod(path.c_str(), 0640);
    ASSERT_TRUE(saveSceneFile(sampleScene(), path.string()));
    struct stat info { };
    ASSERT_EQ(::stat(path.c_str(), &info), 0);
    EXPECT_EQ(info.st_mode & 07777, 0640u);
}

TEST(SceneFileSave, ANewFileGetsTheUsualPermissionsNotThoseOfATemporaryFile)
{
    ScratchDir dir;
    const mode_t previous = ::umask(022);
    const fs::path path = dir / "new.json";
    const auto error = saveSceneFile(sampleScene(), path.string());
    ::umask(previous);
    ASSERT_TRUE(error.ok()) << error.error().message;
    struct stat info { };
    ASSERT_EQ(::stat(path.c_str(), &info), 0);
    EXPECT_EQ(info.st_mode & 07777, 0644u);
}

TEST(SceneFileSave, SavingThroughASymbolicLinkReplacesTheFileItPointsTo)
{
    ScratchDir dir;
    fs::create_directories(dir / "real");
    std::ofstream(dir / "real" / "scene.json") << kOldText;
    fs::create_symlink(dir / "real" / "scene.json", dir / "link.json");
    ASSERT_TRUE(saveSceneFile(sampleScene(), (dir / "link.json").string()));
    EXPECT_TRUE(fs::is_symlink(dir / "link.json"));
    EXPECT_EQ(readText(dir / "real" / "scene.json"), serializeScene(sampleScene()));
}

TEST(SceneFileSave, ADirectoryAsTargetIsRefusedAndLeftAlone)
{
    ScratchDir dir;
    fs::create_directories(dir / "scene.json");
    std::ofstream(dir / "scene.json" / "inside.txt") << kOldText;
    const std::string path = (dir / "scene.json").string();
    const auto error = saveSceneFile(sampleScene(), path);
    ASSERT_FALSE(error.ok());
    EXPECT_TRUE(error.error().isError());
    EXPECT_NE(error.error().message.find("cannot save " + path), std::string::npos) << error.error().message;
    EXPECT_NE(error.error().message.find("Is a directory"), std::string::npos) << error.error().message;
    EXPECT_EQ(readText(dir / "scene.json" / "inside.txt"), kOldText);
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"scene.json"});
}

TEST(SceneFileSave, AMissingDirectoryIsReportedWithItsPath)
{
    ScratchDir dir;
    const std::string path = (dir / "no" / "such" / "scene.json").string();
    const auto error = saveSceneFile(sampleScene(), path);
    ASSERT_FALSE(error.ok());
    EXPECT_NE(error.error().message.find("cannot save " + path), std::string::npos) << error.error().message;
    EXPECT_NE(error.error().message.find("No such file or directory"), std::string::npos) << error.error().message;
}

// Permission bits do not stop root, so the save runs in a child process that
// first gives up root (to "nobody") when it has it.
TEST(SceneFileSave, AnUnwritableDirectoryLeavesTheOldFileIntact)
{
    ScratchDir dir;
    const fs::path path = dir / "scene.json";
    std::ofstream(path) << kOldText;
    ::chmod(path.c_str(), 0644);
    ::chmod(dir.path().c_str(), 0555);
    const Scene scene = sampleScene();
    int pipeFds[2];
    ASSERT_EQ(::pipe(pipeFds), 0);
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        ::close(pipeFds[0]);
        if (::geteuid() == 0 && (::setgid(65534) != 0 || ::setuid(65534) != 0))
            ::_exit(3);
        const auto error = saveSceneFile(scene, path.string());
        const std::string message = !error.ok() ? error.error().message : "";
        if (::write(pipeFds[1], message.data(), message.size()) < 0)
            ::_exit(4);
        ::_exit(!error.ok() ? 0 : 1);
    }
    ::close(pipeFds[1]);
    std::string message;
    char buffer[512];
    for (ssize_t n; (n = ::read(pipeFds[0], buffer, sizeof buffer)) > 0;)
        message.append(buffer, static_cast<std::size_t>(n));
    ::close(pipeFds[0]);
    int status = 0;
    ::waitpid(child, &status, 0);
    ::chmod(dir.path().c_str(), 0755);
    ASSERT_TRUE(WIFEXITED(status));
    ASSERT_NE(WEXITSTATUS(status), 3) << "could not drop root privileges";
    EXPECT_EQ(WEXITSTATUS(status), 0) << "the save into a read-only directory succeeded";
    EXPECT_NE(message.find("cannot save " + path.string()), std::string::npos) << message;
    EXPECT_NE(message.find("cannot create a temporary file in " + dir.path().string()), std::string::npos) << message;
    EXPECT_NE(message.find("Permission denied"), std::string::npos) << message;
    EXPECT_EQ(readText(path), kOldText);
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"scene.json"});
}

// A disk that fills up halfway: the file size limit makes write() fail with
// EFBIG after the first bytes, as ENOSPC would.
TEST(SceneFileSave, AWriteThatFailsHalfwayLeavesTheOldFileAndNoTemporaryFile)
{
    ScratchDir dir;
    const fs::path path = dir / "scene.json";
    std::ofstream(path) << kOldText;
    rlimit previous{};
    ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &previous), 0);
    const auto previousHandler = std::signal(SIGXFSZ, SIG_IGN);
    rlimit small = previous;
    small.rlim_cur = 1000;
    ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
    const auto error = saveSceneFile(sampleScene(), path.string());
    ::setrlimit(RLIMIT_FSIZE, &previous);
    std::signal(SIGXFSZ, previousHandler);
    ASSERT_FALSE(error.ok());
    EXPECT_NE(error.error().message.find("cannot save " + path.string() + ": cannot write "), std::string::npos)
        << error.error().message;
    EXPECT_NE(error.error().message.find("File too large"), std::string::npos) << error.error().message;
    EXPECT_EQ(readText(path), kOldText);
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"scene.json"});
}

TEST(SceneFileSave, ASceneThatWouldNotLoadBackIsNotWritten)
{
    ScratchDir dir;
    const fs::path path = dir / "scene.json";
    std::ofstream(path) << kOldText;
    Scene scene = sampleScene();
    // JSON has no NaN: it would be written as null and the file would not load.
    scene.objects[1].parts[0].vertices[2].y = std::numeric_limits<double>::quiet_NaN();
    const auto nan = saveSceneFile(scene, path.string());
    ASSERT_FALSE(nan.ok());
    EXPECT_EQ(nan.error().pointer, "/objects/1/parts/0/vertices/2/1");
    EXPECT_NE(nan.error().message.find("the scene would not load back"), std::string::npos) << nan.error().message;
    EXPECT_EQ(nan.error().idPath, (std::vector<std::string>{"box", "box.cube"}));

    scene = sampleScene();
    scene.materials[0].reflectance.r = 1.0;
    const auto reflectance = saveSceneFile(scene, path.string());
    ASSERT_FALSE(reflectance.ok());
    EXPECT_EQ(reflectance.error().pointer, "/materials/0/reflectance/0");

    EXPECT_EQ(readText(path), kOldText);
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"scene.json"});
}
