#pragma once
// Automatic regions (paper §3, last paragraph, "similar to the Warnock
// algorithm"): while a box of space holds more patches than a threshold, it is
// cut in two by an axis-aligned plane and its polygons are clipped to the two
// halves. The final boxes become the regions of a scene that has none.
#include "solver/prepare/face_polygon.h"
#include "solver/prepare/prepared_scene.h"

#include <vector>

namespace regio::solver {

// The default patch-count threshold of automatic regions (and of the
// editor's region proposals): a box holding more estimated patches is split.
inline constexpr int kAutoRegionPatchThreshold = 256;

// Patches a polygon of this area is expected to give at this patch size: two
// triangles per patchSize^2 square, at least one.
double estimatedPatches(double area, double patchSize);

// Splits `bounds` (which holds every polygon) recursively: the longest axis,
// at the median of the polygon centroids, kept within the middle half of the
// box so that every cut makes progress. A box stops splitting when its
// estimated patches are at most `patchThreshold`, when it holds a single
// polygon, or when it is thinner than two patch sizes. The boxes tile `bounds`
// (a kd-tree), so the regional tree always separates them.
std::vector<Box3> autoRegionBoxes(const std::vector<FacePolygon>& polygons, const Box3& bounds, int patchThreshold,
                                  double patchSize);

} // namespace regio::solver
