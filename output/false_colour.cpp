#include "output/false_colour.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace regio::output {

namespace {

// Viridis (van der Walt and Smith, 2015, CC0), sampled at 33 evenly spaced
// points; linear interpolation between them stays within 2/255 of the
// 256-entry original.
constexpr std::array<std::array<float, 3>, 33> kViridis{{
    {0.2670f, 0.0049f, 0.3294f}, {0.2770f, 0.0502f, 0.3755f}, {0.2823f, 0.0946f, 0.4170f}, {0.2829f, 0.1354f, 0.4530f},
    {0.2789f, 0.1749f, 0.4830f}, {0.2708f, 0.2133f, 0.5066f}, {0.2593f, 0.2507f, 0.5244f}, {0.2454f, 0.2867f, 0.5370f},
    {0.2302f, 0.3213f, 0.5455f}, {0.2148f, 0.3545f, 0.5510f}, {0.2000f, 0.3864f, 0.5545f}, {0.1861f, 0.4173f, 0.5567f},
    {0.1733f, 0.4474f, 0.5579f}, {0.1613f, 0.4770f, 0.5581f}, {0.1497f, 0.5064f, 0.5573f}, {0.1384f, 0.5358f, 0.5551f},
    {0.1281f, 0.5651f, 0.5509f}, {0.1209f, 0.5945f, 0.5442f}, {0.1203f, 0.6238f, 0.5343f}, {0.1310f, 0.6529f, 0.5208f},
    {0.1554f, 0.6815f, 0.5032f}, {0.1930f, 0.7096f, 0.4812f}, {0.2415f, 0.7366f, 0.4545f}, {0.2986f, 0.7624f, 0.4230f},
    {0.3629f, 0.7867f, 0.3866f}, {0.4330f, 0.8091f, 0.3453f}, {0.5081f, 0.8292f, 0.2992f}, {0.5873f, 0.8470f, 0.2489f},
    {0.6694f, 0.8622f, 0.1954f}, {0.7529f, 0.8751f, 0.1427f}, {0.8359f, 0.8861f, 0.1025f}, {0.9166f, 0.8961f, 0.1008f},
    {0.9932f, 0.9062f, 0.1439f},
}};

// Default depth of an automatic logarithmic range: three decades show the
// structure of indirect light without drowning in the shadows' noise.
constexpr double kAutomaticLogDecades = 3.0;

std::string formatTick(double v)
{
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.4g", v);
    return buffer;
}

// 1, 2 or 5 times a power of ten, the smallest not below `x`.
double niceStep(double x)
{
    const double decade = std::pow(10.0, std::floor(std::log10(x)));
    for (double m : {1.0, 2.0, 5.0, 10.0}) {
        if (m * decade >= x * (1.0 - 1e-9))
            return m * decade;
    }
    return 10.0 * decade;
}

} // namespace

FalseColour::FalseColour(FalseColourScale scale, double minimum, double maximum)
    : m_scale(scale)
    , m_min(std::isfinite(minimum) ? minimum : 0.0)
    , m_max(std::isfinite(maximum) ? maximum : 1.0)
{
    if (m_scale == FalseColourScale::Logarithmic) {
        if (!(m_max > 0.0))
            m_max = 1.0;
        if (!(m_min > 0.0))
            m_min = m_max / std::pow(10.0, kAutomaticLogDecades);
        if (!(m_max > m_min))
            m_max = m_min * 10.0;
    } else {
        m_min = std::max(m_min, 0.0);
        if (!(m_max > m_min))
            m_max = m_min > 0.0 ? 2.0 * m_min : 1.0;
    }
}

FalseColour FalseColour::forMesh(const FalseColourSettings& settings, const LitMesh& mesh, const glm::vec3& ambient)
{
    double maxLum = 0.0;
    double minPositive = 0.0;
    for (size_t v = 0; v < mesh.vertexCount(); ++v) {
        const double lum = displayLuminance(mesh.displayRadiosity(v, ambient));
        maxLum = std::max(maxLum, lum);
        if (lum > 0.0 && (minPositive == 0.0 || lum < minPositive))
            minPositive = lum;
    }
    const double max = settings.maximum.value_or(maxLum);
    double min = 0.0;
    if (settings.minimum) {
        min = *settings.minimum;
    } else if (settings.scale == FalseColourScale::Logarithmic) {
        min = std::max(minPositive, max / std::pow(10.0, kAutomaticLogDecades));
    }
    return FalseColour(settings.scale, min, max);
}

