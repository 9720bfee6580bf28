#include "editor/viewport/scene_mesh.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <unordered_set>

namespace regio::editor {

namespace {

float toSrgb(double c)
{
    c = std::clamp(c, 0.0, 1.0);
    return float(c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055);
}

void push3(std::vector<float>& out, const model::Vec3& v)
{
    out.push_back(float(v.x));
    out.push_back(float(v.y));
    out.push_back(float(v.z));
}

bool validLoop(const model::Part& part, const model::Face& face)
{
    if (face.loop.size() < 3)
        return false;
    return std::all_of(face.loop.begin(), face.loop.end(),
                       [&](int i) { return i >= 0 && i < int(part.vertices.size()); });
}

} // namespace

FaceAppearance faceAppearance(const model::Scene& scene, const model::Part& part, const model::Face& face)
{
    FaceAppearance out;
    const model::Material* material = scene.materialOf(part, face);
    if (!material)
        return out;
    const model::Rgb& e = material->emission;
    const double peak = std::max({e.r, e.g, e.b});
    if (peak > 0.0) {
        out = {toSrgb(e.r / peak), toSrgb(e.g / peak), toSrgb(e.b / peak), true};
        return out;
    }
    const model::Rgb& rho = material->reflectance;
    return {toSrgb(rho.r), toSrgb(rho.g), toSrgb(rho.b), false};
}

const FaceRange* SceneMesh::findFace(const std::string& faceId) const
{
    auto it = m_faceIndex.find(faceId);
    return it == m_faceIndex.end() ? nullptr : &m_faces[size_t(it->second)];
}

void SceneMesh::rebuildGeometry(const model::Scene& scene)
{
    m_surface.clear();
    m_edges.clear();
    m_normals.clear();
    m_faces.clear();
    m_faceIndex.clear();
    m_bounds = {};

    for (const model::Object& object : scene.objects) {
        for (const model::Part& part : object.parts) {
            for (const model::Face& face : part.faces) {
                if (!validLoop(part, face))
                    continue; // validation reports it; nothing sensible to draw
                const std::vector<model::Vec3> loop = model::loopPositions(part.vertices, face.loop);
                FaceRange range;
                range.objectId = object.id;
                range.partId = part.id;
                range.faceId = face.id;
                range.normal = model::polygonNormal(loop);
                range.centroid = model::polygonCentroid(loop);
                range.firstVertex = int(m_surface.size() / 6);
                // Faces are convex, so a fan is a correct triangulation.
                for (size_t i = 1; i + 1 < loop.size(); ++i) {
                    for (const model::Vec3& p : {loop[0], loop[i], loop[i + 1]}) {
                        push3(m_surface, p);
                        push3(m_surface, range.normal);
                    }
                }
                range.vertexCount = int(m_surface.size() / 6) - range.firstVertex;
                range.firstEdgeVertex = int(m_edges.size() / 3);
                for (size_t i = 0; i < loop.size(); ++i) {
                    push3(m_edges, loop[i]);
                    push3(m_edges, loop[(i + 1) % loop.size()]);
                    m_bounds.extend(loop[i]);
                }
                range.edgeVertexCount = int(m_edges.size() / 3) - range.firstEdgeVertex;
                // Whisker length follows the face size so it reads at any scale.
                const double size = std::sqrt(std::max(model::polygonArea(loop), 0.0));
                push3(m_normals, range.centroid);
                push3(m_normals, range.centroid + range.normal * std::clamp(size * 0.3, 0.01, 0.5));
                m_faceIndex.emplace(face.id, int(m_faces.size()));
                m_faces.push_back(std::move(range));
            }
        }
    }
    rebuildColours(scene);
}

void SceneMesh::rebuildColours(const model::Scene& scene)
{
    m_colours.assign(size_t(triangleVertexCount()) * 4, 0.0f);
    for (const model::Object& object : scene.objects)
        for (const model::Part& part : object.parts)
            for (const model::Face& face : part.faces) {
                const FaceRange* range = findFace(face.id);
                if (!range || range->partId != part.id)
                    continue;
                const FaceAppearance look = faceAppearance(scene, part, face);
                for (int v = range->firstVertex; v < range->firstVertex + range->vertexCount; ++v) {
                    float* c = &m_colours[size_t(v) * 4];
                    c[0] = look.r;
                    c[1] = look.g;
                    c[2] = look.b;
                    c[3] = look.emissive ? 1.0f : 0.0f;
                }
            }
}

model::Box3 boundsOfFaces(const model::Scene& scene, const std::vector<std::string>& faceIds)
{
    std::unordered_set<std::string> wanted(faceIds.begin(), faceIds.end());
    model::Box3 box;
    for (const model::Object& object : scene.objects)
        for (const model::Part& part : object.parts)
            for (const model::Face& face : part.faces) {
                if (!faceIds.empty() && !wanted.count(face.id))
                    continue;
                for (int i : face.loop)
                    if (i >= 0 && i < int(part.vertices.size()))
                        box.extend(part.vertices[size_t(i)]);
            }
    return box;
}

} // namespace regio::editor
