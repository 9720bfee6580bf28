// Tone mapping: exposure, white reference, gamma and sRGB encoding, clamping
// and the ambient term, applied to display copies only.
#include "output/tone_map.h"

#include "lit_mesh_fixtures.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace regio::output;
using namespace regio::solver;
using regio::test::addQuad;
using regio::test::sampleRoom;

namespace {

ToneMapSettings settingsWithWhite(double white)
{
    ToneMapSettings s;
    s.whiteReference = white;
    return s;
}

} // namespace

TEST(ToneMap, TheWhiteReferenceShowsAsWhiteAtExposureZero)
{
    const ToneMap map(settingsWithWhite(8.0), 8.0);
    const glm::vec3 v = map.linear({8.0f, 8.0f, 8.0f});
    EXPECT_FLOAT_EQ(v.x, 1.0f);
    EXPECT_FLOAT_EQ(map.display({8.0f, 8.0f, 8.0f}).y, 1.0f);
    EXPECT_FLOAT_EQ(map.linear({2.0f, 4.0f, 0.0f}).x, 0.25f);
    EXPECT_FLOAT_EQ(map.linear({2.0f, 4.0f, 0.0f}).y, 0.5f);
}

TEST(ToneMap, DisplayedValuesGrowMonotonicallyWithRadiosity)
{
    for (Transfer transfer : {Transfer::Gamma, Transfer::Srgb, Transfer::Linear}) {
        ToneMapSettings s = settingsWithWhite(10.0);
        s.encoding.transfer = transfer;
        const ToneMap map(s, 10.0);
        float previous = -1.0f;
        for (int i = 0; i <= 200; ++i) {
            const float b = 0.1f * static_cast<float>(i);
            const float shown = map.display({b, b, b}).x;
            EXPECT_GE(shown, previous) << "radiosity " << b;
            if (b <= 10.0f) {
                EXPECT_GT(shown, previous) << "radiosity " << b;
            }
            previous = shown;
        }
    }
}

TEST(ToneMap, OneStopMoreExposureDoublesEveryUnclampedLinearValue)
{
    ToneMapSettings s = settingsWithWhite(5.0);
    s.clamp = false;
    const ToneMap base(s, 5.0);
    s.exposure = 1.0;
    const ToneMap brighter(s, 5.0);
    s.exposure = -2.0;
    const ToneMap darker(s, 5.0);
    for (float b : {0.01f, 0.7f, 3.0f, 12.0f}) {
        EXPECT_FLOAT_EQ(brighter.linear({b, b, b}).x, 2.0f * base.linear({b, b, b}).x);
        EXPECT_FLOAT_EQ(darker.linear({b, b, b}).x, 0.25f * base.linear({b, b, b}).x);
    }
    EXPECT_DOUBLE_EQ(brighter.scale(), 2.0 * base.scale());
}

TEST(ToneMap, ClampingLimitsLinearValuesToOneAndKeepsHighlightsWhenOff)
{
    ToneMapSettings s = settingsWithWhite(1.0);
    EXPECT_FLOAT_EQ(ToneMap(s, 1.0).linear({3.0f, 0.5f, -1.0f}).x, 1.0f);
    EXPECT_FLOAT_EQ(ToneMap(s, 1.0).linear({3.0f, 0.5f, -1.0f}).z, 0.0f);
    s.clamp = false;
    EXPECT_FLOAT_EQ(ToneMap(s, 1.0).linear({3.0f, 0.5f, -1.0f}).x, 3.0f);
    EXPECT_FLOAT_EQ(ToneMap(s, 1.0).linear({3.0f, 0.5f, -1.0f}).z, 0.0f) << "negative light is never shown";
}

TEST(ToneMap, GammaEncodingRaisesToOneOverGammaAndDecodesBack)
{
    DisplayEncoding e;
    EXPECT_EQ(e.transfer, Transfer::Gamma);
    EXPECT_DOUBLE_EQ(e.gamma, 2.2);
    EXPECT_NEAR(e.encode(0.5f), std::pow(0.5, 1.0 / 2.2), 1e-6);
    EXPECT_NEAR(e.encode(0.18f), 0.4587, 1e-4);
    EXPECT_FLOAT_EQ(e.encode(0.0f), 0.0f);
    EXPECT_FLOAT_EQ(e.encode(1.0f), 1.0f);
    e.gamma = 1.8;
    EXPECT_NEAR(e.encode(0.5f), std::pow(0.5, 1.0 / 1.8), 1e-6);
    for (float c : {0.0f, 0.01f, 0.2f, 0.5f, 0.9f, 1.0f})
        EXPECT_NEAR(e.decode(e.encode(c)), c, 1e-6);
}

