#pragma once
// PNG output of software images through stb_image_write (Debian's libstb-dev),
// written atomically; errors name the path.
#include "output/software_render.h"

#include <optional>
#include <string>

namespace regio::output {

// The PNG file's bytes (8-bit RGB, no interlace); empty for an empty image.
std::string encodePng(const Image& image);

model::Check writePng(const std::string& path, const Image& image);

} // namespace regio::output
