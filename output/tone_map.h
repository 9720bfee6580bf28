#pragma once
// Display values of a solution (paper §6 "Scene rendering"; the last step of the pipeline):
// exposure and gamma tone mapping, applied when a solution is shown or
// exported, never to the solution itself.
//
//   linear  = (B + rho * ambient) * 2^exposure / white        (clamped to [0,1])
//   encoded = linear^(1/gamma), or the sRGB curve
//
// `white` is the radiosity (W/m^2, by luminance) that shows as white at
// exposure 0. Left empty it is chosen from the mesh (automaticWhiteReference),
// so exposure 0 gives a usable picture of any scene whatever its power, and
// `exposure` then brightens (+1 = twice as bright) or darkens from there.
#include "output/lit_mesh.h"

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace regio::output {

// Rec. 709 luminance of a linear colour (the weights shooting.h uses too).
float displayLuminance(const glm::vec3& c);

enum class Transfer {
    Gamma, // encoded = linear^(1/gamma)
    Srgb,  // the piecewise sRGB curve (IEC 61966-2-1)
    Linear // no encoding (for consumers that encode themselves)
};

// How linear display values in [0,1] become the values a screen or an 8-bit
// file expects.
struct DisplayEncoding {
    Transfer transfer = Transfer::Gamma;
    double gamma = 2.2;

    float encode(float linear) const;
    float decode(float encoded) const;
    glm::vec3 encode(const glm::vec3& linear) const;
    glm::vec3 decode(const glm::vec3& encoded) const;
    std::string describe() const; // "gamma 2.2", "sRGB", "linear"
};

struct ToneMapSettings {
    double exposure = 0.0;                // stops: +1 doubles every displayed value
    std::optional<double> whiteReference; // W/m^2 shown as white at exposure 0; empty = automatic
    DisplayEncoding encoding;
    bool clamp = true;       // clip linear values to [0,1]; off keeps highlights above 1
    glm::vec3 ambient{0.0f}; // ambient term (W/m^2) added as reflectance x ambient
};

// The luminance that an area-weighted 95 % of the surface does not exceed:
// white then sits at the brightest lit surfaces, and small emitters (a few %
// of the area) saturate as lamps do on a photograph instead of darkening the
// whole picture. 1 for a mesh with no light at all.
double automaticWhiteReference(const LitMesh& mesh, const glm::vec3& ambient);

class ToneMap {
public:
    ToneMap(const ToneMapSettings& settings, double whiteReference);
    // With the settings' white reference, or the automatic one of the mesh.
    static ToneMap forMesh(const ToneMapSettings& settings, const LitMesh& mesh);

    const ToneMapSettings& settings() const { return m_settings; }
    double whiteReference() const { return m_white; }
    // Linear display value per W/m^2: 2^exposure / white.
    double scale() const { return m_scale; }

    // Linear display value of a displayed radiosity (ambient already added).
    glm::vec3 linear(const glm::vec3& radiosity) const;
    // Encoded display value (what an 8-bit file or a screen holds).
    glm::vec3 display(const glm::vec3& radiosity) const { return m_settings.encoding.encode(linear(radiosity)); }

    std::string describe() const; // for file headers: exposure, white, encoding

private:
    ToneMapSettings m_settings;
    double m_white = 1.0;
    double m_scale = 1.0;
};

// Per-vertex display colours of a lit mesh, ready for a writer or the
// renderer: linear values (glTF COLOR_0, Gouraud interpolation) and the
// encoding that turns them into 8-bit or screen values.
struct DisplayColours {
    std::vector<glm::vec3> linear;
    DisplayEncoding encoding;
    std::string description; // how they were made, for comments in files

    glm::vec3 encoded(size_t vertex) const { return encoding.encode(linear[vertex]); }
};

DisplayColours toneMappedColours(const LitMesh& mesh, const ToneMap& toneMap);

// 8-bit value of an encoded display value: clamped to [0,1], rounded.
uint8_t toByte(float encoded);
std::array<uint8_t, 3> toBytes(const glm::vec3& encoded);

} // namespace regio::output
