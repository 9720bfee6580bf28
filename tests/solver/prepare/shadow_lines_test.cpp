// The lines where a solid's shadows begin at its feet
// (solver/prepare/shadow_lines.h), and the cuts along them.
#include "solver/prepare/shadow_lines.h"

#include "solver/prepare/covered_parts.h"
#include "solver/prepare/face_polygon.h"

#include "support/adaptive_scenes.h"
#include "support/covered_faces.h"
#include "support/prepared_scenes.h"
#include "support/sample_scenes.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <set>
#include <vector>

using namespace regio;
using namespace regio::solver;
using model::Vec3;

namespace {

const Vec3 kUp{0.0, 1.0, 0.0};

// The lamp vertex whose edge-vertex plane holds the line (the plane through
// the box's vertical edge at the line's corner and the vertex), if any.
bool drawnBy(const ShadowLine& line, const std::vector<Vec3>& lamp)
{
    for (const Vec3& light : lamp) {
        const Vec3 inPlane = glm::cross(kUp, light - line.origin);
        if (std::abs(glm::dot(inPlane, line.direction)) < 1e-9 && glm::dot(line.direction, line.origin - light) > 0.0)
            return true;
    }
    return false;
}

ShadowLine lineFrom(const Vec3& origin, const Vec3& direction, double length)
{
    ShadowLine line;
    line.origin = origin;
    line.direction = direction;
    line.length = length;
    return line;
}

model::Scene boxUnderTwoLamps()
{
    model::Scene scene = test::boxUnderLamp();
    // A dim lamp on the other side.
    test::addMaterial(scene, "dim", Rgb{0.0}, Rgb{1.0});
    test::addPolygon(scene, "dim-lamp", {{0.6, 1.5, -0.2}, {1.0, 1.5, -0.2}, {1.0, 1.5, 0.2}, {0.6, 1.5, 0.2}}, "dim");
    return scene;
}

// Every patch of face `f` lies within one of its uncovered pieces (corners
// inside or on its outline): none crosses a line between two pieces.
void expectPatchesWithinPieces(const PreparedScene& s, size_t f)
{
    const std::vector<std::vector<Vec3>> pieces = uncoveredPieces(s)[f];
    const Vec3& normal = s.properties[f].plane.normal;
    for (int p = s.faces[f].firstPatch; p < s.faces[f].firstPatch + s.faces[f].patchCount; ++p) {
        const Patch& patch = s.patches[size_t(p)];
        const bool inOne = std::any_of(pieces.begin(), pieces.end(), [&](const std::vector<Vec3>& piece) {
            return std::all_of(patch.vertices.begin(), patch.vertices.end(),
                               [&](int v) { return insideConvex(piece, normal, s.vertices[size_t(v)]); });
        });
        EXPECT_TRUE(inOne) << s.faces[f].id << ": the patch at (" << patch.centroid.x << ", " << patch.centroid.z
                           << ") crosses a line between pieces";
    }
}

} // namespace

