#pragma once
// Face splitting into triangle patches by the strip method of the paper
// (§5.4, after Baum et al. 1991): the convex polygon is moved into its plane's
// 2D frame (rotation + translation; the longest edge becomes the bottom, along
// +x), cut into horizontal strips about the patch size high, and each strip is
// triangulated lengthwise ("in L direction"): a zig-zag between its bottom and
// top edges, both divided into pieces no longer than the patch size, closed by
// a triangle at each end. Every cut line is divided once and shared by the
// strips above and below it, so the patches of one polygon meet vertex to
// vertex (no T-vertices inside a fragment).
//
// Quality: a cut that would pass just beside a corner moves onto it (strips
// then range from half to one and a half patch sizes), and the zig-zag of each
// strip is the one whose worst triangle is best (dynamic programming over the
// rungs). Measured guarantee: regular polygons and triangles with corners of at
// least 60 degrees and edges of at least half the patch size get no patch
// angle below kStripMinAngleDegrees; squares of at least the patch size no
// angle below atan(1/2) = 26.6 degrees. A polygon thinner than the patch size
// gives patches of aspect about patchSize : thickness (it allows no better
// without many more patches), a sharp corner keeps its angle, and a corner of
// nearly 180 degrees between short edges can force thin ears.
#include "model/types.h"

#include <glm/vec2.hpp>

#include <array>
#include <span>
#include <vector>

namespace regio::solver {

inline constexpr double kStripMinAngleDegrees = 15.0;

using Vec2 = glm::dvec2;
using Triangle = std::array<int, 3>;

struct StripMesh2D {
    std::vector<Vec2> points;        // the input corners first, in input order, then new points
    std::vector<Triangle> triangles; // counter-clockwise, indices into points
};

// `polygon` is convex and counter-clockwise, without repeated or collinear
// corners (cleanConvexLoop). patchSize > 0.
StripMesh2D stripTriangulate2D(std::span<const Vec2> polygon, double patchSize);

struct StripMesh {
    std::vector<model::Vec3> points; // the input corners first (bit-identical), then new points
    std::vector<Triangle> triangles; // counter-clockwise seen from `normal`
};

// The 3D entry: `loop` convex, counter-clockwise around the unit `normal`.
StripMesh stripTriangulate(std::span<const model::Vec3> loop, const model::Vec3& normal, double patchSize);

// Smallest interior angle of a triangle, in degrees (0 for a degenerate one).
double minimumAngleDegrees(const model::Vec3& a, const model::Vec3& b, const model::Vec3& c);

} // namespace regio::solver
