#pragma once
// Wavefront OBJ export of a lit model with vertex colours
// in the common "v x y z r g b" extension (MeshLab, Blender, CloudCompare read
// it): r g b are the display colour, display-encoded, in [0,1]. Normals as
// "vn"; triangles grouped by input face ("g <face id>") in scene order, so a
// user can pick a wall out of the model and an importer sees the faces apart,
// under one "o <object id>" per object of the scene (Assimp makes every
// group an object; Regio's importer puts them back under their "o"). Where the mesh knows the scene's
// materials, FILE.mtl beside it holds them (Kd the reflectance, Ke the
// emission in W/m^2) and every group names its own ("usemtl"). The parts of
// faces that solids cover are filled in, black. Written atomically (the .mtl
// before the .obj that names it); errors name the path.
#include "output/lit_mesh.h"
#include "output/tone_map.h"

#include <optional>
#include <string>

namespace regio::output {

model::Check writeObj(const std::string& path, const LitMesh& mesh, const DisplayColours& colours);

// The material file that writeObj(path, ...) writes beside `path`.
std::string mtlPath(const std::string& objPath);

} // namespace regio::output
