#include "output/legend_overlay.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

// stb_easy_font is a header of static functions; not all of them are used.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#include <stb_easy_font.h>
#pragma GCC diagnostic pop

namespace regio::output {

namespace {

using Colour = std::array<uint8_t, 3>;

void fillRect(Image& image, int x0, int y0, int x1, int y1, const Colour& c)
{
    x0 = std::max(x0, 0);
    y0 = std::max(y0, 0);
    x1 = std::min(x1, image.width);
    y1 = std::min(y1, image.height);
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x)
            image.setPixel(x, y, c);
    }
}

// Darkens a rectangle to a quarter of its brightness: text stays readable
// and the picture still shows through.
void shadeRect(Image& image, int x0, int y0, int x1, int y1)
{
    x0 = std::max(x0, 0);
    y0 = std::max(y0, 0);
    x1 = std::min(x1, image.width);
    y1 = std::min(y1, image.height);
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) {
            Colour c = image.pixel(x, y);
            for (uint8_t& v : c)
                v = static_cast<uint8_t>(v / 4);
            image.setPixel(x, y, c);
        }
    }
}

int textWidth(const std::string& text, int scale)
{
    return stb_easy_font_width(const_cast<char*>(text.c_str())) * scale;
}

int textHeight(int scale) { return stb_easy_font_height(const_cast<char*>("0")) * scale; }

constexpr int kFloatsPerVertex = 4; // x, y, z, packed colour

// stb_easy_font's quads for `text`, four vertices each. It stops writing when
// the buffer is full, silently: a glyph takes up to a dozen quads of 64
// bytes ('0' with its slash, after a '5', lost its right stroke in a buffer
// of 300 bytes a character), so the buffer is sized for sixteen.
std::vector<float> textQuads(const std::string& text, int& quads)
{
    constexpr size_t kBytesPerQuad = 4 * kFloatsPerVertex * sizeof(float);
    std::vector<float> buffer((text.size() * 16 + 1) * kBytesPerQuad / sizeof(float));
    quads = stb_easy_font_print(0.0f, 0.0f, const_cast<char*>(text.c_str()), nullptr, buffer.data(),
                                static_cast<int>(buffer.size() * sizeof(float)));
    return buffer;
}

// stb_easy_font turns text into axis-aligned quads; draw them scaled.
void drawText(Image& image, int x, int y, const std::string& text, int scale, const Colour& colour)
{
    int quads = 0;
    const std::vector<float> buffer = textQuads(text, quads);
    const float* v = buffer.data();
    for (int q = 0; q < quads; ++q) {
        const float* quad = v + q * 4 * kFloatsPerVertex;
        const float qx0 = quad[0], qy0 = quad[1];
        const float qx1 = quad[2 * kFloatsPerVertex], qy1 = quad[2 * kFloatsPerVertex + 1];
        fillRect(image, x + static_cast<int>(std::lround(std::min(qx0, qx1) * static_cast<float>(scale))),
                 y + static_cast<int>(std::lround(std::min(qy0, qy1) * static_cast<float>(scale))),
                 x + static_cast<int>(std::lround(std::max(qx0, qx1) * static_cast<float>(scale))),
                 y + static_cast<int>(std::lround(std::max(qy0, qy1) * static_cast<float>(scale))), colour);
    }
}

} // namespace

int legendTextQuads(const std::string& text)
{
    int quads = 0;
    textQuads(text, quads);
    return quads;
}

LegendBox drawLegend(Image& image, const FalseColourLegend& legend)
{
    LegendBox box;
    if (image.width < 120 || image.height < 80)
        return box;
    const Colour white{235, 235, 235};
    const int scale = std::max(1, static_cast<int>(std::lround(image.height / 250.0)));
    const int margin = std::max(6, image.width / 100);
    const int lineHeight = textHeight(scale);

    const std::string title = legend.quantity;
    const std::string unit =
        legend.unit + (legend.scale == FalseColourScale::Logarithmic ? ", log scale" : ", linear scale");
    int labelWidth = 0;
    for (const LegendTick& t : legend.ticks)
        labelWidth = std::max(labelWidth, textWidth(t.label, scale));
    box.barWidth = std::max(8, image.width / 50);
    const int tickLength = std::max(3, box.barWidth / 2);
    const int columnWidth = box.barWidth + tickLength + margin / 2 + labelWidth;
    const int headerWidth = std::max(textWidth(title, scale), textWidth(unit, scale));
    const int contentWidth = std::max(columnWidth, headerWidth);

    box.width = contentWidth + 2 * margin;
    box.x = image.width - margin - box.width;
    box.barX = box.x + margin;
    box.barTop = std::max(image.height / 5, 2 * margin + 2 * lineHeight + margin);
    box.barBottom = image.height - image.height / 5;
    box.y = box.barTop - 2 * lineHeight - 2 * margin;
    box.height = box.barBottom + lineHeight / 2 + margin - box.y;
    if (box.x < 0 || box.barBottom - box.barTop < 2 * lineHeight)
        return LegendBox{};

    shadeRect(image, box.x, box.y, box.x + box.width, box.y + box.height);
    drawText(image, box.x + margin, box.y + margin, title, scale, white);
    drawText(image, box.x + margin, box.y + margin + lineHeight, unit, scale, white);

    // The ramp, maximum at the top.
    const int span = box.barBottom - box.barTop;
    for (int y = box.barTop; y < box.barBottom; ++y) {
        const double t = 1.0 - (y + 0.5 - box.barTop) / span;
        fillRect(image, box.barX, y, box.barX + box.barWidth, y + 1, toBytes(FalseColour::ramp(t)));
    }
    for (const LegendTick& tick : legend.ticks) {
        const int y = box.barBottom - static_cast<int>(std::lround(tick.position * span));
        const int x = box.barX + box.barWidth;
        const int half = std::max(1, scale) / 2;
        fillRect(image, x, y - half, x + tickLength, y - half + std::max(1, scale), white);
        drawText(image, x + tickLength + margin / 2, y - lineHeight / 2, tick.label, scale, white);
    }
    return box;
}

} // namespace regio::output
