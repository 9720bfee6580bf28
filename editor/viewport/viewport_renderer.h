#pragma once
// The OpenGL 3.3 core side of the viewport: shaders and one GlMesh per kind
// of content. Each upload replaces only its own buffers; render() draws the
// current state. Must be used with the viewport's context current.
#include "editor/viewport/gl_buffers.h"
#include "editor/viewport/overlay_lines.h"
#include "editor/viewport/scene_mesh.h"
#include "editor/viewport/viewport_layers.h"

#include <QOpenGLShaderProgram>

#include <glm/mat4x4.hpp>

#include <QString>

#include <map>
#include <memory>

namespace regio::editor {

enum class ShadingMode { Solid, Wireframe, Normals };

struct RenderParams {
    glm::mat4 viewProjection{1.0f};
    glm::vec3 eye{0.0f};
    glm::vec3 viewDirection{0.0f, 0.0f, -1.0f};
    bool orthographic = false;
    ShadingMode shading = ShadingMode::Solid;
    bool cullBackFaces = true;
    bool showGrid = true;
    bool showEdges = true;
    bool showRegions = true;
    glm::vec3 background{0.16f, 0.17f, 0.19f};
};

class ViewportRenderer {
public:
    // False (and `error` set) if the shaders do not compile on this GL.
    bool initialize(QString* error);
    void release();

    void uploadScene(const SceneMesh& mesh);   // geometry, outlines, normals, colours
    void uploadColours(const SceneMesh& mesh); // colours only
    // Selected faces (triangles from the mesh) and their outlines.
    void uploadSelection(const SceneMesh& mesh, const std::vector<std::string>& faceIds);
    void uploadGrid(const LineList& lines);
    void uploadRegions(const LineList& lines);
    // Gizmo, clip plane and other tool overlays: drawn on top of everything.
    void uploadToolLines(const LineList& lines);
    void uploadToolTriangles(const LineList& triangles);
    // Overlay layers (viewport_layers.h): replaces or removes one by name.
    void uploadLayer(const QString& name, const ViewportLayer& layer);
    void removeLayer(const QString& name);

    void render(const RenderParams& params);

private:
    std::unique_ptr<QOpenGLShaderProgram> m_surfaceProgram;
    std::unique_ptr<QOpenGLShaderProgram> m_flatProgram;
    GlMesh m_surfaces, m_edges, m_normals, m_selectionFill, m_selectionEdges;
    GlMesh m_grid, m_regions, m_toolLines, m_toolTriangles;

    struct LayerBuffers {
        GlMesh triangles, lines;
        bool depthTest = true;
        bool replacesSurfaces = false;
        bool offsetTriangles = true;
        int order = 0;
    };
    void drawLayers(bool depthTested);
    std::map<QString, std::unique_ptr<LayerBuffers>> m_layers;
};

} // namespace regio::editor
