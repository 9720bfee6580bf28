#include "editor/viewport/transform_gizmo.h"

#include <QCoreApplication>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace regio::editor {

namespace {

constexpr double kHandlePixels = 90.0;
constexpr double kHitPixels = 8.0;

glm::vec4 axisColour(GizmoHandle handle, bool highlighted)
{
    if (highlighted)
        return {1.0f, 0.9f, 0.2f, 1.0f};
    switch (handle) {
    case GizmoHandle::X: return {0.95f, 0.25f, 0.25f, 1.0f};
    case GizmoHandle::Y: return {0.3f, 0.9f, 0.3f, 1.0f};
    case GizmoHandle::Z: return {0.3f, 0.5f, 1.0f, 1.0f};
    default: return {0.9f, 0.9f, 0.9f, 1.0f};
    }
}

double distanceToSegment(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b)
{
    const glm::dvec2 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + t * ab));
}

double snapTo(double value, double step) { return step > 0.0 ? std::round(value / step) * step : value; }

const char* axisName(GizmoHandle handle)
{
    switch (handle) {
    case GizmoHandle::X: return "X";
    case GizmoHandle::Y: return "Y";
    case GizmoHandle::Z: return "Z";
    default: return "";
    }
}

} // namespace

model::Vec3 gizmoAxis(GizmoHandle handle)
{
    switch (handle) {
    case GizmoHandle::X: return {1, 0, 0};
    case GizmoHandle::Y: return {0, 1, 0};
    case GizmoHandle::Z: return {0, 0, 1};
    default: return {0, 0, 0};
    }
}

double TransformGizmo::handleLength(const ScreenView& view) const
{
    return kHandlePixels * view.worldPerPixelAt(m_pivot);
}

LineList TransformGizmo::lines(const ScreenView& view, GizmoHandle highlighted) const
{
    LineList out;
    const double length = handleLength(view);
    const GizmoHandle active = dragging() ? m_dragHandle : highlighted;
    for (GizmoHandle h : {GizmoHandle::X, GizmoHandle::Y, GizmoHandle::Z}) {
        const model::Vec3 axis = gizmoAxis(h);
        const glm::vec4 colour = axisColour(h, h == active);
        if (m_mode == GizmoMode::Rotate) {
            out.addCircle(m_pivot, axis, length * 0.8, colour);
            continue;
        }
        const model::Vec3 tip = m_pivot + axis * length;
        out.add(m_pivot, tip, colour);
        // Arrow heads for move, small squares for scale.
        const model::Vec3 side = glm::normalize(glm::cross(axis, view.camera.forward()) + model::Vec3(1e-9));
        const double s = length * 0.08;
        if (m_mode == GizmoMode::Move) {
            out.add(tip, tip - axis * s * 2.0 + side * s, colour);
            out.add(tip, tip - axis * s * 2.0 - side * s, colour);
        } else {
            const model::Vec3 up = glm::normalize(glm::cross(side, axis));
            const model::Vec3 a = tip + side * s + up * s, b = tip - side * s + up * s;
            const model::Vec3 c = tip - side * s - up * s, d = tip + side * s - up * s;
            out.add(a, b, colour);
            out.add(b, c, colour);
            out.add(c, d, colour);
            out.add(d, a, colour);
        }
    }
    if (m_mode != GizmoMode::Rotate) {
        // The centre square: free move in the view plane, or uniform scale.
        const double s = length * 0.07;
        const model::Vec3 r = view.camera.right() * s, u = view.camera.up() * s;
        const glm::vec4 colour = axisColour(GizmoHandle::Centre, active == GizmoHandle::Centre);
        out.add(m_pivot - r - u, m_pivot + r - u, colour);
        out.add(m_pivot + r - u, m_pivot + r + u, colour);
        out.add(m_pivot + r + u, m_pivot - r + u, colour);
        out.add(m_pivot - r + u, m_pivot - r - u, colour);
    }
    return out;
}

GizmoHandle TransformGizmo::hitTest(const ScreenView& view, double px, double py) const
{
    const auto centre = view.toPixels(m_pivot);
    if (!centre)
        return GizmoHandle::None;
    const glm::dvec2 mouse(px, py);
    const double length = handleLength(view);
    if (m_mode != GizmoMode::Rotate && glm::length(mouse - *centre) < kHitPixels * 1.2)
        return GizmoHandle::Centre;
    GizmoHandle best = GizmoHandle::None;
    double bestDistance = kHitPixels;
    for (GizmoHandle h : {GizmoHandle::X, GizmoHandle::Y, GizmoHandle::Z}) {
        const model::Vec3 axis = gizmoAxis(h);
        double d = 1e9;
        if (m_mode == GizmoMode::Rotate) {
            const model::Vec3 helper = std::abs(axis.y) < 0.9 ? model::Vec3(0, 1, 0) : model::Vec3(1, 0, 0);
            const model::Vec3 u = glm::normalize(glm::cross(axis, helper));
            const model::Vec3 v = glm::cross(axis, u);
            const int segments = 48;
            for (int i = 0; i < segments; ++i) {
                const double a0 = 2 * M_PI * i / segments, a1 = 2 * M_PI * (i + 1) / segments;
                const auto p0 = view.toPixels(m_pivot + 0.8 * length * (std::cos(a0) * u + std::sin(a0) * v));
                const auto p1 = view.toPixels(m_pivot + 0.8 * length * (std::cos(a1) * u + std::sin(a1) * v));
                if (p0 && p1)
                    d = std::min(d, distanceToSegment(mouse, *p0, *p1));
            }
        } else if (const auto tip = view.toPixels(m_pivot + axis * length)) {
            d = distanceToSegment(mouse, *centre, *tip);
        }
        if (d < bestDistance) {
            bestDistance = d;
            best = h;
        }
    }
    return best;
}

