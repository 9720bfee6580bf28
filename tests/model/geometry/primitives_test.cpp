#include "model/geometry/primitives.h"

#include "support/part_checks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace regio::model;
using namespace regio::test;

namespace {

void expectSound(const Part& part, double volume)
{
    EXPECT_TRUE(isClosedManifold(part));
    EXPECT_TRUE(facesArePlanarAndConvex(part));
    EXPECT_TRUE(idsAreUnique({&part}));
    EXPECT_NEAR(signedVolume(part), volume, 1e-9 * std::max(1.0, volume));
}

} // namespace

TEST(Primitives, ABoxIsClosedWithSixOutwardFacesNamedByTheirSide)
{
    auto box = makeBox("box1.body", {1, 0, -1}, {3, 1, 2}, "white");
    ASSERT_TRUE(box.ok()) << box.error().message;
    ASSERT_EQ(box->faces.size(), 6u);
    expectSound(*box, 2.0 * 1.0 * 3.0);
    EXPECT_EQ(box->material, "white");
    const std::pair<const char*, Vec3> expected[] = {
        {"box1.body.nx", {-1, 0, 0}}, {"box1.body.px", {1, 0, 0}},  {"box1.body.ny", {0, -1, 0}},
        {"box1.body.py", {0, 1, 0}},  {"box1.body.nz", {0, 0, -1}}, {"box1.body.pz", {0, 0, 1}},
    };
    for (const auto& [id, normal] : expected) {
        const Face* face = findFace(*box, id);
        ASSERT_NE(face, nullptr) << id;
        EXPECT_EQ(faceNormal(*box, *face), normal) << id;
        EXPECT_TRUE(face->material.empty()) << "faces inherit the part's material";
    }
}

TEST(Primitives, ARoomIsABoxWhoseNormalsPointIn)
{
    auto room = makeRoom("room", {0, 0, 0}, {4, 3, 5}, "walls");
    ASSERT_TRUE(room.ok());
    ASSERT_EQ(room->faces.size(), 6u);
    EXPECT_TRUE(isClosedManifold(*room));
    EXPECT_TRUE(facesArePlanarAndConvex(*room));
    EXPECT_NEAR(signedVolume(*room), -60.0, 1e-9);
    EXPECT_EQ(faceNormal(*room, *findFace(*room, "room.ny")), Vec3(0, 1, 0)) << "the floor faces up";
    EXPECT_EQ(faceNormal(*room, *findFace(*room, "room.py")), Vec3(0, -1, 0)) << "the ceiling faces down";
    EXPECT_EQ(faceNormal(*room, *findFace(*room, "room.px")), Vec3(-1, 0, 0));
}

TEST(Primitives, APrismHasTwoCapsAndOneSidePerCorner)
{
    auto prism = makePrism("column", 6, 0.5, 2.0, {1, 0, 1}, "stone");
    ASSERT_TRUE(prism.ok()) << prism.error().message;
    EXPECT_EQ(prism->faces.size(), 8u);
    // A regular hexagon of circumradius r has area 3 sqrt(3) / 2 r^2.
    expectSound(*prism, 1.5 * std::sqrt(3.0) * 0.25 * 2.0);
    EXPECT_NEAR(faceNormal(*prism, *findFace(*prism, "column.top")).y, 1.0, 1e-12);
    EXPECT_NEAR(faceNormal(*prism, *findFace(*prism, "column.bottom")).y, -1.0, 1e-12);
    EXPECT_NE(findFace(*prism, "column.side6"), nullptr);
}

TEST(Primitives, AManySidedPrismApproachesACylinder)
{
    const int sides = 256;
    auto cylinder = makePrism("cyl", sides, 1.0, 1.0, {0, 0, 0}, "white");
    ASSERT_TRUE(cylinder.ok());
    EXPECT_EQ(cylinder->faces.size(), size_t(sides + 2));
    double polygon = 0.5 * sides * std::sin(2.0 * std::numbers::pi / sides);
    expectSound(*cylinder, polygon);
    EXPECT_NEAR(signedVolume(*cylinder), std::numbers::pi, 1e-3);
}

