#pragma once
// Where two input faces lie side by side in one plane with one material (two
// ceiling tiles, two triangles of an imported floor), their meshes meet along
// a common piece of outline. The smooth output already shades them as one
// surface (paper §6: output/vertex_radiosity.h groups them); adaptive
// subdivision (§5.7) must see them as one too, or a tile refined along a
// shadow border would meet its neighbour's coarse elements with nothing in
// between, and the neighbour would never learn of the border.
//
// These are the pieces of outline that such partner faces share. Adaptive
// subdivision (solver/shooting/adaptive_subdivision.h) compares, interpolates
// and grades elements across them.
#include "solver/prepare/prepared_scene.h"

#include <vector>

namespace regio::solver {

// A piece of a face's outline that lies on the outline of `partner`: a face
// in the same plane, facing the same way, with the same reflectance and
// emission. From a to b.
struct SharedOutline {
    int partner = -1;
    Vec3 a{0.0};
    Vec3 b{0.0};
};

// Per face of the scene (its index), the pieces of its outline it shares with
// partner faces. Faces are bucketed by plane and material and swept along x,
// so a large planar mesh of many triangles costs about its edges, not their
// pairs.
std::vector<std::vector<SharedOutline>> sharedOutlines(const PreparedScene& scene);

// The length of the common part of segments ab and cd when both lie on one
// line (within model::kDistanceEpsilon), else 0.
double collinearOverlap(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

} // namespace regio::solver
