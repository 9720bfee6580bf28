// Every file Regio reads whole or writes goes through model/io/file_io.h:
// reading refuses directories and files past a limit with a clear error,
// writing is atomic and names the file and the step that failed.
#include "model/io/file_io.h"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <string>

namespace regio::model {
namespace {

namespace fs = std::filesystem;

class Scratch {
public:
    Scratch()
    {
        m_path = fs::temp_directory_path() / ("regio-file-io-" + std::to_string(std::random_device{}()));
        fs::create_directories(m_path);
    }
    ~Scratch() { fs::remove_all(m_path); }
    fs::path operator/(const std::string& name) const { return m_path / name; }
    std::size_t entries() const { return std::size_t(std::distance(fs::directory_iterator(m_path), {})); }

private:
    fs::path m_path;
};

std::string contents(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

TEST(ReadFile, ReadsEveryByte)
{
    Scratch dir;
    const std::string bytes("a\0b\xff\n", 5);
    std::ofstream(dir / "f.bin", std::ios::binary) << bytes;
    const Result<std::string> read = readFile((dir / "f.bin").string());
    ASSERT_TRUE(read.ok()) << read.error().message;
    EXPECT_EQ(*read, bytes);
}

TEST(ReadFile, AMissingFileAndADirectoryAreErrorsThatSayWhy)
{
    Scratch dir;
    const Result<std::string> missing = readFile((dir / "absent.json").string());
    ASSERT_FALSE(missing.ok());
    EXPECT_EQ(missing.error().message, "cannot open: No such file or directory");
    const Result<std::string> folder = readFile((dir / "").string(), kMaxSceneFileBytes, "report");
    ASSERT_FALSE(folder.ok());
    EXPECT_EQ(folder.error().message, "is a directory, not a report");
}

TEST(ReadFile, AFileBeyondTheLimitIsRefusedBeforeItIsRead)
{
    Scratch dir;
    std::ofstream(dir / "big.json") << std::string(11, 'x');
    const Result<std::string> read = readFile((dir / "big.json").string(), 10);
    ASSERT_FALSE(read.ok());
    EXPECT_EQ(read.error().message, "file too large (11 bytes; scene files are limited to 10 bytes)");
    EXPECT_TRUE(readFile((dir / "big.json").string(), 11).ok());
}

TEST(WriteFileAtomically, WritesTheBytesAndLeavesNoTemporaryFile)
{
    Scratch dir;
    const std::string path = (dir / "out.txt").string();
    std::ofstream(path) << "the previous file, much longer than the new one\n";
    ASSERT_TRUE(writeFileAtomically(path, "new\n").ok());
    EXPECT_EQ(contents(path), "new\n");
    EXPECT_EQ(dir.entries(), 1u);
}

TEST(WriteFileAtomically, AFailureNamesTheActionTheFileAndTheReasonAndKeepsThePreviousFile)
{
    Scratch dir;
    const std::string missingFolder = (dir / "missing" / "out.glb").string();
    const Check written = writeFileAtomically(missingFolder, "bytes", "export");
    ASSERT_FALSE(written.ok());
    EXPECT_EQ(written.error().message.rfind("cannot export " + missingFolder + ": ", 0), 0u) << written.error().message;
    EXPECT_NE(written.error().message.find("No such file or directory"), std::string::npos) << written.error().message;

    const Check unnamed = writeFileAtomically("", "bytes");
    ASSERT_FALSE(unnamed.ok());
    EXPECT_EQ(unnamed.error().message, "cannot write a file without a name");

    fs::create_directories(dir / "folder");
    const Check onFolder = writeFileAtomically((dir / "folder").string(), "bytes");
    ASSERT_FALSE(onFolder.ok());
    EXPECT_NE(onFolder.error().message.find("the path is a directory"), std::string::npos);
    EXPECT_TRUE(fs::is_directory(dir / "folder"));
}

TEST(WriteFileAtomically, ANewFileGetsTheUsualPermissions)
{
    Scratch dir;
    const mode_t previous = ::umask(022);
    const std::string path = (dir / "new.png").string();
    const Check written = writeFileAtomically(path, "png");
    ::umask(previous);
    ASSERT_TRUE(written.ok());
    struct stat info { };
    ASSERT_EQ(::stat(path.c_str(), &info), 0);
    EXPECT_EQ(info.st_mode & 07777, 0644u);
}

} // namespace
} // namespace regio::model
