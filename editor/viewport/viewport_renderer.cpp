#include "editor/viewport/viewport_renderer.h"

#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>

namespace regio::editor {

namespace {

const char* kSurfaceVertex = R"(#version 330 core
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec4 aColour;
uniform mat4 uViewProjection;
out vec3 vNormal;
out vec3 vWorld;
out vec4 vColour;
void main() {
    vNormal = aNormal;
    vWorld = aPosition;
    vColour = aColour;
    gl_Position = uViewProjection * vec4(aPosition, 1.0);
}
)";

// Headlight shading: the light sits at the eye, so every face the user looks
// at is lit and its brightness tells its orientation. Emitters are unlit and
// bright. Back sides are dark red: in a radiosity scene a face seen from
// behind is usually a winding mistake.
const char* kSurfaceFragment = R"(#version 330 core
in vec3 vNormal;
in vec3 vWorld;
in vec4 vColour;
uniform vec3 uEye;
uniform vec3 uViewDirection;
uniform bool uOrthographic;
uniform int uMode; // 0 material, 1 normals
out vec4 fragColour;
void main() {
    vec3 n = normalize(vNormal);
    if (uMode == 1) {
        fragColour = vec4(gl_FrontFacing ? n * 0.5 + 0.5 : vec3(0.2), 1.0);
        return;
    }
    vec3 toEye = uOrthographic ? -uViewDirection : normalize(uEye - vWorld);
    float lambert = abs(dot(n, toEye));
    vec3 c = vColour.a > 0.5 ? mix(vColour.rgb, vec3(1.0), 0.35)
                             : vColour.rgb * (0.35 + 0.65 * lambert);
    if (!gl_FrontFacing)
        c = mix(c * 0.3, vec3(0.35, 0.05, 0.05), 0.5);
    fragColour = vec4(c, 1.0);
}
)";

const char* kFlatVertex = R"(#version 330 core
layout(location = 0) in vec3 aPosition;
layout(location = 2) in vec4 aColour;
uniform mat4 uViewProjection;
out vec4 vColour;
void main() {
    vColour = aColour;
    gl_Position = uViewProjection * vec4(aPosition, 1.0);
}
)";

const char* kFlatFragment = R"(#version 330 core
in vec4 vColour;
out vec4 fragColour;
void main() { fragColour = vColour; }
)";

std::unique_ptr<QOpenGLShaderProgram> buildProgram(const char* vertex, const char* fragment, QString* error)
{
    auto program = std::make_unique<QOpenGLShaderProgram>();
    if (!program->addShaderFromSourceCode(QOpenGLShader::Vertex, vertex) ||
        !program->addShaderFromSourceCode(QOpenGLShader::Fragment, fragment) || !program->link()) {
        if (error)
            *error = program->log();
        return nullptr;
    }
    return program;
}

} // namespace

bool ViewportRenderer::initialize(QString* error)
{
    m_surfaceProgram = buildProgram(kSurfaceVertex, kSurfaceFragment, error);
    m_flatProgram = buildProgram(kFlatVertex, kFlatFragment, error);
    if (!m_surfaceProgram || !m_flatProgram)
        return false;
    m_surfaces.create(GlMesh::Layout::PositionNormal, true);
    m_edges.create(GlMesh::Layout::Position);
    m_normals.create(GlMesh::Layout::Position);
    m_selectionFill.create(GlMesh::Layout::Position);
    m_selectionEdges.create(GlMesh::Layout::Position);
    m_grid.create(GlMesh::Layout::PositionColour);
    m_regions.create(GlMesh::Layout::PositionColour);
    m_toolLines.create(GlMesh::Layout::PositionColour);
    m_toolTriangles.create(GlMesh::Layout::PositionColour);
    return true;
}

void ViewportRenderer::release()
{
    for (auto& [name, layer] : m_layers) {
        layer->triangles.destroy();
        layer->lines.destroy();
    }
    m_layers.clear();
    for (GlMesh* mesh : {&m_surfaces, &m_edges, &m_normals, &m_selectionFill, &m_selectionEdges, &m_grid, &m_regions,
                         &m_toolLines, &m_toolTriangles})
        mesh->destroy();
    m_surfaceProgram.reset();
    m_flatProgram.reset();
}

