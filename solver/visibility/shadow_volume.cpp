#include "solver/visibility/shadow_volume.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace regio::solver {

namespace {
constexpr double kBehindMargin = 1e-6; // metres behind the occluder's plane
constexpr double kEdgeMargin = 1e-5;   // radians inside the occluder's edges
// Metres the occluder's edges are moved inwards first: its pieces meet its
// outline to within the builders' epsilon (model::kDistanceEpsilon), and a
// ray that passes that close to an edge may miss them.
constexpr double kInset = 10.0 * model::kDistanceEpsilon;
} // namespace

ShadowVolume::ShadowVolume(const Vec3& eye, const Occluder& hider, const Plane& shooterPlane)
    : m_eye(eye)
{
    const std::span<const Vec3> occluder = hider.polygon;
    const Vec3& front = hider.front;
    if (occluder.size() < 3)
        return;
    m_plane = Plane::fromPointNormal(occluder[0], front);
    if (m_plane.signedDistance(eye) <= kBehindMargin)
        return;
    for (const Vec3& corner : occluder)
        if (shooterPlane.signedDistance(corner) <= kBehindMargin)
            return;
    // Seen from the eye, walking the polygon counter-clockwise, each edge's
    // plane through the eye has the polygon on the side of (b - eye) x (a - eye).
    const bool counterClockwise = glm::dot(model::newellNormal(occluder), front) > 0.0;
    const size_t n = occluder.size();
    for (size_t i = 0; i < n; ++i) {
        Vec3 a = occluder[counterClockwise ? i : n - 1 - i];
        Vec3 b = occluder[counterClockwise ? (i + 1) % n : (2 * n - 2 - i) % n];
        const Vec3 along = b - a;
        if (glm::length(along) <= 2.0 * kInset) {
            m_edges.clear();
            return;
        }
        const Vec3 inset = kInset * glm::normalize(glm::cross(front, along)); // into the polygon
        a += inset;
        b += inset;
        const Vec3 inward = glm::cross(b - eye, a - eye);
        const double length = glm::length(inward);
        if (length <= 0.0) {
            m_edges.clear();
            return;
        }
        m_edges.push_back(inward / length);
    }
}

bool ShadowVolume::hides(const Vec3& p) const
{
    if (m_edges.empty() || m_plane.signedDistance(p) >= -kBehindMargin)
        return false;
    const Vec3 d = p - m_eye;
    // The L1 norm bounds the length from above: the margin only grows.
    const double margin = kEdgeMargin * (std::abs(d.x) + std::abs(d.y) + std::abs(d.z));
    for (const Vec3& inward : m_edges)
        if (glm::dot(inward, d) <= margin)
            return false;
    return true;
}

bool ShadowVolume::hides(const Box3& box) const
{
    if (m_edges.empty() || box.empty)
        return false;
    for (int c = 0; c < 8; ++c) {
        const Vec3 corner{c & 1 ? box.max.x : box.min.x, c & 2 ? box.max.y : box.min.y, c & 4 ? box.max.z : box.min.z};
        if (!hides(corner))
            return false;
    }
    return true;
}

} // namespace regio::solver
