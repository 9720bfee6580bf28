#pragma once
// Wavefront OBJ export of a lit model with vertex colours
// in the common "v x y z r g b" extension (MeshLab, Blender, CloudCompare read
// it): r g b are the display colour, display-encoded, in [0,1]. Normals as
// "vn"; triangles grouped by input face ("g <face id>") in scene order, so a
// user can pick a wall out of the model. No .mtl: the colour is per vertex.
// Written atomically; errors name the path.
#include "output/lit_mesh.h"
#include "output/tone_map.h"

#include <optional>
#include <string>

namespace regio::output {

model::Check writeObj(const std::string& path, const LitMesh& mesh, const DisplayColours& colours);

} // namespace regio::output
