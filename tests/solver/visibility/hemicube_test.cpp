// The hemicube's delta form factor table (paper §5.6; Cohen & Greenberg 1985).
#include "solver/visibility/hemicube.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace regio::solver;

namespace {

double faceSum(const Hemicube& h, HemicubeFace face)
{
    double sum = 0.0;
    for (int y = 0; y < h.height(face); ++y)
        for (int x = 0; x < h.width(face); ++x)
            sum += h.delta(face, x, y);
    return sum;
}

double fullSum(const Hemicube& h)
{
    double sum = 0.0;
    for (int f = 0; f < kHemicubeFaceCount; ++f)
        sum += faceSum(h, static_cast<HemicubeFace>(f));
    return sum;
}

// Differential area to a parallel rectangle a x b at distance 1 whose corner
// lies on the normal (Howell's catalogue, C-11).
double cornerRectangle(double a, double b)
{
    const double sa = std::sqrt(1.0 + a * a), sb = std::sqrt(1.0 + b * b);
    return (a / sa * std::atan(b / sa) + b / sb * std::atan(a / sb)) / (2.0 * std::numbers::pi);
}

} // namespace

TEST(Hemicube, TopFaceIsNByNAndSideFacesAreNByHalfN)
{
    Hemicube h(150);
    EXPECT_EQ(h.resolution(), 150);
    EXPECT_EQ(h.width(HemicubeFace::Top), 150);
    EXPECT_EQ(h.height(HemicubeFace::Top), 150);
    for (HemicubeFace f : {HemicubeFace::PosX, HemicubeFace::NegX, HemicubeFace::PosY, HemicubeFace::NegY}) {
        EXPECT_EQ(h.width(f), 150);
        EXPECT_EQ(h.height(f), 75);
    }
    EXPECT_EQ(h.totalPixelCount(), 3 * 150 * 150);
    EXPECT_EQ(h.faceOffset(HemicubeFace::NegY) + h.pixelCount(HemicubeFace::NegY), h.totalPixelCount());
}

TEST(Hemicube, OddResolutionIsRoundedUpToEven)
{
    EXPECT_EQ(Hemicube(151).resolution(), 152);
    EXPECT_EQ(Hemicube(1).resolution(), 2);
    EXPECT_EQ(Hemicube(100000).resolution(), kMaxHemicubeResolution);
}

TEST(Hemicube, StoresOneQuarterOfTheTopAndHalfOfASide)
{
    Hemicube h(150);
    EXPECT_EQ(h.topQuarter().size(), 75u * 75u);
    EXPECT_EQ(h.sideHalf().size(), 75u * 75u);
}

TEST(Hemicube, DeltaFormFactorsSumToOneWithinOneMillionth)
{
    for (int n : {2, 10, 64, 150, 151, 300, 600}) {
        Hemicube h(n);
        EXPECT_NEAR(fullSum(h), 1.0, 1e-6) << "N = " << n;
        EXPECT_NEAR(h.totalSum(), 1.0, 1e-6) << "N = " << n;
    }
}

TEST(Hemicube, TopFaceIsSymmetricInBothAxesAndTheDiagonal)
{
    Hemicube h(40);
    const int n = h.resolution();
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const float d = h.delta(HemicubeFace::Top, x, y);
            EXPECT_EQ(d, h.delta(HemicubeFace::Top, n - 1 - x, y));
            EXPECT_EQ(d, h.delta(HemicubeFace::Top, x, n - 1 - y));
            EXPECT_EQ(d, h.delta(HemicubeFace::Top, y, x));
        }
}

TEST(Hemicube, SideFacesAreSymmetricAboutTheirCentreLineAndVanishAtTheBase)
{
    Hemicube h(40);
    const int n = h.resolution();
    for (int y = 0; y < n / 2; ++y)
        for (int x = 0; x < n; ++x)
            EXPECT_EQ(h.delta(HemicubeFace::PosX, x, y), h.delta(HemicubeFace::PosX, n - 1 - x, y));
    // The cosine at the receiving side grows with height: row 0 holds the smallest values.
    EXPECT_LT(h.delta(HemicubeFace::PosY, n / 2, 0), h.delta(HemicubeFace::PosY, n / 2, n / 2 - 1));
}

TEST(Hemicube, PixelValuesFollowTheDifferentialFormFactorFormula)
{
    Hemicube h(100);
    const double step = 2.0 / 100, dA = step * step, k = h.normalisation();
    // Top pixel (60, 70): centre (0.21, 0.41, 1).
    const double tx = -1 + 60.5 * step, ty = -1 + 70.5 * step;
    const double rt = tx * tx + ty * ty + 1;
    const double expectedTop = k * dA / (std::numbers::pi * rt * rt);
    EXPECT_NEAR(h.delta(HemicubeFace::Top, 60, 70), expectedTop, 1e-7 * expectedTop); // stored as float
    // Side pixel (10, 30): centre (1, -0.79, 0.61).
    const double sy = -1 + 10.5 * step, sz = 30.5 * step;
    const double rs = sy * sy + sz * sz + 1;
    const double expectedSide = k * sz * dA / (std::numbers::pi * rs * rs);
    EXPECT_NEAR(h.delta(HemicubeFace::NegX, 10, 30), expectedSide, 1e-7 * expectedSide);
    // The midpoint rule alone is already close to 1: normalisation is a small correction.
    EXPECT_NEAR(k, 1.0, 1e-3);
}

TEST(Hemicube, TopFaceCarriesTheAnalyticFormFactorOfItsSquare)
{
    Hemicube h(300);
    const double top = 4.0 * cornerRectangle(1.0, 1.0); // 0.55413
    EXPECT_NEAR(faceSum(h, HemicubeFace::Top), top, 1e-4);
    for (int f = 1; f < kHemicubeFaceCount; ++f)
        EXPECT_NEAR(faceSum(h, static_cast<HemicubeFace>(f)), (1.0 - top) / 4.0, 1e-4);
}
