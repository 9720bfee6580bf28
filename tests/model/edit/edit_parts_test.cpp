#include "model/edit/edit_parts.h"

#include "model/validation/validation.h"

#include "edit_fixture.h"
#include "support/part_checks.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

using namespace regio::model;
using namespace regio::model::testing;
using namespace regio::test;

namespace {

std::vector<std::string> partIds(const Scene& scene, const std::string& objectId)
{
    std::vector<std::string> ids;
    for (const Part& part : scene.findObject(objectId)->parts)
        ids.push_back(part.id);
    return ids;
}

const std::vector<std::string>& order(const Scene& scene, const std::string& regionId)
{
    return scene.findRegion(regionId)->bspOrder;
}

} // namespace

TEST(EditParts, AddingAPartAtAnIndexAndRemovingItRestoresTheScene)
{
    const Scene original = sampleScene();
    Scene scene = original;
    Part drawer = makeBox("table.drawer", {0.4, 0.6, 0.1}, {0.8, 0.7, 0.6}, "white").value();
    auto index = addPart(scene, "table", drawer, 1);
    ASSERT_TRUE(index.ok()) << index.error().message;
    EXPECT_EQ(partIds(scene, "table"), (std::vector<std::string>{"table.desk", "table.drawer", "table.legs"}));
    auto removed = removePart(scene, "table.drawer");
    ASSERT_TRUE(removed.ok());
    EXPECT_EQ(removed->objectId, "table");
    EXPECT_EQ(removed->index, 1);
    EXPECT_EQ(removed->part, drawer);
    EXPECT_TRUE(scene == original);
}

TEST(EditParts, APartWithTakenIdsOrAnUnknownOwnerIsRefused)
{
    Scene scene = sampleScene();
    Part part = makeBox("crate.body", {0, 0, 0}, {1, 1, 1}, "white").value();
    auto taken = expectRefused(scene, [&](Scene& s) { return addPart(s, "table", part); });
    EXPECT_EQ(taken.pointer, "/objects/0/parts/2/id");
    part.id = "table.drawer"; // its faces are still named crate.body.*
    expectRefused(scene, [&](Scene& s) { return addPart(s, "table", part); });
    Part fresh = makeBox("table.drawer", {0, 0, 0}, {1, 1, 1}, "white").value();
    expectRefused(scene, [&](Scene& s) { return addPart(s, "chair", fresh); });
    expectRefused(scene, [&](Scene& s) { return addPart(s, "table", fresh, 7); });
}

TEST(EditParts, RemovingAPartTakesItsFacesOutOfTheBspOrdersAndRestoringPutsThemBack)
{
    const Scene original = sampleScene();
    Scene scene = original;
    auto removed = removePart(scene, "table.desk");
    ASSERT_TRUE(removed.ok());
    EXPECT_EQ(order(scene, "west"), (std::vector<std::string>{"table.legs.px", "room.shell.nx"}));
    EXPECT_EQ(removed->bspOrders.size(), 1u);
    ASSERT_TRUE(restorePart(scene, *removed).ok());
    EXPECT_TRUE(scene == original);
    expectRefused(scene, [](Scene& s) { return removePart(s, "chair.seat"); });
}

TEST(EditParts, DuplicatingAPartPlacesAFreshCopyRightAfterIt)
{
    const Scene original = sampleScene();
    Scene scene = original;
    auto id = duplicatePart(scene, "table.legs");
    ASSERT_TRUE(id.ok());
    EXPECT_EQ(*id, "table.legs-2");
    EXPECT_EQ(partIds(scene, "table"), (std::vector<std::string>{"table.desk", "table.legs", "table.legs-2"}));
    EXPECT_EQ(scene.findPart(*id)->faces[0].id, "table.legs-2.nx");
    ASSERT_TRUE(removePart(scene, *id).ok());
    EXPECT_TRUE(scene == original);
}

TEST(EditParts, RenamingAPartChangesOnlyItsId)
{
    const Scene original = sampleScene();
    Scene scene = original;
    ASSERT_TRUE(renamePart(scene, "table.desk", "table.top").ok());
    EXPECT_EQ(scene.objects[0].parts[0].id, "table.top");
    EXPECT_EQ(scene.objects[0].parts[0].faces[0].id, "table.desk.nx");
    ASSERT_TRUE(renamePart(scene, "table.top", "table.desk").ok());
    EXPECT_TRUE(scene == original);
    expectRefused(scene, [](Scene& s) { return renamePart(s, "table.desk", "table.legs"); });
    expectRefused(scene, [](Scene& s) { return renamePart(s, "table.desk", ""); });
    expectRefused(scene, [](Scene& s) { return renamePart(s, "nothing", "x"); });
}

