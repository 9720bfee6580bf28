#include "model/geometry/convex_decomposition.h"

#include <gtest/gtest.h>

#include <map>
#include <utility>

using namespace regio::model;

namespace {

using V2 = glm::dvec2;

double cross(V2 a, V2 b) { return a.x * b.y - a.y * b.x; }

// Every piece convex and counter-clockwise; every rim edge on exactly one
// piece, in its direction; every other piece edge matched by the reverse
// edge of another piece (a diagonal); the areas add up to the polygon's.
void expectExactConvexCover(const std::vector<V2>& p, const Polygon2Loop& outer, const std::vector<Polygon2Loop>& holes,
                            const std::vector<Polygon2Loop>& pieces)
{
    std::map<std::pair<int, int>, int> uses;
    double area = 0.0;
    for (const Polygon2Loop& piece : pieces) {
        ASSERT_GE(piece.size(), 3u);
        for (size_t i = 0; i < piece.size(); ++i) {
            V2 a = p[size_t(piece[i])], b = p[size_t(piece[(i + 1) % piece.size()])],
               c = p[size_t(piece[(i + 2) % piece.size()])];
            EXPECT_GE(cross(b - a, c - b), -1e-12) << "reflex corner in a piece";
            ++uses[{piece[i], piece[(i + 1) % piece.size()]}];
        }
        double a = signedArea2(p, piece);
        EXPECT_GT(a, 0.0);
        area += a;
    }
    double expected = signedArea2(p, outer);
    std::vector<Polygon2Loop> rims{outer};
    for (const Polygon2Loop& hole : holes) {
        expected += signedArea2(p, hole);
        rims.push_back(hole);
    }
    EXPECT_NEAR(area, expected, 1e-9);
    for (const Polygon2Loop& rim : rims)
        for (size_t i = 0; i < rim.size(); ++i) {
            std::pair<int, int> edge{rim[i], rim[(i + 1) % rim.size()]};
            EXPECT_EQ(uses[edge], 1) << "rim edge " << edge.first << "->" << edge.second;
            uses.erase(edge);
        }
    for (const auto& [edge, count] : uses) {
        EXPECT_EQ(count, 1);
        auto twin = uses.find({edge.second, edge.first});
        EXPECT_TRUE(twin != uses.end() && twin->second == 1)
            << "diagonal " << edge.first << "->" << edge.second << " has no twin";
    }
}

} // namespace

TEST(ConvexDecomposition, AConvexPolygonComesBackAsItIs)
{
    std::vector<V2> p{{0, 0}, {1, 0}, {2, 0}, {2, 1}, {0, 1}};
    auto pieces = convexDecomposition(p, {0, 1, 2, 3, 4}, {}, 1e-9);
    ASSERT_TRUE(pieces.ok());
    ASSERT_EQ(pieces->size(), 1u);
    EXPECT_EQ((*pieces)[0], (Polygon2Loop{0, 1, 2, 3, 4})) << "the collinear corner stays";
}

TEST(ConvexDecomposition, ACombIsSplitIntoFewConvexPiecesWithTheTeethIntact)
{
    // Three teeth on a bar: a "E" turned on its back.
    std::vector<V2> p{{0, 0}, {5, 0}, {5, 2}, {4, 2}, {4, 1}, {3, 1}, {3, 2}, {2, 2}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
    Polygon2Loop outer{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11};
    auto pieces = convexDecomposition(p, outer, {}, 1e-9);
    ASSERT_TRUE(pieces.ok()) << pieces.error().message;
    expectExactConvexCover(p, outer, {}, *pieces);
    // Four reflex corners: Hertel-Mehlhorn needs at most 2r + 1 = 9 pieces;
    // ear clipping alone would give 10 triangles.
    EXPECT_LE(pieces->size(), 9u);
}

TEST(ConvexDecomposition, HolesAreBridgedAndCoveredAround)
{
    std::vector<V2> p{{0, 0}, {6, 0}, {6, 3}, {0, 3},  // outer
                      {1, 1}, {1, 2}, {2, 2}, {2, 1},  // first hole (clockwise)
                      {4, 1}, {4, 2}, {5, 2}, {5, 1}}; // second hole
    Polygon2Loop outer{0, 1, 2, 3};
    std::vector<Polygon2Loop> holes{{4, 5, 6, 7}, {8, 9, 10, 11}};
    auto pieces = convexDecomposition(p, outer, holes, 1e-9);
    ASSERT_TRUE(pieces.ok()) << pieces.error().message;
    expectExactConvexCover(p, outer, holes, *pieces);
}

TEST(ConvexDecomposition, CollinearRimVerticesStayOnThePieceEdges)
{
    // An L whose long edges carry extra corners, as a cap's outline does
    // where side faces meet along the cut.
    std::vector<V2> p{{0, 0}, {1, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}, {0, 1}};
    Polygon2Loop outer{0, 1, 2, 3, 4, 5, 6, 7};
    auto pieces = convexDecomposition(p, outer, {}, 1e-9);
    ASSERT_TRUE(pieces.ok());
    expectExactConvexCover(p, outer, {}, *pieces);
    EXPECT_EQ(pieces->size(), 2u);
}

TEST(ConvexDecomposition, ADegenerateOutlineIsRefused)
{
    std::vector<V2> p{{0, 0}, {1, 0}, {2, 0}};
    EXPECT_FALSE(convexDecomposition(p, {0, 1, 2}, {}, 1e-9).ok());
}
