// The regional tree of separating planes (paper §5.2) and the assignment of
// faces to its cells with clipping (the Warnock variant, §3).
#include "solver/prepare/regional_tree.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <functional>
#include <map>
#include <vector>

using namespace regio;
using namespace regio::solver;
using model::Vec3;

namespace {

Box3 box(Vec3 min, Vec3 max)
{
    Box3 b;
    b.extend(min);
    b.extend(max);
    return b;
}

// Four boxes around an empty centre that no axis-aligned plane separates.
std::vector<Box3> pinwheel()
{
    return {box({0, 0, 0}, {2, 1, 1}), box({2, 0, 0}, {3, 2, 1}), box({1, 2, 0}, {3, 3, 1}), box({0, 1, 0}, {1, 3, 1})};
}

// Regions below a node, and a check that every inner plane separates the
// boxes of its back subtree from those of its front subtree.
std::vector<int> regionsBelow(const RegionalTree& tree, int index)
{
    const RegionalNode& node = tree.nodes[size_t(index)];
    if (node.isLeaf())
        return {node.region};
    std::vector<int> all = regionsBelow(tree, node.back);
    std::vector<int> front = regionsBelow(tree, node.front);
    all.insert(all.end(), front.begin(), front.end());
    return all;
}

void expectValidTree(const RegionalTree& tree, const std::vector<Box3>& boxes)
{
    ASSERT_GE(tree.root, 0);
    std::vector<int> leaves = regionsBelow(tree, tree.root);
    std::sort(leaves.begin(), leaves.end());
    std::vector<int> expected(boxes.size());
    for (size_t i = 0; i < expected.size(); ++i)
        expected[i] = int(i);
    EXPECT_EQ(leaves, expected) << "every region in exactly one leaf";
    for (size_t i = 0; i < tree.nodes.size(); ++i) {
        const RegionalNode& node = tree.nodes[i];
        if (node.isLeaf())
            continue;
        for (int r : regionsBelow(tree, node.back))
            EXPECT_LE(boxes[size_t(r)].max[node.axis], node.position + 1e-9);
        for (int r : regionsBelow(tree, node.front))
            EXPECT_GE(boxes[size_t(r)].min[node.axis], node.position - 1e-9);
    }
}

// The cell of a leaf: the sides of all separating planes on the way to it.
bool insideCell(const RegionalTree& tree, int region, const Vec3& p)
{
    std::function<bool(int)> walk = [&](int index) -> bool {
        const RegionalNode& node = tree.nodes[size_t(index)];
        if (node.isLeaf())
            return node.region == region;
        if (p[node.axis] >= node.position - 1e-9 && walk(node.front))
            return true;
        return p[node.axis] <= node.position + 1e-9 && walk(node.back);
    };
    return walk(tree.root);
}

double totalArea(const std::vector<FacePolygon>& polygons)
{
    double area = 0.0;
    for (const FacePolygon& p : polygons)
        area += model::polygonArea(p.loop);
    return area;
}

} // namespace

TEST(RegionalTree, OneRegionIsASingleLeaf)
{
    std::vector<Box3> boxes{box({0, 0, 0}, {1, 1, 1})};
    RegionalTreeBuild build = buildRegionalTree(boxes);
    ASSERT_TRUE(build.ok());
    ASSERT_EQ(build.tree.nodes.size(), 1u);
    EXPECT_TRUE(build.tree.nodes[0].isLeaf());
    EXPECT_EQ(build.tree.nodes[0].region, 0);
}

