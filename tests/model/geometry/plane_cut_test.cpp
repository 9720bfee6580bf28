#include "model/geometry/plane_cut.h"

#include "model/geometry/primitives.h"
#include "support/part_checks.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <cmath>
#include <random>

using namespace regio::model;
using namespace regio::test;

namespace {

Part unitCube(const std::string& id = "slab") { return makeBox(id, {0, 0, 0}, {1, 1, 1}, "wood").value(); }

// A prism over a 2-D outline in the x-y plane, from z = 0 to z = depth.
// `pieces` are the convex pieces of the outline (counter-clockwise), `rims`
// its boundary loops (outer counter-clockwise, holes clockwise); both index
// `points`, and every point on a rim must be on the pieces' edges where they
// meet it, so the part has no T-junctions.
Part extrude(const std::string& id, const std::vector<glm::dvec2>& points, const std::vector<std::vector<int>>& pieces,
             const std::vector<std::vector<int>>& rims, double depth)
{
    Part part;
    part.id = id;
    part.material = "white";
    const int n = int(points.size());
    for (double z : {0.0, depth})
        for (const auto& p : points)
            part.vertices.push_back({p.x, p.y, z});
    int faceNo = 0;
    for (const auto& piece : pieces) {
        Face bottom{id + ".back" + std::to_string(faceNo), {}, {}};
        Face top{id + ".front" + std::to_string(faceNo), {}, {}};
        for (size_t i = 0; i < piece.size(); ++i) {
            top.loop.push_back(n + piece[i]);
            bottom.loop.push_back(piece[(piece.size() - i) % piece.size()]);
        }
        part.faces.push_back(bottom);
        part.faces.push_back(top);
        ++faceNo;
    }
    int side = 0;
    for (const auto& rim : rims)
        for (size_t i = 0; i < rim.size(); ++i) {
            int a = rim[i], b = rim[(i + 1) % rim.size()];
            part.faces.push_back({id + ".side" + std::to_string(++side), {a, b, n + b, n + a}, {}});
        }
    return part;
}

// An L: the bar [0,2] x [0,1] and the bar [0,1] x [1,2], one unit deep.
Part lPrism()
{
    std::vector<glm::dvec2> points{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}, {0, 1}};
    return extrude("ell", points, {{0, 1, 2, 3, 6}, {6, 3, 4, 5}}, {{0, 1, 2, 3, 4, 5, 6}}, 1.0);
}

// A square frame: [0,3]^2 without [1,2]^2, as the eight cells of a 3 x 3 grid.
Part frame()
{
    std::vector<glm::dvec2> points;
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x)
            points.push_back({x, y});
    auto at = [](int x, int y) { return y * 4 + x; };
    std::vector<std::vector<int>> cells;
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 3; ++x)
            if (x != 1 || y != 1)
                cells.push_back({at(x, y), at(x + 1, y), at(x + 1, y + 1), at(x, y + 1)});
    std::vector<int> outer{at(0, 0), at(1, 0), at(2, 0), at(3, 0), at(3, 1), at(3, 2),
                           at(3, 3), at(2, 3), at(1, 3), at(0, 3), at(0, 2), at(0, 1)};
    std::vector<int> hole{at(1, 1), at(1, 2), at(2, 2), at(2, 1)};
    return extrude("frame", points, cells, {outer, hole}, 1.0);
}

void expectSoundHalves(const PlaneCut& cut, double volume)
{
    for (const Part* part : {&cut.front, &cut.back}) {
        EXPECT_TRUE(isClosedManifold(*part));
        EXPECT_TRUE(facesArePlanarAndConvex(*part));
    }
    EXPECT_TRUE(idsAreUnique({&cut.front, &cut.back}));
    EXPECT_GT(signedVolume(cut.front), 0.0);
    EXPECT_GT(signedVolume(cut.back), 0.0);
    EXPECT_NEAR(signedVolume(cut.front) + signedVolume(cut.back), volume, 1e-9);
}

