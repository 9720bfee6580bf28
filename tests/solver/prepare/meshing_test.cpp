// Patches to elements (paper §5.5) and the storage order the painter relies on.
#include "solver/prepare/meshing.h"

#include "solver/prepare/bsp_tree.h"
#include "solver/prepare/pieces.h"
#include "solver/prepare/strip_triangulation.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <map>
#include <numeric>
#include <utility>

using namespace regio;
using namespace regio::solver;
using model::Vec3;

namespace {

// Fragments from a one-region BSP build of the given faces, the faces meshed,
// and the elements cut into pieces by that tree.
PreparedScene meshed(const std::vector<std::vector<Vec3>>& faces, double patchSize, int elementsPerPatch,
                     const std::vector<bool>& emits = {})
{
    PreparedScene scene;
    std::vector<FacePolygon> polygons;
    for (const auto& loop : faces) {
        const int index = int(scene.faces.size());
        InputFace info;
        info.id = "f" + std::to_string(index);
        info.area = model::polygonArea(loop);
        info.polygon = loop;
        scene.faces.push_back(info);
        Properties props;
        props.plane = model::polygonPlane(loop);
        props.face = index;
        if (size_t(index) < emits.size() && emits[size_t(index)])
            props.emission = {1.0, 1.0, 1.0};
        scene.properties.push_back(props);
        polygons.push_back({loop, index});
    }
    std::vector<int> rank(faces.size());
    std::iota(rank.begin(), rank.end(), 0);
    scene.regions.assign(1, Region{});
    scene.regionalNodes.assign(1, RegionalNode{});
    scene.regionalNodes[0].region = 0;
    scene.regionalRoot = 0;
    buildRegionBsp(scene, 0, polygons, rank);
    scene.patchSize = patchSize;
    scene.elementsPerPatch = elementsPerPatch;
    meshFaces(scene);
    buildPieces(scene);
    return scene;
}

double triangleArea(const PreparedScene& s, const std::array<int, 3>& v)
{
    return 0.5 * glm::length(glm::cross(s.vertices[size_t(v[1])] - s.vertices[size_t(v[0])],
                                        s.vertices[size_t(v[2])] - s.vertices[size_t(v[0])]));
}

const std::vector<std::vector<Vec3>> kRoomCorner{
    {{0, 0, 0}, {0, 0, 2}, {3, 0, 2}, {3, 0, 0}},             // floor, normal +y
    {{0, 0, 0}, {3, 0, 0}, {3, 2.5, 0}, {0, 2.5, 0}},         // back wall, normal +z
    {{1, 0.5, 0.5}, {1.4, 0.5, 0.5}, {1.2, 0.9, 0.5}},        // a small triangle in the room, normal +z
    {{0.3, 1, 1}, {0.3, 1, 0.2}, {2.3, 1, 0.2}, {2.3, 1, 1}}, // a shelf seen from below, normal -y
};

} // namespace

TEST(Meshing, RoundsTheElementRatioToTheNearestSquareGrid)
{
    EXPECT_EQ(elementGridDivisions(1), 1);
    EXPECT_EQ(elementGridDivisions(2), 1);
    EXPECT_EQ(elementGridDivisions(3), 2);
    EXPECT_EQ(elementGridDivisions(4), 2);
    EXPECT_EQ(elementGridDivisions(6), 2);
    EXPECT_EQ(elementGridDivisions(7), 3);
    EXPECT_EQ(elementGridDivisions(9), 3);
    EXPECT_EQ(elementGridDivisions(16), 4);
    EXPECT_EQ(elementGridDivisions(0), 1);
}

TEST(Meshing, OneElementPerPatchIsThePatchItself)
{
    PreparedScene s = meshed(kRoomCorner, 0.5, 1);
    ASSERT_EQ(s.elements.size(), s.patches.size());
    for (size_t p = 0; p < s.patches.size(); ++p) {
        EXPECT_EQ(s.patches[p].elementCount, 1);
        EXPECT_EQ(s.elements[size_t(s.patches[p].firstElement)].vertices, s.patches[p].vertices);
    }
}

