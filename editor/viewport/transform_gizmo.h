#pragma once
// The move / rotate / scale gizmo: its lines, which handle is under the
// cursor, and the transform a drag describes. The viewport turns that
// transform into undo commands; this class only does the geometry.
#include "editor/viewport/camera.h"
#include "editor/viewport/overlay_lines.h"

#include <QCoreApplication>
#include <QString>

#include <glm/mat4x4.hpp>

namespace regio::editor {

enum class GizmoMode { Move, Rotate, Scale };
enum class GizmoHandle { None, X, Y, Z, Centre };

struct GizmoSnap {
    bool enabled = true;
    double step = 0.1;        // metres, for moves
    double angleDegrees = 15; // for rotations
    double scaleStep = 0.1;   // for scale factors
};

class TransformGizmo {
    Q_DECLARE_TR_FUNCTIONS(TransformGizmo)
public:
    void setMode(GizmoMode mode) { m_mode = mode; }
    GizmoMode mode() const { return m_mode; }
    void setPivot(const model::Vec3& pivot) { m_pivot = pivot; }
    model::Vec3 pivot() const { return m_pivot; }

    LineList lines(const ScreenView& view, GizmoHandle highlighted) const;
    // The handle within a few pixels of the cursor, if any.
    GizmoHandle hitTest(const ScreenView& view, double px, double py) const;

    void beginDrag(GizmoHandle handle, const ScreenView& view, double px, double py);
    // The whole transform since beginDrag, about the pivot, snapped.
    glm::dmat4 dragTo(const ScreenView& view, double px, double py, const GizmoSnap& snap);
    void endDrag() { m_dragHandle = GizmoHandle::None; }
    bool dragging() const { return m_dragHandle != GizmoHandle::None; }
    GizmoHandle dragHandle() const { return m_dragHandle; }
    // A short description of the current drag ("Move 0.3 m along X").
    QString dragDescription() const { return m_description; }

private:
    double handleLength(const ScreenView& view) const;
    // Parameter along the axis of the point nearest to the ray.
    double axisParameter(const Ray& ray, const model::Vec3& axis) const;
    // Angle of the ray's hit on the plane through the pivot normal to `axis`.
    std::optional<double> planeAngle(const Ray& ray, const model::Vec3& axis) const;

    GizmoMode m_mode = GizmoMode::Move;
    model::Vec3 m_pivot{0.0};
    GizmoHandle m_dragHandle = GizmoHandle::None;
    ScreenView m_dragView;
    double m_startParameter = 0.0;
    double m_startAngle = 0.0;
    double m_startPixelDistance = 1.0;
    model::Vec3 m_startPlanePoint{0.0};
    QString m_description;
};

model::Vec3 gizmoAxis(GizmoHandle handle);

} // namespace regio::editor