void expectCapsFace(const Part& part, const std::vector<std::string>& caps, const Vec3& normal)
{
    ASSERT_FALSE(caps.empty());
    for (const std::string& id : caps) {
        const Face* face = findFace(part, id);
        ASSERT_NE(face, nullptr) << id;
        EXPECT_NEAR(glm::dot(faceNormal(part, *face), normal), 1.0, 1e-9) << id;
        EXPECT_TRUE(face->material.empty()) << "caps take the part's material";
    }
}

} // namespace

TEST(PlaneCut, ACubeCutInTwoGivesTwoClosedBoxesWhoseVolumesAddUp)
{
    Plane plane = Plane::fromPointNormal({0.3, 0, 0}, {1, 0, 0});
    auto cut = splitPart(unitCube(), plane, "desk", "legs");
    ASSERT_TRUE(cut.ok()) << cut.error().message;
    expectSoundHalves(*cut, 1.0);
    EXPECT_NEAR(signedVolume(cut->front), 0.7, 1e-12);
    EXPECT_NEAR(signedVolume(cut->back), 0.3, 1e-12);
    EXPECT_EQ(cut->front.faces.size(), 6u);
    EXPECT_EQ(cut->back.faces.size(), 6u);
    EXPECT_EQ(cut->front.vertices.size(), 8u) << "the new corners are shared, not repeated";
    ASSERT_EQ(cut->frontCaps, std::vector<std::string>{"desk.cut"});
    ASSERT_EQ(cut->backCaps, std::vector<std::string>{"legs.cut"});
    // The caps face each other: out of each half, towards the other.
    expectCapsFace(cut->front, cut->frontCaps, {-1, 0, 0});
    expectCapsFace(cut->back, cut->backCaps, {1, 0, 0});
}

TEST(PlaneCut, PiecesTakeTheNewPartIdInPlaceOfTheOldAndKeepTheirMaterial)
{
    Part cube = unitCube();
    cube.faces[2].material = "red"; // slab.ny, the bottom
    Plane plane = Plane::fromPointNormal({0, 0.5, 0}, {0, 1, 0});
    auto cut = splitPart(cube, plane, "desk", "legs");
    ASSERT_TRUE(cut.ok());
    EXPECT_EQ(cut->front.material, "wood");
    EXPECT_NE(findFace(cut->front, "desk.py"), nullptr) << "the top lies wholly in front";
    EXPECT_EQ(findFace(cut->front, "desk.ny"), nullptr);
    ASSERT_NE(findFace(cut->back, "legs.ny"), nullptr);
    EXPECT_EQ(findFace(cut->back, "legs.ny")->material, "red");
    // The map from source faces to pieces: a side face has a piece on each side.
    ASSERT_EQ(cut->pieces.size(), 6u);
    EXPECT_EQ(cut->pieces[0].sourceId, "slab.nx");
    EXPECT_EQ(cut->pieces[0].pieceIds, (std::vector<std::string>{"desk.nx", "legs.nx"}));
    EXPECT_EQ(cut->pieces[3].pieceIds, std::vector<std::string>{"desk.py"});
    EXPECT_EQ(cutPieceId("top", "slab", "desk"), "desk.top");
    EXPECT_EQ(cutPieceId("slab.top", "slab", "slab"), "slab.top");
}

TEST(PlaneCut, AnObliqueCutThroughTheCentreGivesAHexagonalCap)
{
    Plane plane = Plane::fromPointNormal({0.5, 0.5, 0.5}, {1, 1, 1});
    auto cut = splitPart(unitCube(), plane, "a", "b");
    ASSERT_TRUE(cut.ok());
    expectSoundHalves(*cut, 1.0);
    EXPECT_NEAR(signedVolume(cut->front), 0.5, 1e-12);
    ASSERT_EQ(cut->frontCaps.size(), 1u);
    const Face* cap = findFace(cut->front, cut->frontCaps[0]);
    EXPECT_EQ(cap->loop.size(), 6u);
    // A regular hexagon of side sqrt(2)/2: 3 sqrt(3) / 2 * 1/2.
    EXPECT_NEAR(polygonArea(loopPositions(cut->front.vertices, cap->loop)), 0.75 * std::sqrt(3.0), 1e-12);
    expectCapsFace(cut->back, cut->backCaps, glm::normalize(Vec3{1, 1, 1}));
}

