// Another scene's materials and objects made ready to add to a scene (the
// editor's import into the open scene).
#include "model/edit/merge_scene.h"

#include "model/edit/edit_materials.h"
#include "model/edit/edit_objects.h"
#include "model/validation/validation.h"

#include "edit_fixture.h"

#include <gtest/gtest.h>

using namespace regio::model;
using namespace regio::model::testing;

TEST(MergeScene, AnotherCopyOfTheSceneComesInWithFreshIdsAndTheSameMaterials)
{
    const Scene scene = sampleScene();
    const MergeItems items = itemsToMerge(scene, scene);
    EXPECT_TRUE(items.materials.empty()) << "the same ids with the same values are the scene's own";
    ASSERT_EQ(items.objects.size(), scene.objects.size());
    Scene merged = scene;
    for (const Object& o : items.objects) {
        EXPECT_EQ(merged.findObject(o.id), nullptr) << o.id;
        ASSERT_TRUE(addObject(merged, o)) << o.id;
    }
    EXPECT_FALSE(hasErrors(validateScene(merged)));
    EXPECT_EQ(merged.objects.size(), 2 * scene.objects.size());
}

TEST(MergeScene, AMaterialOfTheSameIdButOtherValuesIsRenamedAndItsUsersFollow)
{
    const Scene scene = sampleScene();
    Scene incoming = sampleScene();
    incoming.materials[0].reflectance = {0.1, 0.2, 0.3};
    const std::string id = incoming.materials[0].id;
    const MergeItems items = itemsToMerge(scene, incoming);
    ASSERT_EQ(items.materials.size(), 1u);
    EXPECT_EQ(items.materials[0].id, id + "-2");
    EXPECT_EQ(items.materials[0].reflectance, (Rgb{0.1, 0.2, 0.3}));
    Scene merged = scene;
    for (const Material& m : items.materials)
        ASSERT_TRUE(addMaterial(merged, m));
    int users = 0;
    for (const Object& o : items.objects) {
        ASSERT_TRUE(addObject(merged, o)) << o.id;
        for (const Part& part : o.parts) {
            EXPECT_NE(part.material, id) << "every user of the renamed material follows it";
            users += part.material == id + "-2";
        }
    }
    EXPECT_GT(users, 0);
    EXPECT_FALSE(hasErrors(validateScene(merged)));
}
