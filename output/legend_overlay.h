#pragma once
// Draws a false-colour legend into a software image: the ramp as a vertical
// bar on the right, labelled ticks beside it and the quantity and unit above,
// on a darkened panel so it reads on any picture. Text comes from
// stb_easy_font (Debian's libstb-dev), scaled to the image size.
#include "output/false_colour.h"
#include "output/software_render.h"

#include <string>

namespace regio::output {

// The part of the image the legend covers (for tests and callers that want
// to keep something else clear of it).
struct LegendBox {
    int x = 0, y = 0, width = 0, height = 0;
    // The ramp bar inside it: y of the maximum (top) and of the minimum (bottom).
    int barX = 0, barWidth = 0, barTop = 0, barBottom = 0;
};

// The ramp's colours are display values and go into the image as they are,
// the same bytes the model's false colours get. An image too small to hold a
// readable legend (under 120 x 80 pixels) is left alone (empty box).
LegendBox drawLegend(Image& image, const FalseColourLegend& legend);

// How many quads the legend's text is drawn with (all of them, however long
// the text: tests).
int legendTextQuads(const std::string& text);

} // namespace regio::output
