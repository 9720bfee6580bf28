#pragma once
// The lit model: what every output of a solution (glTF, PLY and OBJ exports,
// the software image, the editor's view) draws from. A triangle mesh with the
// radiosity *solution* per vertex, linear W/m^2 per channel; tone mapping and
// false colour are applied on top of it at display time (tone_map.h,
// false_colour.h) and never written back.
//
// Vertices are never shared across input faces of different planes or
// materials, so a vertex's reflectance (and its normal) is well defined. Two
// producers fill it:
//   - litMeshFromSolution(): flat, every element's three corners duplicated
//     with the element's radiosity (the element mesh as it is, no averaging);
//   - the vertex radiosity of paper §6 (angle-weighted averages at shared
//     vertices within one plane), which yields the same type.
#include "model/result.h"
#include "solver/prepare/prepared_scene.h"
#include "solver/solution.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace regio::output {

using model::Rgb;
using model::Vec3;
using solver::PreparedScene;
using solver::SolutionSnapshot;

// A material as the scene file has it, for exports that keep materials.
struct LitMaterial {
    std::string id;
    glm::vec3 reflectance{0.0f}; // diffuse coefficient per channel
    glm::vec3 emission{0.0f};    // W/m^2 per channel
};

// A part of an input face that a solid covers (a floor under a block): the
// solver neither meshes nor lights it, the views do not draw it, and model
// exports fill it in (black) so that the face comes out whole.
struct CoveredPolygon {
    int32_t face = -1;           // index into faceIds
    std::vector<glm::vec3> loop; // convex, counter-clockwise seen from the front
    glm::vec3 normal{0.0f, 0.0f, 1.0f};
};

struct LitMesh {
    std::vector<glm::vec3> positions;   // metres
    std::vector<glm::vec3> normals;     // unit, the front side of the surface
    std::vector<glm::vec3> radiosity;   // W/m^2 per channel: the solution, not tone-mapped
    std::vector<glm::vec3> reflectance; // diffuse reflectance; weights the ambient term at display
    std::vector<uint32_t> indices;      // three per triangle, counter-clockwise seen from the normal
    std::vector<int32_t> triangleFace;  // per triangle: index into faceIds
    std::vector<std::string> faceIds;   // the input faces of the scene file, scene order

    // Where the mesh was made from a prepared scene (describeFaces): per
    // input face its object's id and its material, and the covered parts.
    // Empty otherwise; writers then write one anonymous material.
    std::vector<std::string> faceObjects; // per face, parallel to faceIds
    std::vector<int32_t> faceMaterials;   // per face: index into materials
    std::vector<LitMaterial> materials;
    std::vector<CoveredPolygon> covered;

    size_t vertexCount() const { return positions.size(); }
    size_t triangleCount() const { return indices.size() / 3; }
    bool empty() const { return indices.empty(); }

    // What a display shows at vertex v: the radiosity plus the ambient term
    // of progressive refinement weighted by the reflectance (Cohen et al.
    // 1988; zero ambient = the solution itself).
    glm::vec3 displayRadiosity(size_t v, const glm::vec3& ambient) const
    {
        return radiosity[v] + reflectance[v] * ambient;
    }
};

// Consistency of the arrays (equal per-vertex sizes, whole triangles, indices
// in range, face indices in range, finite values). Writers refuse an
// inconsistent mesh with this message instead of producing a broken file.
model::Check checkLitMesh(const LitMesh& mesh);

// Fills faceObjects, faceMaterials, materials and covered from the scene the
// mesh was made from (its faceIds are the scene's faces, in order).
void describeFaces(LitMesh& mesh, const PreparedScene& scene);

// The mesh with its covered polygons appended as triangles (fresh vertices
// at the end, radiosity 0, the face's reflectance and normal) and `covered`
// emptied: what a model file holds.
LitMesh withCoveredParts(const LitMesh& mesh);

// Axis-aligned bounds of the positions (min > max when empty).
struct LitBounds {
    glm::vec3 min{0.0f};
    glm::vec3 max{0.0f};
    bool empty = true;
};
LitBounds litMeshBounds(const LitMesh& mesh);

// Flat lit mesh from per-element radiosity (W/m^2, one per element of the
// prepared scene, in its element order): every element becomes one triangle
// with its own three vertices carrying the element's value.
LitMesh litMeshFromSolution(const PreparedScene& scene, const std::vector<Rgb>& elementRadiosity);

// The same from a solver snapshot (its mesh and radiosity), which is what
// the editor and the batch command hold.
LitMesh litMeshFromSolution(const SolutionSnapshot& snapshot);

} // namespace regio::output
