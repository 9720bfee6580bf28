#pragma once
// False colour for analysis: the luminance of the displayed radiosity mapped
// through a perceptually uniform ramp (viridis: dark blue - teal - green -
// yellow, monotone in lightness, readable by colour-blind viewers and in grey
// print), on a linear or logarithmic scale, with a legend given as data (range
// and labelled ticks) that the editor and the image writer draw themselves.
// Like tone mapping it is a display value only (tone_map.h).
#include "output/lit_mesh.h"
#include "output/tone_map.h"

#include <glm/vec3.hpp>

#include <optional>
#include <string>
#include <vector>

namespace regio::output {

enum class FalseColourScale { Linear, Logarithmic };

struct FalseColourSettings {
    FalseColourScale scale = FalseColourScale::Logarithmic;
    // Luminance (W/m^2) at the ends of the ramp; empty = from the data:
    // linear [0, max], logarithmic [max / 1000 or the darkest lit value if
    // brighter, max]. Values outside the range take the end colours.
    std::optional<double> minimum;
    std::optional<double> maximum;
};

struct LegendTick {
    double value = 0.0;    // luminance, W/m^2
    double position = 0.0; // along the ramp: 0 = minimum, 1 = maximum
    std::string label;     // e.g. "0.5", "20", "1e+03"
};

struct FalseColourLegend {
    std::string quantity = "luminance";
    std::string unit = "W/m^2";
    FalseColourScale scale = FalseColourScale::Logarithmic;
    double minimum = 0.0;
    double maximum = 1.0;
    std::vector<LegendTick> ticks; // ascending; round values (1-2-5 steps, or decades) inside the range
};

class FalseColour {
public:
    // A logarithmic scale needs 0 < minimum; bad ranges are repaired (a
    // minimum of 0 on a log scale becomes maximum / 1000, an empty range is
    // widened) rather than refused: a picture is always possible.
    FalseColour(FalseColourScale scale, double minimum, double maximum);
    static FalseColour forMesh(const FalseColourSettings& settings, const LitMesh& mesh, const glm::vec3& ambient);

    FalseColourScale scale() const { return m_scale; }
    double minimum() const { return m_min; }
    double maximum() const { return m_max; }

    // Position of a luminance along the ramp, clamped to [0,1].
    double position(double luminance) const;
    // The ramp colour (display-encoded, sRGB-like) of a luminance.
    glm::vec3 colour(double luminance) const { return ramp(position(luminance)); }
    // The ramp itself, t in [0,1] (clamped): display-encoded colours.
    static glm::vec3 ramp(double t);

    // Range and ticks: at most `maxTicks` labelled round values.
    FalseColourLegend legend(int maxTicks = 7) const;

private:
    FalseColourScale m_scale;
    double m_min;
    double m_max;
};

// Per-vertex false colours. The ramp colours are display values: they are
// decoded with `encoding` into linear values so that encoding them again
// (the renderer, the 8-bit writers) gives back the ramp colour exactly.
DisplayColours falseColours(const LitMesh& mesh, const FalseColour& falseColour, const glm::vec3& ambient,
                            const DisplayEncoding& encoding);

} // namespace regio::output
