#include "model/edit/edit_settings.h"

#include "edit_fixture.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

using namespace regio::model;
using namespace regio::model::testing;

TEST(EditSettings, SettingSolverSettingsReturnsThePreviousOnes)
{
    const Scene original = sampleScene();
    Scene scene = original;
    SolverSettings settings;
    settings.hemicube = 300;
    settings.patchSize = 0.25;
    settings.adaptive.enabled = false;
    auto previous = setSolverSettings(scene, settings);
    ASSERT_TRUE(previous.ok());
    EXPECT_EQ(*previous, original.solver);
    EXPECT_EQ(scene.solver, settings);
    ASSERT_TRUE(setSolverSettings(scene, *previous).ok());
    EXPECT_TRUE(scene == original);
}

TEST(EditSettings, EachSolverSettingOutOfRangeIsRefusedWithAPointerToIt)
{
    const std::pair<const char*, std::function<void(SolverSettings&)>> cases[] = {
        {"/solver/hemicube", [](SolverSettings& s) { s.hemicube = 151; }},
        {"/solver/hemicube", [](SolverSettings& s) { s.hemicube = 4; }},
        {"/solver/hemicube", [](SolverSettings& s) { s.hemicube = 8192; }},
        {"/solver/patchSize", [](SolverSettings& s) { s.patchSize = 0.0; }},
        {"/solver/patchSize", [](SolverSettings& s) { s.patchSize = NAN; }},
        {"/solver/elementsPerPatch", [](SolverSettings& s) { s.elementsPerPatch = 0; }},
        {"/solver/adaptive/threshold", [](SolverSettings& s) { s.adaptive.threshold = 0.0; }},
        {"/solver/adaptive/threshold", [](SolverSettings& s) { s.adaptive.threshold = 1.5; }},
        {"/solver/adaptive/minEdge", [](SolverSettings& s) { s.adaptive.minEdge = -0.01; }},
        {"/solver/maxIterations", [](SolverSettings& s) { s.maxIterations = 0; }},
        {"/solver/convergence", [](SolverSettings& s) { s.convergence = 1.0; }},
        {"/solver/convergence", [](SolverSettings& s) { s.convergence = INFINITY; }},
    };
    Scene scene = sampleScene();
    for (const auto& [pointer, breakIt] : cases) {
        SolverSettings settings;
        breakIt(settings);
        EXPECT_TRUE(!checkSolverSettings(settings).ok()) << pointer;
        auto error = expectRefused(scene, [&](Scene& s) { return setSolverSettings(s, settings); });
        EXPECT_EQ(error.pointer, pointer);
    }
    EXPECT_FALSE(!checkSolverSettings(SolverSettings{}).ok()) << "the defaults are valid";
}

TEST(EditSettings, SettingAndClearingTheCameraReturnThePreviousCamera)
{
    const Scene original = sampleScene();
    Scene scene = original;
    Camera camera{{0, 1.7, 4}, {0, 1, 0}, {0, 1, 0}, 60};
    auto previous = setCamera(scene, camera);
    ASSERT_TRUE(previous.ok());
    EXPECT_EQ(*previous, original.camera);
    EXPECT_EQ(scene.camera, camera);
    auto cleared = clearCamera(scene);
    ASSERT_TRUE(cleared.ok());
    EXPECT_EQ(*cleared, camera);
    EXPECT_FALSE(scene.camera.has_value());
    ASSERT_TRUE(setCamera(scene, *previous).ok());
    EXPECT_TRUE(scene == original);
}

TEST(EditSettings, ADegenerateCameraIsRefused)
{
    Scene scene = sampleScene();
    Camera good{{0, 1.7, 4}, {0, 1, 0}, {0, 1, 0}, 60};
    Camera atTarget = good;
    atTarget.target = atTarget.position;
    Camera upAlongView = good;
    upAlongView.up = good.target - good.position;
    Camera wide = good;
    wide.fovY = 180;
    Camera notFinite = good;
    notFinite.position.x = NAN;
    for (const Camera& bad : {atTarget, upAlongView, wide, notFinite}) {
        auto error = expectRefused(scene, [&](Scene& s) { return setCamera(s, bad); });
        EXPECT_EQ(error.pointer.rfind("/camera", 0), 0u) << error.pointer;
    }
}
