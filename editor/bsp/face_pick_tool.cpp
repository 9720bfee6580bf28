#include "editor/bsp/face_pick_tool.h"

#include "editor/document/scene_document.h"
#include "editor/viewport/viewport.h"

#include <QMouseEvent>

#include <algorithm>

namespace regio::editor {

namespace {
constexpr int kClickSlopPixels = 4;
}

FacePickTool::FacePickTool(const SceneDocument* document, PickHandler onPick, std::function<void()> onDeactivated,
                           bool once)
    : m_document(document)
    , m_onPick(std::move(onPick))
    , m_onDeactivated(std::move(onDeactivated))
    , m_once(once)
{
}

std::optional<PickHit> FacePickTool::pickAt(const Viewport& viewport, const model::Scene& scene, const QPoint& pos)
{
    const Ray ray = viewport.screenView().ray(pos.x(), pos.y());
    const bool ignoreBack = viewport.cullBackFaces() && viewport.shading() != ShadingMode::Wireframe;
    return pickFace(scene, ray, ignoreBack);
}

bool FacePickTool::mousePress(Viewport&, QMouseEvent* event)
{
    if (event->button() != Qt::LeftButton || event->modifiers() != Qt::NoModifier)
        return false;
    m_pressed = true;
    m_pressPos = event->position().toPoint();
    return true;
}

bool FacePickTool::mouseRelease(Viewport& viewport, QMouseEvent* event)
{
    if (event->button() != Qt::LeftButton || !m_pressed)
        return false;
    m_pressed = false;
    const QPoint pos = event->position().toPoint();
    if ((pos - m_pressPos).manhattanLength() > kClickSlopPixels)
        return true;
    const auto hit = pickAt(viewport, m_document->scene(), pos);
    if (!hit)
        return true;
    // Handing the hit over may drop this tool (and with `once` it does).
    PickHandler handler = m_onPick;
    if (m_once)
        viewport.setTool(nullptr);
    handler(*hit);
    return true;
}

void FacePickTool::deactivated()
{
    m_pressed = false;
    if (m_onDeactivated)
        m_onDeactivated();
}

model::Vec3 eyeAbovePick(const PickHit& hit, double sceneSize)
{
    const double nudge = std::max(1e-3, sceneSize * 1e-4);
    const model::Vec3 towardsViewer = hit.backFacing ? -hit.normal : hit.normal;
    return hit.point + nudge * towardsViewer;
}

} // namespace regio::editor