void ViewportRenderer::uploadScene(const SceneMesh& mesh)
{
    m_surfaces.upload(mesh.surfaceVertices());
    m_surfaces.uploadColours(mesh.colourVertices());
    m_edges.upload(mesh.edgeVertices());
    m_normals.upload(mesh.normalVertices());
}

void ViewportRenderer::uploadColours(const SceneMesh& mesh) { m_surfaces.uploadColours(mesh.colourVertices()); }

void ViewportRenderer::uploadSelection(const SceneMesh& mesh, const std::vector<std::string>& faceIds)
{
    std::vector<float> fill, edges;
    const auto& surface = mesh.surfaceVertices();
    const auto& outline = mesh.edgeVertices();
    for (const std::string& id : faceIds) {
        const FaceRange* range = mesh.findFace(id);
        if (!range)
            continue;
        for (int v = range->firstVertex; v < range->firstVertex + range->vertexCount; ++v)
            fill.insert(fill.end(), surface.begin() + v * 6, surface.begin() + v * 6 + 3);
        edges.insert(edges.end(), outline.begin() + range->firstEdgeVertex * 3,
                     outline.begin() + (range->firstEdgeVertex + range->edgeVertexCount) * 3);
    }
    m_selectionFill.upload(fill);
    m_selectionEdges.upload(edges);
}

void ViewportRenderer::uploadGrid(const LineList& lines) { m_grid.upload(lines.vertices()); }
void ViewportRenderer::uploadRegions(const LineList& lines) { m_regions.upload(lines.vertices()); }
void ViewportRenderer::uploadToolLines(const LineList& lines) { m_toolLines.upload(lines.vertices()); }
void ViewportRenderer::uploadToolTriangles(const LineList& triangles) { m_toolTriangles.upload(triangles.vertices()); }

void ViewportRenderer::uploadLayer(const QString& name, const ViewportLayer& layer)
{
    std::unique_ptr<LayerBuffers>& buffers = m_layers[name];
    if (!buffers) {
        buffers = std::make_unique<LayerBuffers>();
        buffers->triangles.create(GlMesh::Layout::PositionColour);
        buffers->lines.create(GlMesh::Layout::PositionColour);
    }
    buffers->triangles.upload(layer.triangles.vertices());
    buffers->lines.upload(layer.lines.vertices());
    buffers->depthTest = layer.depthTest;
    buffers->replacesSurfaces = layer.replacesSurfaces;
    buffers->offsetTriangles = layer.offsetTriangles;
    buffers->order = layer.order;
}

void ViewportRenderer::removeLayer(const QString& name)
{
    auto it = m_layers.find(name);
    if (it == m_layers.end())
        return;
    it->second->triangles.destroy();
    it->second->lines.destroy();
    m_layers.erase(it);
}

// Draws the depth-tested or the on-top layers in ascending order; the flat
// program is bound and the depth test is set up by the caller.
void ViewportRenderer::drawLayers(bool depthTested)
{
    std::vector<LayerBuffers*> layers;
    for (const auto& [name, layer] : m_layers)
        if (layer->depthTest == depthTested)
            layers.push_back(layer.get());
    std::stable_sort(layers.begin(), layers.end(),
                     [](const LayerBuffers* a, const LayerBuffers* b) { return a->order < b->order; });
    QOpenGLExtraFunctions* gl = QOpenGLContext::currentContext()->extraFunctions();
    for (LayerBuffers* layer : layers) {
        if (layer->offsetTriangles) {
            gl->glEnable(GL_POLYGON_OFFSET_FILL);
            gl->glPolygonOffset(1.0f, 1.0f);
        }
        layer->triangles.draw(GL_TRIANGLES);
        gl->glDisable(GL_POLYGON_OFFSET_FILL);
        layer->lines.draw(GL_LINES);
    }
}

