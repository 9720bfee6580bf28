#pragma once
// The clip tool's three-point mode, as in level editors: the user clicks
// three points on surfaces; they define the cutting plane. This class holds
// the points and draws them; the viewport feeds it clicks.
#include "editor/viewport/overlay_lines.h"
#include "model/geometry/geometry.h"

#include <optional>
#include <vector>

namespace regio::editor {

class ClipTool {
public:
    void start()
    {
        m_points.clear();
        m_active = true;
    }
    void cancel()
    {
        m_points.clear();
        m_active = false;
    }
    bool active() const { return m_active; }
    const std::vector<model::Vec3>& points() const { return m_points; }

    // Adds a clicked point; returns the plane once three points that are not
    // collinear have been given (the tool then stops).
    std::optional<model::Plane> addPoint(const model::Vec3& point);

    // Crosses at the points given so far and the lines between them.
    LineList lines(double markerSize) const;

    // The plane through three points (normal by the right-hand rule a->b->c),
    // nullopt when they are (nearly) collinear.
    static std::optional<model::Plane> planeThrough(const model::Vec3& a, const model::Vec3& b, const model::Vec3& c);

private:
    std::vector<model::Vec3> m_points;
    bool m_active = false;
};

} // namespace regio::editor
