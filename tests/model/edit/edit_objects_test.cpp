#include "model/edit/edit_objects.h"

#include "model/validation/validation.h"

#include "edit_fixture.h"
#include "support/part_checks.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

using namespace regio::model;
using namespace regio::model::testing;
using namespace regio::test;

namespace {

Object lampObject(const std::string& id = "lamp1")
{
    return Object{id, "Lamp", {makeBox(id + ".body", {1, 2.9, 1}, {1.5, 3, 1.5}, "lamp").value()}};
}

std::vector<std::string> objectIds(const Scene& scene)
{
    std::vector<std::string> ids;
    for (const Object& object : scene.objects)
        ids.push_back(object.id);
    return ids;
}

std::vector<std::string> partIds(const Object& object)
{
    std::vector<std::string> ids;
    for (const Part& part : object.parts)
        ids.push_back(part.id);
    return ids;
}

} // namespace

TEST(EditObjects, InsertingAnObjectPutsItAtTheIndexAndRemovingItUndoesThat)
{
    const Scene original = sampleScene();
    Scene scene = original;
    auto index = insertObject(scene, lampObject(), 1);
    ASSERT_TRUE(index.ok()) << index.error().message;
    EXPECT_EQ(*index, 1);
    EXPECT_EQ(objectIds(scene), (std::vector<std::string>{"table", "lamp1", "crate", "room"}));
    auto removed = removeObject(scene, "lamp1");
    ASSERT_TRUE(removed.ok());
    EXPECT_EQ(removed->index, 1);
    EXPECT_TRUE(removed->bspOrders.empty());
    EXPECT_TRUE(scene == original);
}

TEST(EditObjects, AddingAnObjectAppendsIt)
{
    Scene scene = sampleScene();
    auto index = addObject(scene, lampObject());
    ASSERT_TRUE(index.ok());
    EXPECT_EQ(*index, 3);
    EXPECT_EQ(scene.objects.back().id, "lamp1");
}

TEST(EditObjects, AnObjectWithATakenOrBrokenIdOrLoopIsRefused)
{
    Scene scene = sampleScene();
    auto taken = expectRefused(scene, [](Scene& s) { return addObject(s, lampObject("crate")); });
    EXPECT_NE(taken.message.find("already in use"), std::string::npos);
    EXPECT_EQ(taken.pointer, "/objects/3/id");
    expectRefused(scene, [](Scene& s) { return addObject(s, lampObject("")); });
    // A material's id: ids are unique across every kind of element.
    expectRefused(scene, [](Scene& s) { return addObject(s, lampObject("white")); });
    expectRefused(scene, [](Scene& s) {
        Object o = lampObject();
        o.parts[0].faces[2].id = "table.desk.py"; // a face of another part
        return addObject(s, o);
    });
    expectRefused(scene, [](Scene& s) {
        Object o = lampObject();
        o.parts[0].faces[2].id = o.parts[0].faces[1].id; // twice in the same part
        return addObject(s, o);
    });
    auto material = expectRefused(scene, [](Scene& s) {
        Object o = lampObject();
        o.parts[0].material = "gold";
        return addObject(s, o);
    });
    EXPECT_EQ(material.pointer, "/objects/3/parts/0/material");
    expectRefused(scene, [](Scene& s) {
        Object o = lampObject();
        o.parts[0].faces[0].loop = {0, 1, 8};
        return addObject(s, o);
    });
    expectRefused(scene, [](Scene& s) { return insertObject(s, lampObject(), 5); });
}

TEST(EditObjects, RemovingAnObjectTakesItsFacesOutOfTheBspOrdersAndRestoringPutsThemBack)
{
    const Scene original = sampleScene();
    Scene scene = original;
    auto removed = removeObject(scene, "table");
    ASSERT_TRUE(removed.ok());
    EXPECT_EQ(removed->index, 0);
    EXPECT_EQ(removed->object, original.objects[0]);
    EXPECT_EQ(scene.findRegion("west")->bspOrder, std::vector<std::string>{"room.shell.nx"});
    EXPECT_EQ(scene.findRegion("east")->bspOrder, original.findRegion("east")->bspOrder);
    ASSERT_EQ(removed->bspOrders.size(), 1u);
    ASSERT_TRUE(restoreObject(scene, *removed).ok());
    EXPECT_TRUE(scene == original);
    expectRefused(scene, [](Scene& s) { return removeObject(s, "chair"); });
}

