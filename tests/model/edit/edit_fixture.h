#pragma once
// The scene every edit test starts from, and the two checks every edit test
// makes: the inverse gives back the original scene, and a refusal leaves the
// scene untouched.
#include "model/geometry/primitives.h"
#include "model/result.h"
#include "model/scene.h"

#include <gtest/gtest.h>

namespace regio::model::testing {

// A table (desk and legs), a crate and a room; three materials; two regions
// whose BSP orders name table and crate faces; a camera.
inline Scene sampleScene()
{
    Scene scene;
    scene.materials = {
        {"white", "White paint", {0.7, 0.7, 0.7}, {0, 0, 0}},
        {"red", "", {0.6, 0.1, 0.1}, {0, 0, 0}},
        {"lamp", "Ceiling lamp", {0.5, 0.5, 0.5}, {12, 12, 10}},
    };
    Object table{"table", "Table", {}};
    table.parts.push_back(makeBox("table.desk", {0, 0.7, 0}, {1.2, 0.75, 0.8}, "white").value());
    table.parts.back().faces[3].material = "red"; // table.desk.py
    table.parts.push_back(makeBox("table.legs", {0.05, 0, 0.05}, {1.15, 0.7, 0.75}, "white").value());
    scene.objects.push_back(table);
    Object crate{"crate", "", {makeBox("crate.body", {2, 0, 0}, {2.5, 0.5, 0.5}, "red").value()}};
    scene.objects.push_back(crate);
    Object room{"room", "Room", {makeRoom("room.shell", {-1, 0, -1}, {4, 3, 3}, "white").value()}};
    room.parts.back().faces[3].material = "lamp"; // the ceiling
    scene.objects.push_back(room);
    scene.regions = {
        {"west", "West", {-1, 0, -1}, {1.5, 3, 3}, {"table.desk.py", "table.legs.px", "room.shell.nx"}},
        {"east", "", {1.5, 0, -1}, {4, 3, 3}, {"crate.body.nx"}},
    };
    scene.camera = Camera{{1.5, 1.6, 6}, {1.5, 1, 0}, {0, 1, 0}, 50};
    return scene;
}

// Runs an edit expected to be refused; checks the scene did not change and
// returns the diagnostic.
template <typename Edit>
Diagnostic expectRefused(Scene& scene, Edit edit)
{
    const Scene before = scene;
    auto result = edit(scene);
    EXPECT_FALSE(result.ok()) << "the edit should have been refused";
    EXPECT_TRUE(scene == before) << "a refused edit changed the scene";
    if (result.ok())
        return {};
    EXPECT_FALSE(result.error().message.empty());
    EXPECT_TRUE(result.error().isError());
    return result.error();
}

} // namespace regio::model::testing
