// Projection and scan conversion onto the hemicube (paper §5.6): clipping
// against the five face frusta, one pixel-centre rule, shared edges exact.
#include "solver/visibility/hemicube_raster.h"
#include "solver/visibility/item_buffer.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

using namespace regio::solver;
using regio::model::Vec3;

namespace {

// How many times each pixel of the hemicube was written.
struct Coverage {
    explicit Coverage(const Hemicube& h)
        : n(h.resolution())
        , count(static_cast<size_t>(h.totalPixelCount()), 0)
    {
        for (int f = 0; f < kHemicubeFaceCount; ++f)
            offset[size_t(f)] = h.faceOffset(static_cast<HemicubeFace>(f));
    }
    void operator()(HemicubeFace f, int row, int x0, int x1)
    {
        for (int x = x0; x < x1; ++x)
            ++count[static_cast<size_t>(offset[static_cast<int>(f)] + row * n + x)];
    }
    int at(HemicubeFace f, int x, int y) const
    {
        return count[static_cast<size_t>(offset[static_cast<int>(f)] + y * n + x)];
    }
    int n;
    std::array<int, kHemicubeFaceCount> offset{};
    std::vector<int> count;
};

// Exact form factor from a differential area at the origin, normal +z, to a
// polygon lying wholly above its plane (the contour integral of Lambert).
double pointToPolygon(const std::vector<Vec3>& poly)
{
    double sum = 0.0;
    for (size_t i = 0; i < poly.size(); ++i) {
        const Vec3 a = glm::normalize(poly[i]);
        const Vec3 b = glm::normalize(poly[(i + 1) % poly.size()]);
        const Vec3 c = glm::cross(a, b);
        const double len = glm::length(c);
        if (len < 1e-15)
            continue;
        const double angle = std::atan2(len, glm::dot(a, b));
        sum += angle * c.z / len;
    }
    return std::abs(sum) / (2.0 * std::numbers::pi);
}

double rasterFormFactor(const Hemicube& h, const std::vector<Vec3>& poly)
{
    HemicubeRaster raster(h);
    ItemBuffer buffer(h);
    raster.rasterize(poly, [&](HemicubeFace f, int row, int x0, int x1) {
        ItemId* ids = buffer.face(f) + row * h.resolution();
        for (int x = x0; x < x1; ++x)
            ids[x] = itemOfElement(0);
    });
    std::vector<double> perItem(3, 0.0);
    buffer.accumulate(h, perItem);
    return perItem[itemOfElement(0)];
}

// A box [lo, hi] with every face cut into a grid x grid lattice of
// triangles, wound so that their normals point into the box.
std::vector<std::array<Vec3, 3>> triangulatedBox(Vec3 lo, Vec3 hi, int grid, std::mt19937* jitterDiagonals = nullptr)
{
    std::vector<std::array<Vec3, 3>> tris;
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side) {
            const int ua = (axis + 1) % 3, va = (axis + 2) % 3;
            auto point = [&](int i, int j) {
                Vec3 p;
                p[axis] = side ? hi[axis] : lo[axis];
                p[ua] = lo[ua] + (hi[ua] - lo[ua]) * i / grid;
                p[va] = lo[va] + (hi[va] - lo[va]) * j / grid;
                return p;
            };
            for (int i = 0; i < grid; ++i)
                for (int j = 0; j < grid; ++j) {
                    Vec3 a = point(i, j), b = point(i + 1, j), c = point(i + 1, j + 1), d = point(i, j + 1);
                    const bool flip = jitterDiagonals && ((*jitterDiagonals)() & 1);
                    std::array<Vec3, 3> t1 = flip ? std::array<Vec3, 3>{a, b, d} : std::array<Vec3, 3>{a, b, c};
                    std::array<Vec3, 3> t2 = flip ? std::array<Vec3, 3>{b, c, d} : std::array<Vec3, 3>{a, c, d};
                    // Inward normals: the low side winds one way, the high side the other.
                    if (side == 1) {
                        std::swap(t1[1], t1[2]);
                        std::swap(t2[1], t2[2]);
                    }
                    tris.push_back(t1);
                    tris.push_back(t2);
                }
        }
    return tris;
}

