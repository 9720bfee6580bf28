#include "editor/viewport/camera.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>

namespace regio::editor {

namespace {

constexpr double kMinDistance = 1e-3;
constexpr double kMaxPitch = 89.0;

double radians(double degrees) { return degrees * M_PI / 180.0; }
double degrees(double radians) { return radians * 180.0 / M_PI; }

// Direction from the target to the eye.
model::Vec3 backward(double yaw, double pitch)
{
    const double y = radians(yaw), p = radians(pitch);
    return {std::cos(p) * std::sin(y), std::sin(p), std::cos(p) * std::cos(y)};
}

} // namespace

model::Vec3 Camera::eye() const { return m_target + m_distance * backward(m_yaw, m_pitch); }
model::Vec3 Camera::forward() const { return -backward(m_yaw, m_pitch); }

model::Vec3 Camera::up() const
{
    // d(backward)/d(pitch): well defined at the poles, unlike world-up x forward.
    const double y = radians(m_yaw), p = radians(m_pitch);
    return {-std::sin(p) * std::sin(y), std::cos(p), -std::sin(p) * std::cos(y)};
}

model::Vec3 Camera::right() const { return glm::normalize(glm::cross(forward(), up())); }

glm::dmat4 Camera::viewMatrix() const { return glm::lookAt(eye(), m_target, up()); }

double Camera::nearPlane() const { return std::max(1e-4, std::min(m_distance * 0.01, 0.05 * m_sceneRadius + 1e-3)); }

double Camera::farPlane() const { return m_distance * 4.0 + m_sceneRadius * 8.0 + 10.0; }

glm::dmat4 Camera::projectionMatrix(double aspect) const
{
    aspect = aspect > 0.0 ? aspect : 1.0;
    if (m_orthographic) {
        const double h = m_distance * std::tan(radians(m_fovY) * 0.5);
        // Ortho keeps the eye where it is but sees behind it too: the depth
        // range spans the whole scene around the target.
        const double depth = m_distance + m_sceneRadius * 4.0 + 10.0;
        return glm::ortho(-h * aspect, h * aspect, -h, h, -depth, depth);
    }
    return glm::perspective(radians(m_fovY), aspect, nearPlane(), farPlane());
}

void Camera::orbit(double deltaYaw, double deltaPitch)
{
    m_yaw = std::remainder(m_yaw + deltaYaw, 360.0);
    m_pitch = std::clamp(m_pitch + deltaPitch, -kMaxPitch, kMaxPitch);
}

void Camera::pan(double dxNdc, double dyNdc)
{
    // The point under the cursor stays under it: the scene follows the mouse.
    m_target -= (dxNdc * right() + dyNdc * up()) * worldPerNdcAtTarget();
}

void Camera::zoom(double factor)
{
    if (!(factor > 0.0) || !std::isfinite(factor))
        return;
    m_distance = std::clamp(m_distance * factor, kMinDistance, 1e7);
}

void Camera::fly(const model::Vec3& v) { m_target += v.x * right() + v.y * up() + v.z * forward(); }

void Camera::look(double deltaYaw, double deltaPitch)
{
    const model::Vec3 eyeBefore = eye();
    orbit(deltaYaw, deltaPitch);
    m_target = eyeBefore - m_distance * backward(m_yaw, m_pitch);
}

void Camera::frame(const model::Box3& box, double aspect)
{
    if (box.empty)
        return;
    m_target = box.center();
    const double radius = std::max(0.5 * glm::length(box.size()), 0.05);
    const double halfFovY = radians(m_fovY) * 0.5;
    const double halfFovX = std::atan(std::tan(halfFovY) * (aspect > 0.0 ? aspect : 1.0));
    const double halfFov = std::min(halfFovY, halfFovX);
    m_distance = radius / std::sin(halfFov) * 1.02;
    m_sceneRadius = std::max(m_sceneRadius, radius);
}

void Camera::setStandardView(StandardView view)
{
    switch (view) {
    case StandardView::Front:
        m_yaw = 0;
        m_pitch = 0;
        break;
    case StandardView::Back:
        m_yaw = 180;
        m_pitch = 0;
        break;
    case StandardView::Right:
        m_yaw = 90;
        m_pitch = 0;
        break;
    case StandardView::Left:
        m_yaw = -90;
        m_pitch = 0;
        break;
    case StandardView::Top:
        m_yaw = 0;
        m_pitch = 90;
        break;
    case StandardView::Bottom:
        m_yaw = 0;
        m_pitch = -90;
        break;
    case StandardView::Iso:
        m_yaw = 35;
        m_pitch = 30;
        break;
    }
}

void Camera::setFovY(double fov) { m_fovY = std::clamp(fov, 5.0, 150.0); }

void Camera::setFromSceneCamera(const model::Camera& camera)
{
    const model::Vec3 offset = camera.position - camera.target;
    const double length = glm::length(offset);
    if (!(length > kMinDistance) || !std::isfinite(length))
        return;
    m_target = camera.target;
    m_distance = length;
    const model::Vec3 b = offset / length;
    m_pitch = std::clamp(degrees(std::asin(std::clamp(b.y, -1.0, 1.0))), -kMaxPitch, kMaxPitch);
    m_yaw = degrees(std::atan2(b.x, b.z));
    setFovY(camera.fovY);
    m_orthographic = false;
}

model::Camera Camera::toSceneCamera() const
{
    model::Camera c;
    c.position = eye();
    c.target = m_target;
    c.up = {0.0, 1.0, 0.0};
    c.fovY = m_fovY;
    return c;
}

void Camera::setTargetAndDistance(const model::Vec3& target, double distance)
{
    m_target = target;
    m_distance = std::max(distance, kMinDistance);
}

Ray Camera::rayThrough(const glm::dvec2& ndc, double aspect) const
{
    const glm::dmat4 inverse = glm::inverse(projectionMatrix(aspect) * viewMatrix());
    glm::dvec4 nearPoint = inverse * glm::dvec4(ndc.x, ndc.y, -1.0, 1.0);
    glm::dvec4 farPoint = inverse * glm::dvec4(ndc.x, ndc.y, 1.0, 1.0);
    const model::Vec3 a = model::Vec3(nearPoint) / nearPoint.w;
    const model::Vec3 b = model::Vec3(farPoint) / farPoint.w;
    return {a, glm::normalize(b - a)};
}

glm::dvec3 Camera::project(const model::Vec3& world, double aspect) const
{
    const glm::dvec4 clip = projectionMatrix(aspect) * viewMatrix() * glm::dvec4(world, 1.0);
    if (std::abs(clip.w) < 1e-12)
        return {0.0, 0.0, 2.0};
    return glm::dvec3(clip) / clip.w;
}

double Camera::worldPerNdcAtTarget() const { return m_distance * std::tan(radians(m_fovY) * 0.5); }

glm::dvec2 ScreenView::toNdc(double px, double py) const { return {2.0 * px / width - 1.0, 1.0 - 2.0 * py / height}; }

std::optional<glm::dvec2> ScreenView::toPixels(const model::Vec3& world) const
{
    if (!camera.orthographic() && glm::dot(world - camera.eye(), camera.forward()) <= 0.0)
        return std::nullopt;
    const glm::dvec3 ndc = camera.project(world, aspect());
    return glm::dvec2((ndc.x + 1.0) * 0.5 * width, (1.0 - ndc.y) * 0.5 * height);
}

Ray ScreenView::ray(double px, double py) const { return camera.rayThrough(toNdc(px, py), aspect()); }

double ScreenView::worldPerPixelAt(const model::Vec3& p) const
{
    const double depth =
        camera.orthographic() ? camera.distance() : std::max(glm::dot(p - camera.eye(), camera.forward()), 1e-6);
    return 2.0 * depth * std::tan(radians(camera.fovYDegrees()) * 0.5) / std::max(height, 1.0);
}

} // namespace regio::editor
