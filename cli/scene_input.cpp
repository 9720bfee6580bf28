#include "cli/scene_input.h"

#include "cli/commands.h"

#include "model/io/scene_json.h"
#include "model/validation/validation.h"

#include <cerrno>
#include <cstring>
#include <exception>
#include <ostream>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace regio::cli {

namespace {

// Scene files beyond this are refused before reading, as the model does.
constexpr std::size_t kMaxInputBytes = std::size_t{1} << 30;

// Reads a whole file or standard input; on failure returns false with the
// reason. The CLI reads by itself (instead of model::loadSceneFile) to tell an
// unreadable file (exit 2) from a broken one (exit 1).
bool readWholeInput(const std::string& name, std::string& text, std::string& reason)
{
    const bool standardInput = name == "-";
    const int fd = standardInput ? STDIN_FILENO : ::open(name.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) {
        reason = std::string("cannot open: ") + std::strerror(errno);
        return false;
    }
    struct Closer {
        int fd;
        bool owned;
        ~Closer()
        {
            if (owned)
                ::close(fd);
        }
    } closer{fd, !standardInput};

    struct stat info {};
    if (::fstat(fd, &info) != 0) {
        reason = std::string("cannot read: ") + std::strerror(errno);
        return false;
    }
    if (S_ISDIR(info.st_mode)) {
        reason = "is a directory, not a scene file";
        return false;
    }
    char buffer[1 << 16];
    for (;;) {
        const ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n < 0) {
            if (errno == EINTR)
                continue;
            reason = std::string("cannot read: ") + std::strerror(errno);
            return false;
        }
        if (n == 0)
            return true;
        if (text.size() + static_cast<std::size_t>(n) > kMaxInputBytes) {
            reason = "file too large (scene files are limited to 1 GiB)";
            return false;
        }
        text.append(buffer, static_cast<std::size_t>(n));
    }
}

std::string escaped(const std::string& text)
{
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size(); ++i) {
        const auto byte = static_cast<unsigned char>(text[i]);
        std::size_t length = byte < 0x80 ? 1 : (byte >> 5) == 0x6 ? 2 : (byte >> 4) == 0xE ? 3
                                          : (byte >> 3) == 0x1E ? 4 : 0;
        bool valid = length > 0 && i + length <= text.size() && !(length == 1 && (byte < 0x20 || byte == 0x7F));
        for (std::size_t k = 1; valid && k < length; ++k)
            valid = (static_cast<unsigned char>(text[i + k]) & 0xC0) == 0x80;
        if (!valid) {
            static const char* hex = "0123456789ABCDEF";
            out += "\\x";
            out += hex[byte >> 4];
            out += hex[byte & 0xF];
            continue;
        }
        out.append(text, i, length);
        i += length - 1;
    }
    return out;
}

} // namespace

SceneInput readSceneInput(const std::string& name)
{
    SceneInput input;
    input.name = name;
    try {
        std::string text;
        std::string reason;
        if (!readWholeInput(name, text, reason)) {
            input.unreadable = true;
            input.diagnostics.push_back(model::makeError(reason));
            return input;
        }
        model::SceneReadResult read = model::parseScene(text);
        input.diagnostics = std::move(read.diagnostics);
        input.scene = std::move(read.scene);
        if (input.scene) {
            model::Diagnostics validation = model::validateScene(*input.scene);
            input.diagnostics.insert(input.diagnostics.end(),
                                     std::make_move_iterator(validation.begin()),
                                     std::make_move_iterator(validation.end()));
        }
    } catch (const std::bad_alloc&) {
        input.unreadable = true;
        input.diagnostics.push_back(model::makeError("out of memory while reading"));
    }
    return input;
}

int exitCodeOf(const SceneInput& input)
{
    if (input.unreadable)
        return kExitFailure;
    return model::hasErrors(input.diagnostics) ? kExitErrors : kExitOk;
}

std::string formatDiagnostic(const std::string& file, const model::Diagnostic& diagnostic)
{
    std::string out = escaped(file);
    if (diagnostic.line > 0)
        out += ":" + std::to_string(diagnostic.line) + ":" + std::to_string(diagnostic.column);
    if (!diagnostic.pointer.empty())
        out += ": " + escaped(diagnostic.pointer);
    out += diagnostic.isError() ? ": error: " : ": warning: ";
    out += escaped(diagnostic.message);
    return out;
}

void printDiagnostics(std::ostream& out, const SceneInput& input)
{
    const std::string file = input.name == "-" ? "<stdin>" : input.name;
    for (const model::Diagnostic& diagnostic : input.diagnostics)
        out << formatDiagnostic(file, diagnostic) << '\n';
}

} // namespace regio::cli
