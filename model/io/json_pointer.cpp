#include "model/io/json_pointer.h"

#include <algorithm>

namespace regio::model {

std::string appendPointer(const std::string& pointer, std::string_view token)
{
    std::string out = pointer;
    out += '/';
    for (char c : token) {
        if (c == '~')
            out += "~0";
        else if (c == '/')
            out += "~1";
        else
            out += c;
    }
    return out;
}

std::vector<std::string> pointerTokens(std::string_view pointer)
{
    std::vector<std::string> tokens;
    for (std::size_t start = 1; start <= pointer.size();) {
        const std::size_t slash = std::min(pointer.find('/', start), pointer.size());
        std::string token(pointer.substr(start, slash - start));
        for (std::size_t at = 0; (at = token.find('~', at)) != std::string::npos; ++at)
            token.replace(at, 2, token.compare(at, 2, "~1") == 0 ? "/" : "~");
        tokens.push_back(std::move(token));
        start = slash + 1;
    }
    return tokens;
}

std::string appendPointer(const std::string& pointer, std::size_t index)
{
    return pointer + '/' + std::to_string(index);
}

} // namespace regio::model
