// The back-to-front walk of the regional tree and the region BSP trees
// (paper Appendix A, with back faces kept as blockers).
#include "solver/visibility/traversal.h"

#include "solver/prepare/prepare.h"
#include "support/random_scenes.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <random>

using namespace regio;
using namespace regio::solver;
using model::Vec3;

namespace {

PreparedScene prepared(const model::Scene& scene, RegionsMode mode)
{
    PrepareOptions options;
    options.regions = mode;
    options.autoRegionPatchThreshold = 60;
    model::Result<PreparedScene> result = prepareScene(scene, options);
    EXPECT_TRUE(result.ok());
    return std::move(*result);
}

std::vector<int> positions(const std::vector<int>& order, size_t nodeCount)
{
    std::vector<int> at(nodeCount, -1);
    for (size_t i = 0; i < order.size(); ++i)
        at[size_t(order[i])] = int(i);
    return at;
}

void collect(const PreparedScene& s, int node, std::vector<int>& out)
{
    if (node < 0)
        return;
    out.push_back(node);
    collect(s, s.nodes[size_t(node)].back, out);
    collect(s, s.nodes[size_t(node)].front, out);
}

// Möller-Trumbore; returns the distance along the ray or -1.
double hit(const PreparedScene& s, const Piece& e, const Vec3& origin, const Vec3& direction)
{
    const Vec3 a = s.pieceVertices[size_t(e.vertices[0])], b = s.pieceVertices[size_t(e.vertices[1])],
               c = s.pieceVertices[size_t(e.vertices[2])];
    const Vec3 e1 = b - a, e2 = c - a, p = glm::cross(direction, e2);
    const double det = glm::dot(e1, p);
    if (std::abs(det) < 1e-14)
        return -1.0;
    const Vec3 t = origin - a;
    const double u = glm::dot(t, p) / det;
    if (u < 0.0 || u > 1.0)
        return -1.0;
    const Vec3 q = glm::cross(t, e1);
    const double v = glm::dot(direction, q) / det;
    if (v < 0.0 || u + v > 1.0)
        return -1.0;
    const double distance = glm::dot(e2, q) / det;
    return distance > 1e-9 ? distance : -1.0;
}

Vec3 randomEye(std::mt19937& random, const Vec3& size)
{
    std::uniform_real_distribution<double> unit(0.02, 0.98);
    return {unit(random) * size.x, unit(random) * size.y, unit(random) * size.z};
}

Vec3 randomDirection(std::mt19937& random)
{
    std::normal_distribution<double> normal;
    return glm::normalize(Vec3{normal(random), normal(random), normal(random)});
}

} // namespace

TEST(Traversal, VisitsEveryNodeOnceBackFacingOnesIncluded)
{
    const model::Scene scene = test::roomWithRegions(3, 2, 2, 3);
    for (RegionsMode mode : {RegionsMode::Authored, RegionsMode::None, RegionsMode::Auto}) {
        PreparedScene s = prepared(scene, mode);
        std::mt19937 random(11);
        for (int trial = 0; trial < 20; ++trial) {
            std::vector<int> order;
            backToFrontNodes(s, randomEye(random, {6, 3, 4}), nullptr, order);
            std::vector<int> sorted = order;
            std::sort(sorted.begin(), sorted.end());
            ASSERT_EQ(sorted.size(), s.nodes.size());
            for (size_t i = 0; i < sorted.size(); ++i)
                EXPECT_EQ(sorted[i], int(i));
        }
    }
}

TEST(Traversal, PutsTheFarSubtreeOfEveryNodeBeforeItAndTheNearSubtreeAfter)
{
    const model::Scene scene = test::roomWithRegions(5, 3, 2, 3);
    PreparedScene s = prepared(scene, RegionsMode::Authored);
    std::mt19937 random(12);
    for (int trial = 0; trial < 50; ++trial) {
        const Vec3 eye = randomEye(random, {6, 3, 4});
        std::vector<int> order;
        backToFrontNodes(s, eye, nullptr, order);
        const std::vector<int> at = positions(order, s.nodes.size());
        for (size_t n = 0; n < s.nodes.size(); ++n) {
            const BspNode& node = s.nodes[n];
            const bool inFront = node.plane.signedDistance(eye) > 0.0;
            std::vector<int> far, near;
            collect(s, inFront ? node.back : node.front, far);
            collect(s, inFront ? node.front : node.back, near);
            for (int f : far)
                EXPECT_LT(at[size_t(f)], at[n]);
            for (int f : near)
                EXPECT_GT(at[size_t(f)], at[n]);
        }
    }
}

