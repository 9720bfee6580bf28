#pragma once
// Picking by ray casting on the CPU against the model's faces: exact, no GL
// read-back, and testable without a window.
#include "editor/viewport/camera.h"
#include "model/scene.h"

#include <optional>
#include <string>

namespace regio::editor {

struct PickHit {
    std::string objectId;
    std::string partId;
    std::string faceId;
    model::Vec3 point{0.0};
    model::Vec3 normal{0.0}; // the face's normal
    double distance = 0.0;   // along the ray
    bool backFacing = false; // the ray hit the face's back side
};

// The nearest face the ray hits. With `ignoreBackFaces` faces seen from
// behind are transparent, as they are in the viewport when culling is on.
std::optional<PickHit> pickFace(const model::Scene& scene, const Ray& ray, bool ignoreBackFaces);

// Where the ray crosses the plane y = height (the grid), if ahead of it.
std::optional<model::Vec3> intersectGround(const Ray& ray, double height = 0.0);

} // namespace regio::editor
