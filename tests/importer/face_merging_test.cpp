// Triangles back to B-rep faces (importer/face_merging.h): what a model file
// writes as triangles comes back as the planar convex faces it was.
#include "importer/face_merging.h"

#include "model/geometry/geometry.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>

using namespace regio;
using namespace regio::importer;
using model::Vec3;

namespace {

// A soup builder: quads and triangles by their corners, counter-clockwise.
struct Soup {
    TriangleSoup soup;
    Soup()
    {
        soup.materials = {{"grey", {0.5, 0.5, 0.5}, {0, 0, 0}, false}, {"red", {0.6, 0.1, 0.1}, {0, 0, 0}, false}};
        soup.meshes = {{"mesh"}, {"other"}};
    }
    void triangle(Vec3 a, Vec3 b, Vec3 c, int material = 0, int mesh = 0)
    {
        const int base = int(soup.positions.size());
        soup.positions.insert(soup.positions.end(), {a, b, c});
        soup.triangles.push_back({{base, base + 1, base + 2}, material, mesh});
    }
    void quad(Vec3 a, Vec3 b, Vec3 c, Vec3 d, int material = 0, int mesh = 0)
    {
        triangle(a, b, c, material, mesh);
        triangle(a, c, d, material, mesh);
    }
    // An n x n grid of quads over [x0, x1] x [z0, z1] at height y, facing up,
    // leaving out the cells `skip` says.
    template <typename Skip>
    void grid(double x0, double x1, double z0, double z1, int n, Skip skip)
    {
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                if (skip(i, j))
                    continue;
                const double xa = x0 + (x1 - x0) * i / n, xb = x0 + (x1 - x0) * (i + 1) / n;
                const double za = z0 + (z1 - z0) * j / n, zb = z0 + (z1 - z0) * (j + 1) / n;
                quad({xa, 0, za}, {xa, 0, zb}, {xb, 0, zb}, {xb, 0, za}); // counter-clockwise from +y
            }
    }
};

double areaOf(const MergedModel& m, const MergedFace& f)
{
    return model::polygonArea(model::loopPositions(m.positions, f.loop));
}

double totalArea(const MergedModel& m)
{
    double sum = 0.0;
    for (const MergedFace& f : m.faces)
        sum += areaOf(m, f);
    return sum;
}

void expectConvexFacingUp(const MergedModel& m)
{
    for (const MergedFace& f : m.faces) {
        const auto corners = model::loopPositions(m.positions, f.loop);
        const Vec3 normal = model::polygonNormal(corners);
        EXPECT_GT(normal.y, 0.999) << "the winding of the triangles is kept";
        EXPECT_TRUE(model::isConvex(corners, normal));
    }
}

} // namespace

TEST(FaceMerging, TheTwoTrianglesOfAQuadAreOneFace)
{
    Soup s;
    s.quad({0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0});
    const MergedModel m = mergeTriangles(s.soup);
    ASSERT_EQ(m.faces.size(), 1u);
    EXPECT_EQ(m.faces[0].loop.size(), 4u);
    EXPECT_NEAR(areaOf(m, m.faces[0]), 1.0, 1e-12);
    EXPECT_EQ(m.counts.trianglesIn, 2u);
    EXPECT_EQ(m.counts.weldedVertices, 2u) << "the diagonal's two ends were written twice";
    expectConvexFacingUp(m);
}

TEST(FaceMerging, AFinelyTriangulatedFloorIsOneFaceWithItsFourCorners)
{
    // 200 triangles, 81 vertices inside: what an exporter writes for a
    // subdivided floor. The inner vertices and those along the edges go.
    Soup s;
    s.grid(0, 3, 0, 2, 10, [](int, int) { return false; });
    const MergedModel m = mergeTriangles(s.soup);
    ASSERT_EQ(m.faces.size(), 1u);
    EXPECT_EQ(m.faces[0].loop.size(), 4u);
    EXPECT_NEAR(totalArea(m), 6.0, 1e-9);
    expectConvexFacingUp(m);
}

TEST(FaceMerging, AnLShapedFloorIsCutIntoTwoConvexFaces)
{
    Soup s;
    s.grid(0, 2, 0, 2, 4, [](int i, int j) { return i >= 2 && j >= 2; }); // a quarter left out
    const MergedModel m = mergeTriangles(s.soup);
    EXPECT_EQ(m.faces.size(), 2u);
    EXPECT_NEAR(totalArea(m), 3.0, 1e-9);
    expectConvexFacingUp(m);
}

TEST(FaceMerging, AFloorWithAHoleIsCutIntoConvexFacesAroundIt)
{
    Soup s;
    s.grid(0, 3, 0, 3, 6, [](int i, int j) { return i >= 2 && i < 4 && j >= 2 && j < 4; });
    const MergedModel m = mergeTriangles(s.soup);
    EXPECT_GE(m.faces.size(), 4u);
    EXPECT_LE(m.faces.size(), 8u) << "a few pieces, not the 64 triangles";
    EXPECT_NEAR(totalArea(m), 9.0 - 1.0, 1e-9);
    expectConvexFacingUp(m);
}

TEST(FaceMerging, ASurfaceTouchingItselfAtACornerIsStillMergedIntoConvexFaces)
{
    // Two squares meeting at one corner: the outline passes that corner
    // twice, so the triangles are merged pairwise instead.
    Soup s;
    s.quad({0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0});
    s.quad({1, 0, 1}, {1, 0, 2}, {2, 0, 2}, {2, 0, 1});
    const MergedModel m = mergeTriangles(s.soup);
    EXPECT_EQ(m.faces.size(), 2u);
    EXPECT_NEAR(totalArea(m), 2.0, 1e-12);
    expectConvexFacingUp(m);
}