TEST(PlaneCut, ACutThroughTwoEdgesUsesTheCubesOwnCorners)
{
    // The plane x = z holds the vertical edges at (0, y, 0) and (1, y, 1).
    Plane plane = Plane::fromPointNormal({0, 0, 0}, {1, 0, -1});
    auto cut = splitPart(unitCube(), plane, "a", "b");
    ASSERT_TRUE(cut.ok()) << cut.error().message;
    expectSoundHalves(*cut, 1.0);
    EXPECT_NEAR(signedVolume(cut->front), 0.5, 1e-12);
    EXPECT_EQ(cut->front.vertices.size(), 6u) << "a triangular prism";
    EXPECT_EQ(cut->front.faces.size(), 5u);
    EXPECT_EQ(cut->back.faces.size(), 5u);
}

TEST(PlaneCut, ACutThroughThreeCornersCutsOffATetrahedron)
{
    Plane plane = Plane::fromPointNormal({1, 0, 0}, {-1, -1, -1}); // x + y + z = 1, front = origin
    auto cut = splitPart(unitCube(), plane, "tip", "rest");
    ASSERT_TRUE(cut.ok()) << cut.error().message;
    expectSoundHalves(*cut, 1.0);
    EXPECT_NEAR(signedVolume(cut->front), 1.0 / 6.0, 1e-12);
    EXPECT_EQ(cut->front.faces.size(), 4u);
    EXPECT_EQ(cut->front.vertices.size(), 4u);
    EXPECT_EQ(findFace(cut->front, cut->frontCaps[0])->loop.size(), 3u);
}

TEST(PlaneCut, AnLShapedPrismCutAcrossBothLegsGetsTwoCapPiecesPerSide)
{
    // x + y = 2.5 crosses the foot of the L near x = 2 and its upright near
    // y = 2: the cut outline is two segments, so each side has two caps.
    Part ell = lPrism();
    ASSERT_TRUE(isClosedManifold(ell));
    ASSERT_NEAR(signedVolume(ell), 3.0, 1e-12);
    Plane plane = Plane::fromPointNormal({2, 0.5, 0}, {1, 1, 0});
    auto cut = splitPart(ell, plane, "tips", "body");
    ASSERT_TRUE(cut.ok()) << cut.error().message;
    expectSoundHalves(*cut, 3.0);
    EXPECT_NEAR(signedVolume(cut->front), 0.25, 1e-12) << "two corner triangles of 1/8";
    EXPECT_EQ(cut->frontCaps, (std::vector<std::string>{"tips.cut1", "tips.cut2"}));
    EXPECT_EQ(cut->backCaps.size(), 2u);
    expectCapsFace(cut->front, cut->frontCaps, -glm::normalize(Vec3{1, 1, 0}));
    expectCapsFace(cut->back, cut->backCaps, glm::normalize(Vec3{1, 1, 0}));
}

TEST(PlaneCut, ACutAlongAnLShapedProfileSplitsTheNonConvexCapIntoConvexFaces)
{
    Plane plane = Plane::fromPointNormal({0, 0, 0.4}, {0, 0, 1});
    auto cut = splitPart(lPrism(), plane, "top", "bottom");
    ASSERT_TRUE(cut.ok()) << cut.error().message;
    expectSoundHalves(*cut, 3.0);
    EXPECT_NEAR(signedVolume(cut->back), 1.2, 1e-12);
    // Hertel-Mehlhorn merging leaves the two rectangles of the L, not triangles.
    EXPECT_EQ(cut->frontCaps.size(), 2u);
    EXPECT_EQ(cut->backCaps.size(), 2u);
    double area = 0.0;
    for (const std::string& id : cut->frontCaps)
        area += polygonArea(loopPositions(cut->front.vertices, findFace(cut->front, id)->loop));
    EXPECT_NEAR(area, 3.0, 1e-12);
    expectCapsFace(cut->front, cut->frontCaps, {0, 0, -1});
}

