#pragma once
// glTF 2.0 export of a lit model: one mesh, one triangle
// primitive with
//   POSITION    float vec3, metres (glTF is y-up, right-handed, metres: as Regio)
//   NORMAL      float vec3, unit
//   COLOR_0     float vec3, the display colour *linear* in [0,1] (glTF vertex
//               colours are linear; the viewer encodes for the screen)
//   _RADIOSITY  float vec3, the raw solution in W/m^2 (an application-specific
//               attribute; viewers ignore it, analysis tools can read it)
// and an unlit material (KHR_materials_unlit) so viewers show the baked
// lighting instead of lighting it again. Single-sided like the solution: the
// back of a surface emits nothing.
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
