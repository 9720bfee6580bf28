#pragma once
// Atomic file output for the solver's exports and images: the bytes go to a
// temporary file beside the target, are flushed, and the temporary replaces
// the target by rename(). A crash, a full disk or a refused rename leaves any
// previous file untouched, and a reader never sees a half-written file.
#include <optional>
#include <string>
#include <string_view>

namespace regio::model {

// Writes `bytes` to `path` atomically. Returns an error message that names
// the path and the reason, or nothing on success.
std::optional<std::string> writeFileAtomically(const std::string& path, std::string_view bytes);

} // namespace regio::model
