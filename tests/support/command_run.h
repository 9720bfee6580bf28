#pragma once
// Running the real regio-solve executable from a test: a scratch directory per
// run, shell quoting, and the exit status and both output streams captured.
// Each test binary receives the executable's path as REGIO_SOLVE_EXE.
#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

namespace regio::test {

namespace fs = std::filesystem;

struct CommandRun {
    bool exited = false; // false: killed by a signal (a crash)
    int exitCode = -1;
    std::string out;
    std::string err;
};

inline std::string readText(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::stringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
}

inline std::string shellQuoted(const std::string& arg)
{
    std::string out = "'";
    for (char c : arg)
        out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

// A scratch directory per test, removed afterwards.
class ScratchDir {
public:
    ScratchDir()
    {
        static std::atomic<int> counter{0};
        m_path = fs::temp_directory_path() /
                 ("regio-cli-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
        fs::create_directories(m_path);
    }
    ~ScratchDir()
    {
        std::error_code ec;
        fs::remove_all(m_path, ec);
    }
    const fs::path& path() const { return m_path; }
    fs::path operator/(const std::string& name) const { return m_path / name; }
    fs::path write(const std::string& name, const std::string& text) const
    {
        std::ofstream(m_path / name, std::ios::binary) << text;
        return m_path / name;
    }

private:
    fs::path m_path;
};

// In a forked child: replaces it with regio-solve ARGS (127 if that fails).
[[noreturn]] inline void execRegioSolve(const std::vector<std::string>& args)
{
    std::vector<std::string> all{REGIO_SOLVE_EXE};
    all.insert(all.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& a : all)
        argv.push_back(a.data());
    argv.push_back(nullptr);
    ::execv(argv[0], argv.data());
    ::_exit(127);
}

// Runs regio-solve with `args` from `workDir`, standard input from
// `stdinFile`, after the shell commands `shellPrefix` (e.g. "ulimit -v N").
inline CommandRun runRegioSolve(const std::vector<std::string>& args, const fs::path& workDir = {},
                                const fs::path& stdinFile = "/dev/null", const std::string& shellPrefix = {})
{
    ScratchDir scratch;
    std::string command = shellPrefix.empty() ? std::string() : shellPrefix + " && ";
    if (!workDir.empty())
        command += "cd " + shellQuoted(workDir.string()) + " && ";
    command += shellQuoted(REGIO_SOLVE_EXE);
    for (const std::string& arg : args)
        command += " " + shellQuoted(arg);
    command += " <" + shellQuoted(stdinFile.string()) + " >" + shellQuoted((scratch.path() / "out").string()) + " 2>" +
               shellQuoted((scratch.path() / "err").string());
    const int status = std::system(command.c_str());
    CommandRun run;
    // The shell reports a child killed by signal N as exit status 128 + N.
    run.exited = WIFEXITED(status) && WEXITSTATUS(status) < 128;
    run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    run.out = readText(scratch.path() / "out");
    run.err = readText(scratch.path() / "err");
    return run;
}

} // namespace regio::test