TEST(EditObjects, RenamingAnObjectChangesOnlyItsId)
{
    const Scene original = sampleScene();
    Scene scene = original;
    ASSERT_TRUE(renameObject(scene, "table", "desk-table").ok());
    EXPECT_EQ(scene.objects[0].id, "desk-table");
    EXPECT_EQ(scene.objects[0].parts[0].id, "table.desk");
    ASSERT_TRUE(renameObject(scene, "desk-table", "table").ok());
    EXPECT_TRUE(scene == original);
    expectRefused(scene, [](Scene& s) { return renameObject(s, "table", ""); });
    expectRefused(scene, [](Scene& s) { return renameObject(s, "table", "crate"); });
    expectRefused(scene, [](Scene& s) { return renameObject(s, "table", "west"); });
    expectRefused(scene, [](Scene& s) { return renameObject(s, "chair", "stool"); });
}

TEST(EditObjects, SettingAnObjectNameReturnsThePreviousName)
{
    const Scene original = sampleScene();
    Scene scene = original;
    auto previous = setObjectName(scene, "table", "Dining table");
    ASSERT_TRUE(previous.ok());
    EXPECT_EQ(*previous, "Table");
    EXPECT_EQ(scene.objects[0].name, "Dining table");
    ASSERT_TRUE(setObjectName(scene, "table", *previous).ok());
    EXPECT_TRUE(scene == original);
}

TEST(EditObjects, DuplicatingAnObjectGivesEveryIdAFreshDerivedName)
{
    const Scene original = sampleScene();
    Scene scene = original;
    auto id = duplicateObject(scene, "table");
    ASSERT_TRUE(id.ok());
    EXPECT_EQ(*id, "table-2");
    ASSERT_EQ(scene.objects[1].id, "table-2");
    const Object& copy = scene.objects[1];
    EXPECT_EQ(partIds(copy), (std::vector<std::string>{"table-2.desk", "table-2.legs"}));
    EXPECT_EQ(copy.parts[0].faces[3].id, "table-2.desk.py");
    EXPECT_EQ(copy.parts[0].faces[3].material, "red");
    EXPECT_EQ(copy.parts[0].vertices, original.objects[0].parts[0].vertices);
    std::vector<const Part*> all;
    for (const Object& object : scene.objects)
        for (const Part& part : object.parts)
            all.push_back(&part);
    EXPECT_TRUE(idsAreUnique(all));
    ASSERT_TRUE(removeObject(scene, *id).ok());
    EXPECT_TRUE(scene == original);

    // A second copy of the same object does not collide with the first.
    ASSERT_TRUE(duplicateObject(scene, "table").ok());
    EXPECT_EQ(*duplicateObject(scene, "table"), "table-3");
    expectRefused(scene, [](Scene& s) { return duplicateObject(s, "chair"); });
}

TEST(EditObjects, FreshIdsMakeANewPrimitiveSafeToAdd)
{
    Scene scene = sampleScene();
    Object crate{"crate", "", {makeBox("crate.body", {3, 0, 0}, {3.5, 0.5, 0.5}, "red").value()}};
    Object fresh = withFreshIds(scene, crate);
    EXPECT_EQ(fresh.id, "crate-2");
    EXPECT_EQ(fresh.parts[0].id, "crate-2.body");
    EXPECT_EQ(fresh.parts[0].faces[0].id, "crate-2.body.nx");
    EXPECT_TRUE(addObject(scene, fresh).ok());
}

TEST(EditObjects, GroupingPartsMakesANewObjectWhereTheFirstSourceWasAndDropsEmptiedObjects)
{
    const Scene original = sampleScene();
    Scene scene = original;
    auto previous = groupParts(scene, {"table.legs", "crate.body"}, "support", "Support");
    ASSERT_TRUE(previous.ok()) << previous.error().message;
    EXPECT_EQ(objectIds(scene), (std::vector<std::string>{"support", "table", "room"}));
    EXPECT_EQ(scene.objects[0].name, "Support");
    EXPECT_EQ(partIds(scene.objects[0]), (std::vector<std::string>{"table.legs", "crate.body"}));
    EXPECT_EQ(partIds(scene.objects[1]), std::vector<std::string>{"table.desk"});
    EXPECT_EQ(*scene.findPart("crate.body"), original.objects[1].parts[0]) << "parts move untouched";
    EXPECT_EQ(*previous, objectLayout(original));
    ASSERT_TRUE(restoreObjectLayout(scene, *previous).ok());
    EXPECT_TRUE(scene == original);
}

