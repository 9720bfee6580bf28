#pragma once
// JSON pointers (RFC 6901) into the scene file. Diagnostics name the value at
// fault this way; positions in the model equal positions in the file, so the
// same pointer serves the reader, validation, the edit functions, the solver,
// the command line and the editor.
#include <cstddef>
#include <string>
#include <string_view>

namespace regio::model {

// Appends "/" + token, escaping "~" and "/".
std::string appendPointer(const std::string& pointer, std::string_view token);
std::string appendPointer(const std::string& pointer, std::size_t index);

// The elements of a scene file, by index.
std::string materialPointer(std::size_t material);
std::string objectPointer(std::size_t object);
std::string partPointer(std::size_t object, std::size_t part);
std::string facePointer(std::size_t object, std::size_t part, std::size_t face);
std::string regionPointer(std::size_t region);

} // namespace regio::model