TEST(ShadowLines, EveryLampVertexDrawsALineFromTheBoxsFootCornersAwayFromTheLampAsFarAsTheEdgesShadow)
{
    const PreparedScene s = test::prepared(test::boxUnderLamp());
    const size_t floor = test::faceNamed(s, "floor.face");
    const std::vector<Vec3>& lamp = s.faces[test::faceNamed(s, "lamp.face")].polygon;
    const std::vector<ShadowLine> lines = footShadowLines(s, floor, test::coversOf(s, floor), lightFaces(s), 0.0, 1000);
    ASSERT_FALSE(lines.empty());
    std::set<std::pair<double, double>> corners;
    for (const ShadowLine& line : lines) {
        // From a corner of the box's footprint, in the floor.
        EXPECT_NEAR(std::abs(line.origin.x), 0.3, 1e-12);
        EXPECT_NEAR(std::abs(line.origin.z), 0.3, 1e-12);
        EXPECT_NEAR(line.origin.y, 0.0, 1e-12);
        EXPECT_NEAR(line.direction.y, 0.0, 1e-12);
        EXPECT_NEAR(glm::length(line.direction), 1.0, 1e-12);
        corners.insert({line.origin.x, line.origin.z});
        // In the plane of the vertical edge and a lamp vertex, away from the lamp.
        EXPECT_TRUE(drawnBy(line, lamp));
        // Into the floor the box leaves uncovered.
        const Vec3 probe = line.origin + line.direction * 1e-3;
        EXPECT_TRUE(std::abs(probe.x) > 0.3 || std::abs(probe.z) > 0.3);
        // As far as the shadow of the edge's top: the ray from some lamp
        // vertex over the top lands at the line's end.
        const Vec3 end = line.origin + line.direction * line.length;
        const Vec3 top = line.origin + kUp * 0.6;
        bool landsThere = false;
        for (const Vec3& light : lamp)
            landsThere =
                landsThere || glm::length(glm::cross(glm::normalize(end - light), glm::normalize(top - light))) < 1e-9;
        EXPECT_TRUE(landsThere) << "a line of length " << line.length;
    }
    // The corners away from the lamp (x = +0.3) and those beside it.
    EXPECT_EQ(corners.size(), 4u);
    // Lines at one corner differ in direction by more than 2 degrees.
    for (size_t i = 0; i < lines.size(); ++i)
        for (size_t j = i + 1; j < lines.size(); ++j)
            if (lines[i].origin == lines[j].origin) {
                EXPECT_LT(glm::dot(lines[i].direction, lines[j].direction), std::cos(2.0 * M_PI / 180.0));
            }
}

TEST(ShadowLines, ASolidNarrowerThanTheMinimumWidthDrawsNone)
{
    const PreparedScene s = test::prepared(test::boxUnderLamp());
    const size_t floor = test::faceNamed(s, "floor.face");
    // The box's footprint is 0.6 m square: twice its area over its perimeter is 0.3 m.
    EXPECT_FALSE(footShadowLines(s, floor, test::coversOf(s, floor), lightFaces(s), 0.29, 1000).empty());
    EXPECT_TRUE(footShadowLines(s, floor, test::coversOf(s, floor), lightFaces(s), 0.31, 1000).empty());
}

TEST(ShadowLines, PastTheBudgetTheLinesOfTheBrightestLightAreKept)
{
    const PreparedScene s = test::prepared(boxUnderTwoLamps());
    const size_t floor = test::faceNamed(s, "floor.face");
    const std::vector<Vec3>& bright = s.faces[test::faceNamed(s, "lamp.face")].polygon;
    const std::vector<Vec3>& dim = s.faces[test::faceNamed(s, "dim-lamp.face")].polygon;
    const std::vector<ShadowLine> all = footShadowLines(s, floor, test::coversOf(s, floor), lightFaces(s), 0.0, 1000);
    int fromBright = 0, fromDim = 0;
    for (const ShadowLine& line : all) {
        fromBright += drawnBy(line, bright);
        fromDim += drawnBy(line, dim);
    }
    ASSERT_GT(fromBright, 2);
    ASSERT_GT(fromDim, 0);
    const std::vector<ShadowLine> kept = footShadowLines(s, floor, test::coversOf(s, floor), lightFaces(s), 0.0, 3);
    ASSERT_EQ(kept.size(), 3u);
    for (const ShadowLine& line : kept)
        EXPECT_TRUE(drawnBy(line, bright));
}

