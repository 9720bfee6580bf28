#include "model/io/file_io.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <new>
#include <random>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace regio::model {

namespace {

std::string errnoText(int error) { return std::strerror(error); }

class FileDescriptor {
public:
    explicit FileDescriptor(int fd = -1, bool owned = true)
        : m_fd(fd)
        , m_owned(owned)
    {
    }
    ~FileDescriptor() { reset(); }
    FileDescriptor(const FileDescriptor&) = delete;
    FileDescriptor& operator=(const FileDescriptor&) = delete;

    int get() const { return m_fd; }
    bool valid() const { return m_fd >= 0; }
    // Closes now and reports the error close() may carry (NFS reports
    // failed writes there).
    int close()
    {
        const int result = ::close(m_fd);
        m_fd = -1;
        return result;
    }
    void reset()
    {
        if (m_fd >= 0 && m_owned)
            ::close(m_fd);
        m_fd = -1;
    }

private:
    int m_fd;
    bool m_owned;
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
        bytes.remove_prefix(static_cast<std::size_t>(n));
    }
    return true;
}

// Creates `<target>.tmp-XXXXXX` beside the target. Not mkstemp: that creates
// mode 0600, while a new file should get the usual 0666 & ~umask, which
// open() applies by itself (reading the umask is not thread-safe).
FileDescriptor createTemporary(const std::string& target, std::string& tempPath, int& error)
{
    static const char alphabet[] = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
    std::random_device device;
    std::mt19937 random(device());
    std::uniform_int_distribution<int> pick(0, static_cast<int>(sizeof(alphabet)) - 2);
    for (int attempt = 0; attempt < 100; ++attempt) {
        tempPath = target + ".tmp-";
        for (int i = 0; i < 6; ++i)
            tempPath += alphabet[pick(random)];
        const int fd = ::open(tempPath.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0)
            return FileDescriptor(fd);
        if (errno != EEXIST) {
            error = errno;
            return FileDescriptor();
        }
    }
    error = EEXIST;
    return FileDescriptor();
}

// Writing through a symbolic link replaces the file it points to, not the link.
std::string resolveTarget(const std::string& path)
{
    struct stat info { };
    if (::lstat(path.c_str(), &info) == 0 && S_ISLNK(info.st_mode)) {
        std::error_code ec;
        const std::filesystem::path resolved = std::filesystem::canonical(path, ec);
        if (!ec)
            return resolved.string();
    }
    return path;
}

std::string tooLarge(std::uint64_t maxBytes, std::string_view kind, std::int64_t size = -1)
{
    const std::string limit = maxBytes % (std::uint64_t{1} << 30) == 0 ? std::to_string(maxBytes >> 30) + " GiB"
                                                                       : std::to_string(maxBytes) + " bytes";
    return "file too large (" + (size >= 0 ? std::to_string(size) + " bytes; " : std::string()) + std::string(kind) +
           "s are limited to " + limit + ")";
}

Result<std::string> readDescriptor(const FileDescriptor& file, std::uint64_t maxBytes, std::string_view kind)
{
    struct stat info { };
    if (::fstat(file.get(), &info) != 0)
        return makeError("cannot read: " + errnoText(errno));
    if (S_ISDIR(info.st_mode))
        return makeError("is a directory, not a " + std::string(kind));
    if (S_ISREG(info.st_mode) && static_cast<std::uint64_t>(info.st_size) > maxBytes)
        return makeError(tooLarge(maxBytes, kind, info.st_size));

    std::string text;
    try {
        if (S_ISREG(info.st_mode))
            text.reserve(static_cast<std::size_t>(info.st_size));
        char buffer[1 << 16];
        for (;;) {
            const ssize_t n = ::read(file.get(), buffer, sizeof buffer);
            if (n < 0) {
                if (errno == EINTR)
                    continue;
                return makeError("cannot read: " + errnoText(errno));
            }
            if (n == 0)
                break;
            // Pipes and devices have no size to check up front.
            if (text.size() + static_cast<std::size_t>(n) > maxBytes)
                return makeError(tooLarge(maxBytes, kind));
            text.append(buffer, static_cast<std::size_t>(n));
        }
    } catch (const std::bad_alloc&) {
        return makeError("out of memory while reading the file");
    }
    return text;
}

} // namespace

Result<std::string> readFile(const std::string& path, std::uint64_t maxBytes, std::string_view kind)
{
    FileDescriptor file(::open(path.c_str(), O_RDONLY | O_CLOEXEC));
    if (!file.valid())
        return makeError("cannot open: " + errnoText(errno));
    return readDescriptor(file, maxBytes, kind);
}

Result<std::string> readStandardInput(std::uint64_t maxBytes, std::string_view kind)
{
    const FileDescriptor input(STDIN_FILENO, false);
    return readDescriptor(input, maxBytes, kind);
}

Check writeFileAtomically(const std::string& path, std::string_view bytes, std::string_view action)
{
    auto fail = [&](const std::string& what, int error) {
        return makeError("cannot " + std::string(action) + " " + path + ": " + what + ": " + errnoText(error));
    };
    if (path.empty())
        return makeError("cannot " + std::string(action) + " a file without a name");
    const std::string target = resolveTarget(path);
    std::string directory = std::filesystem::path(target).parent_path().string();
    if (directory.empty())
        directory = ".";

    struct stat existing { };
    const bool exists = ::stat(target.c_str(), &existing) == 0;
    if (exists && S_ISDIR(existing.st_mode))
        return fail("the path is a directory", EISDIR);

    std::string tempPath;
    int error = 0;
    FileDescriptor file = createTemporary(target, tempPath, error);
    if (!file.valid())
        return fail("cannot create a temporary file in " + directory, error);

    auto abandon = [&](const std::string& what) {
        const int saved = errno;
        file.reset();
        ::unlink(tempPath.c_str());
        return fail(what, saved);
    };
    // An existing file keeps its permissions (a private scene stays private).
    if (exists && ::fchmod(file.get(), existing.st_mode & 07777) != 0)
        return abandon("cannot set the permissions of " + tempPath);
    if (!writeAll(file.get(), bytes))
        return abandon("cannot write " + tempPath);
    if (::fsync(file.get()) != 0)
        return abandon("cannot flush " + tempPath + " to disk");
    if (file.close() != 0)
        return abandon("cannot write " + tempPath);
    if (::rename(tempPath.c_str(), target.c_str()) != 0)
        return abandon("cannot replace " + target);

    // Make the rename itself durable; a failure here cannot undo the write.
    FileDescriptor dir(::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
    if (dir.valid())
        ::fsync(dir.get());
    return success();
}

} // namespace regio::model