TEST(RegionalTree, SeparatesTwoTouchingRoomsOnTheirSharedWall)
{
    std::vector<Box3> boxes{box({0, 0, 0}, {2, 3, 4}), box({2, 0, 0}, {5, 3, 4})};
    RegionalTreeBuild build = buildRegionalTree(boxes);
    ASSERT_TRUE(build.ok());
    const RegionalNode& root = build.tree.nodes[size_t(build.tree.root)];
    EXPECT_EQ(root.axis, 0);
    EXPECT_DOUBLE_EQ(root.position, 2.0);
    EXPECT_EQ(build.tree.nodes[size_t(root.back)].region, 0);
    EXPECT_EQ(build.tree.nodes[size_t(root.front)].region, 1);
    expectValidTree(build.tree, boxes);
}

TEST(RegionalTree, SeparatesThreeRegionsOnTwoAxes)
{
    // Two rooms side by side along x, a third above both.
    std::vector<Box3> boxes{box({0, 0, 0}, {2, 3, 4}), box({2, 0, 0}, {5, 3, 4}), box({0, 3, 0}, {5, 5, 4})};
    RegionalTreeBuild build = buildRegionalTree(boxes);
    ASSERT_TRUE(build.ok());
    expectValidTree(build.tree, boxes);
    EXPECT_EQ(build.tree.nodes[size_t(build.tree.root)].axis, 1) << "only y separates the upper region first";
}

TEST(RegionalTree, SeparatesFiveRegionsWithGapsBetweenThem)
{
    std::vector<Box3> boxes{box({0, 0, 0}, {1, 1, 1}), box({1.5, 0, 0}, {2.5, 1, 1}), box({0, 2, 0}, {2.5, 3, 1}),
                            box({3, 0, 0}, {4, 3, 1}), box({0, 0, 2}, {4, 3, 3})};
    RegionalTreeBuild build = buildRegionalTree(boxes);
    ASSERT_TRUE(build.ok());
    expectValidTree(build.tree, boxes);
}

TEST(RegionalTree, ChoosesTheMostBalancedSplit)
{
    std::vector<Box3> boxes;
    for (int i = 0; i < 4; ++i)
        boxes.push_back(box({double(i), 0, 0}, {i + 1.0, 1, 1}));
    RegionalTreeBuild build = buildRegionalTree(boxes);
    ASSERT_TRUE(build.ok());
    expectValidTree(build.tree, boxes);
    const RegionalNode& root = build.tree.nodes[size_t(build.tree.root)];
    EXPECT_EQ(root.axis, 0);
    EXPECT_DOUBLE_EQ(root.position, 2.0);
    EXPECT_EQ(build.tree.nodes.size(), 7u); // depth 2, balanced
}

TEST(RegionalTree, ReportsAPinwheelThatNoPlaneSeparatesInsteadOfLooping)
{
    // Four boxes around an empty centre, each overlapping its neighbours'
    // projections on both axes: no axis-aligned plane splits the set.
    RegionalTreeBuild build = buildRegionalTree(pinwheel());
    EXPECT_FALSE(build.ok());
    std::vector<int> reported = build.inseparable;
    std::sort(reported.begin(), reported.end());
    EXPECT_EQ(reported, (std::vector<int>{0, 1, 2, 3}));
}

TEST(RegionalTree, ReportsOnlyTheOverlappingGroup)
{
    // Regions 1 and 2 overlap; region 0 is apart and separates fine.
    std::vector<Box3> boxes{box({0, 0, 0}, {1, 1, 1}), box({2, 0, 0}, {4, 1, 1}), box({3, 0, 0}, {5, 1, 1})};
    RegionalTreeBuild build = buildRegionalTree(boxes);
    EXPECT_FALSE(build.ok());
    std::vector<int> reported = build.inseparable;
    std::sort(reported.begin(), reported.end());
    EXPECT_EQ(reported, (std::vector<int>{1, 2}));
}

