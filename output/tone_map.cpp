#include "output/tone_map.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

namespace regio::output {

namespace {

constexpr double kAutomaticWhiteFraction = 0.95;

float srgbEncode(float c) { return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f; }

float srgbDecode(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

std::string formatNumber(double v)
{
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.6g", v);
    return buffer;
}

} // namespace

float displayLuminance(const glm::vec3& c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

float DisplayEncoding::encode(float linear) const
{
    const float c = std::max(linear, 0.0f);
    switch (transfer) {
    case Transfer::Srgb: return srgbEncode(c);
    case Transfer::Linear: return c;
    case Transfer::Gamma: break;
    }
    return gamma > 0.0 ? std::pow(c, static_cast<float>(1.0 / gamma)) : c;
}

float DisplayEncoding::decode(float encoded) const
{
    const float c = std::max(encoded, 0.0f);
    switch (transfer) {
    case Transfer::Srgb: return srgbDecode(c);
    case Transfer::Linear: return c;
    case Transfer::Gamma: break;
    }
    return gamma > 0.0 ? std::pow(c, static_cast<float>(gamma)) : c;
}

glm::vec3 DisplayEncoding::encode(const glm::vec3& linear) const
{
    return {encode(linear.x), encode(linear.y), encode(linear.z)};
}

glm::vec3 DisplayEncoding::decode(const glm::vec3& encoded) const
{
    return {decode(encoded.x), decode(encoded.y), decode(encoded.z)};
}

std::string DisplayEncoding::describe() const
{
    switch (transfer) {
    case Transfer::Srgb: return "sRGB";
    case Transfer::Linear: return "linear";
    case Transfer::Gamma: break;
    }
    return "gamma " + formatNumber(gamma);
}

double automaticWhiteReference(const LitMesh& mesh, const glm::vec3& ambient)
{
    // (luminance, area) per triangle, then the area-weighted quantile.
    std::vector<std::pair<double, double>> samples;
    samples.reserve(mesh.triangleCount());
    double totalArea = 0.0;
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        const uint32_t a = mesh.indices[3 * t], b = mesh.indices[3 * t + 1], c = mesh.indices[3 * t + 2];
        const double area =
            0.5 * glm::length(glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]));
        if (!(area > 0.0))
            continue;
        const double lum =
            (displayLuminance(mesh.displayRadiosity(a, ambient)) + displayLuminance(mesh.displayRadiosity(b, ambient)) +
             displayLuminance(mesh.displayRadiosity(c, ambient))) /
            3.0;
        samples.emplace_back(lum, area);
        totalArea += area;
    }
    if (samples.empty())
        return 1.0;
    std::sort(samples.begin(), samples.end());
    const double wanted = kAutomaticWhiteFraction * totalArea;
    double cumulative = 0.0;
    double white = samples.back().first;
    for (const auto& [lum, area] : samples) {
        cumulative += area;
        if (cumulative >= wanted) {
            white = lum;
            break;
        }
    }
    // All but a few percent dark (a lamp in a black room): fall back to the
    // brightest surface rather than to nothing.
    if (!(white > 0.0))
        white = samples.back().first;
    return white > 0.0 ? white : 1.0;
}

ToneMap::ToneMap(const ToneMapSettings& settings, double whiteReference)
    : m_settings(settings)
    , m_white(whiteReference > 0.0 && std::isfinite(whiteReference) ? whiteReference : 1.0)
{
    m_scale = std::exp2(m_settings.exposure) / m_white;
}

ToneMap ToneMap::forMesh(const ToneMapSettings& settings, const LitMesh& mesh)
{
    const double white =
        settings.whiteReference ? *settings.whiteReference : automaticWhiteReference(mesh, settings.ambient);
    return ToneMap(settings, white);
}

glm::vec3 ToneMap::linear(const glm::vec3& radiosity) const
{
    glm::vec3 v = glm::max(radiosity * static_cast<float>(m_scale), glm::vec3(0.0f));
    if (m_settings.clamp)
        v = glm::min(v, glm::vec3(1.0f));
    return v;
}

std::string ToneMap::describe() const
{
    std::string s = "exposure " + formatNumber(m_settings.exposure) + " stops, white " + formatNumber(m_white) +
                    " W/m^2" + (m_settings.whiteReference ? "" : " (automatic)") + ", " +
                    m_settings.encoding.describe();
    if (m_settings.ambient != glm::vec3(0.0f))
        s += ", ambient " + formatNumber(m_settings.ambient.x) + " " + formatNumber(m_settings.ambient.y) + " " +
             formatNumber(m_settings.ambient.z) + " W/m^2";
    return s;
}

DisplayColours toneMappedColours(const LitMesh& mesh, const ToneMap& toneMap)
{
    DisplayColours out;
    out.encoding = toneMap.settings().encoding;
    out.description = "tone-mapped radiosity: " + toneMap.describe();
    out.linear.reserve(mesh.vertexCount());
    const glm::vec3 ambient = toneMap.settings().ambient;
    for (size_t v = 0; v < mesh.vertexCount(); ++v)
        out.linear.push_back(toneMap.linear(mesh.displayRadiosity(v, ambient)));
    return out;
}

uint8_t toByte(float encoded)
{
    if (!(encoded > 0.0f))
        return 0;
    if (encoded >= 1.0f)
        return 255;
    return static_cast<uint8_t>(std::lround(encoded * 255.0f));
}

std::array<uint8_t, 3> toBytes(const glm::vec3& encoded)
{
    return {toByte(encoded.x), toByte(encoded.y), toByte(encoded.z)};
}

} // namespace regio::output
