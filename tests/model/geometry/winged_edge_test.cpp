#include "model/geometry/winged_edge.h"

#include "model/geometry/geometry.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

using namespace regio::model;

namespace {

Part makePart(std::vector<Vec3> vertices, std::vector<std::vector<int>> loops)
{
    Part part;
    part.id = "part";
    part.vertices = std::move(vertices);
    for (size_t i = 0; i < loops.size(); ++i)
        part.faces.push_back(Face{"f" + std::to_string(i), std::move(loops[i]), {}});
    return part;
}

// Unit cube, every face counter-clockwise seen from outside.
Part cube()
{
    return makePart({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}},
                    {{0, 3, 2, 1},   // bottom, -z
                     {4, 5, 6, 7},   // top, +z
                     {0, 1, 5, 4},   // front, -y
                     {2, 3, 7, 6},   // back, +y
                     {0, 4, 7, 3},   // left, -x
                     {1, 2, 6, 5}}); // right, +x
}

Part hexagonalPrism()
{
    std::vector<Vec3> vertices;
    for (int ring = 0; ring < 2; ++ring)
        for (int i = 0; i < 6; ++i) {
            double a = i * std::numbers::pi / 3.0;
            vertices.push_back({std::cos(a), std::sin(a), double(ring)});
        }
    std::vector<std::vector<int>> loops{{5, 4, 3, 2, 1, 0}, {6, 7, 8, 9, 10, 11}};
    for (int i = 0; i < 6; ++i) {
        int j = (i + 1) % 6;
        loops.push_back({i, j, 6 + j, 6 + i});
    }
    return makePart(std::move(vertices), std::move(loops));
}

// A room without its ceiling: the cube's walls and floor wound inwards.
Part openRoom()
{
    Part room = cube();
    room.faces.erase(room.faces.begin() + 1); // the top
    for (Face& face : room.faces)
        std::reverse(face.loop.begin(), face.loop.end());
    return room;
}

Vec3 faceNormal(const Part& part, int f)
{
    return polygonNormal(loopPositions(part.vertices, part.faces[size_t(f)].loop));
}

// The direction in which face f's loop traverses the vertex pair (a, b): +1
// a -> b, -1 b -> a, 0 not an edge of f.
int traversal(const Part& part, int f, int a, int b)
{
    const auto& loop = part.faces[size_t(f)].loop;
    for (size_t i = 0; i < loop.size(); ++i) {
        int p = loop[i];
        int q = loop[(i + 1) % loop.size()];
        if (p == a && q == b)
            return 1;
        if (p == b && q == a)
            return -1;
    }
    return 0;
}

// Walking the next-wings from a face's edge runs once around its loop.
void expectWingsWalkEveryLoop(const WingedEdgeMesh& mesh, const Part& part)
{
    for (int f = 0; f < mesh.faceCount(); ++f) {
        if (!mesh.faceInTopology(f))
            continue;
        const auto& loop = part.faces[size_t(f)].loop;
        auto row = mesh.edgesOfFace(f);
        ASSERT_EQ(row.size(), loop.size());
        for (size_t i = 0; i < loop.size(); ++i)
            EXPECT_EQ(row[i], mesh.findEdge(loop[i], loop[(i + 1) % loop.size()]));
        int e = mesh.faceEdge(f);
        for (size_t i = 0; i < loop.size(); ++i) {
            EXPECT_EQ(e, row[i]) << "face " << f << " step " << i;
            int next = mesh.nextEdgeInFace(f, e);
            EXPECT_EQ(mesh.prevEdgeInFace(f, next), e);
            e = next;
        }
        EXPECT_EQ(e, mesh.faceEdge(f));
    }
}

bool contains(const std::vector<int>& values, int value)
{
    return std::find(values.begin(), values.end(), value) != values.end();
}

} // namespace

