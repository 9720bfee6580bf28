#include "model/geometry/geometry.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <vector>

using namespace regio::model;

namespace {
const std::vector<Vec3> kUnitSquare{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
}

TEST(Geometry, UnitSquareHasAreaOneAndNormalPlusZ)
{
    EXPECT_DOUBLE_EQ(polygonArea(kUnitSquare), 1.0);
    EXPECT_EQ(polygonNormal(kUnitSquare), Vec3(0, 0, 1));
    EXPECT_EQ(polygonCentroid(kUnitSquare), Vec3(0.5, 0.5, 0));
    EXPECT_DOUBLE_EQ(planarityDeviation(kUnitSquare), 0.0);
}

TEST(Geometry, ConvexityFollowsTheWindingAroundTheNormal)
{
    EXPECT_TRUE(isConvex(kUnitSquare, Vec3(0, 0, 1)));
    EXPECT_FALSE(isConvex(kUnitSquare, Vec3(0, 0, -1)));
    std::vector<Vec3> arrow{{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {1, 0.5, 0}, {0, 2, 0}};
    EXPECT_FALSE(isConvex(arrow, Vec3(0, 0, 1)));
    // A collinear corner is still convex.
    std::vector<Vec3> withMidpoint{{0, 0, 0}, {0.5, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    EXPECT_TRUE(isConvex(withMidpoint, Vec3(0, 0, 1)));
    // A pentagram turns left at every corner but winds twice.
    std::vector<Vec3> star;
    for (int i = 0; i < 5; ++i) {
        double a = i * 4.0 * 3.14159265358979 / 5.0;
        star.push_back({std::cos(a), std::sin(a), 0});
    }
    EXPECT_FALSE(isConvex(star, Vec3(0, 0, 1)));
}

TEST(Geometry, SplittingASquareKeepsItsArea)
{
    Plane plane = Plane::fromPointNormal({0.25, 0, 0}, {1, 0, 0});
    EXPECT_EQ(classifyPolygon(kUnitSquare, plane), Side::Spanning);
    std::vector<Vec3> front, back;
    splitPolygon(kUnitSquare, plane, front, back);
    EXPECT_NEAR(polygonArea(front), 0.75, 1e-12);
    EXPECT_NEAR(polygonArea(back), 0.25, 1e-12);
}

TEST(Geometry, APolygonTouchingThePlaneIsNotSplit)
{
    Plane plane = Plane::fromPointNormal({1, 0, 0}, {1, 0, 0});
    EXPECT_EQ(classifyPolygon(kUnitSquare, plane), Side::Back);
    std::vector<Vec3> front, back;
    splitPolygon(kUnitSquare, plane, front, back);
    EXPECT_TRUE(front.empty());
    EXPECT_NEAR(polygonArea(back), 1.0, 1e-12);
}

TEST(Geometry, BoxesThatOnlyTouchDoNotOverlap)
{
    Box3 a{{0, 0, 0}, {1, 1, 1}, false};
    Box3 b{{1, 0, 0}, {2, 1, 1}, false};
    Box3 c{{0.5, 0.5, 0.5}, {2, 2, 2}, false};
    EXPECT_FALSE(a.overlapsInterior(b));
    EXPECT_TRUE(a.overlapsInterior(c));
}
