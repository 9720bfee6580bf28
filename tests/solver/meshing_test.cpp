// Patches to elements (paper §5.5) and the storage order the painter relies on.
#include "solver/meshing.h"

#include "solver/bsp_tree.h"
#include "solver/strip_triangulation.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <map>
#include <numeric>
#include <utility>

using namespace regio;
using namespace regio::solver;
using model::Vec3;

namespace {

// Fragments from a one-region BSP build of the given faces, then meshed.
PreparedScene meshed(const std::vector<std::vector<Vec3>>& faces, double patchSize, int elementsPerPatch)
{
    PreparedScene scene;
    std::vector<FacePolygon> polygons;
    for (const auto& loop : faces) {
        const int index = int(scene.faces.size());
        InputFace info;
        info.id = "f" + std::to_string(index);
        info.area = model::polygonArea(loop);
        scene.faces.push_back(info);
        Properties props;
        props.plane = model::polygonPlane(loop);
        props.face = index;
        scene.properties.push_back(props);
        polygons.push_back({loop, index});
    }
    std::vector<int> rank(faces.size());
    std::iota(rank.begin(), rank.end(), 0);
    scene.regions.assign(1, Region{});
    buildRegionBsp(scene, 0, polygons, rank);
    scene.patchSize = patchSize;
    scene.elementsPerPatch = elementsPerPatch;
    meshFragments(scene);
    return scene;
}

double triangleArea(const PreparedScene& s, const std::array<int, 3>& v)
{
    return 0.5 * glm::length(glm::cross(s.vertices[size_t(v[1])] - s.vertices[size_t(v[0])],
                                        s.vertices[size_t(v[2])] - s.vertices[size_t(v[0])]));
}

const std::vector<std::vector<Vec3>> kRoomCorner{
    {{0, 0, 0}, {0, 0, 2}, {3, 0, 2}, {3, 0, 0}},       // floor, normal +y
    {{0, 0, 0}, {3, 0, 0}, {3, 2.5, 0}, {0, 2.5, 0}},   // back wall, normal +z
    {{1, 0.5, 0.5}, {1.4, 0.5, 0.5}, {1.2, 0.9, 0.5}},  // a small triangle in the room, normal +z
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
                const Vec3 n = glm::cross(s.vertices[size_t(element.vertices[1])] - s.vertices[size_t(element.vertices[0])],
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
        const double patchAngle = minimumAngleDegrees(s.vertices[size_t(patch.vertices[0])], s.vertices[size_t(patch.vertices[1])],
                                                      s.vertices[size_t(patch.vertices[2])]);
        for (int e = patch.firstElement; e < patch.firstElement + patch.elementCount; ++e) {
            const auto& v = s.elements[size_t(e)].vertices;
            EXPECT_NEAR(minimumAngleDegrees(s.vertices[size_t(v[0])], s.vertices[size_t(v[1])], s.vertices[size_t(v[2])]),
                        patchAngle, 1e-6);
        }
    }
}

TEST(Meshing, TheElementMeshOfAFragmentIsConforming)
{
    // Inside one fragment every element edge is either shared, in opposite
    // directions, by two elements, or lies on the fragment's boundary: no
    // T-vertices, so later smoothing and subdivision see real neighbours.
    PreparedScene s = meshed(kRoomCorner, 0.5, 4);
    for (const Fragment& fragment : s.fragments) {
        std::map<std::pair<int, int>, int> directed;
        for (int p = fragment.firstPatch; p < fragment.firstPatch + fragment.patchCount; ++p) {
            const Patch& patch = s.patches[size_t(p)];
            for (int e = patch.firstElement; e < patch.firstElement + patch.elementCount; ++e)
                for (int i = 0; i < 3; ++i)
                    ++directed[{s.elements[size_t(e)].vertices[size_t(i)], s.elements[size_t(e)].vertices[size_t((i + 1) % 3)]}];
        }
        double boundary = 0.0;
        for (const auto& [edge, count] : directed) {
            EXPECT_EQ(count, 1);
            if (!directed.count({edge.second, edge.first}))
                boundary += glm::length(s.vertices[size_t(edge.second)] - s.vertices[size_t(edge.first)]);
        }
        double perimeter = 0.0;
        for (int i = 0; i < fragment.pointCount; ++i)
            perimeter += glm::length(s.fragmentPoints[size_t(fragment.firstPoint + (i + 1) % fragment.pointCount)] -
                                     s.fragmentPoints[size_t(fragment.firstPoint + i)]);
        EXPECT_NEAR(boundary, perimeter, 1e-9) << "the open edges are exactly the fragment's outline";
    }
}

TEST(Meshing, KeepsPatchesAndElementsOfOneNodeContiguousWithForwardOnesFirst)
{
    // Two coplanar faces of opposite orientation share the root node.
    std::vector<std::vector<Vec3>> faces = kRoomCorner;
    faces.push_back({{0, 2.5, 0.1}, {3, 2.5, 0.1}, {3, 2.5, 1}, {0, 2.5, 1}}); // normal -y
    faces.push_back({{0, 2.5, 1.1}, {0, 2.5, 2}, {3, 2.5, 2}, {3, 2.5, 1.1}}); // normal +y, same plane
    PreparedScene s = meshed(faces, 0.5, 4);
    int nextPatch = 0, nextElement = 0;
    for (size_t n = 0; n < s.nodes.size(); ++n) {
        const BspNode& node = s.nodes[n];
        EXPECT_EQ(node.firstPatch, nextPatch);
        EXPECT_EQ(node.firstElement, nextElement);
        nextPatch += node.patchCount;
        nextElement += node.elementCount;
        for (int e = node.firstElement; e < node.firstElement + node.elementCount; ++e) {
            const Element& element = s.elements[size_t(e)];
            EXPECT_EQ(element.node, int(n));
            const bool forward = glm::dot(element.normal, node.plane.normal) > 0.0;
            EXPECT_EQ(forward, e < node.firstElement + node.forwardElements);
        }
        for (int p = node.firstPatch; p < node.firstPatch + node.patchCount; ++p)
            EXPECT_EQ(p < node.firstPatch + node.forwardPatches,
                      glm::dot(s.properties[size_t(s.patches[size_t(p)].properties)].plane.normal, node.plane.normal) > 0.0);
    }
    EXPECT_EQ(nextPatch, int(s.patches.size()));
    EXPECT_EQ(nextElement, int(s.elements.size()));
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