TEST(WingedEdge, CubeHasTwelveEdgesEachWithTwoFaces)
{
    Part part = cube();
    WingedEdgeMesh mesh = WingedEdgeMesh::build(part);
    EXPECT_EQ(mesh.vertexCount(), 8);
    EXPECT_EQ(mesh.faceCount(), 6);
    EXPECT_EQ(mesh.edgeCount(), 12);
    for (const auto& edge : mesh.edges()) {
        EXPECT_GE(edge.leftFace, 0);
        EXPECT_GE(edge.rightFace, 0);
        EXPECT_NE(edge.leftFace, edge.rightFace);
    }
    EXPECT_TRUE(mesh.problems().empty());
    EXPECT_TRUE(mesh.isClosed());
    EXPECT_TRUE(mesh.isManifold());
    EXPECT_TRUE(mesh.hasConsistentWinding());
    EXPECT_TRUE(mesh.boundaryEdges().empty());
    EXPECT_TRUE(mesh.windingRepair().facesToFlip.empty());
}

TEST(WingedEdge, LeftFaceTraversesTheEdgeForwardAndRightFaceBackward)
{
    Part part = cube();
    WingedEdgeMesh mesh = WingedEdgeMesh::build(part);
    for (const auto& edge : mesh.edges()) {
        EXPECT_EQ(traversal(part, edge.leftFace, edge.v0, edge.v1), 1);
        EXPECT_EQ(traversal(part, edge.rightFace, edge.v0, edge.v1), -1);
    }
}

TEST(WingedEdge, WingsAreTheNeighbouringEdgesInEachFaceLoop)
{
    Part part = cube();
    WingedEdgeMesh mesh = WingedEdgeMesh::build(part);
    for (const auto& edge : mesh.edges()) {
        // leftPrev ends where the edge starts; leftNext starts where it ends.
        EXPECT_TRUE(mesh.edge(edge.leftPrev).v0 == edge.v0 || mesh.edge(edge.leftPrev).v1 == edge.v0);
        EXPECT_TRUE(mesh.edge(edge.leftNext).v0 == edge.v1 || mesh.edge(edge.leftNext).v1 == edge.v1);
        // The right face runs v1 -> v0.
        EXPECT_TRUE(mesh.edge(edge.rightPrev).v0 == edge.v1 || mesh.edge(edge.rightPrev).v1 == edge.v1);
        EXPECT_TRUE(mesh.edge(edge.rightNext).v0 == edge.v0 || mesh.edge(edge.rightNext).v1 == edge.v0);
    }
    expectWingsWalkEveryLoop(mesh, part);
}

TEST(WingedEdge, EveryCubeFaceHasFourNeighboursAndNotItsOpposite)
{
    Part part = cube();
    WingedEdgeMesh mesh = WingedEdgeMesh::build(part);
    const int opposite[6] = {1, 0, 3, 2, 5, 4};
    for (int f = 0; f < 6; ++f) {
        std::vector<int> neighbours = mesh.facesAdjacentTo(f);
        EXPECT_EQ(neighbours.size(), 4u);
        EXPECT_FALSE(contains(neighbours, f));
        EXPECT_FALSE(contains(neighbours, opposite[f]));
        // In loop order: neighbour i lies across edge i.
        auto row = mesh.edgesOfFace(f);
        for (size_t i = 0; i < row.size(); ++i)
            EXPECT_EQ(neighbours[i], mesh.faceAcross(f, row[i]));
    }
}

TEST(WingedEdge, FindEdgeWorksInBothDirectionsAndMissesNonEdges)
{
    WingedEdgeMesh mesh = WingedEdgeMesh::build(cube());
    int e = mesh.findEdge(0, 1);
    ASSERT_GE(e, 0);
    EXPECT_EQ(mesh.findEdge(1, 0), e);
    EXPECT_EQ(mesh.findEdge(0, 6), -1); // a body diagonal
    EXPECT_EQ(mesh.findEdge(0, 2), -1); // a face diagonal
    EXPECT_EQ(mesh.findEdge(0, 99), -1);
}

