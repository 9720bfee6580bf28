// The shadings' lookups of points: FlatIndex numbers keys in the order they
// come, PointGrid finds the points near a point.
#include "output/flat_index.h"
#include "output/point_grid.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <random>
#include <vector>

using namespace regio;
using namespace regio::output;

namespace {

using Key = std::array<std::int64_t, 3>;

struct GoodHash {
    std::uint64_t operator()(const Key& k) const { return hashIntegers({k[0], k[1], k[2]}); }
};
// Every key in one slot chain and with one tag: only the keys tell them apart.
struct WorstHash {
    std::uint64_t operator()(const Key&) const { return 42; }
};

template <typename Hash>
void numbersKeysInTheOrderTheyCome(size_t count)
{
    FlatIndex<Key, Hash> index;
    for (std::int64_t i = 0; i < std::int64_t(count); ++i) {
        const auto [number, added] = index.insert({i, -i, 7 * i});
        EXPECT_TRUE(added);
        EXPECT_EQ(number, std::uint32_t(i));
    }
    EXPECT_EQ(index.size(), count);
    for (std::int64_t i = 0; i < std::int64_t(count); ++i) {
        const auto [number, added] = index.insert({i, -i, 7 * i});
        EXPECT_FALSE(added);
        EXPECT_EQ(number, std::uint32_t(i));
        EXPECT_EQ(index.find({i, -i, 7 * i}), std::uint32_t(i));
        EXPECT_EQ(index.key(std::uint32_t(i)), (Key{i, -i, 7 * i}));
    }
    EXPECT_EQ(index.find({-1, 1, -7}), (FlatIndex<Key, Hash>::kNone));
    EXPECT_EQ(index.size(), count);
}

} // namespace

TEST(FlatIndex, NumbersKeysInTheOrderTheyComeThroughGrowth)
{
    numbersKeysInTheOrderTheyCome<GoodHash>(100000); // from 16 slots, doubled 14 times
}

TEST(FlatIndex, TellsKeysApartWhenEveryHashIsTheSame) { numbersKeysInTheOrderTheyCome<WorstHash>(300); }

TEST(FlatIndex, AReservedIndexKeepsItsNumbers)
{
    FlatIndex<Key, GoodHash> index(1000);
    EXPECT_EQ(index.insert({1, 2, 3}).first, 0u);
    index.reserve(50000);
    EXPECT_EQ(index.find({1, 2, 3}), 0u);
    EXPECT_EQ(index.insert({3, 2, 1}).first, 1u);
}

TEST(PointGrid, FindsEveryPointWithinACellAndVisitsEachOnce)
{
    // Random points in a 5 cm cube, cells of 1 cm: forNear must find every
    // point within 1 cm of a probe, forNearest every point within half a
    // cell, each once.
    std::mt19937 random(7);
    std::uniform_real_distribution<double> coordinate(-0.025, 0.025);
    std::vector<Vec3> points(2000);
    PointGrid grid(0.01);
    for (size_t i = 0; i < points.size(); ++i) {
        points[i] = Vec3(coordinate(random), coordinate(random), coordinate(random));
        grid.insert(points[i], int(i));
    }
    for (int probe = 0; probe < 200; ++probe) {
        const Vec3 p(coordinate(random), coordinate(random), coordinate(random));
        for (const bool nearest : {false, true}) {
            const double reach = nearest ? 0.005 : 0.01;
            std::vector<int> seen;
            const auto visit = [&](int id) { seen.push_back(id); };
            if (nearest)
                grid.forNearest(p, visit);
            else
                grid.forNear(p, visit);
            std::vector<int> sorted = seen;
            std::sort(sorted.begin(), sorted.end());
            EXPECT_TRUE(std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end()) << "a point seen twice";
            for (size_t i = 0; i < points.size(); ++i) {
                if (glm::length(points[i] - p) < reach) {
                    EXPECT_TRUE(std::binary_search(sorted.begin(), sorted.end(), int(i)))
                        << "point " << i << " at " << glm::length(points[i] - p) << " m not found";
                }
            }
        }
    }
}

TEST(PointGrid, VisitsACellsPointsInTheOrderTheyCame)
{
    // The smooth shading welds a corner to the first point it finds.
    PointGrid grid(1.0);
    for (int id : {5, 3, 9, 1})
        grid.insert(Vec3(0.5, 0.5, 0.5), id);
    std::vector<int> seen;
    grid.forNearest(Vec3(0.5, 0.5, 0.5), [&](int id) { seen.push_back(id); });
    EXPECT_EQ(seen, (std::vector<int>{5, 3, 9, 1}));
}