TEST(Traversal, PaintsRegionsOnTheFarSideOfEachSeparatingPlaneFirst)
{
    const model::Scene scene = test::roomWithRegions(6, 3, 2, 2);
    PreparedScene s = prepared(scene, RegionsMode::Authored);
    std::mt19937 random(13);
    for (int trial = 0; trial < 50; ++trial) {
        const Vec3 eye = randomEye(random, {6, 3, 4});
        std::vector<int> regionOrder;
        forEachNodeBackToFront(
            s, eye,
            [&](int region) {
                regionOrder.push_back(region);
                return true;
            },
            [](int, bool) {});
        std::vector<int> at(s.regions.size(), -1);
        for (size_t i = 0; i < regionOrder.size(); ++i)
            at[size_t(regionOrder[i])] = int(i);
        for (const RegionalNode& node : s.regionalNodes) {
            if (node.isLeaf())
                continue;
            // Regions of the eye's side come after all regions of the other side.
            std::vector<int> backRegions, frontRegions;
            std::function<void(int, std::vector<int>&)> leaves = [&](int index, std::vector<int>& out) {
                const RegionalNode& n = s.regionalNodes[size_t(index)];
                if (n.isLeaf()) {
                    out.push_back(n.region);
                    return;
                }
                leaves(n.back, out);
                leaves(n.front, out);
            };
            leaves(node.back, backRegions);
            leaves(node.front, frontRegions);
            const bool eyeInFront = eye[node.axis] > node.position;
            for (int far : eyeInFront ? backRegions : frontRegions)
                for (int near : eyeInFront ? frontRegions : backRegions)
                    if (at[size_t(far)] >= 0 && at[size_t(near)] >= 0) {
                        EXPECT_LT(at[size_t(far)], at[size_t(near)]);
                    }
        }
    }
}

TEST(Traversal, NeverPaintsAnOccludedPieceAfterTheOneHidingIt)
{
    // Ray casting: along any ray from the eye, the nearer of two element
    // pieces hit must be painted later. Checked in all three region modes.
    const model::Scene scene = test::roomWithRegions(8, 2, 2, 4);
    for (RegionsMode mode : {RegionsMode::Authored, RegionsMode::None, RegionsMode::Auto}) {
        PreparedScene s = prepared(scene, mode);
        std::mt19937 random(14);
        int pairs = 0;
        for (int trial = 0; trial < 12; ++trial) {
            const Vec3 eye = randomEye(random, {6, 3, 4});
            std::vector<int> order;
            backToFrontNodes(s, eye, nullptr, order);
            const std::vector<int> at = positions(order, s.nodes.size());
            for (int ray = 0; ray < 150; ++ray) {
                const Vec3 direction = randomDirection(random);
                std::vector<std::pair<double, int>> hits;
                for (size_t n = 0; n < s.nodes.size(); ++n)
                    for (int i = s.nodes[n].firstPiece; i < s.nodes[n].firstPiece + s.nodes[n].pieceCount; ++i)
                        if (double t = hit(s, s.pieces[size_t(i)], eye, direction); t > 0.0)
                            hits.push_back({t, int(n)});
                std::sort(hits.begin(), hits.end());
                for (size_t i = 0; i + 1 < hits.size(); ++i) {
                    if (hits[i + 1].first - hits[i].first < 1e-7 || hits[i].second == hits[i + 1].second)
                        continue; // an edge hit twice, or one plane
                    EXPECT_GT(at[size_t(hits[i].second)], at[size_t(hits[i + 1].second)])
                        << "nearer node painted before a farther one it hides";
                    ++pairs;
                }
            }
        }
        EXPECT_GT(pairs, 500) << "the rays did test occlusion";
    }
}

TEST(Traversal, CullsRegionsEntirelyBehindTheShooterPlaneAndNothingElse)
{
    const model::Scene scene = test::roomWithRegions(9, 3, 2, 2);
    PreparedScene s = prepared(scene, RegionsMode::Authored);
    // A shooter in the middle third (x = 2.5) facing east (+x).
    const Plane lookingEast = Plane::fromPointNormal({2.5, 1, 1}, {1, 0, 0});
    std::vector<int> order;
    backToFrontNodes(s, Vec3{2.5, 1, 1}, &lookingEast, order);
    std::vector<bool> regionSeen(s.regions.size(), false);
    for (int n : order)
        regionSeen[size_t(s.nodes[size_t(n)].region)] = true;
    for (size_t r = 0; r < s.regions.size(); ++r) {
        const bool behind = boxBehindPlane(s.regions[r].bounds, lookingEast);
        EXPECT_EQ(regionSeen[r], !behind) << s.regions[r].id;
    }
    // The west cells (x < 2) lie behind, apart from geometry clipped into them.
    EXPECT_FALSE(regionSeen[0]);
    EXPECT_TRUE(regionSeen[s.regions.size() - 1]);
}

TEST(Traversal, BoxBehindPlaneUsesTheCornerFarthestAlongTheNormal)
{
    Box3 box;
    box.extend(Vec3{0, 0, 0});
    box.extend(Vec3{1, 1, 1});
    EXPECT_TRUE(boxBehindPlane(box, Plane::fromPointNormal({1, 0, 0}, {1, 0, 0}))); // touching counts as behind
    EXPECT_FALSE(boxBehindPlane(box, Plane::fromPointNormal({0.99, 0, 0}, {1, 0, 0})));
    EXPECT_FALSE(boxBehindPlane(box, Plane::fromPointNormal({1.5, 1.5, 1.5}, glm::normalize(Vec3{-1, -1, -1}))));
    EXPECT_TRUE(boxBehindPlane(box, Plane::fromPointNormal({1.01, 1.01, 1.01}, glm::normalize(Vec3{1, 1, 1}))));
    EXPECT_TRUE(boxBehindPlane(Box3{}, Plane{}));
}
