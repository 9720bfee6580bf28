#pragma once
// Every file Regio reads whole or writes goes through here.
//
// Writing is atomic: the bytes go to a temporary file beside the target,
// are flushed to disk, and the temporary replaces the target by rename(),
// after which the directory is flushed too. A crash, a full disk or a refused
// rename leaves any previous file untouched, and a reader never sees half a
// file. A new file gets the usual permissions (0666 less the umask); an
// existing one keeps its own; writing through a symbolic link replaces the
// file it points to and keeps the link.
//
// Reading takes the whole file, refusing directories and anything larger
// than a limit before it runs out of memory.
#include "model/result.h"

#include <cstdint>
#include <string>
#include <string_view>

namespace regio::model {

// A scene of a million faces is about 100 MB of JSON; a bigger file is a
// mistake, and refusing it early beats running out of memory.
inline constexpr std::uint64_t kMaxSceneFileBytes = std::uint64_t{1} << 30;

// Reads the file at `path`. Errors: "cannot open: <reason>", "cannot read:
// <reason>", "is a directory, not a <kind>", "file too large (...)". Out of
// memory is an error too, never an exception.
Result<std::string> readFile(const std::string& path, std::uint64_t maxBytes = kMaxSceneFileBytes,
                             std::string_view kind = "scene file");

// The same for standard input.
Result<std::string> readStandardInput(std::uint64_t maxBytes = kMaxSceneFileBytes,
                                      std::string_view kind = "scene file");

// Writes `bytes` to `path` atomically. The error reads "cannot <action>
// <path>: <what failed>: <reason>" ("cannot save scene.json: cannot flush
// scene.json.tmp-x1Y2z3 to disk: No space left on device").
Check writeFileAtomically(const std::string& path, std::string_view bytes, std::string_view action = "write");

} // namespace regio::model
