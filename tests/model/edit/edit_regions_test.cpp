#include "model/edit/edit_regions.h"

#include "edit_fixture.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace regio::model;
using namespace regio::model::testing;

namespace {

using Order = std::vector<std::string>;

const Order& order(const Scene& scene, const std::string& regionId) { return scene.findRegion(regionId)->bspOrder; }

} // namespace

TEST(EditRegions, AddingARegionAtAnIndexAndRemovingItRestoresTheScene)
{
    const Scene original = sampleScene();
    Scene scene = original;
    Region north{"north", "North", {-1, 0, 3}, {4, 3, 5}, {"crate.body.pz"}};
    auto index = addRegion(scene, north, 0);
    ASSERT_TRUE(index.ok()) << index.error().message;
    EXPECT_EQ(scene.regions[0], north);
    auto removed = removeRegion(scene, "north");
    ASSERT_TRUE(removed.ok());
    EXPECT_EQ(*removed, (RemovedRegion{north, 0}));
    EXPECT_TRUE(scene == original);
    expectRefused(scene, [](Scene& s) { return removeRegion(s, "south"); });
}

TEST(EditRegions, ARegionNeedsAFreshIdAPositiveBoxAndAnOrderOfKnownDistinctFaces)
{
    Scene scene = sampleScene();
    Region good{"north", "", {-1, 0, 3}, {4, 3, 5}, {}};
    auto withId = [&](std::string id) {
        Region r = good;
        r.id = id;
        return r;
    };
    expectRefused(scene, [&](Scene& s) { return addRegion(s, withId("west")); });
    expectRefused(scene, [&](Scene& s) { return addRegion(s, withId("table")); });
    expectRefused(scene, [&](Scene& s) { return addRegion(s, withId("")); });
    Region flat = good;
    flat.max.y = flat.min.y;
    auto flatError = expectRefused(scene, [&](Scene& s) { return addRegion(s, flat); });
    EXPECT_EQ(flatError.pointer, "/regions/2");
    Region unknownFace = good;
    unknownFace.bspOrder = {"crate.body.nx", "chair.seat"};
    auto unknown = expectRefused(scene, [&](Scene& s) { return addRegion(s, unknownFace); });
    EXPECT_EQ(unknown.pointer, "/regions/2/bspOrder/1");
    Region twice = good;
    twice.bspOrder = {"crate.body.nx", "crate.body.nx"};
    expectRefused(scene, [&](Scene& s) { return addRegion(s, twice); });
    expectRefused(scene, [&](Scene& s) { return addRegion(s, good, 3); });
}

TEST(EditRegions, OverlappingRegionsAreAllowedWhileEditing)
{
    Scene scene = sampleScene();
    EXPECT_TRUE(addRegion(scene, {"overlap", "", {0, 0, 0}, {2, 2, 2}, {}}).ok())
        << "validation reports overlaps live; an author dragging a box passes through them";
}

TEST(EditRegions, RenameNameAndBoxEditsAreUndoneWithTheReturnedValues)
{
    const Scene original = sampleScene();
    Scene scene = original;
    ASSERT_TRUE(renameRegion(scene, "west", "left").ok());
    auto name = setRegionName(scene, "left", "Left side");
    ASSERT_TRUE(name.ok());
    EXPECT_EQ(*name, "West");
    auto box = setRegionBox(scene, "left", {-1, 0, -1}, {1.2, 3, 3});
    ASSERT_TRUE(box.ok());
    EXPECT_EQ(*box, (RegionBox{{-1, 0, -1}, {1.5, 3, 3}}));
    EXPECT_EQ(scene.findRegion("left")->max.x, 1.2);
    ASSERT_TRUE(setRegionBox(scene, "left", box->min, box->max).ok());
    ASSERT_TRUE(setRegionName(scene, "left", *name).ok());
    ASSERT_TRUE(renameRegion(scene, "left", "west").ok());
    EXPECT_TRUE(scene == original);
    expectRefused(scene, [](Scene& s) { return renameRegion(s, "west", "east"); });
    expectRefused(scene, [](Scene& s) { return renameRegion(s, "west", ""); });
    expectRefused(scene, [](Scene& s) { return setRegionBox(s, "west", {0, 0, 0}, {1, 1, -1}); });
    expectRefused(scene, [](Scene& s) { return setRegionBox(s, "west", {0, 0, 0}, {1, NAN, 1}); });
    expectRefused(scene, [](Scene& s) { return setRegionBox(s, "south", {0, 0, 0}, {1, 1, 1}); });
}

