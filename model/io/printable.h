#pragma once
// Text from a file or a command line shown back to a person (diagnostics,
// messages): invalid UTF-8 and control characters become \xNN escapes, so a
// hostile file cannot garble a terminal or a log, and whatever is valid
// stays readable.
#include <cstddef>
#include <string>
#include <string_view>

namespace regio::model {

// `text` with every byte that is not part of printable UTF-8 written as
// \xNN. Past `maxBytes` of output the rest is cut and "..." appended.
std::string printable(std::string_view text, std::size_t maxBytes = std::string::npos);

} // namespace regio::model
