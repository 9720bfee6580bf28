#include "output/png_writer.h"

#include "model/io/file_io.h"

#include <stb_image_write.h>

namespace regio::output {

namespace {

void appendBytes(void* context, void* data, int size)
{
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<size_t>(size));
}

} // namespace

std::string encodePng(const Image& image)
{
    std::string bytes;
    if (image.width <= 0 || image.height <= 0 ||
        image.rgb.size() != static_cast<size_t>(image.width) * static_cast<size_t>(image.height) * 3)
        return bytes;
    const int ok =
        stbi_write_png_to_func(appendBytes, &bytes, image.width, image.height, 3, image.rgb.data(), image.width * 3);
    if (ok == 0)
        bytes.clear();
    return bytes;
}

model::Check writePng(const std::string& path, const Image& image)
{
    if (image.width <= 0 || image.height <= 0)
        return model::makeError("cannot write " + path + ": the image is empty");
    const std::string bytes = encodePng(image);
    if (bytes.empty())
        return model::makeError("cannot write " + path + ": the PNG encoder failed");
    return model::writeFileAtomically(path, bytes);
}

} // namespace regio::output
