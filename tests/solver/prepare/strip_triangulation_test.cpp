// Strip triangulation of convex faces into triangle patches (paper §5.4).
#include "solver/prepare/strip_triangulation.h"

#include "model/geometry/geometry.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <map>
#include <numbers>
#include <random>
#include <utility>
#include <vector>

using namespace regio;
using namespace regio::solver;
using model::Vec3;

namespace {

std::vector<Vec3> regularPolygon(int corners, double radius, const Vec3& centre = Vec3{0.0})
{
    std::vector<Vec3> loop;
    for (int i = 0; i < corners; ++i) {
        double a = 2.0 * std::numbers::pi * i / corners + 0.3;
        loop.push_back(centre + Vec3{radius * std::cos(a), radius * std::sin(a), 0.0});
    }
    return loop;
}

std::vector<Vec3> rectangle(double w, double h) { return {{0, 0, 0}, {w, 0, 0}, {w, h, 0}, {0, h, 0}}; }

struct CoverReport {
    double area = 0.0;
    double smallestTriangle = 1e300;
    double minAngle = 180.0;
    bool allCounterClockwise = true;
    int boundaryEdgesLongerThanPatch = 0;
};

CoverReport inspect(const StripMesh& mesh, const Vec3& normal)
{
    CoverReport r;
    for (const Triangle& t : mesh.triangles) {
        const Vec3 &a = mesh.points[size_t(t[0])], &b = mesh.points[size_t(t[1])], &c = mesh.points[size_t(t[2])];
        double signedArea = 0.5 * glm::dot(glm::cross(b - a, c - a), normal);
        r.allCounterClockwise = r.allCounterClockwise && signedArea > 0.0;
        r.area += signedArea;
        r.smallestTriangle = std::min(r.smallestTriangle, signedArea);
        r.minAngle = std::min(r.minAngle, minimumAngleDegrees(a, b, c));
    }
    return r;
}

// Every inner edge is shared by exactly two triangles running in opposite
// directions and every outer edge lies on the polygon's boundary: together
// with the area sum this means the triangles tile the polygon without gaps,
// overlaps or T-vertices.
void expectConformingTiling(const StripMesh& mesh, const std::vector<Vec3>& polygon)
{
    std::map<std::pair<int, int>, int> directed;
    for (const Triangle& t : mesh.triangles)
        for (int i = 0; i < 3; ++i)
            ++directed[{t[size_t(i)], t[size_t((i + 1) % 3)]}];
    for (const auto& [edge, count] : directed) {
        EXPECT_EQ(count, 1) << "edge used twice in one direction";
        if (directed.count({edge.second, edge.first}))
            continue;
        // A boundary edge: both ends on one polygon edge.
        const Vec3 p = mesh.points[size_t(edge.first)], q = mesh.points[size_t(edge.second)];
        bool onBoundary = false;
        for (size_t i = 0; i < polygon.size() && !onBoundary; ++i) {
            const Vec3 a = polygon[i], b = polygon[(i + 1) % polygon.size()];
            auto distance = [&](const Vec3& x) { return glm::length(glm::cross(x - a, b - a)) / glm::length(b - a); };
            onBoundary = distance(p) < 1e-9 && distance(q) < 1e-9;
        }
        EXPECT_TRUE(onBoundary) << "an outer edge inside the polygon (gap or T-vertex)";
    }
}

void expectExactCover(const std::vector<Vec3>& polygon, double patchSize, double minAngle)
{
    const Vec3 normal = model::polygonNormal(polygon);
    StripMesh mesh = stripTriangulate(polygon, normal, patchSize);
    ASSERT_FALSE(mesh.triangles.empty());
    CoverReport r = inspect(mesh, normal);
    EXPECT_NEAR(r.area, model::polygonArea(polygon), 1e-12 * std::max(1.0, r.area));
    EXPECT_TRUE(r.allCounterClockwise);
    EXPECT_GT(r.smallestTriangle, 0.0);
    EXPECT_GE(r.minAngle, minAngle);
    expectConformingTiling(mesh, polygon);
    for (size_t i = 0; i < polygon.size(); ++i)
        EXPECT_EQ(mesh.points[i], polygon[i]) << "input corners come first, unchanged";
}

} // namespace

TEST(StripTriangulation, SplitsAUnitSquareIntoRightIsoscelesTrianglesOfThePatchSize)
{
    StripMesh mesh = stripTriangulate(rectangle(1, 1), Vec3{0, 0, 1}, 0.5);
    EXPECT_EQ(mesh.triangles.size(), 8u); // 2 strips x 4 triangles
    CoverReport r = inspect(mesh, Vec3{0, 0, 1});
    EXPECT_NEAR(r.minAngle, 45.0, 1e-9);
    expectExactCover(rectangle(1, 1), 0.5, 45.0 - 1e-9);
}

TEST(StripTriangulation, CoversSquaresOfAnySizeExactlyWithoutSlivers)
{
    const double halfPatchAspect = std::atan(0.5) * 180.0 / std::numbers::pi;
    for (double side : {0.1, 0.5, 0.51, 0.99, 1.0, 1.7, 3.0})
        expectExactCover(rectangle(side, side), 0.5, halfPatchAspect - 1e-9);
}

TEST(StripTriangulation, CoversTrianglesExactlyWithoutSliversUnlessTheirCornersAreSharp)
{
    const double h = std::sqrt(3.0) / 2.0;
    expectExactCover({{0, 0, 0}, {1, 0, 0}, {0.5, h, 0}}, 0.3, kStripMinAngleDegrees); // equilateral
    expectExactCover({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}}, 0.5, kStripMinAngleDegrees);   // right isosceles
    expectExactCover({{0, 0, 0}, {3, 0, 0}, {2.5, 0.4, 0}}, 0.5, 0.0);                 // obtuse and flat
}