TEST(EditRegions, SettingAWholeBspOrderReturnsThePreviousOrder)
{
    const Scene original = sampleScene();
    Scene scene = original;
    auto previous = setBspOrder(scene, "east", {"crate.body.py", "crate.body.nx"});
    ASSERT_TRUE(previous.ok());
    EXPECT_EQ(*previous, Order{"crate.body.nx"});
    ASSERT_TRUE(setBspOrder(scene, "east", *previous).ok());
    EXPECT_TRUE(scene == original);
    expectRefused(scene, [](Scene& s) { return setBspOrder(s, "east", {"a.b"}); });
    expectRefused(scene, [](Scene& s) { return setBspOrder(s, "east", {"crate.body.py", "crate.body.py"}); });
}

TEST(EditRegions, InsertingAnEntryAndRemovingItAtItsIndexRestoresTheOrder)
{
    const Scene original = sampleScene();
    Scene scene = original;
    auto index = insertBspEntry(scene, "west", "table.legs.py", 1);
    ASSERT_TRUE(index.ok());
    EXPECT_EQ(*index, 1);
    EXPECT_EQ(order(scene, "west"), (Order{"table.desk.py", "table.legs.py", "table.legs.px", "room.shell.nx"}));
    auto removed = removeBspEntry(scene, "west", 1);
    ASSERT_TRUE(removed.ok());
    EXPECT_EQ(*removed, (BspEntry{"table.legs.py", 1}));
    EXPECT_TRUE(scene == original);
    auto appended = insertBspEntry(scene, "east", "crate.body.py");
    ASSERT_TRUE(appended.ok());
    EXPECT_EQ(*appended, 1);
}

TEST(EditRegions, AnEntryIsRefusedWhenUnknownAlreadyListedOrOutOfRange)
{
    Scene scene = sampleScene();
    expectRefused(scene, [](Scene& s) { return insertBspEntry(s, "west", "chair.seat"); });
    expectRefused(scene, [](Scene& s) { return insertBspEntry(s, "west", "table.desk.py"); });
    expectRefused(scene, [](Scene& s) { return insertBspEntry(s, "west", "table.legs.py", 4); });
    expectRefused(scene, [](Scene& s) { return insertBspEntry(s, "south", "table.legs.py"); });
    expectRefused(scene, [](Scene& s) { return removeBspEntry(s, "west", 3); });
    expectRefused(scene, [](Scene& s) { return removeBspEntry(s, "west", -1); });
}

TEST(EditRegions, MovingAnEntryAndMovingItBackRestoresTheOrder)
{
    const Scene original = sampleScene();
    Scene scene = original;
    ASSERT_TRUE(moveBspEntry(scene, "west", 0, 2).ok());
    EXPECT_EQ(order(scene, "west"), (Order{"table.legs.px", "room.shell.nx", "table.desk.py"}));
    ASSERT_TRUE(moveBspEntry(scene, "west", 2, 0).ok());
    EXPECT_TRUE(scene == original);
    ASSERT_TRUE(moveBspEntry(scene, "west", 2, 1).ok()) << "move towards the root";
    EXPECT_EQ(order(scene, "west"), (Order{"table.desk.py", "room.shell.nx", "table.legs.px"}));
    ASSERT_TRUE(moveBspEntry(scene, "west", 1, 2).ok());
    EXPECT_TRUE(scene == original);
    ASSERT_TRUE(moveBspEntry(scene, "west", 1, 1).ok());
    EXPECT_TRUE(scene == original);
    expectRefused(scene, [](Scene& s) { return moveBspEntry(s, "west", 0, 3); });
    expectRefused(scene, [](Scene& s) { return moveBspEntry(s, "west", -1, 0); });
}

TEST(EditRegions, RemovedFacesLeaveEveryOrderAndTheSnapshotsPutThemBack)
{
    const Scene original = sampleScene();
    Scene scene = original;
    BspOrderSnapshots snapshots = removeFacesFromBspOrders(scene, {"table.desk.py", "crate.body.nx", "room.shell.py"});
    EXPECT_EQ(order(scene, "west"), (Order{"table.legs.px", "room.shell.nx"}));
    EXPECT_TRUE(order(scene, "east").empty());
    ASSERT_EQ(snapshots.size(), 2u);
    restoreBspOrders(scene, snapshots);
    EXPECT_TRUE(scene == original);
    EXPECT_TRUE(removeFacesFromBspOrders(scene, {"room.shell.py"}).empty())
        << "only regions that change are snapshotted";
    EXPECT_EQ(regionOrderingFace(scene, "crate.body.nx")->id, "east");
    EXPECT_EQ(regionOrderingFace(scene, "room.shell.py"), nullptr);
}
