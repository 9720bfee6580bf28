#pragma once
// CPU side of what the viewport draws: every face fanned into triangles with
// its flat normal, per-vertex material colours, face outlines and normal
// whiskers. Geometry and colours are separate arrays so a material edit
// re-uploads colours only.
#include "model/geometry/geometry.h"
#include "model/scene.h"

#include <string>
#include <unordered_map>
#include <vector>

namespace regio::editor {

struct FaceRange {
    std::string objectId;
    std::string partId;
    std::string faceId;
    int firstVertex = 0; // into the triangle arrays
    int vertexCount = 0;
    int firstEdgeVertex = 0; // into the edge line array
    int edgeVertexCount = 0;
    model::Vec3 centroid{0.0};
    model::Vec3 normal{0.0};
};

class SceneMesh {
public:
    // Triangles: position xyz + normal xyz per vertex.
    const std::vector<float>& surfaceVertices() const { return m_surface; }
    // Per triangle vertex: display colour rgb + emissive flag (0 or 1).
    const std::vector<float>& colourVertices() const { return m_colours; }
    // Lines: position xyz per vertex, two per segment.
    const std::vector<float>& edgeVertices() const { return m_edges; }
    const std::vector<float>& normalVertices() const { return m_normals; }
    const std::vector<FaceRange>& faces() const { return m_faces; }
    int triangleVertexCount() const { return int(m_surface.size() / 6); }
    const model::Box3& bounds() const { return m_bounds; }
    const FaceRange* findFace(const std::string& faceId) const;

    // Rebuilds triangles, outlines and normals (and colours, which follow the
    // triangles).
    void rebuildGeometry(const model::Scene& scene);
    // Rebuilds only the colours, after a material change.
    void rebuildColours(const model::Scene& scene);

private:
    std::vector<float> m_surface;
    std::vector<float> m_colours;
    std::vector<float> m_edges;
    std::vector<float> m_normals;
    std::vector<FaceRange> m_faces;
    std::unordered_map<std::string, int> m_faceIndex;
    model::Box3 m_bounds;
};

// Display colour of a face's material: sRGB of the reflectance, or of the
// emission's hue for emitters (drawn unlit). Magenta marks a missing material.
struct FaceAppearance {
    float r = 1.0f, g = 0.0f, b = 1.0f;
    bool emissive = false;
};
FaceAppearance faceAppearance(const model::Scene& scene, const model::Part& part, const model::Face& face);

// Bounds of the given faces (all faces when ids is empty).
model::Box3 boundsOfFaces(const model::Scene& scene, const std::vector<std::string>& faceIds);

} // namespace regio::editor