TEST(WingedEdge, EdgesAroundACubeCornerTurnCounterClockwiseSeenFromOutside)
{
    Part part = cube();
    WingedEdgeMesh mesh = WingedEdgeMesh::build(part);
    const Vec3 centre{0.5, 0.5, 0.5};
    for (int v = 0; v < 8; ++v) {
        EXPECT_TRUE(mesh.isVertexManifold(v));
        std::vector<int> edges = mesh.edgesAroundVertex(v);
        std::vector<int> faces = mesh.facesAroundVertex(v);
        ASSERT_EQ(edges.size(), 3u);
        ASSERT_EQ(faces.size(), 3u);
        const Vec3 p = part.vertices[size_t(v)];
        const Vec3 outward = p - centre;
        for (size_t i = 0; i < 3; ++i) {
            Vec3 a = part.vertices[size_t(mesh.edge(edges[i]).otherVertex(v))] - p;
            Vec3 b = part.vertices[size_t(mesh.edge(edges[(i + 1) % 3]).otherVertex(v))] - p;
            EXPECT_GT(glm::dot(glm::cross(a, b), outward), 0.0) << "vertex " << v;
            // Face i lies between edge i and edge i + 1.
            auto row = mesh.edgesOfFace(faces[i]);
            EXPECT_NE(std::find(row.begin(), row.end(), edges[i]), row.end());
            EXPECT_NE(std::find(row.begin(), row.end(), edges[(i + 1) % 3]), row.end());
        }
    }
}

TEST(WingedEdge, HexagonalPrismHasEighteenEdgesAndSixSidedCaps)
{
    Part part = hexagonalPrism();
    for (int f = 0; f < 8; ++f) // the fixture itself is wound outwards
        EXPECT_GT(glm::dot(faceNormal(part, f),
                           polygonCentroid(loopPositions(part.vertices, part.faces[size_t(f)].loop)) - Vec3(0, 0, 0.5)),
                  0.0);
    WingedEdgeMesh mesh = WingedEdgeMesh::build(part);
    EXPECT_EQ(mesh.edgeCount(), 18);
    EXPECT_TRUE(mesh.isClosed());
    EXPECT_TRUE(mesh.isManifold());
    EXPECT_TRUE(mesh.hasConsistentWinding());
    EXPECT_EQ(mesh.edgesOfFace(0).size(), 6u);
    EXPECT_EQ(mesh.facesAdjacentTo(0).size(), 6u); // the bottom touches every side
    EXPECT_EQ(mesh.facesAdjacentTo(2).size(), 4u); // a side: both caps and two sides
    for (int v = 0; v < 12; ++v)
        EXPECT_EQ(mesh.edgesAroundVertex(v).size(), 3u);
    expectWingsWalkEveryLoop(mesh, part);
}

TEST(WingedEdge, RoomWithoutCeilingIsOpenAlongItsRim)
{
    Part part = openRoom();
    WingedEdgeMesh mesh = WingedEdgeMesh::build(part);
    EXPECT_EQ(mesh.edgeCount(), 12);
    EXPECT_FALSE(mesh.isClosed());
    EXPECT_TRUE(mesh.isManifold());
    EXPECT_TRUE(mesh.hasConsistentWinding());
    EXPECT_TRUE(mesh.problems().empty());
    std::vector<int> boundary = mesh.boundaryEdges();
    ASSERT_EQ(boundary.size(), 4u);
    for (int e : boundary) {
        // The rim of the missing ceiling: both ends at z = 1.
        EXPECT_EQ(part.vertices[size_t(mesh.edge(e).v0)].z, 1.0);
        EXPECT_EQ(part.vertices[size_t(mesh.edge(e).v1)].z, 1.0);
        EXPECT_TRUE(mesh.edge(e).isBoundary());
        EXPECT_EQ(mesh.faceAcross(mesh.edge(e).leftFace, e), -1);
    }
    expectWingsWalkEveryLoop(mesh, part);
}

