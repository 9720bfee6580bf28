#pragma once
// Another scene's materials and objects, made ready to be added to a scene
// (an imported model into the open one): what the editor's import adds, one
// addMaterial / addObject each, as one undo step.
//   - A material whose id and values the scene already has is the scene's.
//   - A material whose id the scene uses for something else gets a fresh id
//     ("white" -> "white-2"), and the parts and faces of the incoming objects
//     that use it follow.
//   - Objects get fresh object, part and face ids (withFreshIds), fresh
//     against the scene and against each other.
// Regions, BSP orders, the camera and the solver settings of the other scene
// are not part of it: the scene keeps its own.
#include "model/scene.h"

#include <vector>

namespace regio::model {

struct MergeItems {
    std::vector<Material> materials; // in order, to add after the scene's
    std::vector<Object> objects;     // in order, to add after the scene's
};

MergeItems itemsToMerge(const Scene& scene, const Scene& incoming);

} // namespace regio::model