TEST(Meshing, ElementsCoverTheirPatchExactlyForEveryRatio)
{
    for (int ratio : {1, 4, 9, 16}) {
        PreparedScene s = meshed(kRoomCorner, 0.5, ratio);
        SCOPED_TRACE(ratio);
        for (size_t p = 0; p < s.patches.size(); ++p) {
            const Patch& patch = s.patches[p];
            EXPECT_EQ(patch.elementCount, ratio);
            double area = 0.0;
            for (int e = patch.firstElement; e < patch.firstElement + patch.elementCount; ++e) {
                const Element& element = s.elements[size_t(e)];
                EXPECT_EQ(element.patch, int(p));
                EXPECT_EQ(element.properties, patch.properties);
                EXPECT_NEAR(element.area, triangleArea(s, element.vertices), 1e-15);
                EXPECT_NEAR(element.area, patch.area / ratio, 1e-12) << "the grid gives equal elements";
                // Counter-clockwise around the face normal, like the patch.
                const Vec3 n =
                    glm::cross(s.vertices[size_t(element.vertices[1])] - s.vertices[size_t(element.vertices[0])],
                               s.vertices[size_t(element.vertices[2])] - s.vertices[size_t(element.vertices[0])]);
                EXPECT_GT(glm::dot(n, element.normal), 0.0);
                area += element.area;
            }
            EXPECT_NEAR(area, patch.area, 1e-12);
        }
    }
}

TEST(Meshing, ElementsAreSimilarToTheirPatch)
{
    PreparedScene s = meshed(kRoomCorner, 0.5, 9);
    for (const Patch& patch : s.patches) {
        const double patchAngle =
            minimumAngleDegrees(s.vertices[size_t(patch.vertices[0])], s.vertices[size_t(patch.vertices[1])],
                                s.vertices[size_t(patch.vertices[2])]);
        for (int e = patch.firstElement; e < patch.firstElement + patch.elementCount; ++e) {
            const auto& v = s.elements[size_t(e)].vertices;
            EXPECT_NEAR(
                minimumAngleDegrees(s.vertices[size_t(v[0])], s.vertices[size_t(v[1])], s.vertices[size_t(v[2])]),
                patchAngle, 1e-6);
        }
    }
}

TEST(Meshing, TheElementMeshOfAFaceIsConforming)
{
    // Inside one input face every element edge is either shared, in opposite
    // directions, by two elements, or lies on the face's boundary: no
    // T-vertices, so later smoothing and subdivision see real neighbours. The
    // mesh is the face's, whatever BSP planes cut the face into fragments.
    PreparedScene s = meshed(kRoomCorner, 0.5, 4);
    ASSERT_GT(s.fragments.size(), kRoomCorner.size()) << "the premise: some face is split by a BSP plane";
    for (const InputFace& face : s.faces) {
        std::map<std::pair<int, int>, int> directed;
        for (int p = face.firstPatch; p < face.firstPatch + face.patchCount; ++p) {
            const Patch& patch = s.patches[size_t(p)];
            for (int e = patch.firstElement; e < patch.firstElement + patch.elementCount; ++e)
                for (int i = 0; i < 3; ++i)
                    ++directed[{s.elements[size_t(e)].vertices[size_t(i)],
                                s.elements[size_t(e)].vertices[size_t((i + 1) % 3)]}];
        }
        double boundary = 0.0;
        for (const auto& [edge, count] : directed) {
            EXPECT_EQ(count, 1);
            if (!directed.count({edge.second, edge.first}))
                boundary += glm::length(s.vertices[size_t(edge.second)] - s.vertices[size_t(edge.first)]);
        }
        double perimeter = 0.0;
        for (size_t i = 0; i < face.polygon.size(); ++i)
            perimeter += glm::length(face.polygon[(i + 1) % face.polygon.size()] - face.polygon[i]);
        EXPECT_NEAR(boundary, perimeter, 1e-9) << "the open edges are exactly the face's outline";
    }
}