TEST(WingedEdge, OpenFanAroundARimVertexStartsAndEndsAtTheRim)
{
    Part part = openRoom();
    WingedEdgeMesh mesh = WingedEdgeMesh::build(part);
    const int rimVertex = 4; // (0, 0, 1)
    EXPECT_TRUE(mesh.isVertexManifold(rimVertex));
    std::vector<int> edges = mesh.edgesAroundVertex(rimVertex);
    std::vector<int> faces = mesh.facesAroundVertex(rimVertex);
    ASSERT_EQ(edges.size(), 3u);
    ASSERT_EQ(faces.size(), 2u); // an open fan has one face fewer than edges
    EXPECT_TRUE(mesh.edge(edges.front()).isBoundary());
    EXPECT_TRUE(mesh.edge(edges.back()).isBoundary());
    EXPECT_FALSE(mesh.edge(edges[1]).isBoundary());
}

TEST(WingedEdge, MisWoundCubeFaceBreaksTheWindingAndIsTheFaceToFlip)
{
    Part part = cube();
    std::reverse(part.faces[1].loop.begin(), part.faces[1].loop.end());
    WingedEdgeMesh mesh = WingedEdgeMesh::build(part);
    EXPECT_TRUE(mesh.isClosed());
    EXPECT_FALSE(mesh.hasConsistentWinding());
    int windingProblems = 0;
    for (const TopologyProblem& problem : mesh.problems()) {
        ASSERT_EQ(problem.kind, TopologyProblem::Kind::InconsistentWinding);
        EXPECT_TRUE(contains(problem.faces, 1));
        ++windingProblems;
    }
    EXPECT_EQ(windingProblems, 4); // the four edges around the top
    auto repair = mesh.windingRepair();
    EXPECT_TRUE(repair.orientable);
    EXPECT_EQ(repair.facesToFlip, std::vector<int>{1});
    // Even so, every loop stays walkable through its wings.
    expectWingsWalkEveryLoop(mesh, part);
}

TEST(WingedEdge, ThreeFacesOnOneEdgeAreNonManifold)
{
    // Two squares in the z = 0 plane and a fin standing on their shared edge.
    Part part = makePart({{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, 1, 0}, {0, 0, 1}, {0, 1, 1}},
                         {{0, 2, 3, 1}, {0, 1, 5, 4}, {0, 6, 7, 1}});
    WingedEdgeMesh mesh = WingedEdgeMesh::build(part);
    int e = mesh.findEdge(0, 1);
    ASSERT_GE(e, 0);
    auto faces = mesh.facesOfEdge(e);
    EXPECT_EQ(std::vector<int>(faces.begin(), faces.end()), (std::vector<int>{0, 1, 2}));
    EXPECT_FALSE(mesh.isManifold());
    EXPECT_FALSE(mesh.isVertexManifold(0));
    EXPECT_EQ(mesh.nonManifoldEdges(), std::vector<int>{e});
    ASSERT_EQ(mesh.problems().size(), 1u);
    const TopologyProblem& problem = mesh.problems().front();
    EXPECT_EQ(problem.kind, TopologyProblem::Kind::NonManifoldEdge);
    EXPECT_EQ(problem.edge, e);
    EXPECT_EQ(problem.face, 2);
    EXPECT_EQ(problem.faces, (std::vector<int>{0, 1, 2}));
    // Neighbour queries still see every face on the edge.
    EXPECT_EQ(mesh.facesAdjacentTo(2), (std::vector<int>{0, 1}));
    std::vector<int> around = mesh.edgesAroundVertex(0);
    std::sort(around.begin(), around.end());
    EXPECT_EQ(around.size(), 4u); // 0-1, 0-2, 0-4, 0-6, each once
    EXPECT_EQ(std::adjacent_find(around.begin(), around.end()), around.end());
    expectWingsWalkEveryLoop(mesh, part);
}

TEST(WingedEdge, TwoCubesTouchingAtACornerMakeANonManifoldVertex)
{
    Part part = cube();
    Part other = cube();
    // Second cube shifted by (1, 1, 1) sharing vertex 6 = (1, 1, 1) as its vertex 0.
    const int base = int(part.vertices.size()) - 1;
    for (size_t i = 1; i < other.vertices.size(); ++i)
        part.vertices.push_back(other.vertices[i] + Vec3(1, 1, 1));
    for (Face face : other.faces) {
        for (int& index : face.loop)
            index = index == 0 ? 6 : index + base;
        part.faces.push_back(face);
    }
    WingedEdgeMesh mesh = WingedEdgeMesh::build(part);
    EXPECT_TRUE(mesh.isClosed());
    EXPECT_TRUE(mesh.nonManifoldEdges().empty());
    EXPECT_FALSE(mesh.isVertexManifold(6));
    EXPECT_FALSE(mesh.isManifold());
    EXPECT_EQ(mesh.edgesAroundVertex(6).size(), 6u);
    EXPECT_EQ(mesh.facesAroundVertex(6).size(), 6u);
}

