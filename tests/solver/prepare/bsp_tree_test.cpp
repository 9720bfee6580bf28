// Regional BSP trees (paper §5.3): validity, area bookkeeping, the author's
// root order, coplanar faces and statistics.
#include "solver/prepare/bsp_tree.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <map>
#include <numeric>
#include <random>
#include <vector>

using namespace regio;
using namespace regio::solver;
using model::Vec3;

namespace {

constexpr double kEps = 1e-6;

// A scene holding just the faces' Properties and one region, ready for a build.
struct Fixture {
    PreparedScene scene;
    std::vector<FacePolygon> polygons;

    int add(std::vector<Vec3> loop)
    {
        const int face = int(scene.faces.size());
        InputFace info;
        info.id = "f" + std::to_string(face);
        info.area = model::polygonArea(loop);
        scene.faces.push_back(info);
        Properties props;
        props.plane = model::polygonPlane(loop);
        props.face = face;
        scene.properties.push_back(props);
        polygons.push_back({std::move(loop), face});
        return face;
    }

    void build(std::vector<int> rank = {})
    {
        if (rank.empty()) {
            rank.resize(scene.faces.size());
            std::iota(rank.begin(), rank.end(), 0);
        }
        scene.regions.assign(1, Region{});
        buildRegionBsp(scene, 0, polygons, rank);
    }

    std::vector<int> subtreeFragments(int node) const
    {
        std::vector<int> out;
        if (node < 0)
            return out;
        const BspNode& n = scene.nodes[size_t(node)];
        for (int i = 0; i < n.fragmentCount; ++i)
            out.push_back(n.firstFragment + i);
        for (int child : {n.back, n.front}) {
            std::vector<int> below = subtreeFragments(child);
            out.insert(out.end(), below.begin(), below.end());
        }
        return out;
    }

    std::vector<Vec3> points(int fragment) const
    {
        const Fragment& f = scene.fragments[size_t(fragment)];
        return {scene.fragmentPoints.begin() + f.firstPoint,
                scene.fragmentPoints.begin() + f.firstPoint + f.pointCount};
    }
};

std::vector<Vec3> quad(Vec3 a, Vec3 b, Vec3 c, Vec3 d) { return {a, b, c, d}; }

// The defining properties of a BSP tree, checked on every node.
void expectValidBsp(const Fixture& fx)
{
    const PreparedScene& s = fx.scene;
    ASSERT_GE(s.regions[0].bspRoot, 0);
    for (size_t n = 0; n < s.nodes.size(); ++n) {
        const BspNode& node = s.nodes[n];
        EXPECT_GT(node.fragmentCount, 0);
        for (int i = 0; i < node.fragmentCount; ++i) {
            const Fragment& f = s.fragments[size_t(node.firstFragment + i)];
            EXPECT_EQ(f.node, int(n));
            for (const Vec3& p : fx.points(node.firstFragment + i))
                EXPECT_NEAR(node.plane.signedDistance(p), 0.0, kEps) << "fragment off its node's plane";
            const bool forward = glm::dot(s.properties[size_t(f.properties)].plane.normal, node.plane.normal) > 0;
            EXPECT_EQ(forward, i < node.forwardFragments) << "forward fragments come first";
        }
        for (int f : fx.subtreeFragments(node.front))
            for (const Vec3& p : fx.points(f))
                EXPECT_GE(node.plane.signedDistance(p), -kEps) << "front subtree behind the plane";
        for (int f : fx.subtreeFragments(node.back))
            for (const Vec3& p : fx.points(f))
                EXPECT_LE(node.plane.signedDistance(p), kEps) << "back subtree in front of the plane";
    }
}

void expectAreasAddUp(const Fixture& fx)
{
    std::map<int, double> areas;
    for (const Fragment& f : fx.scene.fragments) {
        areas[f.properties] += f.area;
        EXPECT_NEAR(f.area, model::polygonArea(fx.points(int(&f - fx.scene.fragments.data()))), 1e-12);
    }
    for (const InputFace& face : fx.scene.faces) {
        const int index = int(&face - fx.scene.faces.data());
        EXPECT_NEAR(areas[index], face.area, 1e-9 * std::max(1.0, face.area)) << face.id;
    }
}

std::vector<Vec3> randomTriangle(std::mt19937& random)
{
    std::uniform_real_distribution<double> coordinate(0.0, 10.0);
    std::uniform_real_distribution<double> offset(-2.0, 2.0);
    Vec3 a{coordinate(random), coordinate(random), coordinate(random)};
    std::vector<Vec3> t{a, a + Vec3{offset(random), offset(random), offset(random)},
                        a + Vec3{offset(random), offset(random), offset(random)}};
    return t;
}

} // namespace

