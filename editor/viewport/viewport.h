#pragma once
// The 3D view of a SceneDocument (QOpenGLWidget, OpenGL 3.3 core). It keeps
// GPU buffers in step with the document's change signals, rebuilding only
// what a signal names, and turns mouse and keyboard input into camera moves,
// selection, gizmo drags and clip-tool clicks.
#include "editor/viewport/camera.h"
#include "editor/viewport/clip_tool.h"
#include "editor/viewport/scene_mesh.h"
#include "editor/viewport/transform_gizmo.h"
#include "editor/viewport/viewport_layers.h"
#include "editor/viewport/viewport_renderer.h"
#include "editor/viewport/viewport_tool.h"

#include <QElapsedTimer>
#include <QOpenGLWidget>
#include <QPoint>
#include <QSet>
#include <QSurfaceFormat>
#include <QTimer>

#include <glm/mat4x4.hpp>

#include <map>

namespace regio::editor {

class SceneDocument;

enum class PickMode { Object, Part, Face };

class Viewport : public QOpenGLWidget {
    Q_OBJECT
public:
    explicit Viewport(SceneDocument* document, QWidget* parent = nullptr);
    ~Viewport() override;

    // The format the application requests before creating any widget.
    static QSurfaceFormat requestedFormat();

    Camera& camera() { return m_camera; }
    const Camera& camera() const { return m_camera; }
    ScreenView screenView() const;

    ShadingMode shading() const { return m_params.shading; }
    void setShading(ShadingMode mode);
    bool cullBackFaces() const { return m_params.cullBackFaces; }
    void setCullBackFaces(bool on);
    bool showGrid() const { return m_params.showGrid; }
    void setShowGrid(bool on);
    bool showRegions() const { return m_params.showRegions; }
    void setShowRegions(bool on);
    PickMode pickMode() const { return m_pickMode; }
    void setPickMode(PickMode mode);
    GizmoMode gizmoMode() const { return m_gizmo.mode(); }
    void setGizmoMode(GizmoMode mode);
    const GizmoSnap& snap() const { return m_snap; }
    void setSnapEnabled(bool on);
    void setGridStep(double metres);
    void setAngleStep(double degrees);

    void frameSelection();
    void frameAll();
    void setStandardView(StandardView view);
    void setOrthographic(bool on);
    // After a new scene: its stored camera if it has one, else frame all.
    void resetView();

    // Overlay layers (viewport_layers.h), kept across GL context changes.
    // Setting a layer of the same name replaces it.
    void setLayer(const QString& name, ViewportLayer layer);
    void removeLayer(const QString& name);
    bool hasLayer(const QString& name) const;
    const ViewportLayer* layer(const QString& name) const;

    // The interactive tool that gets input first (viewport_tool.h); nullptr
    // = none. The viewport does not own it; setting another one (or nullptr)
    // calls the previous one's deactivated().
    void setTool(ViewportTool* tool);
    ViewportTool* tool() const { return m_tool; }

    void startClipByPoints();
    void cancelTool();
    bool clipToolActive() const { return m_clip.active(); }

    bool hasRenderedFrame() const { return m_framesRendered > 0; }
    // Empty while rendering works; else why the view cannot draw.
    QString renderingError() const { return m_renderingError; }

signals:
    void frameRendered();
    void renderingFailed(const QString& message);
    void statusMessage(const QString& message);
    void viewChanged();
    // Three clicked points defined a cutting plane (clip tool).
    void clipPlaneChosen(const model::Plane& plane);
    // A gizmo drag: the whole transform since the drag began, for the parts
    // given. `serial` identifies the drag so its steps merge into one edit.
    void transformDragged(const std::vector<std::string>& partIds, const glm::dmat4& transform, int serial);
    void transformDragFinished();

protected:
    void initializeGL() override;
    void resizeGL(int w, int h) override;
    void paintGL() override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void keyReleaseEvent(QKeyEvent* event) override;
    void focusOutEvent(QFocusEvent* event) override;
    bool event(QEvent* event) override;

private:
    enum class Drag { None, Orbit, Pan, Zoom, Look, Gizmo, Click };

    void onObjectsChanged();
    void onMaterialsChanged();
    void onRegionsChanged();
    void onSelectionChanged();
    void updateGrid();
    void updateGizmo();
    void updateToolOverlay();
    void selectAt(const QPoint& pos, bool toggle);
    void flyStep();
    double sceneRadius() const;
    bool gizmoVisible() const;
    void makeCurrentAndUpload();
    void releaseGl();

    SceneDocument* m_document;
    Camera m_camera;
    SceneMesh m_mesh;
    ViewportRenderer m_renderer;
    RenderParams m_params;
    TransformGizmo m_gizmo;
    GizmoSnap m_snap;
    GizmoHandle m_hoverHandle = GizmoHandle::None;
    ClipTool m_clip;
    PickMode m_pickMode = PickMode::Object;

    // What must be uploaded before the next frame (the GL context may not be
    // current when a signal arrives).
    bool m_geometryDirty = true;
    bool m_coloursDirty = true;
    bool m_selectionDirty = true;
    bool m_regionsDirty = true;
    bool m_gridDirty = true;
    bool m_toolDirty = true;
    bool m_glReady = false;
    std::map<QString, ViewportLayer> m_layers;
    ViewportTool* m_tool = nullptr;
    QSet<QString> m_dirtyLayers;
    int m_framesRendered = 0;
    QString m_renderingError;
    QMetaObject::Connection m_contextConnection;

    Drag m_drag = Drag::None;
    QPoint m_pressPos;
    QPoint m_lastPos;
    std::vector<std::string> m_dragParts;
    int m_dragSerial = 0;
    bool m_dragMoved = false; // the gizmo drag left the click slop

    QSet<int> m_flyKeys;
    QTimer m_flyTimer;
    QElapsedTimer m_flyClock;
};

} // namespace regio::editor
