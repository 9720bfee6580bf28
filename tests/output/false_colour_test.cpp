// False colour: the viridis ramp, linear and logarithmic scales, automatic
// ranges and the legend given as data.
#include "output/false_colour.h"

#include "lit_mesh_fixtures.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace regio::output;
using namespace regio::solver;
using regio::test::addQuad;

TEST(FalseColour, TheRampRunsFromDarkPurpleToYellow)
{
    const glm::vec3 low = FalseColour::ramp(0.0);
    const glm::vec3 high = FalseColour::ramp(1.0);
    EXPECT_NEAR(low.x, 0.267, 0.002);
    EXPECT_NEAR(low.y, 0.005, 0.002);
    EXPECT_NEAR(low.z, 0.329, 0.002);
    EXPECT_NEAR(high.x, 0.993, 0.002);
    EXPECT_NEAR(high.y, 0.906, 0.002);
    EXPECT_NEAR(high.z, 0.144, 0.002);
    EXPECT_GT(low.z, low.y) << "bottom is blue-purple";
    EXPECT_GT(high.x, high.z) << "top is yellow";
    const glm::vec3 mid = FalseColour::ramp(0.5);
    EXPECT_GT(mid.y, mid.x) << "the middle is teal";
    EXPECT_EQ(FalseColour::ramp(-3.0), low) << "clamped below";
    EXPECT_EQ(FalseColour::ramp(7.0), high) << "clamped above";
}

TEST(FalseColour, TheRampGetsBrighterAllTheWay)
{
    DisplayEncoding srgb;
    srgb.transfer = Transfer::Srgb;
    float previous = -1.0f;
    for (int i = 0; i <= 100; ++i) {
        const float lum = displayLuminance(srgb.decode(FalseColour::ramp(i / 100.0)));
        EXPECT_GT(lum, previous) << "t = " << i / 100.0;
        previous = lum;
    }
}

TEST(FalseColour, ALinearScaleMapsTheRangeEvenly)
{
    const FalseColour fc(FalseColourScale::Linear, 2.0, 10.0);
    EXPECT_DOUBLE_EQ(fc.position(2.0), 0.0);
    EXPECT_DOUBLE_EQ(fc.position(6.0), 0.5);
    EXPECT_DOUBLE_EQ(fc.position(10.0), 1.0);
    EXPECT_DOUBLE_EQ(fc.position(-5.0), 0.0);
    EXPECT_DOUBLE_EQ(fc.position(50.0), 1.0);
    EXPECT_EQ(fc.colour(10.0), FalseColour::ramp(1.0));
    EXPECT_EQ(fc.colour(0.0), FalseColour::ramp(0.0));
}

TEST(FalseColour, ALogarithmicScaleMapsEqualRatiosToEqualSteps)
{
    const FalseColour fc(FalseColourScale::Logarithmic, 0.1, 1000.0);
    EXPECT_DOUBLE_EQ(fc.position(0.1), 0.0);
    EXPECT_NEAR(fc.position(10.0), 0.5, 1e-12);
    EXPECT_NEAR(fc.position(1.0), 0.25, 1e-12);
    EXPECT_DOUBLE_EQ(fc.position(1000.0), 1.0);
    EXPECT_DOUBLE_EQ(fc.position(0.0), 0.0) << "black is the bottom of the ramp";
}

TEST(FalseColour, BadRangesAreRepairedNotRefused)
{
    const FalseColour logZero(FalseColourScale::Logarithmic, 0.0, 50.0);
    EXPECT_DOUBLE_EQ(logZero.maximum(), 50.0);
    EXPECT_NEAR(logZero.minimum(), 0.05, 1e-12);
    const FalseColour empty(FalseColourScale::Linear, 3.0, 3.0);
    EXPECT_GT(empty.maximum(), empty.minimum());
    const FalseColour dark(FalseColourScale::Logarithmic, 0.0, 0.0);
    EXPECT_GT(dark.maximum(), dark.minimum());
    EXPECT_GT(dark.minimum(), 0.0);
}