TEST(RegionalTree, ClipsAFloorCrossingThreeCellsIntoPiecesThatKeepItsArea)
{
    std::vector<Box3> boxes{box({0, 0, 0}, {2, 3, 4}), box({2, 0, 0}, {3, 3, 4}), box({3, 0, 0}, {6, 3, 4})};
    RegionalTreeBuild build = buildRegionalTree(boxes);
    ASSERT_TRUE(build.ok());
    FacePolygon floor{{{0, 0, 0}, {0, 0, 4}, {6, 0, 4}, {6, 0, 0}}, 7}; // normal +y
    auto cells = assignToCells(build.tree, {floor}, 3);
    ASSERT_EQ(cells.size(), 3u);
    double area = 0.0;
    for (int r = 0; r < 3; ++r) {
        ASSERT_EQ(cells[size_t(r)].size(), 1u) << "one piece per cell";
        const FacePolygon& piece = cells[size_t(r)][0];
        EXPECT_EQ(piece.face, 7) << "pieces keep their face";
        EXPECT_TRUE(model::isConvex(piece.loop, Vec3{0, 1, 0}));
        for (const Vec3& p : piece.loop)
            EXPECT_TRUE(insideCell(build.tree, r, p));
        area += model::polygonArea(piece.loop);
    }
    EXPECT_NEAR(area, 24.0, 1e-12);
    EXPECT_NEAR(model::polygonArea(cells[1][0].loop), 4.0, 1e-12);
}

TEST(RegionalTree, PutsAWallOnASeparatingPlaneIntoTheCellItFaces)
{
    std::vector<Box3> boxes{box({0, 0, 0}, {2, 3, 4}), box({2, 0, 0}, {5, 3, 4})};
    RegionalTreeBuild build = buildRegionalTree(boxes);
    ASSERT_TRUE(build.ok());
    FacePolygon facingWest{{{2, 0, 0}, {2, 0, 4}, {2, 3, 4}, {2, 3, 0}}, 0}; // normal -x
    FacePolygon facingEast{{{2, 0, 0}, {2, 3, 0}, {2, 3, 4}, {2, 0, 4}}, 1}; // normal +x
    auto cells = assignToCells(build.tree, {facingWest, facingEast}, 2);
    ASSERT_EQ(cells[0].size(), 1u);
    ASSERT_EQ(cells[1].size(), 1u);
    EXPECT_EQ(cells[0][0].face, 0);
    EXPECT_EQ(cells[1][0].face, 1);
}

TEST(RegionalTree, AssignsFacesOutsideEveryRegionBoxToSomeCell)
{
    std::vector<Box3> boxes{box({0, 0, 0}, {1, 1, 1}), box({2, 0, 0}, {3, 1, 1})};
    RegionalTreeBuild build = buildRegionalTree(boxes);
    ASSERT_TRUE(build.ok());
    std::vector<FacePolygon> polygons{
        {{{-5, 7, -5}, {-4, 7, -5}, {-4, 8, -5}}, 0},              // far beyond region 0
        {{{9, 7, 9}, {10, 7, 9}, {10, 8, 9}}, 1},                  // far beyond region 1
        {{{1.2, 5, 0}, {1.8, 5, 0}, {1.8, 6, 0}, {1.2, 6, 0}}, 2}, // in the gap, crosses the plane
    };
    const double before = totalArea(polygons);
    auto cells = assignToCells(build.tree, polygons, 2);
    EXPECT_EQ(cells[0].size() + cells[1].size(), 4u);
    EXPECT_NEAR(totalArea(cells[0]) + totalArea(cells[1]), before, 1e-12);
    for (int r = 0; r < 2; ++r)
        for (const FacePolygon& piece : cells[size_t(r)])
            for (const Vec3& p : piece.loop)
                EXPECT_TRUE(insideCell(build.tree, r, p));
}

// Wall-clock bound (CTest label "timing"): the search for a separating plane
// gives up on a set it cannot split instead of trying on.
TEST(RegionalTreeTiming, ReportsAPinwheelWithinOneSecond)
{
    const std::vector<Box3> boxes = pinwheel();
    const auto start = std::chrono::steady_clock::now();
    buildRegionalTree(boxes);
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(1));
}
