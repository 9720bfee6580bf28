// Scene files on disk. Reading refuses what is not a readable regular file;
// writing is atomic so that a crash, a full disk or a refused rename never
// leaves a half-written scene where the user's file was.
#include "model/io/scene_json.h"

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

// A scene of a million faces is about 100 MB of JSON; a bigger file is a
// mistake, and refusing it early beats running out of memory.
constexpr off_t kMaxSceneFileBytes = off_t{1} << 30;

std::string errnoText(int error)
{
    return std::strerror(error);
}

class FileDescriptor {
public:
    explicit FileDescriptor(int fd = -1) : m_fd(fd) {}
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
        if (m_fd >= 0)
            ::close(m_fd);
        m_fd = -1;
    }

private:
    int m_fd;
};

bool writeAll(int fd, const std::string& text)
{
    std::size_t written = 0;
    while (written < text.size()) {
        const ssize_t n = ::write(fd, text.data() + written, text.size() - written);
        if (n < 0) {
            if (errno == EINTR)
                continue;
            return false;
        }
        written += static_cast<std::size_t>(n);
    }
    return true;
}

// Creates `<target>.tmp-XXXXXX` beside the target. Not mkstemp: that creates
// mode 0600, while a new scene should get the usual 0666 & ~umask, which
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

// Saving through a symbolic link replaces the file it points to, not the link.
std::string resolveTarget(const std::string& path)
{
    struct stat info {};
    if (::lstat(path.c_str(), &info) == 0 && S_ISLNK(info.st_mode)) {
        std::error_code ec;
        const std::filesystem::path resolved = std::filesystem::canonical(path, ec);
        if (!ec)
            return resolved.string();
    }
    return path;
}

std::optional<Diagnostic> writeAtomically(const std::string& text, const std::string& path)
{
    const std::string target = resolveTarget(path);
    std::string directory = std::filesystem::path(target).parent_path().string();
    if (directory.empty())
        directory = ".";
    auto fail = [&](const std::string& what, int error) {
        return makeError("cannot save " + path + ": " + what + ": " + errnoText(error));
    };

    struct stat existing {};
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
    // Keep an existing file's permissions (a private scene stays private).
    if (exists && ::fchmod(file.get(), existing.st_mode & 07777) != 0)
        return abandon("cannot set the permissions of " + tempPath);
    if (!writeAll(file.get(), text))
        return abandon("cannot write " + tempPath);
    if (::fsync(file.get()) != 0)
        return abandon("cannot flush " + tempPath + " to disk");
    if (file.close() != 0)
        return abandon("cannot write " + tempPath);
    if (::rename(tempPath.c_str(), target.c_str()) != 0)
        return abandon("cannot replace " + target);

    // Make the rename itself durable; a failure here cannot undo the save.
    FileDescriptor dir(::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
    if (dir.valid())
        ::fsync(dir.get());
    return std::nullopt;
}

} // namespace

SceneReadResult loadSceneFile(const std::string& path)
{
    SceneReadResult result;
    auto fail = [&](std::string message) {
        result.diagnostics.push_back(makeError(std::move(message)));
        return result;
    };
    FileDescriptor file(::open(path.c_str(), O_RDONLY | O_CLOEXEC));
    if (!file.valid())
        return fail("cannot open: " + errnoText(errno));
    struct stat info {};
    if (::fstat(file.get(), &info) != 0)
        return fail("cannot read: " + errnoText(errno));
    if (S_ISDIR(info.st_mode))
        return fail("is a directory, not a scene file");
    if (S_ISREG(info.st_mode) && info.st_size > kMaxSceneFileBytes)
        return fail("file too large (" + std::to_string(info.st_size) +
                    " bytes; scene files are limited to 1 GiB)");

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
                return fail("cannot read: " + errnoText(errno));
            }
            if (n == 0)
                break;
            if (text.size() + static_cast<std::size_t>(n) > static_cast<std::size_t>(kMaxSceneFileBytes))
                return fail("file too large (scene files are limited to 1 GiB)");
            text.append(buffer, static_cast<std::size_t>(n));
        }
    } catch (const std::bad_alloc&) {
        return fail("out of memory while reading the file");
    }
    return parseScene(text);
}

std::optional<Diagnostic> saveSceneFile(const Scene& scene, const std::string& path)
{
    try {
        const std::string text = serializeScene(scene);
        // Whatever Regio saves, Regio must load: a value the reader refuses
        // (a NaN that JSON would turn into null, a reflectance of 1) is refused
        // here, while the user still has the scene in memory.
        const SceneReadResult check = parseScene(text);
        for (const Diagnostic& d : check.diagnostics) {
            if (d.isError())
                return makeError("cannot save " + path + ": the scene would not load back: " +
                                     (d.pointer.empty() ? "" : d.pointer + ": ") + d.message,
                                 d.pointer, d.idPath);
        }
        if (!check.scene || !(*check.scene == scene))
            return makeError("cannot save " + path +
                             ": the scene would not read back unchanged (a name or id that is not "
                             "valid UTF-8?)");
        return writeAtomically(text, path);
    } catch (const std::bad_alloc&) {
        return makeError("cannot save " + path + ": out of memory");
    }
}

} // namespace regio::model