TEST(Meshing, KeepsPiecesOfOneNodeContiguousInTheirFourGroups)
{
    // Two coplanar faces of opposite orientation share the root node.
    std::vector<std::vector<Vec3>> faces = kRoomCorner;
    faces.push_back({{0, 2.5, 0.1}, {3, 2.5, 0.1}, {3, 2.5, 1}, {0, 2.5, 1}}); // normal -y
    faces.push_back({{0, 2.5, 1.1}, {0, 2.5, 2}, {3, 2.5, 2}, {3, 2.5, 1.1}}); // normal +y, same plane
    PreparedScene s = meshed(faces, 0.5, 4);
    s.properties[4].solid = true; // groups [F solid | F open | O open | O solid] all in use
    buildPieces(s);
    int next = 0;
    for (size_t n = 0; n < s.nodes.size(); ++n) {
        const BspNode& node = s.nodes[n];
        EXPECT_EQ(node.firstPiece, next);
        next += node.pieceCount;
        for (int i = node.firstPiece; i < node.firstPiece + node.pieceCount; ++i) {
            const Element& element = s.elements[size_t(s.pieces[size_t(i)].element)];
            const bool forward = glm::dot(element.normal, node.plane.normal) > 0.0;
            const bool solid = s.properties[size_t(element.properties)].solid;
            const int at = i - node.firstPiece;
            EXPECT_EQ(forward, at < node.forwardPieces);
            if (forward)
                EXPECT_EQ(solid, at < node.forwardSolidPieces);
            else
                EXPECT_EQ(solid, at >= node.pieceCount - node.oppositeSolidPieces);
            // The node holds a fragment of the piece's face.
            bool holds = false;
            for (int f = node.firstFragment; f < node.firstFragment + node.fragmentCount; ++f)
                holds = holds || s.fragments[size_t(f)].properties == element.properties;
            EXPECT_TRUE(holds) << "piece " << i << " in node " << n;
        }
    }
    EXPECT_EQ(next, int(s.pieces.size()));
    EXPECT_EQ(s.stats.lostPieces, 0);
}

// A light shares its power from its patches' centres, and its shots carry
// all the direct light: faces that emit are cut at a quarter of the patch
// size, or a half, or the patch size, whichever first keeps them at 256
// patches or fewer (solver/prepare/meshing.cpp).
TEST(Meshing, LightsAreCutIntoPatchesAQuarterOfThePatchSizeWhileTheyStayAt256OrFewer)
{
    const auto square = [](double side, double y) {
        return std::vector<Vec3>{{0, y, 0}, {side, y, 0}, {side, y, side}, {0, y, side}};
    };
    const auto patchesOf = [](const PreparedScene& s, int face) {
        int n = 0;
        for (const Patch& p : s.patches)
            n += p.properties == face;
        return n;
    };
    for (const auto& [side, divisor] : {std::pair{1.0, 4}, std::pair{2.0, 2}, std::pair{10.0, 1}}) {
        SCOPED_TRACE(side);
        const PreparedScene lit = meshed({square(side, 0.0), square(side, 1.0)}, 0.5, 1, {true, false});
        const int lamp = patchesOf(lit, 0), plain = patchesOf(lit, 1);
        EXPECT_EQ(lamp, plain * divisor * divisor);
        if (divisor > 1) {
            EXPECT_LE(lamp, 256);
        }
        double area = 0.0;
        for (const Patch& p : lit.patches)
            area += p.properties == 0 ? p.area : 0.0;
        EXPECT_NEAR(area, side * side, 1e-9);
    }
}

TEST(Meshing, ListsEveryElementOfAnInputFaceOnce)
{
    PreparedScene s = meshed(kRoomCorner, 0.4, 4);
    std::vector<int> seen(s.elements.size(), 0);
    for (size_t f = 0; f < s.faces.size(); ++f) {
        double area = 0.0;
        for (int e : s.faces[f].elements) {
            ++seen[size_t(e)];
            EXPECT_EQ(s.elements[size_t(e)].properties, int(f));
            area += s.elements[size_t(e)].area;
        }
        EXPECT_NEAR(area, s.faces[f].area, 1e-9);
    }
    for (int count : seen)
        EXPECT_EQ(count, 1);
}
