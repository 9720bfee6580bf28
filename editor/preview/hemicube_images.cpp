#include "editor/preview/hemicube_images.h"

#include <algorithm>
#include <cmath>

namespace regio::editor {

std::uint32_t elementColour(int element)
{
    // Golden-ratio hue steps with a hashed lightness: adjacent ids differ.
    std::uint32_t h = static_cast<std::uint32_t>(element) * 2654435761u;
    const double hue = std::fmod(element * 0.6180339887498949, 1.0) * 6.0;
    const double value = 0.65 + 0.35 * ((h >> 16) & 0xff) / 255.0;
    const double saturation = 0.55 + 0.4 * ((h >> 8) & 0xff) / 255.0;
    const int sector = static_cast<int>(hue) % 6;
    const double f = hue - std::floor(hue);
    const double p = value * (1 - saturation), q = value * (1 - saturation * f), t = value * (1 - saturation * (1 - f));
    double r = value, g = t, b = p;
    switch (sector) {
    case 1:
        r = q;
        g = value;
        b = p;
        break;
    case 2:
        r = p;
        g = value;
        b = t;
        break;
    case 3:
        r = p;
        g = q;
        b = value;
        break;
    case 4:
        r = t;
        g = p;
        b = value;
        break;
    case 5:
        r = value;
        g = p;
        b = q;
        break;
    default: break;
    }
    auto byte = [](double x) { return static_cast<std::uint32_t>(std::lround(std::clamp(x, 0.0, 1.0) * 255.0)); };
    return 0xff000000u | (byte(r) << 16) | (byte(g) << 8) | byte(b);
}

HemicubeImages hemicubeImages(const solver::HemicubeView& view, const solver::PreparedScene& scene)
{
    using solver::HemicubeFace;
    HemicubeImages out;
    out.patch = view.patch;
    out.resolution = view.buffer.resolution();
    const solver::Patch& patch = scene.patches[static_cast<size_t>(view.patch)];
    out.faceId = scene.faces[static_cast<size_t>(scene.properties[static_cast<size_t>(patch.properties)].face)].id;
    out.escaped = view.escaped;
    out.blocked = view.blocked;
    for (double f : view.formFactors)
        out.elementsSeen += f > 0.0 ? 1 : 0;
    for (int fi = 0; fi < solver::kHemicubeFaceCount; ++fi) {
        const auto face = static_cast<HemicubeFace>(fi);
        HemicubeFaceImage& image = out.faces[static_cast<size_t>(fi)];
        image.width = view.buffer.width(face);
        image.height = view.buffer.height(face);
        image.argb.resize(size_t(image.width) * size_t(image.height));
        image.element.resize(image.argb.size());
        for (int y = 0; y < image.height; ++y) {
            // Row 0 of the buffer is the bottom (lowest y or height): pictures start at the top.
            const size_t row = size_t(image.height - 1 - y) * size_t(image.width);
            for (int x = 0; x < image.width; ++x) {
                const solver::ItemId id = view.buffer.at(face, x, y);
                int element = -1;
                std::uint32_t colour = 0xff000000u;
                if (id == solver::kBlockerItem) {
                    element = -2;
                    colour = 0xff404040u;
                } else if (id >= solver::kFirstElementItem) {
                    element = static_cast<int>(id - solver::kFirstElementItem);
                    colour = elementColour(element);
                }
                image.argb[row + size_t(x)] = colour;
                image.element[row + size_t(x)] = element;
            }
        }
    }
    return out;
}

} // namespace regio::editor
