// Assimp in a child process (importer/isolated_read.h): the same model as
// a read in this process, and a reader that hangs or crashes fails the
// import with the reason instead of taking the program with it.
#include "importer/isolated_read.h"

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

using namespace regio::importer;
namespace fs = std::filesystem;

namespace {

// The children of this process (every thread's), from /proc.
std::vector<pid_t> children()
{
    std::vector<pid_t> out;
    for (const auto& task : fs::directory_iterator("/proc/self/task")) {
        std::ifstream in(task.path() / "children");
        pid_t pid = 0;
        while (in >> pid)
            out.push_back(pid);
    }
    return out;
}

} // namespace

TEST(IsolatedRead, GivesExactlyTheModelOfAReadInThisProcess)
{
    for (const char* model : {"/usr/share/assimp/models/OBJ/spider.obj", "/usr/share/assimp/models/PLY/cube.ply",
                              "/usr/share/assimp/models/glTF2/BoxTextured-glTF/BoxTextured.gltf"}) {
        if (!fs::exists(model))
            GTEST_SKIP() << model << " is missing (assimp-testmodels)";
        const auto here = readModelFile(model);
        const auto there = readModelFileIsolated(model);
        ASSERT_TRUE(here.ok()) << model;
        ASSERT_TRUE(there.ok()) << model << ": " << there.error().message;
        EXPECT_TRUE(*here == *there) << model << ": positions, triangles, materials, meshes or counts differ";
        ASSERT_EQ(here.diagnostics().size(), there.diagnostics().size()) << model;
        for (std::size_t i = 0; i < here.diagnostics().size(); ++i)
            EXPECT_EQ(here.diagnostics()[i].message, there.diagnostics()[i].message);
    }
}

TEST(IsolatedRead, GivesTheReadersOwnRefusal)
{
    const fs::path file = fs::temp_directory_path() / ("regio-isolated-empty-" + std::to_string(::getpid()) + ".obj");
    std::ofstream(file) << "# nothing\n";
    const auto here = readModelFile(file.string());
    const auto there = readModelFileIsolated(file.string());
    fs::remove(file);
    ASSERT_FALSE(here.ok());
    ASSERT_FALSE(there.ok());
    EXPECT_EQ(here.error().message, there.error().message);
}

TEST(IsolatedRead, AReaderThatHangsIsStoppedAfterTheTimeout)
{
    const auto start = std::chrono::steady_clock::now();
    const auto read = readModelFileIsolated("/usr/share/assimp/models/PLY/cube.ply", {}, 1, [] {
        for (;;)
            ::pause(); // as Assimp reading a broken PLY file for ever
    });
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(10));
    ASSERT_FALSE(read.ok());
    EXPECT_NE(read.error().message.find("did not finish in 1 s"), std::string::npos) << read.error().message;
    EXPECT_TRUE(children().empty()) << "the child is reaped";
}

TEST(IsolatedRead, AReaderThatCrashesFailsTheReadNotTheProgram)
{
    for (const int signal : {SIGSEGV, SIGABRT}) {
        static int raised = 0;
        raised = signal;
        const auto read = readModelFileIsolated("/usr/share/assimp/models/PLY/cube.ply", {}, 30, [] {
            std::signal(raised, SIG_DFL);
            std::raise(raised); // as Assimp failing an assertion or touching freed memory
        });
        ASSERT_FALSE(read.ok());
        EXPECT_NE(read.error().message.find("the model reader (Assimp) crashed on it (" +
                                            std::string(::strsignal(signal)) + ")"),
                  std::string::npos)
            << read.error().message;
    }
    EXPECT_TRUE(children().empty());
}
