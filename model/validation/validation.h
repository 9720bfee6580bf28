#pragma once
// Semantic and geometric validation of a loaded scene (the file format's own
// checks - syntax, types, missing keys - happen in scene_json). Returns every
// problem found; never throws. Pointers index the scene as it would be saved.
//
// Rules, in the order they are reported (E = error, W = warning):
//  ids        E empty id; E duplicate id (objects, parts, faces, materials and
//               regions share one namespace)
//  materials  E reflectance outside [0, 1) per channel (at 1 energy never
//               decays); E negative or non-finite emission; W no face emits
//  references E unknown material on a part or face; E face with no material
//  loops      E fewer than 3 entries; E index out of range; E repeated vertex;
//             E non-finite vertex coordinate
//  faces      E zero area; E/W non-planar (see tolerances); E non-convex;
//             W sliver
//  topology   E inconsistent winding (reported on the faces to reverse);
//             E edge shared by more than two faces; W open part (fine for
//               walls, a leak for solids)
//  regions    E min >= max or non-finite bounds; E overlapping regions;
//             E regions no axis-aligned plane can separate; W part straddling
//               region boundaries (the solver clips it); W part outside every
//               region; E BSP order naming an unknown face or a face with no
//               area inside the region; W face listed twice in one BSP order
#include "model/diagnostic.h"
#include "model/scene.h"

namespace regio::model {

// Tolerances. Sizes are a face's bounding-box diagonal, in metres.
// A face may leave its best-fit (Newell) plane by this fraction of its size
// before a warning: 0.1 mm on a 1 m face, well above modelling round-off. The
// solver meshes the face in that plane, so small warps only shift light.
inline constexpr double kPlanarityWarning = 1e-4;
// Beyond this fraction (1 cm per metre) the flattened face would visibly leave
// its neighbours: an error.
inline constexpr double kPlanarityError = 1e-2;
// Faces below this area (m^2) are degenerate: no normal, no form factor.
inline constexpr double kMinFaceArea = 1e-10;
// A face whose area is below this fraction of its size squared (a rectangle
// about 1000 times longer than wide) is a sliver: hemicubes and the patch
// mesh sample it badly.
inline constexpr double kSliverRatio = 1e-3;

Diagnostics validateScene(const Scene& scene);

} // namespace regio::model