TEST(PlaneCut, ACutAcrossATubeCapsTheRingAroundItsHole)
{
    Part tube = frame();
    ASSERT_TRUE(isClosedManifold(tube));
    ASSERT_NEAR(signedVolume(tube), 8.0, 1e-12);
    Plane plane = Plane::fromPointNormal({0, 0, 0.25}, {0, 0, 1});
    auto cut = splitPart(tube, plane, "upper", "lower");
    ASSERT_TRUE(cut.ok()) << cut.error().message;
    expectSoundHalves(*cut, 8.0);
    EXPECT_NEAR(signedVolume(cut->back), 2.0, 1e-12);
    double area = 0.0;
    for (const std::string& id : cut->backCaps)
        area += polygonArea(loopPositions(cut->back.vertices, findFace(cut->back, id)->loop));
    EXPECT_NEAR(area, 8.0, 1e-12) << "the ring, not the square over the hole";
    EXPECT_GE(cut->backCaps.size(), 4u) << "a ring needs at least four convex pieces";
    expectCapsFace(cut->back, cut->backCaps, {0, 0, 1});
}

TEST(PlaneCut, ACylinderCutLengthwiseKeepsEveryCornerOnTheCapEdges)
{
    Part cylinder = makePrism("cyl", 64, 1.0, 2.0, {0, 0, 0}, "white").value();
    Plane plane = Plane::fromPointNormal({0.1, 0, 0}, {1, 0, 0});
    auto cut = splitPart(cylinder, plane, "a", "b");
    ASSERT_TRUE(cut.ok()) << cut.error().message;
    expectSoundHalves(*cut, signedVolume(cylinder));
    ASSERT_EQ(cut->frontCaps.size(), 1u);
    EXPECT_EQ(findFace(cut->front, "a.cut")->loop.size(), 4u);
}

TEST(PlaneCut, APlaneThatMissesOrOnlyTouchesThePartIsRefused)
{
    auto missing = splitPart(unitCube(), Plane::fromPointNormal({5, 0, 0}, {1, 0, 0}), "a", "b");
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().message.find("misses"), std::string::npos);
    EXPECT_FALSE(splitPart(unitCube(), Plane::fromPointNormal({1, 0, 0}, {1, 0, 0}), "a", "b").ok());
    EXPECT_FALSE(splitPart(unitCube(), Plane::fromPointNormal({0, 0, 0}, {1, 1, 0}), "a", "b").ok())
        << "touching one edge is not a cut";
}

TEST(PlaneCut, BadIdsAndPlanesAreRefused)
{
    Plane plane = Plane::fromPointNormal({0.5, 0, 0}, {1, 0, 0});
    EXPECT_FALSE(splitPart(unitCube(), plane, "a", "a").ok());
    EXPECT_FALSE(splitPart(unitCube(), plane, "", "b").ok());
    EXPECT_FALSE(splitPart(unitCube(), Plane{{0, 0, 0}, 0.5}, "a", "b").ok());
    Part broken = unitCube();
    broken.faces[0].loop[1] = 99;
    EXPECT_FALSE(splitPart(broken, plane, "a", "b").ok());
}

TEST(PlaneCut, AnOpenWallIsCutWithoutCaps)
{
    Part wall;
    wall.id = "wall";
    wall.vertices = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}};
    wall.faces = {{"wall.face", {0, 1, 2, 3}, {}}};
    auto cut = splitPart(wall, Plane::fromPointNormal({1, 0, 0}, {1, 0, 0}), "right", "left");
    ASSERT_TRUE(cut.ok());
    EXPECT_TRUE(cut->frontCaps.empty());
    EXPECT_TRUE(cut->backCaps.empty());
    ASSERT_EQ(cut->front.faces.size(), 1u);
    EXPECT_NEAR(totalArea(cut->front) + totalArea(cut->back), 2.0, 1e-12);
}

