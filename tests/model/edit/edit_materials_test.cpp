#include "model/edit/edit_materials.h"

#include "edit_fixture.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace regio::model;
using namespace regio::model::testing;

TEST(EditMaterials, AddingAMaterialAtAnIndexAndRemovingItRestoresTheScene)
{
    const Scene original = sampleScene();
    Scene scene = original;
    Material blue{"blue", "Blue", {0.1, 0.2, 0.6}, {0, 0, 0}};
    auto index = addMaterial(scene, blue, 1);
    ASSERT_TRUE(index.ok());
    EXPECT_EQ(*index, 1);
    EXPECT_EQ(scene.materials[1], blue);
    auto removed = removeMaterial(scene, "blue");
    ASSERT_TRUE(removed.ok());
    EXPECT_EQ(*removed, (RemovedMaterial{blue, 1}));
    EXPECT_TRUE(scene == original);
    ASSERT_TRUE(addMaterial(scene, blue).ok());
    EXPECT_EQ(scene.materials.back().id, "blue") << "-1 appends";
}

TEST(EditMaterials, AMaterialWithATakenIdOrOutOfRangeValuesIsRefused)
{
    Scene scene = sampleScene();
    expectRefused(scene, [](Scene& s) { return addMaterial(s, {"red", "", {0.5, 0.5, 0.5}, {}}); });
    expectRefused(scene, [](Scene& s) { return addMaterial(s, {"crate", "", {0.5, 0.5, 0.5}, {}}); });
    expectRefused(scene, [](Scene& s) { return addMaterial(s, {"", "", {0.5, 0.5, 0.5}, {}}); });
    auto bright = expectRefused(scene, [](Scene& s) { return addMaterial(s, {"mirror", "", {0.5, 1.0, 0.5}, {}}); });
    EXPECT_EQ(bright.pointer, "/materials/3/reflectance");
    expectRefused(scene, [](Scene& s) { return addMaterial(s, {"m", "", {0.5, 0.5, 0.5}, {-1, 0, 0}}); });
    expectRefused(scene, [](Scene& s) { return addMaterial(s, {"m", "", {0.5, 0.5, 0.5}, {}}, 9); });
}

TEST(EditMaterials, AMaterialInUseCannotBeRemovedAndTheDiagnosticNamesAUser)
{
    Scene scene = sampleScene();
    auto byPart = expectRefused(scene, [](Scene& s) { return removeMaterial(s, "white"); });
    EXPECT_EQ(byPart.pointer, "/objects/0/parts/0/material");
    EXPECT_EQ(byPart.idPath, (std::vector<std::string>{"table", "table.desk"}));
    EXPECT_NE(byPart.message.find("table.desk"), std::string::npos);
    auto byFace = expectRefused(scene, [](Scene& s) { return removeMaterial(s, "lamp"); });
    EXPECT_EQ(byFace.pointer, "/objects/2/parts/0/faces/3/material");
    EXPECT_EQ(byFace.idPath, (std::vector<std::string>{"room", "room.shell", "room.shell.py"}));
    expectRefused(scene, [](Scene& s) { return removeMaterial(s, "gold"); });
}

TEST(EditMaterials, RenamingAMaterialUpdatesEveryPartAndFaceUsingIt)
{
    const Scene original = sampleScene();
    Scene scene = original;
    ASSERT_TRUE(renameMaterial(scene, "red", "crimson").ok());
    EXPECT_EQ(scene.findMaterial("crimson")->reflectance, Rgb(0.6, 0.1, 0.1));
    EXPECT_EQ(scene.findPart("crate.body")->material, "crimson");
    EXPECT_EQ(scene.findPart("table.desk")->faces[3].material, "crimson");
    EXPECT_EQ(scene.findMaterial("red"), nullptr);
    ASSERT_TRUE(renameMaterial(scene, "crimson", "red").ok());
    EXPECT_TRUE(scene == original);
    expectRefused(scene, [](Scene& s) { return renameMaterial(s, "red", "white"); });
    expectRefused(scene, [](Scene& s) { return renameMaterial(s, "red", "table"); });
    expectRefused(scene, [](Scene& s) { return renameMaterial(s, "red", ""); });
    expectRefused(scene, [](Scene& s) { return renameMaterial(s, "gold", "silver"); });
}

TEST(EditMaterials, ReflectanceEmissionAndNameReturnTheirPreviousValues)
{
    const Scene original = sampleScene();
    Scene scene = original;
    auto reflectance = setMaterialReflectance(scene, "white", {0.8, 0.8, 0.75});
    ASSERT_TRUE(reflectance.ok());
    EXPECT_EQ(*reflectance, Rgb(0.7, 0.7, 0.7));
    auto emission = setMaterialEmission(scene, "lamp", {0, 0, 0});
    ASSERT_TRUE(emission.ok());
    EXPECT_EQ(*emission, Rgb(12, 12, 10));
    auto name = setMaterialName(scene, "red", "Signal red");
    ASSERT_TRUE(name.ok());
    EXPECT_EQ(*name, "");
    EXPECT_EQ(scene.findMaterial("white")->reflectance, Rgb(0.8, 0.8, 0.75));
    ASSERT_TRUE(setMaterialName(scene, "red", *name).ok());
    ASSERT_TRUE(setMaterialEmission(scene, "lamp", *emission).ok());
    ASSERT_TRUE(setMaterialReflectance(scene, "white", *reflectance).ok());
    EXPECT_TRUE(scene == original);
}

TEST(EditMaterials, ReflectanceMustLieBelowOneAndEmissionAtOrAboveZero)
{
    Scene scene = sampleScene();
    for (Rgb bad : {Rgb(1.0, 0.5, 0.5), Rgb(-0.01, 0.5, 0.5), Rgb(0.5, NAN, 0.5), Rgb(0.5, 0.5, INFINITY)})
        expectRefused(scene, [&](Scene& s) { return setMaterialReflectance(s, "white", bad); });
    for (Rgb bad : {Rgb(-1, 0, 0), Rgb(0, NAN, 0), Rgb(0, 0, INFINITY)})
        expectRefused(scene, [&](Scene& s) { return setMaterialEmission(s, "lamp", bad); });
    EXPECT_TRUE(setMaterialReflectance(scene, "white", {0, 0.999, 0}).ok());
    EXPECT_TRUE(setMaterialEmission(scene, "lamp", {1000, 0, 0}).ok());
    expectRefused(scene, [](Scene& s) { return setMaterialName(s, "gold", "Gold"); });
}
