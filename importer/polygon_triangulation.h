#pragma once
// Polygons of a model file into triangles. Assimp's own triangulation step
// asserts (and so aborts the whole process) on some broken files; the
// importer reads polygons as the file has them and triangulates them here,
// where a broken polygon only loses its triangles.
#include "model/types.h"

#include <array>
#include <span>
#include <vector>

namespace regio::importer {

// Triangles covering the simple polygon `corners` (in order, either winding,
// planar or nearly so), as indices into `corners`, each turning the way the
// polygon turns. Ear clipping in the plane of the polygon's Newell normal,
// so concave polygons come out right. A polygon with no area (all corners
// on a line, or repeated) gives no triangles; one too twisted to clip (a
// self-crossing outline) is fanned from its first corner, as a modelling
// tool would draw it. Polygons beyond kMaxClippedCorners corners are
// fanned too: clipping costs up to the cube of the corner count.
std::vector<std::array<int, 3>> triangulatePolygon(std::span<const model::Vec3> corners);

inline constexpr int kMaxClippedCorners = 256;

} // namespace regio::importer
