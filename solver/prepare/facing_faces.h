#pragma once
// Faces that stand close in front of each other (paper §5.6: the hemicube's
// proximity error). A shooter's hemicube sees the scene from the patch's
// centre, so a receiver at a distance like the patch's size takes the light
// as if all of the patch sat there. The near-field factors
// (solver/shooting/near_field.h) take the receivers within a patch's reach
// of its centre from the contour formula instead; a face that stands a few
// patches in front of another across its whole extent (the Cornell box's
// tall block 8-13 cm from the red wall with 10 cm patches, its top 22 cm
// under the ceiling) is lit by patches whose centres lie
// farther than that, but not far enough for the hemicube: the tall block's
// dark side read 1.6 % too dark. Such pairs of faces are found here, and
// their receivers take the contour formula farther out.
//
// A pair of faces counts as facing when their normals are within 60 degrees
// of opposite, each one's centroid lies in front of the other's plane, and
// the gap between their polygons is more than a hundredth of the largest
// gap and less than it (faces that touch, a block's bottom on the floor, are
// the covered parts' business: solver/prepare/covered_parts.h).
#include "solver/prepare/prepared_scene.h"

#include <span>
#include <vector>

namespace regio::solver {

// The largest gap between facing faces, in patch sizes (PreparedScene::patchSize).
inline constexpr double kFacingGapPatches = 3.0;

// The shortest distance between two convex planar polygons (either may be
// given in any winding; at least three corners each).
double polygonGap(std::span<const Vec3> a, std::span<const Vec3> b);

// For every input face of `scene` (faces and properties filled, parallel):
// the faces that stand in front of it across a gap under `largestGap`, as
// above, ascending. Faces without a polygon have none. A sweep over the
// faces' boxes: the pairs that are tested are the ones whose boxes, grown by
// `largestGap`, overlap.
std::vector<std::vector<int>> closeFacingFaces(const PreparedScene& scene, double largestGap);

} // namespace regio::solver
