// Polygons into triangles (importer/polygon_triangulation.h): the importer's
// own triangulation, which replaced Assimp's post-processing step.
#include "importer/polygon_triangulation.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>

using namespace regio;
using namespace regio::importer;
using model::Vec3;

namespace {

// The area vector of a triangle of `p`.
Vec3 areaVector(const std::vector<Vec3>& p, const std::array<int, 3>& t)
{
    return 0.5 * glm::cross(p[std::size_t(t[1])] - p[std::size_t(t[0])], p[std::size_t(t[2])] - p[std::size_t(t[0])]);
}

// Newell's area vector of the whole polygon.
Vec3 polygonArea(const std::vector<Vec3>& p)
{
    Vec3 sum{0.0};
    for (std::size_t i = 0; i < p.size(); ++i)
        sum += glm::cross(p[i], p[(i + 1) % p.size()]);
    return 0.5 * sum;
}

// Every triangle turns the polygon's way and together they cover its area
// exactly once.
void expectCovers(const std::vector<Vec3>& p, const std::vector<std::array<int, 3>>& triangles)
{
    const Vec3 whole = polygonArea(p);
    Vec3 sum{0.0};
    for (const auto& t : triangles) {
        const Vec3 a = areaVector(p, t);
        EXPECT_GT(glm::dot(a, whole), 0.0) << "a triangle turns the other way";
        sum += a;
    }
    EXPECT_NEAR(glm::length(sum - whole), 0.0, 1e-9 * glm::length(whole));
}

} // namespace

TEST(PolygonTriangulation, ATriangleIsItself)
{
    const std::vector<Vec3> p{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    EXPECT_EQ(triangulatePolygon(p), (std::vector<std::array<int, 3>>{{0, 1, 2}}));
}

TEST(PolygonTriangulation, AConvexQuadInEitherWindingGivesTwoTrianglesTurningItsWay)
{
    std::vector<Vec3> p{{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}};
    auto t = triangulatePolygon(p);
    EXPECT_EQ(t.size(), 2u);
    expectCovers(p, t);
    std::reverse(p.begin(), p.end());
    t = triangulatePolygon(p);
    EXPECT_EQ(t.size(), 2u);
    expectCovers(p, t);
}

TEST(PolygonTriangulation, AConcaveOutlineIsClippedNotFanned)
{
    // An L in a tilted plane, whose first corner sees the notch: a fan from
    // it would cover the notch and overlap itself.
    const Vec3 u = glm::normalize(Vec3{1, 0, 1});
    const Vec3 v{0, 1, 0};
    std::vector<Vec3> p;
    for (const auto& [x, y] : std::vector<std::pair<double, double>>{{1, 1}, {2, 1}, {2, 2}, {0, 2}, {0, 0}, {1, 0}})
        p.push_back(3.0 + x * u + y * v);
    const auto t = triangulatePolygon(p);
    EXPECT_EQ(t.size(), 4u);
    expectCovers(p, t);
    // And in the other winding, so that the normal's dominant axis points down.
    std::reverse(p.begin(), p.end());
    expectCovers(p, triangulatePolygon(p));
}

TEST(PolygonTriangulation, AStarWithManyReflexCornersIsCovered)
{
    std::vector<Vec3> p;
    const int points = 40;
    for (int i = 0; i < 2 * points; ++i) {
        const double a = std::numbers::pi * i / points;
        const double r = i % 2 == 0 ? 1.0 : 0.3;
        p.push_back({r * std::cos(a), 5.0, -r * std::sin(a)}); // facing down (-y)
    }
    const auto t = triangulatePolygon(p);
    EXPECT_EQ(t.size(), p.size() - 2);
    expectCovers(p, t);
}

TEST(PolygonTriangulation, RepeatedAndCollinearCornersLoseNoArea)
{
    const std::vector<Vec3> p{{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}};
    expectCovers(p, triangulatePolygon(p));
}

TEST(PolygonTriangulation, APolygonWithNoAreaGivesNoTriangles)
{
    EXPECT_TRUE(triangulatePolygon(std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}}).empty());
    EXPECT_TRUE(triangulatePolygon(std::vector<Vec3>{{1, 1, 1}, {1, 1, 1}, {1, 1, 1}, {1, 1, 1}}).empty());
    const double nan = std::nan("");
    EXPECT_TRUE(triangulatePolygon(std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {nan, 1, 0}, {0, 1, 0}}).empty());
    EXPECT_TRUE(triangulatePolygon(std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}}).empty());
}

TEST(PolygonTriangulation, ASelfCrossingOutlineIsFannedFromItsFirstCorner)
{
    // A bow tie whose halves have unequal area: no ear order covers it.
    const std::vector<Vec3> p{{0, 0, 0}, {2, 1, 0}, {2, 0, 0}, {0, 3, 0}};
    const auto t = triangulatePolygon(p);
    EXPECT_EQ(t, (std::vector<std::array<int, 3>>{{0, 1, 2}, {0, 2, 3}}));
}

TEST(PolygonTriangulation, AHugePolygonIsFannedInsteadOfClipped)
{
    std::vector<Vec3> p;
    const int n = 4 * kMaxClippedCorners;
    for (int i = 0; i < n; ++i)
        p.push_back({std::cos(2 * std::numbers::pi * i / n), std::sin(2 * std::numbers::pi * i / n), 0.0});
    const auto t = triangulatePolygon(p);
    ASSERT_EQ(t.size(), std::size_t(n - 2));
    EXPECT_EQ(t[5], (std::array<int, 3>{0, 6, 7}));
    expectCovers(p, t);
}