TEST(BspTree, HonoursTheRootOrderAtEveryLevel)
{
    Fixture fx;
    fx.add(quad({0, 0, 0}, {4, 0, 0}, {4, 0, 4}, {0, 0, 4}));   // floor y = 0 (normal -y)
    fx.add(quad({2, -1, 0}, {2, 3, 0}, {2, 3, 4}, {2, -1, 4})); // wall x = 2, crosses the floor
    fx.add(quad({0, 1, 0}, {0, 1, 4}, {4, 1, 4}, {4, 1, 0}));   // shelf y = 1
    // Wall first, then shelf, then floor.
    fx.build({2, 0, 1});
    expectValidBsp(fx);
    const BspNode& root = fx.scene.nodes[size_t(fx.scene.regions[0].bspRoot)];
    EXPECT_EQ(fx.scene.fragments[size_t(root.firstFragment)].properties, 1) << "the first listed face is the root";
    EXPECT_EQ(root.plane.normal, fx.scene.properties[1].plane.normal);
    // Below the root, each side is rooted at the shelf (the next listed face).
    for (int child : {root.back, root.front}) {
        ASSERT_GE(child, 0);
        EXPECT_EQ(fx.scene.fragments[size_t(fx.scene.nodes[size_t(child)].firstFragment)].properties, 2);
    }
    EXPECT_EQ(fx.scene.regions[0].stats.splits, 2) << "the wall halves the floor and the shelf";
    EXPECT_EQ(fx.scene.regions[0].stats.fragments, 5);
    EXPECT_EQ(fx.scene.regions[0].stats.depth, 3);
    expectAreasAddUp(fx);
}

TEST(BspTree, PutsCoplanarFacesOfBothOrientationsIntoOneNode)
{
    Fixture fx;
    fx.add(quad({0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0})); // z = 0, normal +z
    fx.add(quad({5, 0, 0}, {5, 1, 0}, {6, 1, 0}, {6, 0, 0})); // z = 0, normal -z, elsewhere on the plane
    fx.add(quad({2, 0, 0}, {3, 0, 0}, {3, 1, 0}, {2, 1, 0})); // z = 0, normal +z
    fx.add(quad({0, 0, 2}, {1, 0, 2}, {1, 1, 2}, {0, 1, 2})); // z = 2
    fx.build();
    expectValidBsp(fx);
    const BspNode& root = fx.scene.nodes[size_t(fx.scene.regions[0].bspRoot)];
    EXPECT_EQ(root.fragmentCount, 3);
    EXPECT_EQ(root.forwardFragments, 2);
    EXPECT_EQ(fx.scene.fragments[size_t(root.firstFragment + 2)].properties, 1) << "the opposite face comes last";
    EXPECT_EQ(fx.scene.regions[0].stats.nodes, 2);
}

TEST(BspTree, PutsUnlistedFacesInSceneOrderAfterTheListedOnes)
{
    Fixture fx;
    fx.add(quad({0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}));
    fx.add(quad({0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}));
    fx.add(quad({0, 0, 2}, {1, 0, 2}, {1, 1, 2}, {0, 1, 2}));
    // Only face 2 is listed: ranks are its list position, then list size + scene index.
    fx.build({1 + 0, 1 + 1, 0});
    std::vector<int> preorder;
    for (const BspNode& node : fx.scene.nodes)
        preorder.push_back(fx.scene.fragments[size_t(node.firstFragment)].properties);
    EXPECT_EQ(preorder, (std::vector<int>{2, 0, 1}));
    expectValidBsp(fx);
}

TEST(BspTree, KeepsEverySplitFragmentOnItsSideAndItsAreaOnRandomTriangles)
{
    for (unsigned seed = 1; seed <= 20; ++seed) {
        std::mt19937 random(seed);
        Fixture fx;
        for (int i = 0; i < 60; ++i) {
            std::vector<Vec3> t = randomTriangle(random);
            if (model::polygonArea(t) > 1e-3)
                fx.add(t);
        }
        std::vector<int> rank(fx.scene.faces.size());
        std::iota(rank.begin(), rank.end(), 0);
        std::shuffle(rank.begin(), rank.end(), random);
        fx.build(rank);
        SCOPED_TRACE(seed);
        expectValidBsp(fx);
        expectAreasAddUp(fx);
        const RegionStats& stats = fx.scene.regions[0].stats;
        EXPECT_EQ(stats.inputFaces, int(fx.scene.faces.size()));
        EXPECT_EQ(stats.fragments, int(fx.scene.fragments.size()));
        EXPECT_GE(stats.fragments, stats.inputFaces);
        EXPECT_EQ(stats.nodes, int(fx.scene.nodes.size()));
        // A subtree's root has the lowest rank of everything below it.
        for (const BspNode& node : fx.scene.nodes) {
            int nodeRank = rank[size_t(fx.scene.fragments[size_t(node.firstFragment)].properties)];
            for (int i = 0; i < node.fragmentCount; ++i)
                nodeRank =
                    std::min(nodeRank, rank[size_t(fx.scene.fragments[size_t(node.firstFragment + i)].properties)]);
            for (int child : {node.back, node.front})
                for (int f : fx.subtreeFragments(child))
                    EXPECT_GT(rank[size_t(fx.scene.fragments[size_t(f)].properties)], nodeRank);
        }
    }
}

TEST(BspTree, RecordsTheRegionBoundsOfItsFragments)
{
    Fixture fx;
    fx.add(quad({0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}));
    fx.add(quad({0, 0, 3}, {1, 0, 3}, {1, 2, 3}, {0, 2, 3}));
    fx.build();
    const Box3& bounds = fx.scene.regions[0].bounds;
    EXPECT_EQ(bounds.min, Vec3(0, 0, 0));
    EXPECT_EQ(bounds.max, Vec3(1, 2, 3));
}

TEST(BspTree, LeavesAnEmptyRegionWithoutARoot)
{
    Fixture fx;
    fx.build();
    EXPECT_EQ(fx.scene.regions[0].bspRoot, -1);
    EXPECT_EQ(fx.scene.regions[0].stats.depth, 0);
    EXPECT_TRUE(fx.scene.nodes.empty());
}
