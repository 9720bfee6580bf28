#pragma once
// Smooth vertex radiosity (paper §6): the element solution
// turned into a Gouraud-shaded lit mesh.
//
//   - Element corners are welded by position (quantised hash) within one
//     *group*: all input faces that lie in the same plane (same orientation)
//     and carry the same material (reflectance and emission). Across a crease
//     (another plane) or a material boundary nothing is averaged: the vertex
//     exists once per group, each copy with its own value.
//   - A vertex's radiosity is the average of the elements of its group
//     around it, including elements on whose edge it lies, each weighted by
//     its angle at the vertex (pi on its edge): every direction counts
//     alike, however large the elements on each side.
//   - Fragments of a split face (§5.3) and patches of different sizes meet
//     with T-vertices. Each element is re-triangulated with the vertices that
//     lie on its edges, so the output has none: every interior edge of a group
//     is shared by exactly two triangles and Gouraud shading shows no cracks.
//     Where groups meet (a floor and a wall), the triangles along each
//     group's outline also take the other groups' vertices on their edges,
//     with values interpolated along the edge: the two sides meet vertex to
//     vertex, so no pixel falls between them, and the shading is unchanged.
//   - Values on a group's boundary are extrapolated from the inner vertices
//     (the paper's option), so a gradient reaches the edge; the plain average
//     is an option.
//   - Then one mean-preserving pass: each vertex moves by what the Gouraud
//     triangles around it miss of their elements' values, so the picture
//     keeps each element's mean where the average rounds a bend off (the
//     edge of an umbra).
//   - Neighbour smoothing, off by default: it hides shadow borders (§6).
#include "output/lit_mesh.h"
#include "solver/prepare/prepared_scene.h"

#include <cstdint>
#include <span>
#include <vector>

namespace regio::output {

struct SmoothingOptions {
    // Values on a group's boundary. On (the default): value = 2 x average -
    // mean of the adjacent inner vertices, clamped at 0. The average alone
    // lags half an element behind a gradient, and the steepest gradients of
    // a lit room end at boundaries: a wall's light falls to nothing towards
    // the ceiling it meets, a floor's towards the foot of a block. On the
    // Cornell box against the pointwise reference (docs/accuracy.md) the
    // extrapolation takes the 90th percentile error from 3.5 % to 3.1 % and
    // beside contact lines from 12 % to 5.9 %. Off: the plain average, a
    // convex combination of the element values, which never leaves their
    // range but is visibly too bright in every concave corner. A boundary
    // vertex next to a shadow corner keeps its average: the shadow lines
    // from the corner lie between it and its inner neighbours.
    bool extrapolateBoundary = true;
    // Passes of the mean-preserving correction, after the extrapolation:
    // each vertex moves by what the triangles around it miss of their
    // elements' values (one Jacobi step of the L2 projection of the element
    // values onto the Gouraud mesh, lumped mass as the preconditioner;
    // shadow-corner vertices keep their element's value). The average
    // lags behind a gradient and rounds a bend off: where a block's
    // umbra meets the light, the averaged vertices on the umbra's side
    // take light from the lit elements, and the picture there is brighter
    // than every element under it. One pass takes the Cornell box
    // (docs/accuracy.md) from 0.75 / 2.97 / 8.1 % (median, 90th, 99th
    // percentile) to 0.72 / 2.51 / 6.4 %, its worst point from 43 % to
    // 29 %; more passes ring (two: 0.78 / 2.62 / 6.7 %).
    int meanPreservingPasses = 1;
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

// Smooth shading of one element mesh: the welded, re-triangulated geometry
// and, for every vertex, the elements it averages with their weights. All of
// it depends on the mesh alone, so it is built once per mesh (about 5 us an
// element) and then shades any radiosity of that mesh in time linear in the
// elements (a weighted sum per vertex): what the editor's preview does for
// every frame of a solve, while the mesh stays the same.
class SmoothShading {
public:
    explicit SmoothShading(const PreparedScene& scene, const SmoothingOptions& options = {});

    size_t elementCount() const { return m_elements; }
    // The lit mesh for per-element radiosity (W/m^2, in the scene's element
    // order). Throws std::invalid_argument when the count does not match.
    LitMesh litMesh(std::span<const Rgb> elementRadiosity) const;
    // Only the vertex values, for a mesh litMesh() made before.
    void shade(std::span<const Rgb> elementRadiosity, std::vector<glm::vec3>& vertexRadiosity) const;

private:
    void planGroup(const PreparedScene& scene, const Vec3& planeNormal, const Rgb& reflectance,
                   const std::vector<int>& elements);
    // Where two groups meet (a floor and a wall), each divides the common
    // line at its own points: the triangles along a group's outline take the
    // other groups' vertices on their edges, valued along the edge.
    void closeCracksBetweenGroups();
    // One pass of SmoothingOptions::meanPreservingPasses.
    void preserveMeans(std::span<const Rgb> elementRadiosity, std::vector<Rgb>& value) const;

    SmoothingOptions m_options;
    size_t m_elements = 0;
    LitMesh m_geometry; // everything but the radiosity
    // Per vertex: its terms end at m_termEnd[v] (they begin where the
    // previous vertex's end), each an element and its weight (its angle at
    // the vertex); m_weight[v] is the sum of the weights, in the same order.
    std::vector<uint32_t> m_termEnd;
    std::vector<uint32_t> m_termElement;
    std::vector<double> m_termWeight;
    std::vector<double> m_weight;
    // Only when the options look at neighbours: per vertex, where it lies
    // and its neighbours (ending at m_neighbourEnd[v]).
    enum class Outline : uint8_t {
        Inner,        // not on the group's outline
        Extrapolated, // on it: extrapolated from the inner neighbours
        Averaged,     // on it beside a shadow corner: the average stays
    };
    std::vector<Outline> m_boundary;
    std::vector<uint32_t> m_neighbourEnd;
    std::vector<uint32_t> m_neighbour;
    // Vertices placed on a group's outline where another group has one: the
    // value at `s` of the way from vertex a to vertex b (after the options).
    struct OnEdge {
        uint32_t vertex, a, b;
        double s;
    };
    std::vector<OnEdge> m_onEdge;
    // The groups' triangles with their element and area (before the cracks
    // between groups are closed), and per vertex the lumped mass (0: not
    // corrected), for the mean-preserving correction.
    struct ProjectionTriangle {
        uint32_t v[3];
        uint32_t element;
        double area;
    };
    std::vector<ProjectionTriangle> m_projection;
    std::vector<double> m_mass;
    // While building: every vertex's exact position and group, and the
    // edges on the groups' outlines (as positions in m_geometry.indices).
    std::vector<Vec3> m_exact;
    std::vector<uint32_t> m_groupOf;
    std::vector<uint32_t> m_openEdges;
};

// The smooth lit mesh from per-element radiosity (W/m^2, one per element of
// the prepared scene, in its element order). Throws std::invalid_argument
// when the count does not match.
LitMesh smoothLitMesh(const PreparedScene& scene, std::span<const Rgb> elementRadiosity,
                      const SmoothingOptions& options = {});

// What the outputs (exports, images) should draw: smooth vertex radiosity
// with the default options and the lights' direct part exact
// (exactDirectLitMesh, output/exact_direct.h), or the flat element mesh
// (litMeshFromSolution).
// `directShare`: how much of the lights' emission has been shot (directShare
// in output/exact_direct.h; 1 for a converged solution).
LitMesh litMeshForOutput(const PreparedScene& scene, std::span<const Rgb> elementRadiosity, bool smooth,
                         double directShare = 1.0);

} // namespace regio::output
