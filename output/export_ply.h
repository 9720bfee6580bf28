#pragma once
// PLY export of a lit model: binary little endian, one
// vertex element with
//   x y z                          float, metres
//   nx ny nz                       float, unit normal
//   red green blue                 uchar, the display colour (tone-mapped or
//                                  false colour, display-encoded: what
//                                  MeshLab, CloudCompare and Blender show)
//   radiosity_r radiosity_g radiosity_b   float, the raw solution, W/m^2
// and one face element (list uchar uint vertex_indices, counter-clockwise
// seen from the front). Written atomically; errors name the path.
#include "output/lit_mesh.h"
#include "output/tone_map.h"

#include <optional>
#include <string>

namespace regio::output {

model::Check writePly(const std::string& path, const LitMesh& mesh, const DisplayColours& colours);

} // namespace regio::output
