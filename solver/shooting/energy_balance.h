#pragma once
// The energy books of progressive shooting (watts = W/m^2 x m^2, per
// channel), kept exact: emitted = absorbed + unshot + escaped.
#include "model/types.h"

namespace regio::solver {

using model::Rgb;

struct EnergyBalance {
    Rgb emitted{0.0};
    Rgb absorbed{0.0};
    Rgb unshot{0.0};
    Rgb escaped{0.0};
    // Sum of the magnitudes of the elements' unshot power: `unshot` itself
    // unless overrelaxation left some of it negative.
    Rgb unshotMagnitude{0.0};
};

// Rec. 709 luminance weights: "most unshot power", the ambient term and the
// subdivision criterion are judged by brightness, not by one channel.
double luminance(const Rgb& c);

} // namespace regio::solver
