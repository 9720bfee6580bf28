// Viewport: GPU buffers kept in step with the document, rendering, and the
// view operations (framing, standard views, tools).
#include "editor/viewport/viewport.h"

#include "editor/document/scene_document.h"

#include <QOpenGLContext>
#include <QOpenGLFunctions>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace regio::editor {

QSurfaceFormat Viewport::requestedFormat()
{
    QSurfaceFormat format;
    format.setRenderableType(QSurfaceFormat::OpenGL);
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    format.setStencilBufferSize(8);
    format.setSamples(4);
    return format;
}

Viewport::Viewport(SceneDocument* document, QWidget* parent)
    : QOpenGLWidget(parent)
    , m_document(document)
{
    setFocusPolicy(Qt::StrongFocus);
    setMouseTracking(true);
    setMinimumSize(200, 150);
    setAttribute(Qt::WA_AcceptTouchEvents, false);
    grabGesture(Qt::PinchGesture);

    connect(document, &SceneDocument::objectsChanged, this, &Viewport::onObjectsChanged);
    connect(document, &SceneDocument::geometryChanged, this, &Viewport::onObjectsChanged);
    connect(document, &SceneDocument::materialsChanged, this, &Viewport::onMaterialsChanged);
    connect(document, &SceneDocument::regionsChanged, this, &Viewport::onRegionsChanged);
    connect(document, &SceneDocument::selectionChanged, this, &Viewport::onSelectionChanged);

    m_flyTimer.setInterval(16);
    connect(&m_flyTimer, &QTimer::timeout, this, &Viewport::flyStep);
}

Viewport::~Viewport()
{
    // The base class destroys the context after this object's members are
    // gone: release the GL objects now and stop listening for that.
    disconnect(m_contextConnection);
    releaseGl();
}

void Viewport::releaseGl()
{
    if (!m_glReady)
        return;
    makeCurrent();
    m_renderer.release();
    m_glReady = false;
    doneCurrent();
}

void Viewport::setLayer(const QString& name, ViewportLayer layer)
{
    m_layers[name] = std::move(layer);
    m_dirtyLayers.insert(name);
    update();
}

void Viewport::removeLayer(const QString& name)
{
    if (m_layers.erase(name) == 0)
        return;
    m_dirtyLayers.insert(name);
    update();
}

void Viewport::setTool(ViewportTool* tool)
{
    if (tool == m_tool)
        return;
    ViewportTool* previous = m_tool;
    m_tool = tool;
    if (previous)
        previous->deactivated();
    update();
}

bool Viewport::hasLayer(const QString& name) const { return m_layers.count(name) > 0; }

const ViewportLayer* Viewport::layer(const QString& name) const
{
    auto it = m_layers.find(name);
    return it == m_layers.end() ? nullptr : &it->second;
}

ScreenView Viewport::screenView() const
{
    return ScreenView{m_camera, double(std::max(width(), 1)), double(std::max(height(), 1))};
}

void Viewport::setShading(ShadingMode mode)
{
    m_params.shading = mode;
    update();
}

void Viewport::setCullBackFaces(bool on)
{
    m_params.cullBackFaces = on;
    update();
}

void Viewport::setShowGrid(bool on)
{
    m_params.showGrid = on;
    update();
}

void Viewport::setShowRegions(bool on)
{
    m_params.showRegions = on;
    update();
}

void Viewport::setPickMode(PickMode mode) { m_pickMode = mode; }

void Viewport::setGizmoMode(GizmoMode mode)
{
    m_gizmo.setMode(mode);
    m_toolDirty = true;
    update();
}

void Viewport::setSnapEnabled(bool on) { m_snap.enabled = on; }

void Viewport::setGridStep(double metres)
{
    if (!(metres > 0.0))
        return;
    m_snap.step = metres;
    m_gridDirty = true;
    update();
}

void Viewport::setAngleStep(double degrees)
{
    if (degrees > 0.0)
        m_snap.angleDegrees = degrees;
}

