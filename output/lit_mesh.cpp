#include "output/lit_mesh.h"

#include "solver/prepare/covered_parts.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <stdexcept>
#include <unordered_map>

namespace regio::output {

using solver::Element;
using solver::InputFace;
using solver::Properties;
using solver::SolutionMesh;

namespace {

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

glm::vec3 toFloat(const Vec3& v)
{
    return glm::vec3(static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z));
}

// A unit normal in float; the double normal is unit already, but rounding to
// float may leave it a few ulps off, and glTF validators check unit length.
glm::vec3 unitNormal(const Vec3& n)
{
    const Vec3 u = glm::length(n) > 0.0 ? glm::normalize(n) : Vec3(0.0, 0.0, 1.0);
    return glm::normalize(toFloat(u));
}

// One triangle per element, three fresh vertices each (flat output).
struct FlatBuilder {
    LitMesh mesh;

    void reserve(size_t elements)
    {
        mesh.positions.reserve(3 * elements);
        mesh.normals.reserve(3 * elements);
        mesh.radiosity.reserve(3 * elements);
        mesh.reflectance.reserve(3 * elements);
        mesh.indices.reserve(3 * elements);
        mesh.triangleFace.reserve(elements);
    }

    void add(const std::array<Vec3, 3>& corners, const Vec3& normal, const Rgb& radiosity, const Rgb& reflectance,
             int face)
    {
        const glm::vec3 n = unitNormal(normal);
        for (const Vec3& p : corners) {
            mesh.indices.push_back(static_cast<uint32_t>(mesh.positions.size()));
            mesh.positions.push_back(toFloat(p));
            mesh.normals.push_back(n);
            mesh.radiosity.push_back(toFloat(radiosity));
            mesh.reflectance.push_back(toFloat(reflectance));
        }
        mesh.triangleFace.push_back(face);
    }
};

} // namespace

model::Check checkLitMesh(const LitMesh& mesh)
{
    const size_t n = mesh.positions.size();
    if (mesh.normals.size() != n || mesh.radiosity.size() != n || mesh.reflectance.size() != n)
        return model::makeError("lit mesh: positions, normals, radiosity and reflectance differ in length");
    if (mesh.indices.size() % 3 != 0)
        return model::makeError("lit mesh: the index count is not a multiple of 3");
    if (mesh.triangleFace.size() != mesh.triangleCount())
        return model::makeError("lit mesh: triangleFace does not have one entry per triangle");
    if (n > 0xFFFFFFFFu)
        return model::makeError("lit mesh: too many vertices for 32-bit indices");
    for (uint32_t i : mesh.indices) {
        if (i >= n)
            return model::makeError("lit mesh: vertex index " + std::to_string(i) + " out of range");
    }
    for (int32_t f : mesh.triangleFace) {
        if (f < 0 || static_cast<size_t>(f) >= mesh.faceIds.size())
            return model::makeError("lit mesh: face index " + std::to_string(f) + " out of range");
    }
    if (!mesh.faceObjects.empty() && mesh.faceObjects.size() != mesh.faceIds.size())
        return model::makeError("lit mesh: faceObjects does not have one entry per face");
    if (!mesh.faceMaterials.empty() && mesh.faceMaterials.size() != mesh.faceIds.size())
        return model::makeError("lit mesh: faceMaterials does not have one entry per face");
    for (int32_t m : mesh.faceMaterials) {
        if (m < 0 || static_cast<size_t>(m) >= mesh.materials.size())
            return model::makeError("lit mesh: material index " + std::to_string(m) + " out of range");
    }
    for (const CoveredPolygon& c : mesh.covered) {
        if (c.face < 0 || static_cast<size_t>(c.face) >= mesh.faceIds.size())
            return model::makeError("lit mesh: covered polygon of face index " + std::to_string(c.face) +
                                    " out of range");
        if (c.loop.size() < 3)
            return model::makeError("lit mesh: a covered polygon has fewer than three corners");
        for (const glm::vec3& p : c.loop)
            if (!finite(p))
                return model::makeError("lit mesh: a covered polygon has a corner that is not finite");
    }
    for (size_t v = 0; v < n; ++v) {
        if (!finite(mesh.positions[v]) || !finite(mesh.normals[v]) || !finite(mesh.radiosity[v]) ||
            !finite(mesh.reflectance[v]))
            return model::makeError("lit mesh: vertex " + std::to_string(v) + " has a value that is not finite");
    }
    return model::success();
}

LitBounds litMeshBounds(const LitMesh& mesh)
{
    LitBounds b;
    for (const glm::vec3& p : mesh.positions) {
        if (b.empty) {
            b.min = b.max = p;
            b.empty = false;
        } else {
            b.min = glm::min(b.min, p);
            b.max = glm::max(b.max, p);
        }
    }
    return b;
}

