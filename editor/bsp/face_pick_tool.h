#pragma once
// A viewport tool that turns a left click on a face into a PickHit for its
// owner (insert the face into a BSP order, start a painter-order playback
// there). It picks exactly as the viewport selects: the same ray, and faces
// seen from behind are transparent when the viewport hides back faces.
// Dragging with the left button, and every other button, still moves the camera.
#include "editor/viewport/picking.h"
#include "editor/viewport/viewport_tool.h"

#include <QPoint>

#include <functional>

namespace regio::editor {

class SceneDocument;

class FacePickTool : public ViewportTool {
public:
    using PickHandler = std::function<void(const PickHit&)>;

    // `once`: the tool drops itself after the first face picked.
    FacePickTool(const SceneDocument* document, PickHandler onPick, std::function<void()> onDeactivated = {},
                 bool once = false);

    bool mousePress(Viewport& viewport, QMouseEvent* event) override;
    bool mouseRelease(Viewport& viewport, QMouseEvent* event) override;
    void deactivated() override;

    // The face under a viewport pixel, as this tool sees it.
    static std::optional<PickHit> pickAt(const Viewport& viewport, const model::Scene& scene, const QPoint& pos);

private:
    const SceneDocument* m_document;
    PickHandler m_onPick;
    std::function<void()> m_onDeactivated;
    bool m_once;
    bool m_pressed = false;
    QPoint m_pressPos;
};

// The point a playback starts from: the hit nudged off the surface, towards
// the side the ray came from, so the eye is strictly in front of the face
// that was clicked (never on its plane, where front and back are undecided).
model::Vec3 eyeAbovePick(const PickHit& hit, double sceneSize);

} // namespace regio::editor