void expectEveryPixelCoveredOnce(const Hemicube& h, const ShooterFrame& frame,
                                 const std::vector<std::array<Vec3, 3>>& tris)
{
    HemicubeRaster raster(h);
    Coverage cov(h);
    for (const auto& t : tris) {
        const std::array<Vec3, 3> local{frame.toLocal(t[0]), frame.toLocal(t[1]), frame.toLocal(t[2])};
        raster.rasterize(local, cov);
    }
    int zero = 0, many = 0;
    for (int c : cov.count) {
        zero += c == 0;
        many += c > 1;
    }
    EXPECT_EQ(zero, 0) << "cracks";
    EXPECT_EQ(many, 0) << "pixels counted twice";
}

} // namespace

TEST(HemicubeRaster, OutcodesMarkThePlanesAPointLiesOutside)
{
    // Straight up: inside the top frustum, outside every side face.
    const std::uint32_t up = hemicubeOutcode({0.0, 0.0, 1.0});
    EXPECT_EQ(up & faceOutcodeBits(0), 0u);
    for (int f = 1; f < 5; ++f)
        EXPECT_NE(up & faceOutcodeBits(f), 0u);
    // Below the base plane: outside every face.
    const std::uint32_t below = hemicubeOutcode({0.3, 0.2, -0.1});
    for (int f = 0; f < 5; ++f)
        EXPECT_NE(below & faceOutcodeBits(f), 0u);
    // Low along +x: only the +x side face.
    const std::uint32_t side = hemicubeOutcode({1.0, 0.1, 0.2});
    EXPECT_EQ(side & faceOutcodeBits(static_cast<int>(HemicubeFace::PosX)), 0u);
    EXPECT_NE(side & faceOutcodeBits(static_cast<int>(HemicubeFace::Top)), 0u);
}

TEST(HemicubeRaster, APolygonInTheBasePlaneIsDroppedWithoutCoveringAnything)
{
    EXPECT_NE(hemicubeOutcode({0.5, 0.5, 0.0}) & kBelowBaseBit, 0u);
    EXPECT_EQ(hemicubeOutcode({0.5, 0.5, 0.01}) & kBelowBaseBit, 0u);
    Hemicube h(16);
    HemicubeRaster raster(h);
    Coverage cov(h);
    raster.rasterize(std::vector<Vec3>{{0.1, 0.1, 0}, {2, 0.1, 0}, {2, 2, 0}}, cov);
    for (int c : cov.count)
        EXPECT_EQ(c, 0);
}

TEST(HemicubeRaster, ShooterFrameIsOrthonormalAndRightHanded)
{
    const ShooterFrame f = ShooterFrame::make({1, 2, 3}, glm::normalize(Vec3{1, 1, 0}), {0, 0, 1});
    EXPECT_NEAR(glm::dot(f.u, f.v), 0.0, 1e-12);
    EXPECT_NEAR(glm::dot(f.u, f.n), 0.0, 1e-12);
    EXPECT_NEAR(glm::length(f.u), 1.0, 1e-12);
    EXPECT_NEAR(glm::dot(glm::cross(f.u, f.v), f.n), 1.0, 1e-12);
    EXPECT_NEAR(f.toLocal(Vec3{1, 2, 3} + f.n * 2.0).z, 2.0, 1e-12);
    // A tangent parallel to the normal still gives a frame.
    const ShooterFrame g = ShooterFrame::make({0, 0, 0}, {0, 0, 1}, {0, 0, 5});
    EXPECT_NEAR(glm::length(glm::cross(g.u, g.v) - g.n), 0.0, 1e-12);
}

TEST(HemicubeRaster, PolygonCoveringTheTopFrustumFillsTheWholeTopFace)
{
    Hemicube h(16);
    HemicubeRaster raster(h);
    Coverage cov(h);
    raster.rasterize(std::vector<Vec3>{{-0.9, -0.9, 0.5}, {0.9, -0.9, 0.5}, {0.9, 0.9, 0.5}, {-0.9, 0.9, 0.5}}, cov);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x)
            EXPECT_EQ(cov.at(HemicubeFace::Top, x, y), 1);
    // Seen from the origin the square reaches 61 degrees off the normal: the
    // upper part of every side face sees it too.
    EXPECT_EQ(cov.at(HemicubeFace::PosX, 8, 7), 1);
    EXPECT_EQ(cov.at(HemicubeFace::PosX, 8, 0), 0);
}