TEST(Primitives, AWedgeIsARampRisingTowardsPlusX)
{
    auto wedge = makeWedge("ramp", {0, 0, 0}, {2, 1, 3}, "white");
    ASSERT_TRUE(wedge.ok());
    EXPECT_EQ(wedge->faces.size(), 5u);
    expectSound(*wedge, 0.5 * 2.0 * 1.0 * 3.0);
    Vec3 slope = faceNormal(*wedge, *findFace(*wedge, "ramp.slope"));
    EXPECT_NEAR(slope.x, -1.0 / std::sqrt(5.0), 1e-12);
    EXPECT_NEAR(slope.y, 2.0 / std::sqrt(5.0), 1e-12);
    EXPECT_EQ(findFace(*wedge, "ramp.nz")->loop.size(), 3u);
}

TEST(Primitives, StairsAreOneClosedBoxPerStepClimbingAlongPlusZ)
{
    auto stairs = makeStairs("stairs", 4, 1.0, 2.0, 0.8, {0, 0, 0}, "wood");
    ASSERT_TRUE(stairs.ok()) << stairs.error().message;
    EXPECT_EQ(stairs->id, "stairs");
    ASSERT_EQ(stairs->parts.size(), 4u);
    std::vector<const Part*> parts;
    double volume = 0.0;
    for (int i = 0; i < 4; ++i) {
        const Part& step = stairs->parts[size_t(i)];
        EXPECT_EQ(step.id, "stairs.step" + std::to_string(i + 1));
        EXPECT_EQ(step.material, "wood");
        // Step i is a column 0.5 deep rising to (i + 1) * 0.2.
        expectSound(step, 1.0 * 0.5 * 0.2 * (i + 1));
        volume += signedVolume(step);
        parts.push_back(&step);
    }
    EXPECT_TRUE(idsAreUnique(parts));
    EXPECT_NEAR(volume, 1.0 * 0.5 * 0.2 * (1 + 2 + 3 + 4), 1e-12);
    // The top tread is at the full height and the far end of the run.
    const Part& top = stairs->parts.back();
    const Face* tread = findFace(top, "stairs.step4.py");
    for (int index : tread->loop) {
        EXPECT_DOUBLE_EQ(top.vertices[size_t(index)].y, 0.8);
        EXPECT_GE(top.vertices[size_t(index)].z, 1.5);
    }
}

TEST(Primitives, DegenerateSizesAreRefusedWithAReason)
{
    EXPECT_FALSE(makeBox("b", {0, 0, 0}, {1, 0, 1}, "m").ok());
    EXPECT_FALSE(makeBox("b", {0, 0, 0}, {1, NAN, 1}, "m").ok());
    EXPECT_FALSE(makeBox("", {0, 0, 0}, {1, 1, 1}, "m").ok());
    EXPECT_FALSE(makeRoom("r", {0, 0, 0}, {-1, 1, 1}, "m").ok());
    EXPECT_FALSE(makePrism("p", 2, 1.0, 1.0, {0, 0, 0}, "m").ok());
    EXPECT_FALSE(makePrism("p", 8, 0.0, 1.0, {0, 0, 0}, "m").ok());
    EXPECT_FALSE(makeWedge("w", {0, 0, 0}, {1, 1, 0}, "m").ok());
    auto stairs = makeStairs("s", 0, 1.0, 1.0, 1.0, {0, 0, 0}, "m");
    ASSERT_FALSE(stairs.ok());
    EXPECT_NE(stairs.error().message.find("steps"), std::string::npos);
    EXPECT_FALSE(makeStairs("s", 3, 1.0, -1.0, 1.0, {0, 0, 0}, "m").ok());
}
