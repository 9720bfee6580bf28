#pragma once
// The region tool (paper §5.2: regions are axis-aligned boxes the author
// places). While it is the viewport's tool:
//  - a left drag draws the footprint of a new box on a horizontal plane: the
//    top of the horizontal face under the cursor, else the ground grid (y = 0);
//    the box's height spans the scene's extent above (or below) that plane.
//    Corners snap to the grid step when snapping is on. Release: one undo step
//    (AddRegion), and the new region is selected.
//  - the selected region shows six face handles; dragging one moves that face
//    along its axis (snapped), one undo step per drag (ResizeRegionByHandle).
//  - a click without dragging selects the region whose box the cursor ray
//    enters first (or clears a region selection).
//  - Esc cancels a drawing; otherwise it drops the tool.
// Middle-button and Alt navigation keep working.
#include "editor/viewport/camera.h"
#include "editor/viewport/viewport_tool.h"
#include "model/geometry/geometry.h"

#include <QObject>
#include <QPointF>
#include <QPointer>

#include <optional>
#include <string>

namespace regio::editor {

class SceneDocument;
class Viewport;
struct GizmoSnap;

class RegionBoxTool : public QObject, public ViewportTool {
    Q_OBJECT
public:
    RegionBoxTool(SceneDocument* document, Viewport* viewport, QObject* parent = nullptr);
    ~RegionBoxTool() override;

    // Makes this the viewport's tool (or drops it).
    void setActive(bool on);
    bool isActive() const;

    bool mousePress(Viewport& viewport, QMouseEvent* event) override;
    bool mouseMove(Viewport& viewport, QMouseEvent* event) override;
    bool mouseRelease(Viewport& viewport, QMouseEvent* event) override;
    bool keyPress(Viewport& viewport, QKeyEvent* event) override;
    void deactivated() override;

    // The box being drawn, if a drawing is under way.
    std::optional<model::Box3> draft() const;
    // The handle (0..5, see handlePosition) of the selected region within a
    // few pixels of (px, py), or -1.
    int handleAt(double px, double py) const;
    // The single selected region, or nullptr.
    const model::Region* selectedRegion() const;

    // A coordinate snapped to the grid (unchanged when snapping is off).
    static double snapped(double value, const GizmoSnap& snap);
    // Parameter t of the point of the line origin + t * axis nearest to the
    // ray; nullopt when the ray runs (almost) along the line.
    static std::optional<double> lineParameter(const model::Vec3& origin, const model::Vec3& axis, const Ray& ray);

signals:
    void activeChanged(bool active);
    void statusMessage(const QString& message);

private:
    enum class State { Idle, Pressed, Drawing, Resizing };

    std::optional<model::Vec3> planePoint(const Ray& ray) const;
    model::Box3 boxFromFootprint(const model::Vec3& a, const model::Vec3& b) const;
    void updateHandles();
    void updateDraftLayer();
    void finishDrawing();
    void selectRegionAt(double px, double py);

    SceneDocument* m_document;
    QPointer<Viewport> m_viewport; // may go before the tool when a window closes
    State m_state = State::Idle;
    QPointF m_pressPos;
    // Drawing: the plane height and the footprint corners.
    double m_planeY = 0.0;
    model::Vec3 m_start{0.0}, m_end{0.0};
    bool m_startValid = false;
    // Resizing.
    int m_handle = -1;
    int m_hoverHandle = -1;
    std::string m_regionId;
    model::Box3 m_startBox;
    double m_startParameter = 0.0;
    int m_dragSerial = 0;
};

} // namespace regio::editor
