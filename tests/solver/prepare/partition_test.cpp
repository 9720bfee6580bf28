// The partition rule of preparation (solver/prepare/partition.h), the one
// place that decides where a polygon goes at a plane: every walk down the
// regional tree and the BSP trees calls it, so they cannot disagree.
#include "solver/prepare/partition.h"

#include <gtest/gtest.h>

#include <vector>

using namespace regio;
using namespace regio::solver;
using model::Vec3;

namespace {

// The unit square in the plane z = 0 with its normal along +z, moved by `offset`.
std::vector<Vec3> square(Vec3 offset = Vec3{0.0})
{
    return {offset + Vec3{0, 0, 0}, offset + Vec3{1, 0, 0}, offset + Vec3{1, 1, 0}, offset + Vec3{0, 1, 0}};
}

Plane planeX(double x) { return Plane::fromPointNormal({x, 0, 0}, {1, 0, 0}); }

} // namespace

TEST(Partition, ASplitKeepsBothSidesWithTheirArea)
{
    const PlaneSplit split = splitAcross(square(), planeX(0.25));
    EXPECT_NEAR(model::polygonArea(split.front), 0.75, 1e-12);
    EXPECT_NEAR(model::polygonArea(split.back), 0.25, 1e-12);
}

TEST(Partition, ASideThatIsOnlyASliverIsDropped)
{
    // The plane passes a hair inside the left edge: the back side would be a
    // strip 1e-9 wide, cleaned down to a segment of no area.
    const PlaneSplit split = splitAcross(square(), planeX(1e-9));
    EXPECT_TRUE(split.back.empty());
    EXPECT_NEAR(model::polygonArea(split.front), 1.0, 1e-8);

    std::vector<Vec3> degenerate{{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {2, 0, 0}};
    EXPECT_FALSE(keepSplitSide(degenerate));
}

TEST(Partition, APolygonOnASeparatingPlaneGoesToTheSideItFaces)
{
    // A wall in the plane x = 2 belongs to the room it bounds.
    const std::vector<Vec3> facingPlusX{{2, 0, 0}, {2, 1, 0}, {2, 1, 1}, {2, 0, 1}};
    std::vector<Vec3> facingMinusX(facingPlusX.rbegin(), facingPlusX.rend());
    PlaneSplit unused;
    EXPECT_EQ(routeAtSeparatingPlane(facingPlusX, 0, 2.0, unused), model::Side::Front);
    EXPECT_EQ(routeAtSeparatingPlane(facingMinusX, 0, 2.0, unused), model::Side::Back);
    EXPECT_EQ(routeAtSeparatingPlane(square(), 0, 5.0, unused), model::Side::Back);
    EXPECT_EQ(routeAtSeparatingPlane(square(), 0, -5.0, unused), model::Side::Front);

    PlaneSplit split;
    EXPECT_EQ(routeAtSeparatingPlane(square(), 0, 0.5, split), model::Side::Spanning);
    EXPECT_NEAR(model::polygonArea(split.front) + model::polygonArea(split.back), 1.0, 1e-12);
}

TEST(Partition, ClippingAtASeparatingPlaneKeepsFaceIndicesAndArea)
{
    std::vector<FacePolygon> polygons{{square(), 0}, {square({3, 0, 0}), 1}};
    std::vector<FacePolygon> back, front;
    partitionAtSeparatingPlane(std::move(polygons), 0, 0.5, back, front);
    ASSERT_EQ(back.size(), 1u);
    ASSERT_EQ(front.size(), 2u);
    EXPECT_EQ(back[0].face, 0);
    EXPECT_EQ(front[0].face, 0);
    EXPECT_EQ(front[1].face, 1);
    EXPECT_NEAR(model::polygonArea(back[0].loop) + model::polygonArea(front[0].loop), 1.0, 1e-12);
}

TEST(Partition, TheRootIsThePolygonOfLowestRankTiesToTheEarlier)
{
    const std::vector<FacePolygon> polygons{{square(), 2}, {square(), 0}, {square(), 1}, {square(), 3}};
    EXPECT_EQ(lowestRank(polygons, std::vector<int>{5, 7, 5, 9}), 0u) << "face 2 and face 0 both rank 5";
    EXPECT_EQ(lowestRank(polygons, std::vector<int>{5, 1, 5, 9}), 2u);
}

TEST(Partition, ARootKeepsItsCoplanarPolygonsOfBothOrientationsAndSplitsTheSpanningOnes)
{
    const std::vector<Vec3> root = square();
    const std::vector<Vec3> coplanarBack(root.rbegin(), root.rend());
    const std::vector<Vec3> spanning{{0.5, 0, -1}, {0.5, 0, 1}, {0.5, 1, 1}, {0.5, 1, -1}};
    const std::vector<Vec3> above = square({0, 0, 2});
    std::vector<FacePolygon> polygons{{above, 0}, {root, 1}, {spanning, 2}, {coplanarBack, 3}};
    const BspPartition parts = partitionAtRoot(std::move(polygons), 1, Plane::fromPointNormal({0, 0, 0}, {0, 0, 1}));
    ASSERT_EQ(parts.on.size(), 2u);
    EXPECT_EQ(parts.on[0].face, 1) << "subset order, the root among them";
    EXPECT_EQ(parts.on[1].face, 3);
    EXPECT_EQ(parts.splits, 1);
    ASSERT_EQ(parts.front.size(), 2u);
    EXPECT_EQ(parts.front[0].face, 0);
    EXPECT_EQ(parts.front[1].face, 2);
    ASSERT_EQ(parts.back.size(), 1u);
    EXPECT_EQ(parts.back[0].face, 2);
}