double TransformGizmo::axisParameter(const Ray& ray, const model::Vec3& axis) const
{
    // Closest points of two lines: pivot + s*axis and origin + t*direction.
    const model::Vec3 w = m_pivot - ray.origin;
    const double b = glm::dot(axis, ray.direction);
    const double d = glm::dot(axis, w), e = glm::dot(ray.direction, w);
    const double denom = 1.0 - b * b;
    if (denom < 1e-9)
        return 0.0; // looking straight down the axis
    return (b * e - d) / denom;
}

std::optional<double> TransformGizmo::planeAngle(const Ray& ray, const model::Vec3& axis) const
{
    const double denom = glm::dot(axis, ray.direction);
    if (std::abs(denom) < 1e-9)
        return std::nullopt;
    const double t = glm::dot(axis, m_pivot - ray.origin) / denom;
    const model::Vec3 p = ray.origin + t * ray.direction - m_pivot;
    const model::Vec3 helper = std::abs(axis.y) < 0.9 ? model::Vec3(0, 1, 0) : model::Vec3(1, 0, 0);
    const model::Vec3 u = glm::normalize(glm::cross(axis, helper));
    const model::Vec3 v = glm::cross(axis, u);
    return std::atan2(glm::dot(p, v), glm::dot(p, u));
}

void TransformGizmo::beginDrag(GizmoHandle handle, const ScreenView& view, double px, double py)
{
    m_dragHandle = handle;
    m_dragView = view;
    m_description.clear();
    const Ray ray = view.ray(px, py);
    const model::Vec3 axis = gizmoAxis(handle);
    if (handle == GizmoHandle::Centre) {
        const auto centre = view.toPixels(m_pivot);
        m_startPixelDistance = centre ? std::max(glm::length(glm::dvec2(px, py) - *centre), 4.0) : 1.0;
        // Free move happens in the plane through the pivot facing the camera.
        const model::Vec3 n = view.camera.forward();
        const double t = glm::dot(n, m_pivot - ray.origin) / glm::dot(n, ray.direction);
        m_startPlanePoint = ray.origin + t * ray.direction;
        return;
    }
    if (m_mode == GizmoMode::Rotate)
        m_startAngle = planeAngle(ray, axis).value_or(0.0);
    else
        m_startParameter = axisParameter(ray, axis);
}

glm::dmat4 TransformGizmo::dragTo(const ScreenView& view, double px, double py, const GizmoSnap& snap)
{
    const glm::dmat4 identity(1.0);
    if (!dragging())
        return identity;
    // The drag is measured in the view it started in, so orbiting is not a move.
    (void)view;
    const Ray ray = m_dragView.ray(px, py);
    const model::Vec3 axis = gizmoAxis(m_dragHandle);
    const glm::dmat4 toPivot = glm::translate(identity, m_pivot);
    const glm::dmat4 fromPivot = glm::translate(identity, -m_pivot);

    if (m_mode == GizmoMode::Move) {
        model::Vec3 delta(0.0);
        if (m_dragHandle == GizmoHandle::Centre) {
            const model::Vec3 n = m_dragView.camera.forward();
            const double denom = glm::dot(n, ray.direction);
            if (std::abs(denom) > 1e-9) {
                const double t = glm::dot(n, m_pivot - ray.origin) / denom;
                delta = ray.origin + t * ray.direction - m_startPlanePoint;
            }
            if (snap.enabled)
                delta = {snapTo(delta.x, snap.step), snapTo(delta.y, snap.step), snapTo(delta.z, snap.step)};
        } else {
            double s = axisParameter(ray, axis) - m_startParameter;
            if (snap.enabled)
                s = snapTo(s, snap.step);
            delta = axis * s;
        }
        m_description =
            tr("Move by (%1, %2, %3) m").arg(delta.x, 0, 'g', 4).arg(delta.y, 0, 'g', 4).arg(delta.z, 0, 'g', 4);
        return glm::translate(identity, delta);
    }
    if (m_mode == GizmoMode::Rotate) {
        const auto angle = planeAngle(ray, axis);
        if (!angle)
            return identity;
        double degrees = std::remainder((*angle - m_startAngle) * 180.0 / M_PI, 360.0);
        if (snap.enabled)
            degrees = snapTo(degrees, snap.angleDegrees);
        m_description = tr("Rotate by %1° about %2").arg(degrees, 0, 'g', 4).arg(QLatin1String(axisName(m_dragHandle)));
        return toPivot * glm::rotate(identity, degrees * M_PI / 180.0, axis) * fromPivot;
    }
    // Scale: along an axis by the ratio of distances from the pivot, or
    // uniformly by the ratio of screen distances for the centre handle.
    double factor = 1.0;
    if (m_dragHandle == GizmoHandle::Centre) {
        const auto centre = m_dragView.toPixels(m_pivot);
        if (centre)
            factor = glm::length(glm::dvec2(px, py) - *centre) / m_startPixelDistance;
    } else if (std::abs(m_startParameter) > 1e-9) {
        factor = axisParameter(ray, axis) / m_startParameter;
    }
    if (snap.enabled)
        factor = snapTo(factor, snap.scaleStep);
    // A zero or negative factor would flatten or mirror the part.
    factor = std::max(factor, snap.enabled ? snap.scaleStep : 0.01);
    const model::Vec3 scale =
        m_dragHandle == GizmoHandle::Centre ? model::Vec3(factor) : model::Vec3(1.0) + axis * (factor - 1.0);
    m_description = tr("Scale by %1").arg(factor, 0, 'g', 4);
    return toPivot * glm::scale(identity, scale) * fromPivot;
}

} // namespace regio::editor
