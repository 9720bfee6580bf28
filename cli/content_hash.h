#pragma once
// The SHA-256 of a file's bytes, as lowercase hex: what `sha256sum` prints.
// The batch records it in each report to know a scene it has solved before.
#include <string>
#include <string_view>

namespace regio::cli {

std::string sha256Hex(std::string_view bytes);

} // namespace regio::cli