TEST(ToneMap, SrgbEncodingFollowsThePiecewiseCurveAndDecodesBack)
{
    DisplayEncoding e;
    e.transfer = Transfer::Srgb;
    EXPECT_NEAR(e.encode(0.002f), 12.92 * 0.002, 1e-7) << "linear segment near black";
    EXPECT_NEAR(e.encode(0.5f), 0.735357, 1e-5);
    EXPECT_NEAR(e.encode(0.214041f), 0.5, 1e-5);
    EXPECT_FLOAT_EQ(e.encode(1.0f), 1.0f);
    for (float c : {0.0f, 0.001f, 0.0031308f, 0.2f, 0.5f, 1.0f})
        EXPECT_NEAR(e.decode(e.encode(c)), c, 1e-6);
}

TEST(ToneMap, EightBitValuesAreRoundedAndClamped)
{
    EXPECT_EQ(toByte(0.0f), 0);
    EXPECT_EQ(toByte(1.0f), 255);
    EXPECT_EQ(toByte(0.5f), 128);
    EXPECT_EQ(toByte(-0.2f), 0);
    EXPECT_EQ(toByte(1.7f), 255);
    EXPECT_EQ(toByte(std::nanf("")), 0);
}

TEST(ToneMap, TheAmbientTermAddsReflectanceTimesAmbient)
{
    LitMesh mesh;
    addQuad(mesh, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {1.0f, 2.0f, 3.0f}, "quad", {0.5f, 0.25f, 0.0f});
    ToneMapSettings s = settingsWithWhite(1.0);
    s.clamp = false;
    s.encoding.transfer = Transfer::Linear;
    s.ambient = {2.0f, 4.0f, 8.0f};
    const DisplayColours c = toneMappedColours(mesh, ToneMap::forMesh(s, mesh));
    ASSERT_EQ(c.linear.size(), mesh.vertexCount());
    EXPECT_FLOAT_EQ(c.linear[0].x, 1.0f + 0.5f * 2.0f);
    EXPECT_FLOAT_EQ(c.linear[0].y, 2.0f + 0.25f * 4.0f);
    EXPECT_FLOAT_EQ(c.linear[0].z, 3.0f);
    EXPECT_FLOAT_EQ(mesh.radiosity[0].x, 1.0f) << "the solution itself is untouched";
}

TEST(ToneMap, TheAutomaticWhiteIgnoresASmallBrightEmitter)
{
    LitMesh mesh;
    // 99 % of the area at 4 W/m^2, a small lamp at 500 W/m^2.
    addQuad(mesh, {0, 0, 0}, {10, 0, 0}, {10, 9.9f, 0}, {0, 9.9f, 0}, glm::vec3(4.0f), "wall");
    addQuad(mesh, {0, 9.9f, 0}, {10, 9.9f, 0}, {10, 10, 0}, {0, 10, 0}, glm::vec3(500.0f), "lamp");
    EXPECT_NEAR(automaticWhiteReference(mesh, glm::vec3(0.0f)), 4.0, 1e-5);
    const ToneMap map = ToneMap::forMesh(ToneMapSettings{}, mesh);
    EXPECT_NEAR(map.linear(glm::vec3(4.0f)).x, 1.0f, 1e-5f);
    EXPECT_FLOAT_EQ(map.linear(glm::vec3(500.0f)).x, 1.0f) << "the lamp saturates";
}

TEST(ToneMap, TheAutomaticWhiteIsTheBrightSurfacesOfARoom)
{
    const LitMesh room = sampleRoom();
    // Five walls of equal area: the brightest fifth of the surface holds the
    // 95 % quantile, so the ceiling (the brightest wall) is white.
    const double white = automaticWhiteReference(room, glm::vec3(0.0f));
    EXPECT_FLOAT_EQ(static_cast<float>(white), displayLuminance({8.0f, 6.0f, 3.0f})) << "the ceiling";
    EXPECT_DOUBLE_EQ(automaticWhiteReference(LitMesh{}, glm::vec3(0.0f)), 1.0) << "nothing lit: a neutral scale";
}

TEST(ToneMap, ADescriptionNamesExposureWhiteAndEncoding)
{
    ToneMapSettings s = settingsWithWhite(12.5);
    s.exposure = -1.5;
    const std::string d = ToneMap(s, 12.5).describe();
    EXPECT_NE(d.find("exposure -1.5"), std::string::npos) << d;
    EXPECT_NE(d.find("white 12.5 W/m^2"), std::string::npos) << d;
    EXPECT_NE(d.find("gamma 2.2"), std::string::npos) << d;
}