double Viewport::sceneRadius() const
{
    const model::Box3& b = m_mesh.bounds();
    return b.empty ? 5.0 : std::max(0.5 * glm::length(b.size()), 0.1);
}

void Viewport::frameSelection()
{
    const std::vector<std::string> faces = selectedFaceIds(m_document->scene(), m_document->selection());
    model::Box3 box;
    if (m_document->selection().kind == SelectionKind::Region) {
        for (const std::string& id : m_document->selection().ids)
            if (const model::Region* r = m_document->scene().findRegion(id)) {
                box.extend(r->min);
                box.extend(r->max);
            }
    } else if (!faces.empty()) {
        box = boundsOfFaces(m_document->scene(), faces);
    }
    if (box.empty) {
        frameAll();
        return;
    }
    m_camera.frame(box, screenView().aspect());
    m_toolDirty = true;
    emit viewChanged();
    update();
}

void Viewport::frameAll()
{
    model::Box3 box = boundsOfFaces(m_document->scene(), {});
    if (box.empty) {
        box.extend(model::Vec3(-1.0, 0.0, -1.0));
        box.extend(model::Vec3(1.0, 1.0, 1.0));
    }
    m_camera.setSceneRadius(std::max(0.5 * glm::length(box.size()), 0.1));
    m_camera.frame(box, screenView().aspect());
    m_toolDirty = true;
    emit viewChanged();
    update();
}

void Viewport::setStandardView(StandardView view)
{
    m_camera.setStandardView(view);
    m_toolDirty = true;
    emit viewChanged();
    update();
}

void Viewport::setOrthographic(bool on)
{
    m_camera.setOrthographic(on);
    m_toolDirty = true;
    emit viewChanged();
    update();
}

void Viewport::resetView()
{
    const model::Box3 box = boundsOfFaces(m_document->scene(), {});
    m_camera.setSceneRadius(box.empty ? 5.0 : std::max(0.5 * glm::length(box.size()), 0.1));
    if (m_document->scene().camera) {
        m_camera.setFromSceneCamera(*m_document->scene().camera);
        m_toolDirty = true;
        emit viewChanged();
        update();
        return;
    }
    m_camera.setStandardView(StandardView::Iso);
    frameAll();
}

void Viewport::startClipByPoints()
{
    m_clip.start();
    m_toolDirty = true;
    emit statusMessage(tr("Clip: click three points on surfaces to define the cutting plane (Esc cancels)"));
    update();
}

void Viewport::cancelTool()
{
    m_clip.cancel();
    if (m_gizmo.dragging()) {
        m_gizmo.endDrag();
        m_drag = Drag::None;
        emit transformDragFinished();
    }
    m_toolDirty = true;
    update();
}

// --- document signals: mark what must be uploaded ---------------------------

void Viewport::onObjectsChanged()
{
    m_geometryDirty = true;
    m_selectionDirty = true; // face triangles moved
    m_gridDirty = true;      // the grid follows the scene's size
    m_toolDirty = true;      // the gizmo follows the selection's centre
    update();
}

void Viewport::onMaterialsChanged()
{
    m_coloursDirty = true;
    update();
}

void Viewport::onRegionsChanged()
{
    m_regionsDirty = true;
    update();
}

void Viewport::onSelectionChanged()
{
    m_selectionDirty = true;
    m_regionsDirty = true; // selected regions are drawn brighter
    m_toolDirty = true;
    update();
}

// --- GL -----------------------------------------------------------------------

void Viewport::initializeGL()
{
    const QSurfaceFormat format = context()->format();
    const bool versionOk = format.majorVersion() > 3 || (format.majorVersion() == 3 && format.minorVersion() >= 3);
    QString error;
    if (!versionOk) {
        m_renderingError =
            tr("OpenGL 3.3 is needed, this system offers %1.%2").arg(format.majorVersion()).arg(format.minorVersion());
    } else if (!m_renderer.initialize(&error)) {
        m_renderingError = tr("The viewport shaders do not compile: %1").arg(error);
    } else {
        m_glReady = true;
    }
    if (!m_glReady)
        emit renderingFailed(m_renderingError);
    m_geometryDirty = m_coloursDirty = m_selectionDirty = m_regionsDirty = m_gridDirty = m_toolDirty = true;
    for (const auto& [name, layer] : m_layers)
        m_dirtyLayers.insert(name);
    // The context goes away when the widget moves to another window (docking,
    // reparenting); initializeGL runs again on the new one.
    disconnect(m_contextConnection);
    m_contextConnection = connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &Viewport::releaseGl);
}