TEST(WingedEdge, BadLoopsAreReportedAndLeftOutOfTheTopology)
{
    Part part = makePart({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1}, {0, 1, 7}, {0, 1, 2, 1}, {0, 1, 2, 3}});
    WingedEdgeMesh mesh = WingedEdgeMesh::build(part);
    ASSERT_EQ(mesh.problems().size(), 3u);
    EXPECT_EQ(mesh.problems()[0].kind, TopologyProblem::Kind::LoopTooShort);
    EXPECT_EQ(mesh.problems()[0].face, 0);
    EXPECT_EQ(mesh.problems()[1].kind, TopologyProblem::Kind::VertexOutOfRange);
    EXPECT_EQ(mesh.problems()[1].face, 1);
    EXPECT_EQ(mesh.problems()[1].loopPosition, 2);
    EXPECT_EQ(mesh.problems()[2].kind, TopologyProblem::Kind::RepeatedVertex);
    EXPECT_EQ(mesh.problems()[2].face, 2);
    EXPECT_EQ(mesh.problems()[2].loopPosition, 3);
    EXPECT_FALSE(mesh.faceInTopology(0));
    EXPECT_FALSE(mesh.faceInTopology(1));
    EXPECT_FALSE(mesh.faceInTopology(2));
    EXPECT_TRUE(mesh.faceInTopology(3));
    EXPECT_TRUE(mesh.edgesOfFace(1).empty());
    EXPECT_EQ(mesh.edgeCount(), 4); // only the good square's edges
}

TEST(WingedEdge, EmptyPartIsNeitherClosedNorInTrouble)
{
    WingedEdgeMesh mesh = WingedEdgeMesh::build(Part{});
    EXPECT_EQ(mesh.edgeCount(), 0);
    EXPECT_FALSE(mesh.isClosed());
    EXPECT_TRUE(mesh.isManifold());
    EXPECT_TRUE(mesh.hasConsistentWinding());
    EXPECT_TRUE(mesh.problems().empty());
}

TEST(WingedEdge, HundredThousandFaceTorusBuildsClosedManifoldAndConsistent)
{
    // A 320 x 320 quad grid with both directions wrapped around: a torus.
    const int n = 320;
    std::vector<std::vector<int>> loops;
    loops.reserve(size_t(n) * n);
    auto id = [n](int i, int j) { return ((i + n) % n) * n + (j + n) % n; };
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            loops.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
    auto start = std::chrono::steady_clock::now();
    WingedEdgeMesh mesh = WingedEdgeMesh::build(n * n, loops);
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    RecordProperty("build_seconds", std::to_string(seconds));
    std::printf("winged-edge build of %d faces: %.3f s\n", n * n, seconds);
    EXPECT_EQ(mesh.faceCount(), n * n);
    EXPECT_EQ(mesh.edgeCount(), 2 * n * n);
    EXPECT_TRUE(mesh.isClosed());
    EXPECT_TRUE(mesh.isManifold());
    EXPECT_TRUE(mesh.hasConsistentWinding());
    EXPECT_EQ(mesh.edgesAroundVertex(id(5, 7)).size(), 4u);
}

TEST(WingedEdge, MoebiusBandCannotBeWoundConsistently)
{
    // A strip of four quads whose ends are glued with a half twist.
    std::vector<std::vector<int>> loops{{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 4, 0, 7}};
    WingedEdgeMesh mesh = WingedEdgeMesh::build(8, loops);
    auto repair = mesh.windingRepair();
    EXPECT_FALSE(repair.orientable);
}