TEST(FalseColour, TheAutomaticRangeCoversTheData)
{
    LitMesh mesh;
    addQuad(mesh, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, glm::vec3(2.0f), "dim");
    addQuad(mesh, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}, glm::vec3(40.0f), "bright");
    const FalseColour linear = FalseColour::forMesh({FalseColourScale::Linear, {}, {}}, mesh, glm::vec3(0.0f));
    EXPECT_DOUBLE_EQ(linear.minimum(), 0.0);
    EXPECT_NEAR(linear.maximum(), 40.0, 1e-4);
    const FalseColour log = FalseColour::forMesh({FalseColourScale::Logarithmic, {}, {}}, mesh, glm::vec3(0.0f));
    EXPECT_NEAR(log.minimum(), 2.0, 1e-5) << "the darkest lit value, within three decades of the brightest";
    EXPECT_NEAR(log.maximum(), 40.0, 1e-4);
    const FalseColour fixed = FalseColour::forMesh({FalseColourScale::Logarithmic, 1.0, 100.0}, mesh, glm::vec3(0.0f));
    EXPECT_DOUBLE_EQ(fixed.minimum(), 1.0);
    EXPECT_DOUBLE_EQ(fixed.maximum(), 100.0);
}

TEST(FalseColour, ALinearLegendHasRoundTicksInsideTheRange)
{
    const FalseColourLegend legend = FalseColour(FalseColourScale::Linear, 0.0, 43.0).legend(6);
    EXPECT_EQ(legend.scale, FalseColourScale::Linear);
    EXPECT_DOUBLE_EQ(legend.minimum, 0.0);
    EXPECT_DOUBLE_EQ(legend.maximum, 43.0);
    ASSERT_EQ(legend.ticks.size(), 5u);
    const char* labels[] = {"0", "10", "20", "30", "40"};
    for (size_t i = 0; i < legend.ticks.size(); ++i) {
        EXPECT_EQ(legend.ticks[i].label, labels[i]);
        EXPECT_DOUBLE_EQ(legend.ticks[i].value, 10.0 * static_cast<double>(i));
        EXPECT_NEAR(legend.ticks[i].position, legend.ticks[i].value / 43.0, 1e-12);
    }
    EXPECT_EQ(legend.unit, "W/m^2");
    EXPECT_EQ(legend.quantity, "luminance");
}

TEST(FalseColour, ALogarithmicLegendLabelsDecades)
{
    const FalseColourLegend legend = FalseColour(FalseColourScale::Logarithmic, 0.05, 200.0).legend(7);
    ASSERT_EQ(legend.ticks.size(), 4u);
    EXPECT_EQ(legend.ticks[0].label, "0.1");
    EXPECT_EQ(legend.ticks[1].label, "1");
    EXPECT_EQ(legend.ticks[2].label, "10");
    EXPECT_EQ(legend.ticks[3].label, "100");
    EXPECT_LT(legend.ticks[0].position, legend.ticks[1].position);
    for (const LegendTick& t : legend.ticks) {
        EXPECT_GE(t.position, 0.0);
        EXPECT_LE(t.position, 1.0);
    }
    // Within one decade the legend falls back to 1-2-5 steps.
    const FalseColourLegend narrow = FalseColour(FalseColourScale::Logarithmic, 3.0, 40.0).legend(7);
    ASSERT_EQ(narrow.ticks.size(), 3u);
    EXPECT_EQ(narrow.ticks[0].label, "5");
    EXPECT_EQ(narrow.ticks[1].label, "10");
    EXPECT_EQ(narrow.ticks[2].label, "20");
}

TEST(FalseColour, ManyDecadesAreThinnedToTheTickBudget)
{
    const FalseColourLegend legend = FalseColour(FalseColourScale::Logarithmic, 1e-6, 1e6).legend(5);
    EXPECT_LE(legend.ticks.size(), 5u);
    EXPECT_GE(legend.ticks.size(), 3u);
    EXPECT_EQ(legend.ticks.front().label, "1e-06");
}

TEST(FalseColour, VertexColoursEncodeBackToTheRampColours)
{
    LitMesh mesh;
    addQuad(mesh, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, glm::vec3(40.0f), "bright");
    const FalseColour fc(FalseColourScale::Linear, 0.0, 40.0);
    for (Transfer transfer : {Transfer::Gamma, Transfer::Srgb}) {
        DisplayEncoding e;
        e.transfer = transfer;
        const DisplayColours c = falseColours(mesh, fc, glm::vec3(0.0f), e);
        ASSERT_EQ(c.linear.size(), mesh.vertexCount());
        const glm::vec3 shown = c.encoded(0);
        EXPECT_NEAR(shown.x, FalseColour::ramp(1.0).x, 1e-5);
        EXPECT_NEAR(shown.y, FalseColour::ramp(1.0).y, 1e-5);
        EXPECT_NE(c.description.find("false colour"), std::string::npos);
    }
}