TEST(EditParts, PartNameAndMaterialReturnTheirPreviousValues)
{
    const Scene original = sampleScene();
    Scene scene = original;
    auto name = setPartName(scene, "table.desk", "Desk");
    ASSERT_TRUE(name.ok());
    EXPECT_EQ(*name, "");
    auto material = setPartMaterial(scene, "table.desk", "red");
    ASSERT_TRUE(material.ok());
    EXPECT_EQ(*material, "white");
    EXPECT_EQ(scene.findPart("table.desk")->material, "red");
    ASSERT_TRUE(setPartMaterial(scene, "table.desk", *material).ok());
    ASSERT_TRUE(setPartName(scene, "table.desk", *name).ok());
    EXPECT_TRUE(scene == original);
    auto unknown = expectRefused(scene, [](Scene& s) { return setPartMaterial(s, "table.desk", "gold"); });
    EXPECT_EQ(unknown.pointer, "/objects/0/parts/0/material");
}

TEST(EditParts, MovingAPartToAnotherObjectAndBackRestoresTheScene)
{
    const Scene original = sampleScene();
    Scene scene = original;
    auto from = movePart(scene, "table.legs", "crate", 0);
    ASSERT_TRUE(from.ok()) << from.error().message;
    EXPECT_EQ(*from, (PartPlace{"table", 1}));
    EXPECT_EQ(partIds(scene, "crate"), (std::vector<std::string>{"table.legs", "crate.body"}));
    EXPECT_EQ(partIds(scene, "table"), std::vector<std::string>{"table.desk"});
    ASSERT_TRUE(movePart(scene, "table.legs", from->objectId, from->index).ok());
    EXPECT_TRUE(scene == original);
}

TEST(EditParts, MovingAPartWithinItsObjectReordersIt)
{
    const Scene original = sampleScene();
    Scene scene = original;
    auto from = movePart(scene, "table.desk", "table", -1);
    ASSERT_TRUE(from.ok());
    EXPECT_EQ(partIds(scene, "table"), (std::vector<std::string>{"table.legs", "table.desk"}));
    ASSERT_TRUE(movePart(scene, "table.desk", from->objectId, from->index).ok());
    EXPECT_TRUE(scene == original);
    expectRefused(scene, [](Scene& s) { return movePart(s, "table.desk", "table", 2); });
    expectRefused(scene, [](Scene& s) { return movePart(s, "table.desk", "chair", 0); });
}

TEST(EditParts, RenamingAFaceRenamesItInEveryBspOrder)
{
    const Scene original = sampleScene();
    Scene scene = original;
    ASSERT_TRUE(renameFace(scene, "table.desk.py", "table.desk.top").ok());
    EXPECT_TRUE(scene.locateFace("table.desk.top").valid());
    EXPECT_EQ(order(scene, "west")[0], "table.desk.top");
    ASSERT_TRUE(renameFace(scene, "table.desk.top", "table.desk.py").ok());
    EXPECT_TRUE(scene == original);
    expectRefused(scene, [](Scene& s) { return renameFace(s, "table.desk.py", "crate"); });
    expectRefused(scene, [](Scene& s) { return renameFace(s, "no.face", "x"); });
}

TEST(EditParts, AFaceMaterialCanBeSetOrClearedToInherit)
{
    const Scene original = sampleScene();
    Scene scene = original;
    auto previous = setFaceMaterial(scene, "table.desk.py", "");
    ASSERT_TRUE(previous.ok());
    EXPECT_EQ(*previous, "red");
    const Part& desk = *scene.findPart("table.desk");
    EXPECT_EQ(scene.materialOf(desk, desk.faces[3])->id, "white") << "inherits the part's";
    ASSERT_TRUE(setFaceMaterial(scene, "table.desk.py", *previous).ok());
    EXPECT_TRUE(scene == original);
    auto unknown = expectRefused(scene, [](Scene& s) { return setFaceMaterial(s, "table.desk.py", "gold"); });
    EXPECT_EQ(unknown.pointer, "/objects/0/parts/0/faces/3/material");
}

