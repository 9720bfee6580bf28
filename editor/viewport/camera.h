#pragma once
// The viewport's orbit camera: a target point, a distance and two angles.
// Orbit, pan, zoom and framing move it; fly mode moves the eye and drags the
// target along. Pure maths (no GL, no widgets) so tests can check it.
#include "model/geometry/geometry.h"
#include "model/scene.h"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include <optional>

namespace regio::editor {

enum class StandardView { Front, Back, Left, Right, Top, Bottom, Iso };

struct Ray {
    model::Vec3 origin;
    model::Vec3 direction; // unit length
};

class Camera {
public:
    model::Vec3 target() const { return m_target; }
    double distance() const { return m_distance; }
    double yawDegrees() const { return m_yaw; }
    double pitchDegrees() const { return m_pitch; }
    double fovYDegrees() const { return m_fovY; }
    bool orthographic() const { return m_orthographic; }

    model::Vec3 eye() const;
    // Unit vectors of the view.
    model::Vec3 forward() const;
    model::Vec3 right() const;
    model::Vec3 up() const;

    glm::dmat4 viewMatrix() const;
    glm::dmat4 projectionMatrix(double aspect) const;

    // Rotates about the target (degrees); pitch stays within the poles.
    void orbit(double deltaYaw, double deltaPitch);
    // Moves target and eye in the view plane so the scene follows a cursor
    // that moved by (dx, dy) in normalised device coordinates.
    void pan(double dxNdc, double dyNdc);
    // factor < 1 moves closer; the distance never reaches zero.
    void zoom(double factor);
    // Fly mode: moves eye and target by a vector in view space (right, up, forward).
    void fly(const model::Vec3& viewSpaceMove);
    // Fly mode: turns the view about the eye (degrees).
    void look(double deltaYaw, double deltaPitch);

    // Places the camera so `box` fills the view at the given aspect ratio,
    // keeping the current direction.
    void frame(const model::Box3& box, double aspect);
    void setStandardView(StandardView view);
    void setOrthographic(bool on) { m_orthographic = on; }
    void setFovY(double degrees);
    // Adopts a scene's stored camera (eye, target, field of view).
    void setFromSceneCamera(const model::Camera& camera);
    model::Camera toSceneCamera() const;
    void setTargetAndDistance(const model::Vec3& target, double distance);

    // The ray through a point given in normalised device coordinates
    // (x, y in [-1, 1], y up).
    Ray rayThrough(const glm::dvec2& ndc, double aspect) const;
    // Projects a world point to NDC; z < -1 or > 1 when outside the depth range.
    glm::dvec3 project(const model::Vec3& world, double aspect) const;
    // World size of one NDC unit of height at the target's depth: how far a
    // pan or a gizmo drag moves per unit of mouse travel.
    double worldPerNdcAtTarget() const;

    // Near and far planes follow the distance so zooming never clips the scene.
    double nearPlane() const;
    double farPlane() const;
    void setSceneRadius(double radius) { m_sceneRadius = radius; }

private:
    model::Vec3 m_target{0.0};
    double m_distance = 5.0;
    double m_yaw = 30.0;   // degrees about +y; 0 looks along -z
    double m_pitch = 25.0; // degrees above the horizon
    double m_fovY = 45.0;
    bool m_orthographic = false;
    double m_sceneRadius = 5.0;
};

// A camera seen through a viewport of a given size in pixels (y down, as in
// mouse events): conversions between pixels, NDC and world.
struct ScreenView {
    Camera camera;
    double width = 1.0;
    double height = 1.0;

    double aspect() const { return height > 0.0 ? width / height : 1.0; }
    glm::dvec2 toNdc(double px, double py) const;
    // Pixel position of a world point; nullopt when behind the eye.
    std::optional<glm::dvec2> toPixels(const model::Vec3& world) const;
    Ray ray(double px, double py) const;
    // World length of one pixel at the depth of `p`.
    double worldPerPixelAt(const model::Vec3& p) const;
};

} // namespace regio::editor
