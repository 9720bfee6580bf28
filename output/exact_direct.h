#pragma once
// The smooth lit mesh with the lights' direct part exact at every vertex:
// the picture that the outputs and the editor's preview draw.
//
// Across a penumbra the direct light bends sharply; vertex radiosity
// averaged from the elements (§6) rounds the bend off and carries light a
// vertex into the umbra. So the picture splits each element's value into
// the lights' direct part and the rest: the rest (reflected light, which
// varies slowly) is smoothed as before (SmoothShading), the direct part is
// taken exact at the vertices (solver/picture/direct_light.h), and every
// triangle is cut into four at its edges' midpoints, so that a straight line
// between two vertices spans half an element, and again where the direct
// part still bends between two corners (output/midpoint_cut.h). An
// element's direct part is the mean of the exact values at its edges'
// midpoints (exact for a quadratic), which keeps the elements' means where
// the light is smooth.
//
// On the Cornell box (docs/accuracy.md) no point of the floor is then more
// than 5 % brighter than the reference, where five were with vertex
// radiosity alone (and six with exact direct values at the vertices but
// triangles an element wide).
#include "output/lit_mesh.h"
#include "output/midpoint_cut.h"
#include "output/vertex_radiosity.h"

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace regio::output {

// The direct part at the places a shading computed it, kept between the
// meshes of one scene (a solve's refinement rounds only add corners): a
// shading built with it computes the new places only.
class DirectCache {
public:
    DirectCache();
    ~DirectCache();
    DirectCache(const DirectCache&) = delete;
    DirectCache& operator=(const DirectCache&) = delete;
    size_t size() const; // places known

private:
    friend class ExactDirectShading;
    struct Places;
    std::unique_ptr<Places> m_places;
};

// Built once per mesh, as SmoothShading (the editor's preview shades every
// frame of a solve with it): the lights' direct part at every vertex and
// every element, and the triangles cut at their edges' midpoints. A frame
// then costs SmoothShading's plus a sum per vertex.
class ExactDirectShading {
public:
    // `cache`, when given, must have served only this scene's geometry.
    explicit ExactDirectShading(const PreparedScene& scene, const SmoothingOptions& options = {},
                                DirectCache* cache = nullptr, CutFor cutFor = CutFor::Files);

    size_t elementCount() const { return m_smooth.elementCount(); }
    // The scene has lights; without, litMesh is SmoothShading's mesh.
    bool hasLights() const { return m_hasLights; }

    // The lit mesh for per-element radiosity (W/m^2, in the scene's element
    // order) of which `share` of the lights' direct part has been shot
    // (directShare; 1 once the lights have shot their emission). Throws
    // std::invalid_argument when the count does not match.
    LitMesh litMesh(std::span<const Rgb> elementRadiosity, double share = 1.0) const;

private:
    SmoothShading m_smooth;
    bool m_hasLights = false;
    size_t m_smoothVertices = 0;       // vertices of the smooth mesh; the cut's midpoints follow
    LitMesh m_geometry;                // everything but the radiosity
    std::vector<Rgb> m_elementDirect;  // per element: the direct part's mean
    std::vector<Rgb> m_vertexDirect;   // per vertex of m_geometry: the direct part
    std::vector<std::uint32_t> m_ends; // per midpoint: the two smooth vertices of its edge
};

// How much of the lights' emission has been shot, from the unshot radiosity
// of the elements (0 before the first shot, 1 once every light's patches
// have shot, whatever they received since). 1 for a scene without lights.
double directShare(const PreparedScene& scene, std::span<const Rgb> unshot);

// As smoothLitMesh, with the lights' direct part exact on the cut triangles
// and all of it shot. A scene without lights gives smoothLitMesh's mesh.
// Throws std::invalid_argument when the count does not match.
LitMesh exactDirectLitMesh(const PreparedScene& scene, std::span<const Rgb> elementRadiosity,
                           const SmoothingOptions& options = {});

} // namespace regio::output