TEST(EditParts, TransformingAPartAndSettingTheOldGeometryBackRestoresTheExactNumbers)
{
    const Scene original = sampleScene();
    Scene scene = original;
    glm::dmat4 m = glm::scale(glm::rotate(glm::translate(glm::dmat4(1.0), Vec3{0.3, 0.1, -0.2}), 0.3, Vec3{1, 2, 3}),
                              Vec3{1.5, 0.5, 2.0});
    auto previous = transformPart(scene, "crate.body", m);
    ASSERT_TRUE(previous.ok());
    const Part& crate = *scene.findPart("crate.body");
    EXPECT_NEAR(signedVolume(crate), 0.125 * 1.5 * 0.5 * 2.0, 1e-12);
    EXPECT_TRUE(facesArePlanarAndConvex(crate)) << "affine maps keep faces planar and convex";
    EXPECT_EQ(previous->partId, "crate.body");
    ASSERT_TRUE(setPartGeometry(scene, *previous).ok());
    EXPECT_TRUE(scene == original);
}

TEST(EditParts, AMirrorReversesTheLoopsSoNormalsStayOutward)
{
    const Scene original = sampleScene();
    Scene scene = original;
    glm::dmat4 mirror = glm::scale(glm::dmat4(1.0), Vec3{-1, 1, 1});
    auto previous = transformPart(scene, "crate.body", mirror);
    ASSERT_TRUE(previous.ok());
    const Part& crate = *scene.findPart("crate.body");
    EXPECT_NEAR(signedVolume(crate), 0.125, 1e-12);
    EXPECT_TRUE(isClosedManifold(crate));
    EXPECT_EQ(faceNormal(crate, crate.faces[1]), Vec3(-1, 0, 0)) << ".px now lies at -x";
    ASSERT_TRUE(setPartGeometry(scene, *previous).ok());
    EXPECT_TRUE(scene == original);
}

TEST(EditParts, SingularProjectiveOrNonFiniteTransformsAreRefused)
{
    Scene scene = sampleScene();
    expectRefused(scene, [](Scene& s) {
        return transformPart(s, "crate.body", glm::scale(glm::dmat4(1.0), Vec3{1, 0, 1}));
    });
    glm::dmat4 projective(1.0);
    projective[2][3] = 0.5;
    expectRefused(scene, [&](Scene& s) { return transformPart(s, "crate.body", projective); });
    glm::dmat4 notFinite(1.0);
    notFinite[3][0] = NAN;
    expectRefused(scene, [&](Scene& s) { return transformPart(s, "crate.body", notFinite); });
    expectRefused(scene, [](Scene& s) { return transformParts(s, {"crate.body", "crate.body"}, glm::dmat4(1.0)); });
    // Millimetre-scale parts are fine: the singularity test is relative.
    Scene copy = scene;
    EXPECT_TRUE(transformPart(copy, "crate.body", glm::scale(glm::dmat4(1.0), Vec3{1e-3})).ok());
}

TEST(EditParts, ReplacingGeometryRefusesTakenFaceIdsAndOrphanedBspEntries)
{
    Scene scene = sampleScene();
    PartGeometry geometry = geometryOf(*scene.findPart("table.desk"));
    geometry.faces[0].id = "crate.body.nx";
    expectRefused(scene, [&](Scene& s) { return setPartGeometry(s, geometry); });
    geometry = geometryOf(*scene.findPart("table.desk"));
    geometry.faces.erase(geometry.faces.begin() + 3); // table.desk.py, first in "west"
    auto orphan = expectRefused(scene, [&](Scene& s) { return setPartGeometry(s, geometry); });
    EXPECT_NE(orphan.message.find("west"), std::string::npos);
    geometry = geometryOf(*scene.findPart("table.desk"));
    geometry.faces[0].loop = {0, 1};
    expectRefused(scene, [&](Scene& s) { return setPartGeometry(s, geometry); });
}