void Viewport::resizeGL(int, int) { m_toolDirty = true; }

void Viewport::makeCurrentAndUpload()
{
    const model::Scene& scene = m_document->scene();
    if (m_geometryDirty) {
        m_mesh.rebuildGeometry(scene);
        m_renderer.uploadScene(m_mesh);
        m_camera.setSceneRadius(sceneRadius());
        m_geometryDirty = m_coloursDirty = false;
    }
    if (m_coloursDirty) {
        m_mesh.rebuildColours(scene);
        m_renderer.uploadColours(m_mesh);
        m_coloursDirty = false;
    }
    if (m_selectionDirty) {
        m_renderer.uploadSelection(m_mesh, selectedFaceIds(scene, m_document->selection()));
        m_selectionDirty = false;
    }
    if (m_regionsDirty) {
        const Selection& s = m_document->selection();
        m_renderer.uploadRegions(
            buildRegionBoxes(scene, s.kind == SelectionKind::Region ? s.ids : std::vector<std::string>{}));
        m_regionsDirty = false;
    }
    if (m_gridDirty) {
        m_renderer.uploadGrid(buildGrid(m_snap.step, std::max(10.0, sceneRadius() * 2.0)));
        m_gridDirty = false;
    }
    for (const QString& name : std::as_const(m_dirtyLayers)) {
        if (auto it = m_layers.find(name); it != m_layers.end())
            m_renderer.uploadLayer(name, it->second);
        else
            m_renderer.removeLayer(name);
    }
    m_dirtyLayers.clear();
    if (m_toolDirty) {
        updateToolOverlay();
        m_toolDirty = false;
    }
}

void Viewport::paintGL()
{
    if (!m_glReady) {
        auto* gl = context()->functions();
        gl->glClearColor(0.3f, 0.1f, 0.1f, 1.0f);
        gl->glClear(GL_COLOR_BUFFER_BIT);
        return;
    }
    makeCurrentAndUpload();
    const double aspect = screenView().aspect();
    m_params.viewProjection = glm::mat4(m_camera.projectionMatrix(aspect) * m_camera.viewMatrix());
    m_params.eye = glm::vec3(m_camera.eye());
    m_params.viewDirection = glm::vec3(m_camera.forward());
    m_params.orthographic = m_camera.orthographic();
    m_renderer.render(m_params);
    if (m_framesRendered++ == 0)
        QTimer::singleShot(0, this, &Viewport::frameRendered);
}

bool Viewport::gizmoVisible() const
{
    const Selection& s = m_document->selection();
    return !m_clip.active() && (s.kind == SelectionKind::Object || s.kind == SelectionKind::Part) && !s.empty();
}

void Viewport::updateGizmo()
{
    if (m_gizmo.dragging())
        return; // the pivot stays put during a drag
    const std::vector<std::string> faces = selectedFaceIds(m_document->scene(), m_document->selection());
    const model::Box3 box = boundsOfFaces(m_document->scene(), faces);
    if (!box.empty)
        m_gizmo.setPivot(box.center());
}

void Viewport::updateToolOverlay()
{
    LineList lines;
    if (gizmoVisible()) {
        updateGizmo();
        lines = m_gizmo.lines(screenView(), m_hoverHandle);
    }
    if (m_clip.active()) {
        const ScreenView view = screenView();
        const double marker = 6.0 * view.worldPerPixelAt(m_camera.target());
        lines.append(m_clip.lines(marker));
    }
    m_renderer.uploadToolLines(lines);
}

} // namespace regio::editor