TEST(HemicubeRaster, EdgesThroughPixelCentresIncludeTheLeftAndTopAndExcludeTheRightAndBottom)
{
    // N = 8 at distance 1: pixel centres at -0.875, -0.625, ... A square from
    // centre column 2 to centre column 5 and centre row 1 to row 4 covers
    // columns 2..4 and rows 1..3: exactly one pixel per unit of extent.
    Hemicube h(8);
    HemicubeRaster raster(h);
    Coverage cov(h);
    const double c2 = -1 + 2.5 * 0.25, c5 = -1 + 5.5 * 0.25, r1 = -1 + 1.5 * 0.25, r4 = -1 + 4.5 * 0.25;
    raster.rasterize(std::vector<Vec3>{{c2, r1, 1}, {c5, r1, 1}, {c5, r4, 1}, {c2, r4, 1}}, cov);
    int total = 0;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            const bool inside = x >= 2 && x < 5 && y >= 1 && y < 4;
            EXPECT_EQ(cov.at(HemicubeFace::Top, x, y), inside ? 1 : 0) << x << "," << y;
            total += cov.at(HemicubeFace::Top, x, y);
        }
    EXPECT_EQ(total, 9);
}

TEST(HemicubeRaster, EveryTriangleCoversThePixelCentresThatThePixelCentreRuleGivesIt)
{
    // The rule, pixel by pixel, from the snapped corners: the centre of
    // pixel (x, y) is covered when every edge that spans its row (the edge
    // taken bottom-up, from y_p to y_q with y_p <= centre < y_q) has it on
    // the inner side, a centre on a left edge counting as inside and one on
    // a right edge as outside. Triangles of every size, from slivers under a
    // pixel to many pixels (one-row edges and stepped ones), their corners
    // on quarter pixels so that edges run through centres often.
    constexpr int n = 32;
    Hemicube h(n);
    HemicubeRaster raster(h);
    constexpr std::int64_t one = std::int64_t(1) << HemicubeRaster::kSubpixelBits, half = one / 2;
    std::mt19937 rng(7);
    std::uniform_int_distribution<int> quarter(8, 4 * n - 8); // inside the top face
    std::uniform_real_distribution<double> logSize(std::log(0.3), std::log(40.0));
    int covered = 0, mismatches = 0;
    for (int t = 0; t < 20000; ++t) {
        const double size = std::exp(logSize(rng)); // quarter pixels
        const int cx = quarter(rng), cy = quarter(rng);
        std::uniform_int_distribution<int> offset(-int(size), int(size));
        std::vector<Vec3> tri;
        for (int k = 0; k < 3; ++k) {
            const int qx = std::clamp(cx + offset(rng), 4, 4 * n - 4), qy = std::clamp(cy + offset(rng), 4, 4 * n - 4);
            tri.push_back({qx * 0.5 / n - 1.0, qy * 0.5 / n - 1.0, 1.0});
        }
        Coverage cov(h);
        raster.rasterize(tri, cov);
        const std::vector<FixedVertex> fixed(raster.lastProjection().begin(), raster.lastProjection().end());
        ASSERT_EQ(fixed.size(), 3u);
        const std::int64_t area2 = (std::int64_t(fixed[1].x) - fixed[0].x) * (std::int64_t(fixed[2].y) - fixed[0].y) -
                                   (std::int64_t(fixed[2].x) - fixed[0].x) * (std::int64_t(fixed[1].y) - fixed[0].y);
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const std::int64_t px = x * one + half, py = y * one + half;
                bool inside = area2 != 0;
                int spanning = 0;
                for (int k = 0; k < 3 && inside; ++k) {
                    FixedVertex p = fixed[size_t(k)], q = fixed[size_t((k + 1) % 3)];
                    if (p.y == q.y)
                        continue;
                    const bool upward = q.y > p.y;
                    const bool rightEdge = upward == (area2 > 0);
                    if (!upward)
                        std::swap(p, q);
                    if (!(p.y <= py && py < q.y))
                        continue;
                    ++spanning;
                    const std::int64_t side =
                        (px - p.x) * (std::int64_t(q.y) - p.y) - (py - p.y) * (std::int64_t(q.x) - p.x);
                    inside = rightEdge ? side < 0 : side >= 0;
                }
                inside = inside && spanning > 0;
                covered += inside;
                mismatches += cov.at(HemicubeFace::Top, x, y) != (inside ? 1 : 0);
            }
    }
    EXPECT_EQ(mismatches, 0);
    EXPECT_GT(covered, 20000) << "the triangles were expected to cover pixels";
}