double FalseColour::position(double luminance) const
{
    double t = 0.0;
    if (m_scale == FalseColourScale::Logarithmic)
        t = luminance > 0.0 ? std::log(luminance / m_min) / std::log(m_max / m_min) : 0.0;
    else
        t = (luminance - m_min) / (m_max - m_min);
    if (!(t > 0.0))
        return 0.0;
    return std::min(t, 1.0);
}

glm::vec3 FalseColour::ramp(double t)
{
    const double x = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0) * static_cast<double>(kViridis.size() - 1);
    const size_t i = std::min(static_cast<size_t>(x), kViridis.size() - 2);
    const float f = static_cast<float>(x - static_cast<double>(i));
    const auto& a = kViridis[i];
    const auto& b = kViridis[i + 1];
    return {a[0] + (b[0] - a[0]) * f, a[1] + (b[1] - a[1]) * f, a[2] + (b[2] - a[2]) * f};
}

FalseColourLegend FalseColour::legend(int maxTicks) const
{
    FalseColourLegend legend;
    legend.scale = m_scale;
    legend.minimum = m_min;
    legend.maximum = m_max;
    maxTicks = std::max(maxTicks, 2);
    const double tolerance = 1e-9 * (m_max - m_min);
    auto add = [&](double value) {
        if (value < m_min - tolerance || value > m_max + tolerance)
            return;
        legend.ticks.push_back({value, position(value), formatTick(value)});
    };

    if (m_scale == FalseColourScale::Linear) {
        const double step = niceStep((m_max - m_min) / static_cast<double>(maxTicks - 1));
        const double first = std::ceil(m_min / step - 1e-9);
        for (double k = first; k * step <= m_max + tolerance; k += 1.0)
            add(k * step == 0.0 ? 0.0 : k * step);
        return legend;
    }

    // Decades; every n-th when there are too many, 1-2-5 within them when
    // there are too few to read the scale.
    const int lo = static_cast<int>(std::ceil(std::log10(m_min) - 1e-9));
    const int hi = static_cast<int>(std::floor(std::log10(m_max) + 1e-9));
    const int decades = hi - lo + 1;
    if (decades >= 2) {
        const int every = (decades + maxTicks - 1) / maxTicks;
        for (int e = lo; e <= hi; e += every)
            add(std::pow(10.0, e));
        return legend;
    }
    for (int e = lo - 1; e <= hi; ++e) {
        for (double m : {1.0, 2.0, 5.0})
            add(m * std::pow(10.0, e));
    }
    if (static_cast<int>(legend.ticks.size()) > maxTicks || legend.ticks.size() < 2) {
        // A range inside one 1-2-5 interval: fall back to evenly spaced values.
        legend.ticks.clear();
        const int n = std::min(maxTicks, 5);
        for (int i = 0; i < n; ++i) {
            const double value = m_min * std::pow(m_max / m_min, static_cast<double>(i) / (n - 1));
            legend.ticks.push_back({value, position(value), formatTick(value)});
        }
    }
    return legend;
}

DisplayColours falseColours(const LitMesh& mesh, const FalseColour& falseColour, const glm::vec3& ambient,
                            const DisplayEncoding& encoding)
{
    DisplayColours out;
    out.encoding = encoding;
    out.description = std::string("false colour of luminance, ") +
                      (falseColour.scale() == FalseColourScale::Logarithmic ? "logarithmic" : "linear") + " scale, " +
                      formatTick(falseColour.minimum()) + " to " + formatTick(falseColour.maximum()) +
                      " W/m^2, viridis ramp, " + encoding.describe();
    out.linear.reserve(mesh.vertexCount());
    for (size_t v = 0; v < mesh.vertexCount(); ++v)
        out.linear.push_back(encoding.decode(falseColour.colour(displayLuminance(mesh.displayRadiosity(v, ambient)))));
    return out;
}

} // namespace regio::output