TEST(FaceMerging, MaterialsMeshesAndFoldsKeepFacesApart)
{
    Soup s;
    s.quad({0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0});           // grey
    s.quad({1, 0, 0}, {1, 0, 1}, {2, 0, 1}, {2, 0, 0}, 1);        // red beside it
    s.quad({2, 0, 0}, {2, 0, 1}, {3, 0, 1}, {3, 0, 0}, 0, 1);     // another mesh
    const double rise = std::tan(5.0 * std::numbers::pi / 180.0); // a 5 degree fold
    s.quad({3, 0, 0}, {3, 0, 1}, {4, rise, 1}, {4, rise, 0}, 0, 1);
    const MergedModel m = mergeTriangles(s.soup);
    EXPECT_EQ(m.faces.size(), 4u);
    EXPECT_EQ(m.counts.surfaces, 4u);
}

TEST(FaceMerging, ASlightlyBentQuadIsOneFaceWithinTheToleranceAndTwoBeyondIt)
{
    // One corner 0.4 mm out of the plane of a 1 m quad: within the merge
    // tolerance and the flatness the scene accepts without a warning.
    Soup s;
    s.quad({0, 0, 0}, {0, 0, 1}, {1, 0.0004, 1}, {1, 0, 0});
    EXPECT_EQ(mergeTriangles(s.soup, {1.0, 0.001}).faces.size(), 1u);
    EXPECT_EQ(mergeTriangles(s.soup, {0.01, 0.0001}).faces.size(), 2u);
}

TEST(FaceMerging, CornersWithinTheDistanceAreWeldedAndTrianglesOfNoAreaOrRepeatedAreDropped)
{
    Soup s;
    s.quad({0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0});
    s.triangle({0, 0, 0}, {0, 0, 1}, {1, 0, 1});      // the first triangle again
    s.triangle({5, 0, 5}, {5.0002, 0, 5}, {5, 0, 6}); // two corners 0.2 mm apart
    s.triangle({7, 0, 7}, {7, 0, 8}, {7, 0, 9});      // three in line
    const MergedModel m = mergeTriangles(s.soup);
    EXPECT_EQ(m.counts.trianglesIn, 5u);
    EXPECT_EQ(m.counts.duplicate, 1u);
    EXPECT_EQ(m.counts.degenerate, 2u);
    EXPECT_EQ(m.faces.size(), 1u);
}

TEST(FaceMerging, ANeighbourCutFinerAlongTheSharedEdgeStillMergesIntoOneFace)
{
    // Two unit squares side by side; the right one is cut into four
    // triangles around the middle of the shared edge, a corner the left
    // one's edge passes through (a T-junction).
    Soup s;
    s.quad({0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0});
    const Vec3 mid{1, 0, 0.5};
    s.triangle({1, 0, 0}, mid, {2, 0, 0});
    s.triangle(mid, {1, 0, 1}, {2, 0, 1});
    s.triangle(mid, {2, 0, 1}, {2, 0, 0});
    const MergedModel m = mergeTriangles(s.soup);
    EXPECT_EQ(m.counts.tJunctions, 1u) << "the left square's edge is split at the corner";
    ASSERT_EQ(m.faces.size(), 1u);
    EXPECT_EQ(m.faces[0].loop.size(), 4u) << "the corner on the straight outline goes again";
    EXPECT_NEAR(totalArea(m), 2.0, 1e-9);
    expectConvexFacingUp(m);
}

TEST(FaceMerging, AHoleFilledWithLongEdgesClosesTheSurface)
{
    // A 3 x 3 grid with its middle cell left out, and the hole filled by
    // two triangles of their own whose edges pass the grid's corners only at
    // their ends, plus a finer cut of the ring along one side of the hole.
    Soup s;
    s.grid(0, 3, 0, 3, 3, [](int i, int j) { return i == 1 && j == 1; });
    s.quad({1, 0, 1}, {1, 0, 2}, {2, 0, 2}, {2, 0, 1});
    const MergedModel whole = mergeTriangles(s.soup);
    ASSERT_EQ(whole.faces.size(), 1u);
    EXPECT_NEAR(totalArea(whole), 9.0, 1e-9);

    // The same with the hole's filling cut at a point of its edge that the
    // ring does not have, and the ring's cells cut at points the filling
    // does not have.
    Soup t;
    t.grid(0, 3, 0, 3, 3, [](int i, int j) { return (i == 1 && j == 1) || (i == 0 && j == 1); });
    t.triangle({0, 0, 1}, {0, 0, 2}, {1, 0, 1.5});
    t.triangle({0, 0, 2}, {1, 0, 2}, {1, 0, 1.5});
    t.triangle({0, 0, 1}, {1, 0, 1.5}, {1, 0, 1});
    t.quad({1, 0, 1}, {1, 0, 2}, {2, 0, 2}, {2, 0, 1});
    const MergedModel cut = mergeTriangles(t.soup);
    EXPECT_GE(cut.counts.tJunctions, 1u);
    ASSERT_EQ(cut.faces.size(), 1u);
    EXPECT_NEAR(totalArea(cut), 9.0, 1e-9);
    expectConvexFacingUp(cut);
}

TEST(FaceMerging, ACornerOfAnotherMeshOnAnEdgeDoesNotSplitIt)
{
    Soup s;
    s.quad({0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0});
    s.triangle({1, 0, 0.5}, {2, 0, 1}, {2, 0, 0}, 0, 1); // another mesh touches the edge's middle
    const MergedModel m = mergeTriangles(s.soup);
    EXPECT_EQ(m.counts.tJunctions, 0u);
    EXPECT_EQ(m.faces.size(), 2u);
}
