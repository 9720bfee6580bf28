#include "model/io/atomic_file.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace regio::model {

namespace {

std::string errnoText(int error)
{
    return std::strerror(error);
}

// Closes on scope exit unless released; keeps the error paths short.
class Descriptor {
public:
    explicit Descriptor(int fd) : m_fd(fd) {}
    Descriptor(const Descriptor&) = delete;
    Descriptor& operator=(const Descriptor&) = delete;
    ~Descriptor()
    {
        if (m_fd >= 0)
            ::close(m_fd);
    }
    int get() const { return m_fd; }
    bool valid() const { return m_fd >= 0; }
    int close()
    {
        const int r = ::close(m_fd);
        m_fd = -1;
        return r;
    }

private:
    int m_fd;
};

bool writeAll(int fd, std::string_view bytes)
{
    while (!bytes.empty()) {
        const ssize_t n = ::write(fd, bytes.data(), bytes.size());
        if (n < 0) {
            if (errno == EINTR)
                continue;
            return false;
        }
        bytes.remove_prefix(static_cast<size_t>(n));
    }
    return true;
}

// The process umask without changing it (umask() would, briefly, for every
// thread): Linux reports it in /proc/self/status. 022 where it cannot be read.
mode_t currentUmask()
{
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line)) {
        if (line.rfind("Umask:", 0) != 0)
            continue;
        try {
            return static_cast<mode_t>(std::stoul(line.substr(6), nullptr, 8) & 0777);
        } catch (const std::exception&) {
            break;
        }
    }
    return 022;
}

} // namespace

std::optional<std::string> writeFileAtomically(const std::string& path, std::string_view bytes)
{
    auto fail = [&](const std::string& what, int error) {
        return "cannot write " + path + ": " + what + ": " + errnoText(error);
    };
    if (path.empty())
        return std::string("cannot write a file without a name");

    // Write through a symbolic link to its target, so the link survives.
    std::string target = path;
    struct stat linkInfo {};
    if (::lstat(path.c_str(), &linkInfo) == 0 && S_ISLNK(linkInfo.st_mode)) {
        std::error_code ec;
        const auto resolved = std::filesystem::canonical(path, ec);
        if (!ec)
            target = resolved.string();
    }
    std::string directory = std::filesystem::path(target).parent_path().string();
    if (directory.empty())
        directory = ".";

    struct stat existing {};
    const bool exists = ::stat(target.c_str(), &existing) == 0;
    if (exists && S_ISDIR(existing.st_mode))
        return fail("the path is a directory", EISDIR);

    std::string tempPattern = target + ".tmp-XXXXXX";
    std::vector<char> tempName(tempPattern.begin(), tempPattern.end());
    tempName.push_back('\0');
    Descriptor file(::mkstemp(tempName.data()));
    if (!file.valid())
        return fail("cannot create a temporary file in " + directory, errno);
    const std::string tempPath(tempName.data());

    auto abandon = [&](const std::string& what) {
        const int saved = errno;
        if (file.valid())
            file.close();
        ::unlink(tempPath.c_str());
        return fail(what, saved);
    };
    // mkstemp creates 0600; an export is an ordinary file (0666 less umask),
    // and an existing file keeps its permissions.
    mode_t mode = 0;
    if (exists) {
        mode = existing.st_mode & 07777;
    } else {
        mode = 0666 & ~currentUmask();
    }
    if (::fchmod(file.get(), mode) != 0)
        return abandon("cannot set the permissions of " + tempPath);
    if (!writeAll(file.get(), bytes))
        return abandon("cannot write " + tempPath);
    if (::fsync(file.get()) != 0)
        return abandon("cannot flush " + tempPath + " to disk");
    if (file.close() != 0)
        return abandon("cannot write " + tempPath);
    if (::rename(tempPath.c_str(), target.c_str()) != 0)
        return abandon("cannot replace " + target);

    // Make the rename durable; a failure here cannot undo the write.
    Descriptor dir(::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
    if (dir.valid())
        ::fsync(dir.get());
    return std::nullopt;
}

} // namespace regio::model
