#include "importer/isolated_read.h"

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <type_traits>

namespace regio::importer {

namespace {

// What the child writes: the result, field by field, in the machine's own
// byte order (the reader is the same program on the same machine).
class Writer {
public:
    template <typename T>
    void pod(const T& value)
    {
        static_assert(std::is_trivially_copyable_v<T>);
        m_bytes.append(reinterpret_cast<const char*>(&value), sizeof value);
    }
    void text(const std::string& s)
    {
        pod(std::uint64_t{s.size()});
        m_bytes += s;
    }
    const std::string& bytes() const { return m_bytes; }

private:
    std::string m_bytes;
};

class Reader {
public:
    explicit Reader(const std::string& bytes)
        : m_bytes(bytes)
    {
    }
    template <typename T>
    bool pod(T& value)
    {
        if (m_bytes.size() - m_at < sizeof value)
            return false;
        std::memcpy(&value, m_bytes.data() + m_at, sizeof value);
        m_at += sizeof value;
        return true;
    }
    bool text(std::string& s)
    {
        std::uint64_t n = 0;
        if (!pod(n) || m_bytes.size() - m_at < n)
            return false;
        s.assign(m_bytes.data() + m_at, n);
        m_at += n;
        return true;
    }
    // A count of items of at least `itemBytes` each that the rest can hold.
    bool count(std::uint64_t& n, std::size_t itemBytes) { return pod(n) && n <= (m_bytes.size() - m_at) / itemBytes; }
    bool done() const { return m_at == m_bytes.size(); }

private:
    const std::string& m_bytes;
    std::size_t m_at = 0;
};

void writeDiagnostics(Writer& w, const model::Diagnostics& diagnostics)
{
    w.pod(std::uint64_t{diagnostics.size()});
    for (const model::Diagnostic& d : diagnostics) {
        w.pod(d.severity);
        w.text(d.message);
        w.text(d.pointer);
        w.pod(std::uint64_t{d.idPath.size()});
        for (const std::string& id : d.idPath)
            w.text(id);
        w.pod(d.line);
        w.pod(d.column);
    }
}

bool readDiagnostics(Reader& r, model::Diagnostics& out)
{
    std::uint64_t n = 0;
    if (!r.count(n, 8))
        return false;
    for (std::uint64_t i = 0; i < n; ++i) {
        model::Diagnostic d;
        std::uint64_t ids = 0;
        if (!r.pod(d.severity) || !r.text(d.message) || !r.text(d.pointer) || !r.count(ids, 8))
            return false;
        d.idPath.resize(ids);
        for (std::string& id : d.idPath)
            if (!r.text(id))
                return false;
        if (!r.pod(d.line) || !r.pod(d.column))
            return false;
        out.push_back(std::move(d));
    }
    return true;
}

std::string serialize(const model::Result<ReadModel>& result)
{
    Writer w;
    w.pod(static_cast<std::uint8_t>(result.ok() ? 1 : 0));
    writeDiagnostics(w, result.diagnostics());
    if (!result.ok())
        return w.bytes();
    const ReadModel& m = *result;
    w.pod(std::uint64_t{m.counts.meshes});
    w.pod(std::uint64_t{m.counts.pointsAndLines});
    w.pod(std::uint64_t{m.soup.positions.size()});
    for (const Vec3& p : m.soup.positions)
        w.pod(p);
    w.pod(std::uint64_t{m.soup.triangles.size()});
    for (const SoupTriangle& t : m.soup.triangles)
        w.pod(t);
    w.pod(std::uint64_t{m.soup.materials.size()});
    for (const SoupMaterial& material : m.soup.materials) {
        w.text(material.name);
        w.pod(material.diffuse);
        w.pod(material.emission);
        w.pod(material.textured);
    }
    w.pod(std::uint64_t{m.soup.meshes.size()});
    for (const SoupMesh& mesh : m.soup.meshes) {
        w.text(mesh.name);
        w.pod(mesh.object);
    }
    return w.bytes();
}

std::optional<model::Result<ReadModel>> deserialize(const std::string& bytes)
{
    Reader r(bytes);
    std::uint8_t ok = 0;
    model::Diagnostics diagnostics;
    if (!r.pod(ok) || !readDiagnostics(r, diagnostics))
        return std::nullopt;
    if (ok == 0) {
        if (!model::hasErrors(diagnostics) || !r.done())
            return std::nullopt;
        return model::Result<ReadModel>(std::move(diagnostics));
    }
    ReadModel m;
    std::uint64_t meshes = 0, pointsAndLines = 0, n = 0;
    if (!r.pod(meshes) || !r.pod(pointsAndLines))
        return std::nullopt;
    m.counts.meshes = meshes;
    m.counts.pointsAndLines = pointsAndLines;
    if (!r.count(n, sizeof(Vec3)))
        return std::nullopt;
    m.soup.positions.resize(n);
    for (Vec3& p : m.soup.positions)
        r.pod(p);
    if (!r.count(n, sizeof(SoupTriangle)))
        return std::nullopt;
    m.soup.triangles.resize(n);
    for (SoupTriangle& t : m.soup.triangles)
        r.pod(t);
    if (!r.count(n, 8))
        return std::nullopt;
    m.soup.materials.resize(n);
    for (SoupMaterial& material : m.soup.materials)
        if (!r.text(material.name) || !r.pod(material.diffuse) || !r.pod(material.emission) ||
            !r.pod(material.textured))
            return std::nullopt;
    if (!r.count(n, 8))
        return std::nullopt;
    m.soup.meshes.resize(n);
    for (SoupMesh& mesh : m.soup.meshes)
        if (!r.text(mesh.name) || !r.pod(mesh.object))
            return std::nullopt;
    if (!r.done())
        return std::nullopt;
    // Indices from the other side are checked as if they came from a file.
    for (const SoupTriangle& t : m.soup.triangles) {
        for (const int c : t.corners)
            if (c < 0 || std::size_t(c) >= m.soup.positions.size())
                return std::nullopt;
        if (t.material < 0 || std::size_t(t.material) >= m.soup.materials.size() || t.mesh < 0 ||
            std::size_t(t.mesh) >= m.soup.meshes.size())
            return std::nullopt;
    }
    return model::Result<ReadModel>(std::move(m), std::move(diagnostics));
}

bool writeAll(int fd, const std::string& bytes)
{
    std::size_t at = 0;
    while (at < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + at, bytes.size() - at);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return false;
        at += std::size_t(n);
    }
    return true;
}

} // namespace