TEST(ShadowLines, ACutSplitsThePiecesItsSegmentCrossesIntoTwoConvexOnesAndLeavesTheOthers)
{
    const std::vector<Vec3> crossed{{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}};
    const std::vector<Vec3> beyond{{2, 0, 0}, {2, 0, 1}, {3, 0, 1}, {3, 0, 0}};
    // Counter-clockwise around +y seen from above: (0,0,0) -> (0,0,1) -> (1,0,1).
    ASSERT_GT(glm::dot(glm::cross(crossed[1] - crossed[0], crossed[2] - crossed[0]), kUp), 0.0);
    std::vector<std::vector<Vec3>> pieces{crossed, beyond};
    const ShadowLine line = lineFrom({0.5, 0.0, 0.2}, {0.0, 0.0, 1.0}, 0.5);
    cutAlong(pieces, line, kUp, 0.05, 15.0);
    ASSERT_EQ(pieces.size(), 3u) << "the crossed square in two, the other whole";
    double area = 0.0;
    for (const std::vector<Vec3>& piece : pieces) {
        area += model::polygonArea(piece);
        for (size_t i = 0; i < piece.size(); ++i) {
            const Vec3& a = piece[i];
            const Vec3& b = piece[(i + 1) % piece.size()];
            const Vec3& c = piece[(i + 2) % piece.size()];
            EXPECT_GT(glm::dot(glm::cross(b - a, c - b), kUp), 0.0) << "convex, counter-clockwise";
        }
    }
    EXPECT_NEAR(area, 2.0, 1e-12);
    EXPECT_EQ(pieces.back(), beyond);
}

TEST(ShadowLines, NoCutLeavesASliverOrASharpCorner)
{
    const std::vector<Vec3> square{{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}};
    std::vector<std::vector<Vec3>> pieces{square};
    const ShadowLine nearEdge = lineFrom({0.02, 0.0, 0.0}, {0.0, 0.0, 1.0}, 1.0);
    cutAlong(pieces, nearEdge, kUp, 0.05, 15.0);
    EXPECT_EQ(pieces.size(), 1u) << "2 cm from the edge, the minimum width is 5 cm";
    // Meets the far side 6 degrees from it, leaving a triangle 8 cm wide.
    const ShadowLine slanted = lineFrom({0.0, 0.0, 0.92}, glm::normalize(Vec3{1.0, 0.0, 0.1}), 2.0);
    cutAlong(pieces, slanted, kUp, 0.05, 15.0);
    EXPECT_EQ(pieces.size(), 1u) << "a corner of 6 degrees";
    cutAlong(pieces, slanted, kUp, 0.05, 5.0);
    EXPECT_EQ(pieces.size(), 2u);
}

TEST(ShadowLines, PreparationCutsTheFloorAlongThemAndListsTheCorners)
{
    const PreparedScene s = test::prepared(test::boxUnderLamp());
    const size_t floor = test::faceNamed(s, "floor.face");
    ASSERT_FALSE(s.shadowCorners.empty());
    for (const Vec3& corner : s.shadowCorners) {
        EXPECT_NEAR(std::abs(corner.x), 0.3, 1e-12);
        EXPECT_NEAR(std::abs(corner.z), 0.3, 1e-12);
    }
    // Every cut the limits allow is made: no piece left would be cut again.
    const ShadowLineLimits limits;
    const std::vector<ShadowLine> lines = footShadowLines(s, floor, test::coversOf(s, floor), lightFaces(s),
                                                          limits.solidMinWidth * s.patchSize, limits.maxLines);
    ASSERT_FALSE(lines.empty());
    const std::vector<std::vector<Vec3>> pieces = uncoveredPieces(s)[floor];
    EXPECT_GT(pieces.size(), 4u) << "more than the four around the footprint";
    for (const ShadowLine& line : lines)
        for (const std::vector<Vec3>& piece : pieces) {
            std::vector<std::vector<Vec3>> one{piece};
            cutAlong(one, line, kUp, limits.cutMinWidth * s.patchSize, limits.cutMinAngle);
            EXPECT_EQ(one.size(), 1u) << "a piece the line at (" << line.origin.x << ", " << line.origin.z
                                      << ") still crosses";
        }
}

TEST(ShadowLines, ThePatchesOfTheFloorKeepTheLinesAsEdges)
{
    // Where the pieces' strips meet, fans close the T-vertices and flips
    // widen thin triangles; no flip may swap a line between two pieces for
    // the other diagonal (it did at the Cornell box's tall block, where the
    // umbra's line from its front corner was flipped away).
    const PreparedScene box = test::prepared(test::boxUnderLamp());
    expectPatchesWithinPieces(box, test::faceNamed(box, "floor.face"));
    const PreparedScene cornell = test::prepared(test::loadSample("cornell-box"));
    expectPatchesWithinPieces(cornell, test::faceNamed(cornell, "floor.top"));
}
