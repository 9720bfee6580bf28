#pragma once
// Small lit meshes for the output tests (exports, tone mapping, the software
// renderer), built directly: quads and triangles with chosen radiosity.
#include "output/lit_mesh.h"

#include <glm/geometric.hpp>

#include <string>
#include <vector>

namespace regio::test {

using output::LitMesh;

// Adds a triangle with its own three vertices (flat, as the solver's
// elements); corners counter-clockwise seen from the front. Returns its index.
inline size_t addTriangle(LitMesh& mesh, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 radiosity,
                          const std::string& faceId, glm::vec3 reflectance = glm::vec3(0.5f))
{
    int32_t face = -1;
    for (size_t i = 0; i < mesh.faceIds.size(); ++i) {
        if (mesh.faceIds[i] == faceId)
            face = static_cast<int32_t>(i);
    }
    if (face < 0) {
        face = static_cast<int32_t>(mesh.faceIds.size());
        mesh.faceIds.push_back(faceId);
    }
    const glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
    for (const glm::vec3& p : {a, b, c}) {
        mesh.indices.push_back(static_cast<uint32_t>(mesh.positions.size()));
        mesh.positions.push_back(p);
        mesh.normals.push_back(n);
        mesh.radiosity.push_back(radiosity);
        mesh.reflectance.push_back(reflectance);
    }
    mesh.triangleFace.push_back(face);
    return mesh.triangleCount() - 1;
}

// A quad a-b-c-d (counter-clockwise from the front) as two triangles.
inline void addQuad(LitMesh& mesh, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, glm::vec3 radiosity,
                    const std::string& faceId, glm::vec3 reflectance = glm::vec3(0.5f))
{
    addTriangle(mesh, a, b, c, radiosity, faceId, reflectance);
    addTriangle(mesh, a, c, d, radiosity, faceId, reflectance);
}

// An open box seen from inside, 1 m on a side, each wall its own face and
// colour: a little scene with every kind of value an export must carry.
inline LitMesh sampleRoom()
{
    LitMesh m;
    const glm::vec3 p000(0, 0, 0), p100(1, 0, 0), p010(0, 1, 0), p110(1, 1, 0);
    const glm::vec3 p001(0, 0, 1), p101(1, 0, 1), p011(0, 1, 1), p111(1, 1, 1);
    addQuad(m, p000, p001, p101, p100, {2.0f, 2.0f, 2.0f}, "floor", {0.7f, 0.7f, 0.7f});
    addQuad(m, p010, p110, p111, p011, {8.0f, 6.0f, 3.0f}, "ceiling", {0.78f, 0.78f, 0.78f});
    addQuad(m, p100, p101, p111, p110, {3.0f, 0.4f, 0.3f}, "left-wall", {0.63f, 0.065f, 0.05f});
    addQuad(m, p000, p010, p011, p001, {0.5f, 1.5f, 0.3f}, "right-wall", {0.14f, 0.45f, 0.091f});
    addQuad(m, p001, p011, p111, p101, {1.0f, 1.0f, 1.0f}, "back-wall", {0.7f, 0.7f, 0.7f});
    return m;
}

} // namespace regio::test