TEST(HemicubeRaster, WindingDoesNotChangeTheCoveredPixels)
{
    Hemicube h(32);
    HemicubeRaster raster(h);
    Coverage ccw(h), cw(h);
    std::vector<Vec3> tri{{-0.3, -0.2, 1}, {0.7, 0.1, 1.2}, {0.1, 0.8, 0.9}};
    raster.rasterize(tri, ccw);
    std::swap(tri[1], tri[2]);
    raster.rasterize(tri, cw);
    EXPECT_EQ(ccw.count, cw.count);
}

TEST(HemicubeRaster, TwoTrianglesWithADiagonalThroughPixelCentresCoverTheSquareOnce)
{
    Hemicube h(8);
    HemicubeRaster raster(h);
    Coverage cov(h);
    // Corners on pixel centres; the diagonal passes through centres (2,1), (3,2), (4,3).
    const double c2 = -1 + 2.5 * 0.25, c5 = -1 + 5.5 * 0.25, r1 = -1 + 1.5 * 0.25, r4 = -1 + 4.5 * 0.25;
    raster.rasterize(std::vector<Vec3>{{c2, r1, 1}, {c5, r1, 1}, {c5, r4, 1}}, cov);
    raster.rasterize(std::vector<Vec3>{{c2, r1, 1}, {c5, r4, 1}, {c2, r4, 1}}, cov);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x)
            EXPECT_EQ(cov.at(HemicubeFace::Top, x, y), (x >= 2 && x < 5 && y >= 1 && y < 4) ? 1 : 0);
}

TEST(HemicubeRaster, APolygonBehindTheShooterCoversNothing)
{
    Hemicube h(16);
    HemicubeRaster raster(h);
    Coverage cov(h);
    raster.rasterize(std::vector<Vec3>{{-1, -1, -0.5}, {1, -1, -0.5}, {1, 1, -0.5}, {-1, 1, -0.5}}, cov);
    for (int c : cov.count)
        EXPECT_EQ(c, 0);
}

TEST(HemicubeRaster, APolygonCrossingTheBasePlaneIsCutAtIt)
{
    // A vertical wall x = 1 from z = -1 to z = 1: its lower half is below the
    // horizon, so exactly the +x side face is covered (rows z in [0, 1]).
    Hemicube h(16);
    HemicubeRaster raster(h);
    Coverage cov(h);
    raster.rasterize(std::vector<Vec3>{{1, -1, -1}, {1, 1, -1}, {1, 1, 1}, {1, -1, 1}}, cov);
    int sideCovered = 0, elsewhere = 0;
    for (int f = 0; f < kHemicubeFaceCount; ++f)
        for (int y = 0; y < h.height(static_cast<HemicubeFace>(f)); ++y)
            for (int x = 0; x < 16; ++x) {
                const int c = cov.at(static_cast<HemicubeFace>(f), x, y);
                (f == static_cast<int>(HemicubeFace::PosX) ? sideCovered : elsewhere) += c;
            }
    EXPECT_EQ(sideCovered, 16 * 8);
    EXPECT_EQ(elsewhere, 0);
}