LitMesh litMeshFromSolution(const PreparedScene& scene, const std::vector<Rgb>& elementRadiosity)
{
    if (elementRadiosity.size() != scene.elements.size())
        throw std::invalid_argument("litMeshFromSolution: " + std::to_string(elementRadiosity.size()) +
                                    " radiosity values for " + std::to_string(scene.elements.size()) + " elements");
    FlatBuilder b;
    b.reserve(scene.elements.size());
    for (const InputFace& f : scene.faces)
        b.mesh.faceIds.push_back(f.id);
    for (size_t e = 0; e < scene.elements.size(); ++e) {
        const Element& el = scene.elements[e];
        const Properties& p = scene.properties[static_cast<size_t>(el.properties)];
        const std::array<Vec3, 3> corners{scene.vertices[static_cast<size_t>(el.vertices[0])],
                                          scene.vertices[static_cast<size_t>(el.vertices[1])],
                                          scene.vertices[static_cast<size_t>(el.vertices[2])]};
        b.add(corners, el.normal, elementRadiosity[e], p.reflectance, p.face);
    }
    describeFaces(b.mesh, scene);
    return std::move(b.mesh);
}

LitMesh litMeshFromSolution(const SolutionSnapshot& snapshot)
{
    if (!snapshot.mesh)
        return {};
    const SolutionMesh& m = *snapshot.mesh;
    if (snapshot.radiosity.size() != m.triangles.size())
        throw std::invalid_argument("litMeshFromSolution: " + std::to_string(snapshot.radiosity.size()) +
                                    " radiosity values for " + std::to_string(m.triangles.size()) + " elements");
    FlatBuilder b;
    b.reserve(m.triangles.size());
    b.mesh.faceIds = m.faceIds;
    for (size_t e = 0; e < m.triangles.size(); ++e) {
        const auto& t = m.triangles[e];
        const std::array<Vec3, 3> corners{m.vertices[static_cast<size_t>(t[0])], m.vertices[static_cast<size_t>(t[1])],
                                          m.vertices[static_cast<size_t>(t[2])]};
        b.add(corners, m.normals[e], snapshot.radiosity[e], m.reflectance[e], m.elementFace[e]);
    }
    return std::move(b.mesh);
}

void describeFaces(LitMesh& mesh, const PreparedScene& scene)
{
    mesh.faceObjects.clear();
    mesh.faceMaterials.clear();
    mesh.materials.clear();
    mesh.covered.clear();
    // Materials by id in order of first use; a face the solver could not use
    // (no material) gets an anonymous one, so every face has an entry.
    std::unordered_map<std::string, int32_t> materialIndex;
    for (size_t f = 0; f < scene.faces.size(); ++f) {
        const InputFace& face = scene.faces[f];
        const Properties& p = scene.properties[f];
        mesh.faceObjects.push_back(face.objectId);
        auto [it, added] = materialIndex.try_emplace(face.materialId, static_cast<int32_t>(mesh.materials.size()));
        if (added)
            mesh.materials.push_back({face.materialId, toFloat(p.reflectance), toFloat(p.emission)});
        mesh.faceMaterials.push_back(it->second);
    }
    const std::vector<std::vector<std::vector<Vec3>>> covered = solver::coveredPieces(scene);
    for (size_t f = 0; f < covered.size(); ++f) {
        for (const std::vector<Vec3>& loop : covered[f]) {
            CoveredPolygon c;
            c.face = static_cast<int32_t>(f);
            c.normal = unitNormal(scene.properties[f].plane.normal);
            for (const Vec3& v : loop)
                c.loop.push_back(toFloat(v));
            mesh.covered.push_back(std::move(c));
        }
    }
}

LitMesh withCoveredParts(const LitMesh& mesh)
{
    LitMesh out = mesh;
    out.covered.clear();
    for (const CoveredPolygon& c : mesh.covered) {
        const glm::vec3 reflectance =
            mesh.faceMaterials.empty()
                ? glm::vec3(0.0f)
                : mesh.materials[static_cast<size_t>(mesh.faceMaterials[static_cast<size_t>(c.face)])].reflectance;
        const auto first = static_cast<uint32_t>(out.positions.size());
        for (const glm::vec3& p : c.loop) {
            out.positions.push_back(p);
            out.normals.push_back(c.normal);
            out.radiosity.push_back(glm::vec3(0.0f));
            out.reflectance.push_back(reflectance);
        }
        // A fan: the loop is convex.
        for (uint32_t k = 1; k + 1 < c.loop.size(); ++k) {
            out.indices.insert(out.indices.end(), {first, first + k, first + k + 1});
            out.triangleFace.push_back(c.face);
        }
    }
    return out;
}

} // namespace regio::output
