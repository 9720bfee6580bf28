// Meshing only what no solid covers (solver/prepare/covered_parts.h), as one
// conforming mesh of the uncovered pieces (solver/prepare/conforming_strips.h).
#include "solver/prepare/conforming_strips.h"
#include "solver/prepare/covered_parts.h"

#include "support/adaptive_scenes.h"
#include "support/covered_faces.h"
#include "support/prepared_scenes.h"
#include "support/random_scenes.h"
#include "support/sample_scenes.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cstdio>
#include <map>
#include <string>
#include <utility>
#include <vector>

using namespace regio;
using namespace regio::solver;
using model::Vec3;

namespace {

const Vec3 kUp{0.0, 1.0, 0.0};

double meshArea(const StripMesh& m)
{
    double area = 0.0;
    for (const Triangle& t : m.triangles)
        area += 0.5 * glm::dot(glm::cross(m.points[size_t(t[1])] - m.points[size_t(t[0])],
                                          m.points[size_t(t[2])] - m.points[size_t(t[0])]),
                               kUp);
    return area;
}

// Every edge is used once in each direction, or once and lies on `outline`.
void expectConforming(const StripMesh& m, const std::vector<std::vector<Vec3>>& outlines)
{
    std::map<std::pair<int, int>, int> directed;
    for (const Triangle& t : m.triangles)
        for (int i = 0; i < 3; ++i)
            ++directed[{t[size_t(i)], t[size_t((i + 1) % 3)]}];
    for (const auto& [edge, count] : directed) {
        EXPECT_EQ(count, 1);
        if (directed.count({edge.second, edge.first}))
            continue;
        const Vec3 mid = (m.points[size_t(edge.first)] + m.points[size_t(edge.second)]) * 0.5;
        bool onOutline = false;
        for (const auto& loop : outlines)
            for (size_t i = 0; i < loop.size(); ++i) {
                const Vec3 a = loop[i], ab = loop[(i + 1) % loop.size()] - a;
                const double t = glm::dot(mid - a, ab) / glm::dot(ab, ab);
                onOutline = onOutline || (t > 0.0 && t < 1.0 && glm::length(a + ab * t - mid) < 1e-9);
            }
        EXPECT_TRUE(onOutline) << "an open edge inside the pieces at (" << mid.x << ", " << mid.z << ")";
    }
}

} // namespace

TEST(ConformingStrips, OnePieceIsMeshedExactlyAsTheStripMethodMeshesIt)
{
    const std::vector<Vec3> square{{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}};
    const StripMesh one = stripTriangulatePieces({square}, kUp, 0.3);
    const StripMesh strip = stripTriangulate(square, kUp, 0.3);
    EXPECT_EQ(one.points, strip.points);
    EXPECT_EQ(one.triangles, strip.triangles);
}

TEST(ConformingStrips, PiecesThatDivideTheirCommonLineDifferentlyMeetVertexToVertex)
{
    // Two rectangles of different widths on either side of x = 1: each one's
    // strips cut the line x = 1 at their own heights.
    const std::vector<Vec3> left{{0, 0, 0}, {0, 0, 1.7}, {1, 0, 1.7}, {1, 0, 0}};
    const std::vector<Vec3> right{{1, 0, 0}, {1, 0, 1.7}, {1.45, 0, 1.7}, {1.45, 0, 0}};
    const StripMesh m = stripTriangulatePieces({left, right}, kUp, 0.4);
    EXPECT_NEAR(meshArea(m), 1.7 * 1.45, 1e-12);
    expectConforming(m, {{{0, 0, 0}, {0, 0, 1.7}, {1.45, 0, 1.7}, {1.45, 0, 0}}});
    double worst = 180.0;
    for (const Triangle& t : m.triangles)
        worst = std::min(worst,
                         minimumAngleDegrees(m.points[size_t(t[0])], m.points[size_t(t[1])], m.points[size_t(t[2])]));
    EXPECT_GT(worst, 15.0) << "no sliver where the two divisions nearly meet";
}

