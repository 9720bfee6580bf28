#pragma once
// Semantic and geometric validation of a loaded scene (the file format's own
// checks - syntax, types, missing keys - happen in scene_json). Returns every
// problem found; never throws. Pointers index the scene as it would be saved.
#include "model/diagnostic.h"
#include "model/scene.h"

namespace regio::model {

Diagnostics validateScene(const Scene& scene);

} // namespace regio::model