TEST(EditObjects, GroupingObjectsGathersAllTheirParts)
{
    const Scene original = sampleScene();
    Scene scene = original;
    // The new object may take the id of an object it empties.
    auto previous = groupObjects(scene, {"crate", "table"}, "table", "Furniture");
    ASSERT_TRUE(previous.ok()) << previous.error().message;
    EXPECT_EQ(objectIds(scene), (std::vector<std::string>{"table", "room"}));
    EXPECT_EQ(partIds(scene.objects[0]), (std::vector<std::string>{"crate.body", "table.desk", "table.legs"}));
    ASSERT_TRUE(restoreObjectLayout(scene, *previous).ok());
    EXPECT_TRUE(scene == original);
}

TEST(EditObjects, GroupingIsRefusedForBadListsAndTakenIds)
{
    Scene scene = sampleScene();
    expectRefused(scene, [](Scene& s) { return groupParts(s, {}, "g"); });
    expectRefused(scene, [](Scene& s) { return groupParts(s, {"crate.body", "crate.body"}, "g"); });
    expectRefused(scene, [](Scene& s) { return groupParts(s, {"chair.seat"}, "g"); });
    expectRefused(scene, [](Scene& s) { return groupParts(s, {"crate.body"}, "room"); });
    expectRefused(scene, [](Scene& s) { return groupParts(s, {"crate.body"}, ""); });
    expectRefused(scene, [](Scene& s) { return groupObjects(s, {"crate", "chair"}, "g"); });
}

TEST(EditObjects, UngroupingGivesEachPartItsOwnObjectInPlace)
{
    const Scene original = sampleScene();
    Scene scene = original;
    auto previous = ungroupObject(scene, "table");
    ASSERT_TRUE(previous.ok()) << previous.error().message;
    EXPECT_EQ(objectIds(scene), (std::vector<std::string>{"table", "table-legs", "crate", "room"}));
    EXPECT_EQ(scene.objects[0].name, "Table");
    EXPECT_EQ(partIds(scene.objects[1]), std::vector<std::string>{"table.legs"});
    ASSERT_TRUE(restoreObjectLayout(scene, *previous).ok());
    EXPECT_TRUE(scene == original);
    auto single = expectRefused(scene, [](Scene& s) { return ungroupObject(s, "crate"); });
    EXPECT_NE(single.message.find("only 1 part"), std::string::npos);
}

TEST(EditObjects, ALayoutThatLosesOrRepeatsAPartIsRefused)
{
    Scene scene = sampleScene();
    ObjectLayout layout = objectLayout(scene);
    layout.objects[1].parts.clear();
    expectRefused(scene, [&](Scene& s) { return restoreObjectLayout(s, layout); });
    layout = objectLayout(scene);
    layout.objects[1].parts.push_back("table.desk");
    expectRefused(scene, [&](Scene& s) { return restoreObjectLayout(s, layout); });
    layout = objectLayout(scene);
    layout.objects[1].id = "red"; // a material's id
    expectRefused(scene, [&](Scene& s) { return restoreObjectLayout(s, layout); });
}

TEST(EditObjects, TransformingAnObjectMovesAllItsPartsAndUndoRestoresTheExactNumbers)
{
    const Scene original = sampleScene();
    Scene scene = original;
    glm::dmat4 m = glm::rotate(glm::translate(glm::dmat4(1.0), Vec3{0.1, 0, 0.3}), 0.7, Vec3{0, 1, 0});
    auto previous = transformObject(scene, "table", m);
    ASSERT_TRUE(previous.ok());
    ASSERT_EQ(previous->size(), 2u);
    for (const Part& part : scene.objects[0].parts) {
        EXPECT_TRUE(isClosedManifold(part));
        EXPECT_TRUE(facesArePlanarAndConvex(part));
    }
    EXPECT_NEAR(signedVolume(scene.objects[0].parts[0]), signedVolume(original.objects[0].parts[0]), 1e-12);
    ASSERT_TRUE(setPartGeometries(scene, *previous).ok());
    EXPECT_TRUE(scene == original);
    expectRefused(scene, [](Scene& s) { return transformObject(s, "chair", glm::dmat4(1.0)); });
    expectRefused(scene, [](Scene& s) { return transformObject(s, "table", glm::dmat4(0.0)); });
}

TEST(EditObjects, DuplicatingGroupingAndUngroupingKeepTheSceneFreeOfErrors)
{
    Scene scene = sampleScene();
    auto copy = duplicateObject(scene, "table");
    ASSERT_TRUE(copy.ok());
    ASSERT_TRUE(ungroupObject(scene, *copy).ok());
    ASSERT_TRUE(groupObjects(scene, {"crate", "table"}, "furniture").ok());
    EXPECT_FALSE(hasErrors(validateScene(scene)));
}