model::Result<ReadModel> readModelFileIsolated(const std::string& path, const ReadOptions& options, int timeoutSeconds,
                                               void (*inChild)())
{
    int fds[2];
    if (::pipe(fds) != 0)
        return model::makeError("'" + path + "' could not be read: no pipe for the model reader (" +
                                std::strerror(errno) + ")");
    const pid_t child = ::fork();
    if (child < 0) {
        ::close(fds[0]);
        ::close(fds[1]);
        return model::makeError("'" + path + "' could not be read: no process for the model reader (" +
                                std::strerror(errno) + ")");
    }
    if (child == 0) {
        // The child: read, hand the result over, and leave without running
        // the parent's atexit handlers or flushing its buffers twice.
        ::close(fds[0]);
        if (inChild)
            inChild();
        std::string bytes;
        try {
            bytes = serialize(readModelFile(path, options));
        } catch (const std::bad_alloc&) {
            bytes = serialize(model::Result<ReadModel>(model::makeError(
                "'" + path + "' could not be read: it asks for more memory than there is (a broken file?)")));
        }
        ::_exit(writeAll(fds[1], bytes) ? 0 : 1);
    }

    ::close(fds[1]);
    std::string bytes;
    bool timedOut = false;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(timeoutSeconds);
    for (;;) {
        const auto left =
            std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) {
            timedOut = true;
            break;
        }
        pollfd p{fds[0], POLLIN, 0};
        const int ready = ::poll(&p, 1, int(std::min<long long>(left.count(), 1000)));
        if (ready < 0 && errno == EINTR)
            continue;
        if (ready <= 0)
            continue;
        char buffer[65536];
        const ssize_t n = ::read(fds[0], buffer, sizeof buffer);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            break; // the child closed its end: done or dead
        bytes.append(buffer, std::size_t(n));
    }
    ::close(fds[0]);
    if (timedOut)
        ::kill(child, SIGKILL);
    int status = 0;
    while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
    }
    if (timedOut)
        return model::makeError("'" + path + "' could not be read: the model reader (Assimp) did not finish in " +
                                std::to_string(timeoutSeconds) + " s");
    if (WIFSIGNALED(status))
        return model::makeError("'" + path + "' could not be read: the model reader (Assimp) crashed on it (" +
                                std::string(::strsignal(WTERMSIG(status))) +
                                "); the file is broken, or of a kind "
                                "Assimp mishandles");
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        return model::makeError("'" + path + "' could not be read: the model reader (Assimp) stopped with status " +
                                std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1));
    std::optional<model::Result<ReadModel>> result = deserialize(bytes);
    if (!result)
        return model::makeError("'" + path + "' could not be read: the model reader's answer was garbled");
    return std::move(*result);
}

} // namespace regio::importer
