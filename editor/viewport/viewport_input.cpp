// Viewport: mouse, wheel, gesture and keyboard input (camera, selection,
// gizmo drags, clip-tool clicks, fly mode).
#include "editor/viewport/viewport.h"

#include "editor/document/qt_conversions.h"
#include "editor/document/scene_document.h"
#include "editor/viewport/picking.h"

#include <QGuiApplication>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QNativeGestureEvent>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace regio::editor {

namespace {

constexpr int kClickSlopPixels = 4;
constexpr double kOrbitDegreesPerPixel = 0.4;

bool isFlyKey(int key)
{
    return key == Qt::Key_W || key == Qt::Key_A || key == Qt::Key_S || key == Qt::Key_D || key == Qt::Key_Q ||
           key == Qt::Key_E;
}

} // namespace

// --- input ----------------------------------------------------------------------

void Viewport::selectAt(const QPoint& pos, bool toggle)
{
    const ScreenView view = screenView();
    const Ray ray = view.ray(pos.x(), pos.y());
    const bool ignoreBack = m_params.cullBackFaces && m_params.shading != ShadingMode::Wireframe;
    const auto hit = pickFace(m_document->scene(), ray, ignoreBack);
    if (!hit) {
        if (!toggle)
            m_document->clearSelection();
        return;
    }
    SelectionKind kind = SelectionKind::Object;
    std::string id = hit->objectId;
    if (m_pickMode == PickMode::Part) {
        kind = SelectionKind::Part;
        id = hit->partId;
    } else if (m_pickMode == PickMode::Face) {
        kind = SelectionKind::Face;
        id = hit->faceId;
    }
    const Selection& current = m_document->selection();
    m_document->setSelection(toggle ? current.toggled(kind, id) : Selection::single(kind, id));
}

void Viewport::mousePressEvent(QMouseEvent* event)
{
    setFocus(Qt::MouseFocusReason);
    if (m_tool && m_tool->mousePress(*this, event))
        return;
    m_pressPos = m_lastPos = event->position().toPoint();
    const Qt::KeyboardModifiers mods = event->modifiers();
    const Qt::MouseButton button = event->button();
    if (button == Qt::LeftButton && (mods & Qt::AltModifier)) {
        m_drag = (mods & Qt::ShiftModifier) ? Drag::Pan : (mods & Qt::ControlModifier) ? Drag::Zoom : Drag::Orbit;
    } else if (button == Qt::MiddleButton) {
        m_drag = (mods & Qt::ShiftModifier) ? Drag::Pan : (mods & Qt::ControlModifier) ? Drag::Zoom : Drag::Orbit;
    } else if (button == Qt::RightButton) {
        m_drag = Drag::Look;
        m_flyClock.start();
        m_flyTimer.start();
        setCursor(Qt::CrossCursor);
    } else if (button == Qt::LeftButton) {
        const ScreenView view = screenView();
        if (m_clip.active()) {
            const Ray ray = view.ray(m_pressPos.x(), m_pressPos.y());
            const auto hit = pickFace(m_document->scene(), ray, false);
            std::optional<model::Vec3> point;
            if (hit)
                point = hit->point;
            else
                point = intersectGround(ray);
            if (point) {
                if (auto plane = m_clip.addPoint(*point))
                    emit clipPlaneChosen(*plane);
                m_toolDirty = true;
                update();
            }
            m_drag = Drag::None;
            return;
        }
        updateGizmo(); // the selection may have changed since the last frame
        const GizmoHandle handle =
            gizmoVisible() ? m_gizmo.hitTest(view, m_pressPos.x(), m_pressPos.y()) : GizmoHandle::None;
        if (handle != GizmoHandle::None) {
            m_drag = Drag::Gizmo;
            m_dragMoved = false;
            m_dragParts = selectedPartIds(m_document->scene(), m_document->selection());
            ++m_dragSerial;
            m_gizmo.beginDrag(handle, view, m_pressPos.x(), m_pressPos.y());
        } else {
            m_drag = Drag::Click;
        }
    }
    event->accept();
}

void Viewport::mouseMoveEvent(QMouseEvent* event)
{
    if (m_tool && m_tool->mouseMove(*this, event)) {
        m_lastPos = event->position().toPoint();
        return;
    }
    const QPoint pos = event->position().toPoint();
    const QPoint delta = pos - m_lastPos;
    m_lastPos = pos;
    const ScreenView view = screenView();
    switch (m_drag) {
    case Drag::Orbit: m_camera.orbit(-delta.x() * kOrbitDegreesPerPixel, delta.y() * kOrbitDegreesPerPixel); break;
    case Drag::Pan: m_camera.pan(2.0 * delta.x() / view.height, -2.0 * delta.y() / view.height); break;
    case Drag::Zoom: m_camera.zoom(std::pow(1.01, delta.y())); break;
    case Drag::Look:
        m_camera.look(-delta.x() * kOrbitDegreesPerPixel * 0.5, -delta.y() * kOrbitDegreesPerPixel * 0.5);
        break;
    case Drag::Gizmo: {
        if (!m_dragMoved && (pos - m_pressPos).manhattanLength() <= kClickSlopPixels)
            return; // not a drag yet
        m_dragMoved = true;
        const glm::dmat4 transform = m_gizmo.dragTo(view, pos.x(), pos.y(), m_snap);
        emit transformDragged(m_dragParts, transform, m_dragSerial);
        emit statusMessage(m_gizmo.dragDescription());
        break;
    }
    case Drag::Click: break;
    case Drag::None: {
        // Hover feedback: the gizmo handle, else the face under the cursor.
        const GizmoHandle handle = gizmoVisible() ? m_gizmo.hitTest(view, pos.x(), pos.y()) : GizmoHandle::None;
        if (handle != m_hoverHandle) {
            m_hoverHandle = handle;
            m_toolDirty = true;
            update();
        }
        return;
    }
    }
    if (m_drag != Drag::Click) {
        m_toolDirty = true;
        emit viewChanged();
        update();
    }
}