TEST(HemicubeRaster, ATriangulatedClosedBoxCoversEveryPixelExactlyOnceFromAnAlignedCentre)
{
    // Cube [-1, 1]^3 seen from its centre with an axis-aligned frame: every
    // lattice edge projects onto pixel centres and face borders. The worst case
    // for tie breaking.
    Hemicube h(8);
    expectEveryPixelCoveredOnce(h, ShooterFrame::make({0, 0, 0}, {0, 0, 1}, {1, 0, 0}),
                                triangulatedBox({-1, -1, -1}, {1, 1, 1}, 8));
    Hemicube h16(16);
    expectEveryPixelCoveredOnce(h16, ShooterFrame::make({0, 0, 0}, {0, 0, 1}, {1, 0, 0}),
                                triangulatedBox({-1, -1, -1}, {1, 1, 1}, 4));
}

TEST(HemicubeRaster, ATriangulatedClosedBoxCoversEveryPixelExactlyOnceFromRandomShooters)
{
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const Vec3 lo{-1.0, -0.5, 0.0}, hi{2.0, 1.5, 2.5};
    const auto tris = triangulatedBox(lo, hi, 5, &rng);
    Hemicube h(50);
    for (int trial = 0; trial < 20; ++trial) {
        const Vec3 p = lo + (hi - lo) * Vec3{0.05 + 0.9 * unit(rng), 0.05 + 0.9 * unit(rng), 0.05 + 0.9 * unit(rng)};
        Vec3 normal{unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5};
        const ShooterFrame frame = ShooterFrame::make(p, glm::normalize(normal), {unit(rng), unit(rng), unit(rng)});
        expectEveryPixelCoveredOnce(h, frame, tris);
    }
}

TEST(HemicubeRaster, ProjectedAreaMatchesTheAnalyticFormFactorOfAParallelSquare)
{
    // One hemicube at the centre of a unit square, facing an opposed unit
    // square 1 away: the point-to-area factor, 0.2395 (not the squares'
    // area-to-area 0.1998: the proximity error of Baum et al. 1989).
    Hemicube h(300);
    const std::vector<Vec3> square{{-0.5, -0.5, 1}, {0.5, -0.5, 1}, {0.5, 0.5, 1}, {-0.5, 0.5, 1}};
    EXPECT_NEAR(pointToPolygon(square), 0.23945, 1e-4);
    EXPECT_NEAR(rasterFormFactor(h, square), pointToPolygon(square), 0.002 * pointToPolygon(square));
}

TEST(HemicubeRaster, ProjectedAreaMatchesTheAnalyticFormFactorOfPolygonsAcrossSeveralFaces)
{
    Hemicube h(300);
    // A wall meeting the base plane along y = 0.5 (seen on the top and +y faces).
    const std::vector<Vec3> wall{{-1, 0.5, 0}, {1, 0.5, 0}, {1, 0.5, 1.5}, {-1, 0.5, 1.5}};
    const double exactWall = pointToPolygon(wall);
    EXPECT_NEAR(rasterFormFactor(h, wall), exactWall, 0.005 * exactWall);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> coord(-2.0, 2.0), height(0.3, 2.0);
    for (int trial = 0; trial < 30; ++trial) {
        std::vector<Vec3> tri{{coord(rng), coord(rng), height(rng)},
                              {coord(rng), coord(rng), height(rng)},
                              {coord(rng), coord(rng), height(rng)}};
        const double exact = pointToPolygon(tri);
        if (exact < 0.01)
            continue; // too few pixels for a relative comparison
        EXPECT_NEAR(rasterFormFactor(h, tri), exact, 0.01 * exact) << "trial " << trial;
    }
}

TEST(HemicubeRaster, ProjectedVerticesAreSnappedToFixedPoint)
{
    Hemicube h(10);
    HemicubeRaster raster(h);
    raster.rasterize(std::vector<Vec3>{{0.013, 0.027, 1}, {0.5, 0.0, 1}, {0.0, 0.5, 1}},
                     [](HemicubeFace, int, int, int) {});
    ASSERT_EQ(raster.lastProjection().size(), 3u);
    // (0.013 + 1) * 5 pixels = 5.065 pixels -> 331939.84 / 65536 -> 331940.
    EXPECT_EQ(raster.lastProjection()[0].x, 331940);
    EXPECT_EQ(raster.lastProjection()[1].x, 7.5 * 65536);
}
