#pragma once
// Smooth vertex radiosity (paper §6): the element solution
// turned into a Gouraud-shaded lit mesh.
//
//   - Element corners are welded by position (quantised hash) within one
//     *group*: all input faces that lie in the same plane (same orientation)
//     and carry the same material (reflectance and emission). Across a crease
//     (another plane) or a material boundary nothing is averaged: the vertex
//     exists once per group, each copy with its own value.
//   - A vertex's radiosity is the area-weighted average of the elements of
//     its group around it, including elements on whose edge it lies.
//   - Fragments of a split face (§5.3) and patches of different sizes meet
//     with T-vertices. Each element is re-triangulated with the vertices that
//     lie on its edges, so the output has none: every interior edge of a group
//     is shared by exactly two triangles and Gouraud shading shows no cracks.
//   - Patch-edge values: the plain average by default, or (option) the paper's
//     extrapolation from the inner vertices.
//   - Neighbour smoothing, off by default: it hides shadow borders (§6).
#include "output/lit_mesh.h"
#include "solver/prepare/prepared_scene.h"

#include <span>

namespace regio::output {

struct SmoothingOptions {
    // Values on a group's boundary. Off (the default): the same area-weighted
    // average as every other vertex, a convex combination of the element
    // values, so it never invents a value the solution does not have. On:
    // value = 2 x average - mean of the adjacent inner vertices, clamped at 0,
    // which recovers a linear gradient up to the edge (the average alone lags
    // half an element behind it) but doubles the hemicube noise of the
    // boundary elements and overshoots where a shadow border meets the edge.
    // A predictable picture is the better default; the option is for users
    // who want the walls' corners lit as the gradient says.
    bool extrapolateBoundary = false;
    // Passes of neighbour smoothing (each vertex moves `neighbourWeight` of
    // the way towards the mean of its neighbours in the group). 0 = off: the
    // paper warns that averaging hides correct, important shadow borders.
    int neighbourPasses = 0;
    double neighbourWeight = 0.5;
    // Corners closer than this (metres) are one vertex.
    double weldTolerance = 1e-7;
    // A vertex closer than this (metres) to the inside of an element edge of
    // its group is a T-vertex of that edge.
    double edgeTolerance = 1e-6;
};

// The smooth lit mesh from per-element radiosity (W/m^2, one per element of
// the prepared scene, in its element order). Throws std::invalid_argument
// when the count does not match.
LitMesh smoothLitMesh(const PreparedScene& scene, std::span<const Rgb> elementRadiosity,
                      const SmoothingOptions& options = {});

// What the outputs (exports, images) should draw: smooth vertex radiosity
// with the default options, or the flat element mesh (litMeshFromSolution).
LitMesh litMeshForOutput(const PreparedScene& scene, std::span<const Rgb> elementRadiosity, bool smooth);

} // namespace regio::output
