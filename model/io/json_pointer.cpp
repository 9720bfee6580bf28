#include "model/io/json_pointer.h"

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

std::string appendPointer(const std::string& pointer, std::size_t index)
{
    return pointer + '/' + std::to_string(index);
}

std::string materialPointer(std::size_t material) { return appendPointer("/materials", material); }
std::string objectPointer(std::size_t object) { return appendPointer("/objects", object); }
std::string partPointer(std::size_t object, std::size_t part)
{
    return appendPointer(objectPointer(object) + "/parts", part);
}
std::string facePointer(std::size_t object, std::size_t part, std::size_t face)
{
    return appendPointer(partPointer(object, part) + "/faces", face);
}
std::string regionPointer(std::size_t region) { return appendPointer("/regions", region); }

} // namespace regio::model