void ViewportRenderer::render(const RenderParams& p)
{
    QOpenGLExtraFunctions* gl = QOpenGLContext::currentContext()->extraFunctions();
    gl->glClearColor(p.background.r, p.background.g, p.background.b, 1.0f);
    gl->glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl->glEnable(GL_DEPTH_TEST);
    gl->glDepthFunc(GL_LEQUAL);
    gl->glEnable(GL_BLEND);
    gl->glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    if (!m_surfaceProgram || !m_flatProgram)
        return;
    const float* vp = glm::value_ptr(p.viewProjection);

    // The grid first, without depth: any surface, even a floor lying in the
    // grid's plane, covers it.
    m_flatProgram->bind();
    gl->glUniformMatrix4fv(m_flatProgram->uniformLocation("uViewProjection"), 1, GL_FALSE, vp);
    if (p.showGrid) {
        gl->glDepthMask(GL_FALSE);
        m_grid.draw(GL_LINES);
        gl->glDepthMask(GL_TRUE);
    }

    bool surfacesReplaced = false;
    for (const auto& [name, layer] : m_layers)
        surfacesReplaced = surfacesReplaced || layer->replacesSurfaces;

    // Surfaces sit slightly behind lines drawn at the same depth.
    if (p.shading != ShadingMode::Wireframe && !surfacesReplaced) {
        if (p.cullBackFaces) {
            gl->glEnable(GL_CULL_FACE);
            gl->glCullFace(GL_BACK);
        }
        gl->glEnable(GL_POLYGON_OFFSET_FILL);
        gl->glPolygonOffset(1.0f, 1.0f);
        m_surfaceProgram->bind();
        gl->glUniformMatrix4fv(m_surfaceProgram->uniformLocation("uViewProjection"), 1, GL_FALSE, vp);
        m_surfaceProgram->setUniformValue("uEye", p.eye.x, p.eye.y, p.eye.z);
        m_surfaceProgram->setUniformValue("uViewDirection", p.viewDirection.x, p.viewDirection.y, p.viewDirection.z);
        m_surfaceProgram->setUniformValue("uOrthographic", p.orthographic);
        m_surfaceProgram->setUniformValue("uMode", p.shading == ShadingMode::Normals ? 1 : 0);
        m_surfaces.draw(GL_TRIANGLES);
        gl->glDisable(GL_POLYGON_OFFSET_FILL);
        gl->glDisable(GL_CULL_FACE);
    }

    m_flatProgram->bind();
    gl->glUniformMatrix4fv(m_flatProgram->uniformLocation("uViewProjection"), 1, GL_FALSE, vp);
    if (p.shading == ShadingMode::Wireframe) {
        gl->glVertexAttrib4f(ColourAttribute, 0.85f, 0.88f, 0.92f, 1.0f);
        m_edges.draw(GL_LINES);
    } else if (p.showEdges) {
        gl->glVertexAttrib4f(ColourAttribute, 0.05f, 0.05f, 0.06f, 0.45f);
        m_edges.draw(GL_LINES);
    }
    if (p.shading == ShadingMode::Normals) {
        gl->glVertexAttrib4f(ColourAttribute, 1.0f, 1.0f, 0.3f, 1.0f);
        m_normals.draw(GL_LINES);
    }
    if (p.showRegions)
        m_regions.draw(GL_LINES);
    drawLayers(true);

    // Selection: a translucent fill and a bright outline, faintly visible
    // through whatever hides it.
    gl->glDepthMask(GL_FALSE);
    gl->glVertexAttrib4f(ColourAttribute, 1.0f, 0.55f, 0.1f, 0.35f);
    m_selectionFill.draw(GL_TRIANGLES);
    gl->glVertexAttrib4f(ColourAttribute, 1.0f, 0.65f, 0.15f, 1.0f);
    m_selectionEdges.draw(GL_LINES);
    gl->glDisable(GL_DEPTH_TEST);
    gl->glVertexAttrib4f(ColourAttribute, 1.0f, 0.65f, 0.15f, 0.25f);
    m_selectionEdges.draw(GL_LINES);

    // Tools and on-top layers over everything.
    drawLayers(false);
    m_toolTriangles.draw(GL_TRIANGLES);
    m_toolLines.draw(GL_LINES);
    gl->glDepthMask(GL_TRUE);
    gl->glEnable(GL_DEPTH_TEST);
    m_flatProgram->release();
}

} // namespace regio::editor
