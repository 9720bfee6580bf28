#pragma once
// A number given on the command line: the whole text must be one, as a
// stream reads it (no "nan" or "inf", nothing after it).
#include <sstream>
#include <string>

namespace regio::cli {

template <typename T>
bool parseNumber(const std::string& text, T& value)
{
    std::istringstream in(text);
    in >> value;
    return in && in.peek() == std::char_traits<char>::eof();
}

} // namespace regio::cli