void Viewport::mouseReleaseEvent(QMouseEvent* event)
{
    if (m_tool && m_tool->mouseRelease(*this, event)) {
        m_drag = Drag::None;
        return;
    }
    const QPoint pos = event->position().toPoint();
    if (m_drag == Drag::Click && event->button() == Qt::LeftButton &&
        (pos - m_pressPos).manhattanLength() <= kClickSlopPixels) {
        selectAt(pos, event->modifiers() & (Qt::ControlModifier | Qt::ShiftModifier));
        const Ray ray = screenView().ray(pos.x(), pos.y());
        if (const auto hit = pickFace(m_document->scene(), ray, m_params.cullBackFaces))
            emit statusMessage(
                tr("%1 › %2 › %3").arg(toQString(hit->objectId), toQString(hit->partId), toQString(hit->faceId)));
    }
    if (m_drag == Drag::Gizmo) {
        m_gizmo.endDrag();
        emit transformDragFinished();
        // A click on the gizmo that did not drag still selects what is there.
        if (event->button() == Qt::LeftButton && !m_dragMoved)
            selectAt(pos, event->modifiers() & (Qt::ControlModifier | Qt::ShiftModifier));
    }
    if (m_drag == Drag::Look) {
        m_flyTimer.stop();
        m_flyKeys.clear();
        unsetCursor();
    }
    m_drag = Drag::None;
    m_toolDirty = true;
    update();
}

void Viewport::wheelEvent(QWheelEvent* event)
{
    const QPoint pixels = event->pixelDelta();
    const QPoint angle = event->angleDelta();
    if (!pixels.isNull() && !(event->modifiers() & Qt::ControlModifier)) {
        // Trackpad two-finger scroll: orbit, or pan with Shift.
        const ScreenView view = screenView();
        if (event->modifiers() & Qt::ShiftModifier)
            m_camera.pan(2.0 * pixels.x() / view.height, -2.0 * pixels.y() / view.height);
        else
            m_camera.orbit(pixels.x() * kOrbitDegreesPerPixel, pixels.y() * kOrbitDegreesPerPixel);
    } else {
        const double steps = (angle.y() != 0 ? angle.y() : pixels.y()) / 120.0;
        m_camera.zoom(std::pow(0.85, steps));
    }
    m_toolDirty = true;
    emit viewChanged();
    update();
    event->accept();
}

bool Viewport::event(QEvent* event)
{
    if (event->type() == QEvent::NativeGesture) {
        auto* gesture = static_cast<QNativeGestureEvent*>(event);
        if (gesture->gestureType() == Qt::ZoomNativeGesture) {
            m_camera.zoom(1.0 / (1.0 + gesture->value()));
            m_toolDirty = true;
            emit viewChanged();
            update();
            return true;
        }
    }
    return QOpenGLWidget::event(event);
}

void Viewport::keyPressEvent(QKeyEvent* event)
{
    if (m_tool && m_tool->keyPress(*this, event))
        return;
    if (event->key() == Qt::Key_Escape && m_tool) {
        setTool(nullptr);
        emit statusMessage(tr("Cancelled"));
        return;
    }
    if (event->key() == Qt::Key_Escape && (m_clip.active() || m_gizmo.dragging())) {
        cancelTool();
        emit statusMessage(tr("Cancelled"));
        return;
    }
    if (m_drag == Drag::Look && isFlyKey(event->key())) {
        if (!event->isAutoRepeat())
            m_flyKeys.insert(event->key());
        return;
    }
    QOpenGLWidget::keyPressEvent(event);
}

void Viewport::keyReleaseEvent(QKeyEvent* event)
{
    if (isFlyKey(event->key()) && !event->isAutoRepeat()) {
        m_flyKeys.remove(event->key());
        return;
    }
    QOpenGLWidget::keyReleaseEvent(event);
}

void Viewport::focusOutEvent(QFocusEvent* event)
{
    m_flyKeys.clear();
    QOpenGLWidget::focusOutEvent(event);
}

void Viewport::flyStep()
{
    const double seconds = std::min(double(m_flyClock.restart()) / 1000.0, 0.1);
    if (m_flyKeys.isEmpty())
        return;
    // Cross a room-sized scene in about two seconds; Shift is four times faster.
    double speed = std::max(sceneRadius(), 0.5) * seconds;
    if (QGuiApplication::keyboardModifiers() & Qt::ShiftModifier)
        speed *= 4.0;
    model::Vec3 move(0.0);
    if (m_flyKeys.contains(Qt::Key_W))
        move.z += 1;
    if (m_flyKeys.contains(Qt::Key_S))
        move.z -= 1;
    if (m_flyKeys.contains(Qt::Key_D))
        move.x += 1;
    if (m_flyKeys.contains(Qt::Key_A))
        move.x -= 1;
    if (m_flyKeys.contains(Qt::Key_E))
        move.y += 1;
    if (m_flyKeys.contains(Qt::Key_Q))
        move.y -= 1;
    m_camera.fly(move * speed);
    m_toolDirty = true;
    emit viewChanged();
    update();
}

} // namespace regio::editor
