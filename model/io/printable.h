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

// The length (1 to 4) of the valid UTF-8 sequence that starts at text[i]
// (no overlong form, no surrogate, nothing above U+10FFFF), 0 if none does.
std::size_t utf8SequenceLength(std::string_view text, std::size_t i);

// `text` as valid UTF-8 for a name that is stored: every byte that starts
// no valid sequence becomes U+FFFD, a control character a space (old model
// formats store names in whatever code page their tool used).
std::string validUtf8(std::string_view text);

} // namespace regio::model