TEST(EditParts, SplittingAPartInTheSceneReplacesItByBothHalvesAndTheirFacesInTheOrders)
{
    const Scene original = sampleScene();
    Scene scene = original;
    Plane plane = Plane::fromPointNormal({0.6, 0, 0}, {1, 0, 0});
    auto split = splitPartInScene(scene, "table.desk", plane, "table.right", "table.left");
    ASSERT_TRUE(split.ok()) << split.error().message;
    EXPECT_EQ(partIds(scene, "table"), (std::vector<std::string>{"table.right", "table.left", "table.legs"}));
    EXPECT_EQ(order(scene, "west"),
              (std::vector<std::string>{"table.right.py", "table.left.py", "table.legs.px", "room.shell.nx"}));
    for (const char* id : {"table.right", "table.left"}) {
        const Part& half = *scene.findPart(id);
        EXPECT_TRUE(isClosedManifold(half));
        EXPECT_EQ(half.material, "white");
    }
    EXPECT_EQ(findFace(*scene.findPart("table.right"), "table.right.py")->material, "red");
    EXPECT_EQ(split->frontCaps, std::vector<std::string>{"table.right.cut"});
    ASSERT_TRUE(unsplitPart(scene, *split).ok());
    EXPECT_TRUE(scene == original);
}

TEST(EditParts, ASplitHalfMayKeepTheOriginalId)
{
    const Scene original = sampleScene();
    Scene scene = original;
    Plane plane = Plane::fromPointNormal({0, 0.3, 0}, {0, 1, 0});
    auto split = splitPartInScene(scene, "table.legs", plane, "table.legs", "table.feet");
    ASSERT_TRUE(split.ok()) << split.error().message;
    EXPECT_TRUE(scene.locateFace("table.legs.px").valid());
    EXPECT_TRUE(scene.locateFace("table.feet.px").valid());
    EXPECT_EQ(order(scene, "west")[1], "table.legs.px");
    EXPECT_EQ(order(scene, "west")[2], "table.feet.px");
    ASSERT_TRUE(unsplitPart(scene, *split).ok());
    EXPECT_TRUE(scene == original);
}

TEST(EditParts, ASplitIsRefusedForTakenIdsOrAPlaneMissingThePart)
{
    Scene scene = sampleScene();
    Plane plane = Plane::fromPointNormal({0.6, 0, 0}, {1, 0, 0});
    expectRefused(scene,
                  [&](Scene& s) { return splitPartInScene(s, "table.desk", plane, "crate.body", "table.left"); });
    expectRefused(scene,
                  [&](Scene& s) { return splitPartInScene(s, "table.desk", plane, "table.right", "table.legs"); });
    auto missing = expectRefused(scene, [&](Scene& s) { return splitPartInScene(s, "crate.body", plane, "a", "b"); });
    EXPECT_NE(missing.message.find("misses"), std::string::npos);
    expectRefused(scene, [&](Scene& s) { return splitPartInScene(s, "chair", plane, "a", "b"); });
}

TEST(EditParts, UndoingASplitIsRefusedWhenTheHalvesHaveMoved)
{
    Scene scene = sampleScene();
    Plane plane = Plane::fromPointNormal({0.6, 0, 0}, {1, 0, 0});
    auto split = splitPartInScene(scene, "table.desk", plane, "table.right", "table.left");
    ASSERT_TRUE(split.ok());
    ASSERT_TRUE(movePart(scene, "table.left", "crate").ok());
    expectRefused(scene, [&](Scene& s) { return unsplitPart(s, *split); });
}

TEST(EditParts, AScenePassesValidationAfterCuttingAPartAndClippingTheRoomToTheRegions)
{
    Scene scene = sampleScene();
    ASSERT_FALSE(hasErrors(validateScene(scene)));
    Plane across = Plane::fromPointNormal({0.6, 0, 0}, {1, 0, 0});
    ASSERT_TRUE(splitPartInScene(scene, "table.desk", across, "table.right", "table.left").ok());
    // The room straddles the regions' boundary at x = 1.5; clipping it there
    // without caps keeps it a room (no new wall) and ends the warning.
    Plane boundary = Plane::fromPointNormal({1.5, 0, 0}, {1, 0, 0});
    ASSERT_TRUE(splitPartInScene(scene, "room.shell", boundary, "room.east", "room.west", CutCaps::Open).ok());
    Diagnostics diagnostics = validateScene(scene);
    EXPECT_FALSE(hasErrors(diagnostics));
    for (const Diagnostic& d : diagnostics)
        EXPECT_EQ(d.message.find("straddles"), std::string::npos) << d.message;
}