TEST(StripTriangulation, CoversRegularPolygonsExactlyWithoutSlivers)
{
    for (int corners : {5, 6, 8, 12, 32})
        for (double radius : {0.4, 1.0, 2.3}) {
            std::vector<Vec3> polygon = regularPolygon(corners, radius);
            // The stated angle bound holds for edges of at least half the patch size.
            const bool fair = glm::length(polygon[1] - polygon[0]) >= 0.25;
            expectExactCover(polygon, 0.5, fair ? kStripMinAngleDegrees : 0.0);
        }
}

TEST(StripTriangulation, CoversThinRectanglesWithPatchesAsSquatAsTheRectangleForces)
{
    for (double thickness : {0.01, 0.1, 0.3}) {
        std::vector<Vec3> thin = rectangle(10.0, thickness);
        const double allowed = std::atan(thickness / 0.5) * 180.0 / std::numbers::pi;
        expectExactCover(thin, 0.5, allowed - 1e-9);
        // Lengthwise: no more patches than the patch size asks for.
        StripMesh mesh = stripTriangulate(thin, Vec3{0, 0, 1}, 0.5);
        EXPECT_EQ(mesh.triangles.size(), 40u);
    }
}

TEST(StripTriangulation, WorksInAnyPlaneOrientation)
{
    // A hexagon on a tilted plane, counter-clockwise around its normal.
    std::vector<Vec3> flat = regularPolygon(6, 1.3);
    const Vec3 axis = glm::normalize(Vec3{1, 2, 3});
    const double angle = 0.7;
    std::vector<Vec3> tilted;
    for (const Vec3& p : flat) // Rodrigues' rotation
        tilted.push_back(p * std::cos(angle) + glm::cross(axis, p) * std::sin(angle) +
                         axis * glm::dot(axis, p) * (1 - std::cos(angle)) + Vec3{4, -2, 7});
    expectExactCover(tilted, 0.4, kStripMinAngleDegrees);
}

TEST(StripTriangulation, CoversRandomConvexPolygonsExactly)
{
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int trial = 0; trial < 200; ++trial) {
        // Random points on an ellipse in random angular order make a convex loop.
        const int corners = 3 + int(unit(random) * 9);
        std::vector<double> angles;
        for (int i = 0; i < corners; ++i)
            angles.push_back(unit(random) * 2.0 * std::numbers::pi);
        std::sort(angles.begin(), angles.end());
        const double rx = 0.05 + 3.0 * unit(random), ry = 0.05 + 3.0 * unit(random);
        std::vector<Vec3> loop;
        for (double a : angles) {
            Vec3 p{rx * std::cos(a), ry * std::sin(a), 0.0};
            if (loop.empty() || glm::length(p - loop.back()) > 1e-3)
                loop.push_back(p);
        }
        if (loop.size() < 3 || model::polygonArea(loop) < 1e-4)
            continue;
        expectExactCover(loop, 0.1 + unit(random), 0.0);
    }
}

TEST(StripTriangulation, GivesTwoPatchesPerPatchSizedSquareOfARectangleThatIsAMultipleOfIt)
{
    StripMesh mesh = stripTriangulate(rectangle(4.0, 1.5), Vec3{0, 0, 1}, 0.5);
    EXPECT_EQ(mesh.triangles.size(), 2u * 8u * 3u);
    for (const Triangle& t : mesh.triangles)
        for (int i = 0; i < 3; ++i)
            EXPECT_LE(glm::length(mesh.points[size_t(t[size_t(i)])] - mesh.points[size_t(t[size_t((i + 1) % 3)])]),
                      0.5 * std::sqrt(2.0) + 1e-9);
}

TEST(StripTriangulation, CutsAWholeNumberOfPatchSizesAlikeWhenItsCoordinatesAreRoundedToFloats)
{
    // A 1 m by 0.5 m board at 0.5 m patches is two squares whether its
    // corners lie exactly there or where 32-bit floats put them (a model
    // file's coordinates, moved by up to 6e-8 relative): four patches.
    for (const double x : {10.0, 10.0 + 1e-6, 10.0 - 1e-6})
        for (const double w : {1.0, 1.0 + 2e-7, 1.0 - 2e-7}) {
            const std::vector<Vec3> board{{x, 0, 0}, {x + w, 0, 0}, {x + w, 0.5 + 1e-7, 0}, {x, 0.5, 0}};
            EXPECT_EQ(stripTriangulate(board, Vec3{0, 0, 1}, 0.5).triangles.size(), 4u) << x << " " << w;
        }
    // A length a thousandth of a patch or more beyond takes one piece more.
    EXPECT_EQ(stripTriangulate(rectangle(1.0 + 1e-3, 0.5), Vec3{0, 0, 1}, 0.5).triangles.size(), 6u);
    EXPECT_EQ(stripTriangulate(rectangle(1.0, 0.5 + 1e-3), Vec3{0, 0, 1}, 0.5).triangles.size(), 8u);
}

TEST(StripTriangulation, KeepsPatchesAboutThePatchSizeOnSlantedSides)
{
    // Strips are at most 1.5 patch sizes high and pieces at most one long.
    for (int corners : {3, 5, 6, 8}) {
        StripMesh mesh = stripTriangulate(regularPolygon(corners, 2.0), Vec3{0, 0, 1}, 0.5);
        for (const Triangle& t : mesh.triangles)
            for (int i = 0; i < 3; ++i)
                EXPECT_LE(glm::length(mesh.points[size_t(t[size_t(i)])] - mesh.points[size_t(t[size_t((i + 1) % 3)])]),
                          2.0 * 0.5);
    }
}