TEST(CoveredParts, ABoxStandingOnAFloorLeavesAHoleTheSizeOfItsFootprint)
{
    // The floor is an open polygon and the box a solid: the box's bottom
    // covers the floor, the floor (not a solid) covers nothing.
    const PreparedScene s = test::prepared(test::boxUnderLamp());
    const std::vector<std::vector<std::vector<Vec3>>> pieces = uncoveredPieces(s);
    for (size_t f = 0; f < s.faces.size(); ++f) {
        double elements = 0.0;
        for (int e : s.faces[f].elements) {
            elements += s.elements[size_t(e)].area;
            const Vec3 c = s.elements[size_t(e)].centroid;
            if (s.faces[f].id == "floor.face") {
                EXPECT_FALSE(std::abs(c.x) < 0.3 && std::abs(c.z) < 0.3) << "an element under the box";
            }
        }
        if (s.faces[f].id == "floor.face") {
            EXPECT_GE(pieces[f].size(), 4u);
            EXPECT_NEAR(elements, 9.0 - 0.36, 1e-9);
        } else {
            EXPECT_EQ(pieces[f].size(), 1u) << s.faces[f].id;
            EXPECT_NEAR(elements, s.faces[f].area, 1e-9) << s.faces[f].id;
        }
    }
}

namespace {

// The mesh of a covered face: conforming (open edges only on its outline and
// its covers'), covering exactly what no solid covers; returns its patches'
// smallest angle.
double checkCoveredFace(const PreparedScene& s, size_t f)
{
    std::map<std::pair<int, int>, int> directed;
    for (int e : s.faces[f].elements) {
        const auto& v = s.elements[size_t(e)].vertices;
        for (int i = 0; i < 3; ++i)
            ++directed[{v[size_t(i)], v[size_t((i + 1) % 3)]}];
    }
    for (const auto& [edge, count] : directed) {
        EXPECT_EQ(count, 1) << s.faces[f].id;
        if (directed.count({edge.second, edge.first}))
            continue;
        const Vec3 a = s.vertices[size_t(edge.first)], b = s.vertices[size_t(edge.second)];
        EXPECT_TRUE(test::onOutlineOrCover(s, f, (a + b) * 0.5)) << s.faces[f].id << ": a T-vertex";
    }
    double elements = 0.0;
    for (int e : s.faces[f].elements)
        elements += s.elements[size_t(e)].area;
    EXPECT_NEAR(elements, test::uncoveredArea(s, f), 1e-9) << s.faces[f].id;
    double worst = 180.0;
    for (int p = s.faces[f].firstPatch; p < s.faces[f].firstPatch + s.faces[f].patchCount; ++p) {
        const auto& v = s.patches[size_t(p)].vertices;
        worst = std::min(
            worst, minimumAngleDegrees(s.vertices[size_t(v[0])], s.vertices[size_t(v[1])], s.vertices[size_t(v[2])]));
    }
    return worst;
}

} // namespace

TEST(CoveredParts, TheCornellBoxFloorIsOneConformingMeshAroundTheTurnedBlocks)
{
    const PreparedScene s = test::prepared(test::loadSample("cornell-box"));
    int checked = 0;
    for (size_t f = 0; f < s.faces.size(); ++f) {
        if (test::coversOf(s, f).empty())
            continue;
        ++checked;
        // The shadow lines from the blocks' feet (solver/prepare/shadow_lines.h)
        // cut the floor at angles of 15 degrees or more; the strips and the
        // T-vertices between the pieces leave the smallest patch angle at 7.3.
        EXPECT_GT(checkCoveredFace(s, f), 7.0) << s.faces[f].id << ": patches stay well shaped";
    }
    EXPECT_EQ(checked, 1) << "the floor, under the two blocks (the walls are no solid)";
}

TEST(CoveredParts, AFloorUnderManyBoxesIsCutIntoCellsAndStaysOneConformingMesh)
{
    // Twelve boxes (some standing into each other) on the floor of a closed
    // room: more covers than kCoversForCells, so the floor is cut into cells
    // first; the boxes' bottoms lie on the room's floor and are covered too.
    const PreparedScene s = test::prepared(test::roomWithRegions(21, 3, 2, 3), RegionsMode::None);
    size_t most = 0;
    for (size_t f = 0; f < s.faces.size(); ++f) {
        const size_t covers = test::coversOf(s, f).size();
        if (covers == 0)
            continue;
        most = std::max(most, covers);
        // Boxes a few millimetres apart leave gaps as thin: no angle bound here.
        const double worst = checkCoveredFace(s, f);
        if (covers > 1)
            std::printf("%s under %zu boxes: smallest patch angle %.1f degrees\n", s.faces[f].id.c_str(), covers,
                        worst);
    }
    EXPECT_GT(most, 8u) << "the premise: the floor carries more boxes than the whole-face path takes";
}