TEST(PlaneCut, ARoomCutWithOpenCapsStaysOpenAndWithClosedCapsFacesInwards)
{
    Part room = makeRoom("room", {0, 0, 0}, {4, 3, 5}, "white").value();
    Plane plane = Plane::fromPointNormal({1, 0, 0}, {1, 0, 0});
    auto open = splitPart(room, plane, "east", "west", CutCaps::Open);
    ASSERT_TRUE(open.ok());
    EXPECT_TRUE(open->frontCaps.empty());
    EXPECT_NEAR(totalArea(open->front) + totalArea(open->back), totalArea(room), 1e-9)
        << "clipping a room to regions must not add a wall";

    auto closed = splitPart(room, plane, "east", "west");
    ASSERT_TRUE(closed.ok());
    EXPECT_TRUE(isClosedManifold(closed->front));
    EXPECT_NEAR(signedVolume(closed->front) + signedVolume(closed->back), -60.0, 1e-9);
    // The cap of the east half closes it on its west side, facing into it.
    expectCapsFace(closed->front, closed->frontCaps, {1, 0, 0});
}

TEST(PlaneCut, RandomPlanesThroughNonConvexPartsAlwaysGiveClosedConvexHalves)
{
    // mt19937's sequence is fixed by the standard, so the planes are the same
    // everywhere; the scaling is done by hand for the same reason.
    std::mt19937 random(20240611);
    auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * (double(random()) / 4294967296.0); };
    int cuts = 0;
    for (const Part& part : {lPrism(), frame(), makePrism("p", 7, 1.0, 1.0, {0, 0, 0}, "w").value()}) {
        double volume = signedVolume(part);
        for (int i = 0; i < 150; ++i) {
            Vec3 normal{uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
            if (glm::length(normal) < 0.1)
                continue;
            Vec3 point{uniform(-0.5, 3.5), uniform(-0.5, 3.5), uniform(-0.2, 1.2)};
            Plane plane = Plane::fromPointNormal(point, normal);
            bool front = false, back = false;
            for (const Vec3& v : part.vertices) {
                front |= plane.signedDistance(v) > kDistanceEpsilon;
                back |= plane.signedDistance(v) < -kDistanceEpsilon;
            }
            auto cut = splitPart(part, plane, "f", "b");
            ASSERT_EQ(cut.ok(), front && back) << part.id << " plane " << i;
            if (!cut)
                continue;
            ++cuts;
            SCOPED_TRACE(part.id + " plane " + std::to_string(i));
            expectSoundHalves(*cut, volume);
        }
    }
    EXPECT_GT(cuts, 150);
}

TEST(PlaneCut, AFaceLyingInTheCutPlaneStaysWithTheSolidBehindIt)
{
    // y = 1 holds the top of the L's foot beyond the upright (x in [1, 2]):
    // that face belongs to the foot, and only x in [0, 1] needs a cap.
    Plane plane = Plane::fromPointNormal({0, 1, 0}, {0, 1, 0});
    auto cut = splitPart(lPrism(), plane, "upright", "foot");
    ASSERT_TRUE(cut.ok()) << cut.error().message;
    expectSoundHalves(*cut, 3.0);
    EXPECT_NEAR(signedVolume(cut->back), 2.0, 1e-12);
    ASSERT_EQ(cut->backCaps.size(), 1u);
    EXPECT_NEAR(polygonArea(loopPositions(cut->back.vertices, findFace(cut->back, "foot.cut")->loop)), 1.0, 1e-12);
    EXPECT_NE(findFace(cut->back, "foot.side3"), nullptr) << "the foot's top, x in [1, 2]";
}

TEST(PlaneCut, CutsAlongTheGridOfATubeGiveClosedHalves)
{
    const Vec3 axes[] = {{1, 0, 0}, {0, 1, 0}};
    for (const Vec3& axis : axes)
        for (double at : {0.5, 1.0, 1.5, 2.0, 2.5}) {
            SCOPED_TRACE("axis " + std::to_string(axis.x) + " at " + std::to_string(at));
            auto cut = splitPart(frame(), Plane::fromPointNormal(axis * at, axis), "f", "b");
            ASSERT_TRUE(cut.ok()) << cut.error().message;
            expectSoundHalves(*cut, 8.0);
        }
}
