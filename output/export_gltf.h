#pragma once
// glTF 2.0 export of a lit model. One node and one mesh per object of the
// scene, one triangle primitive per input face (named in its extras), each
// with its own
//   POSITION    float vec3, metres (glTF is y-up, right-handed, metres: as Regio)
//   NORMAL      float vec3, unit
//   COLOR_0     float vec3, the display colour *linear* in [0,1] (glTF vertex
//               colours are linear; the viewer encodes for the screen)
//   _RADIOSITY  float vec3, the raw solution in W/m^2 (an application-specific
//               attribute; viewers ignore it, analysis tools can read it)
// and one material per scene material, unlit (KHR_materials_unlit) so that
// viewers show the baked lighting instead of lighting it again. A material
// keeps the scene's reflectance and emission in its extras ("regio") for
// Regio's importer, and says its emission the glTF way too (emissiveFactor
// and KHR_materials_emissive_strength). The parts of faces that solids cover
// are filled in, black, so that a floor under a block comes out whole.
// Single-sided like the solution: the back of a surface emits nothing.
//
// `.gltf` is written with its buffer beside it (same name, `.bin`), `.glb` as
// one binary file. Both are written atomically (the .bin before the .gltf that
// names it). Every file must pass the Khronos glTF validator (tested).
#include "output/lit_mesh.h"
#include "output/tone_map.h"

#include <optional>
#include <string>

namespace regio::output {

enum class GltfContainer {
    Separate, // FILE.gltf + FILE.bin
    Binary    // FILE.glb
};

// Returns an error message naming the path, or nothing on success.
model::Check writeGltf(const std::string& path, const LitMesh& mesh, const DisplayColours& colours,
                       GltfContainer container);

// The buffer file that writeGltf(path, ..., Separate) writes beside `path`.
std::string gltfBufferPath(const std::string& gltfPath);

} // namespace regio::output
