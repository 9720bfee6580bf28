#pragma once
// JSON pointers (RFC 6901) into the scene file. Diagnostics name the value at
// fault this way; positions in the model equal positions in the file, so the
// same pointer serves the reader, validation, the edit functions, the solver,
// the command line and the editor.
#include <concepts>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace regio::model {

// The tokens of a pointer, "~1" and "~0" unescaped ("/a~1b/0" -> "a/b", "0").
std::vector<std::string> pointerTokens(std::string_view pointer);

// Appends "/" + token, escaping "~" and "/".
std::string appendPointer(const std::string& pointer, std::string_view token);
std::string appendPointer(const std::string& pointer, std::size_t index);

// The elements of a scene file, by index (size_t or int: the edit functions
// count in int; an index is never negative).
template <std::integral I>
std::string materialPointer(I material)
{
    return appendPointer("/materials", static_cast<std::size_t>(material));
}
template <std::integral I>
std::string objectPointer(I object)
{
    return appendPointer("/objects", static_cast<std::size_t>(object));
}
template <std::integral I, std::integral J>
std::string partPointer(I object, J part)
{
    return appendPointer(objectPointer(object) + "/parts", static_cast<std::size_t>(part));
}
template <std::integral I, std::integral J, std::integral K>
std::string facePointer(I object, J part, K face)
{
    return appendPointer(partPointer(object, part) + "/faces", static_cast<std::size_t>(face));
}
template <std::integral I>
std::string regionPointer(I region)
{
    return appendPointer("/regions", static_cast<std::size_t>(region));
}

} // namespace regio::model
