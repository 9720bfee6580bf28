#include "editor/bsp/painter_playback.h"

#include "editor/bsp/bsp_layers.h"
#include "editor/document/scene_document.h"
#include "editor/viewport/viewport.h"
#include "solver/prepare/prepare.h"
#include "solver/settings.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <limits>

namespace regio::editor {

namespace {
constexpr int kTickMilliseconds = 40;
}

PainterPlayback::PainterPlayback(SceneDocument* document, Viewport* viewport, QObject* parent)
    : QObject(parent)
    , m_document(document)
    , m_viewport(viewport)
{
    m_timer.setInterval(kTickMilliseconds);
    connect(&m_timer, &QTimer::timeout, this, &PainterPlayback::advance);
    // Any change makes the order meaningless: the mesh it indexes is gone.
    for (auto signal : {&SceneDocument::objectsChanged, &SceneDocument::geometryChanged, &SceneDocument::regionsChanged,
                        &SceneDocument::settingsChanged, &SceneDocument::materialsChanged, &SceneDocument::sceneReset})
        connect(document, signal, this, [this] {
            m_preparedValid = false;
            m_prepared.reset();
            if (active())
                stop();
        });
}

PainterPlayback::~PainterPlayback() = default;

QString PainterPlayback::layerName() { return QStringLiteral("bsp.playback"); }
QString PainterPlayback::markerLayerName() { return QStringLiteral("bsp.playback.marker"); }

std::shared_ptr<const solver::PreparedScene> PainterPlayback::prepared()
{
    if (!m_preparedValid) {
        const model::Scene& scene = m_document->scene();
        // The preparation the solver runs (Solver::create): the scene's settings.
        model::Result<solver::PreparedScene> result =
            solver::prepareScene(scene, solver::prepareOptionsFor(solver::resolveSettings(scene.solver)));
        m_prepared = result ? std::make_shared<const solver::PreparedScene>(std::move(*result)) : nullptr;
        m_preparedValid = true;
    }
    return m_prepared;
}

bool PainterPlayback::startFromPoint(const model::Vec3& eye)
{
    const auto scene = prepared();
    if (!scene)
        return false;
    m_eye = eye;
    m_patch = -1;
    m_order = solver::painterOrder(*scene, eye);
    m_step = stepCount();
    updateLayers();
    emit changed();
    return true;
}

bool PainterPlayback::startFromPatch(int patch)
{
    const auto scene = prepared();
    if (!scene || patch < 0 || size_t(patch) >= scene->patches.size())
        return false;
    m_patch = patch;
    m_eye = scene->patches[size_t(patch)].centroid;
    m_order = solver::painterOrderFromPatch(*scene, patch);
    m_step = stepCount();
    updateLayers();
    emit changed();
    return true;
}

int PainterPlayback::patchAt(const std::string& faceId, const model::Vec3& point)
{
    const auto scene = prepared();
    if (!scene)
        return -1;
    // The patch whose triangle holds the point; failing that (a point on an
    // edge, rounding), the patch of that face with the nearest centroid.
    int best = -1;
    double bestDistance = std::numeric_limits<double>::max();
    for (size_t i = 0; i < scene->patches.size(); ++i) {
        const solver::Patch& p = scene->patches[i];
        if (scene->faces[size_t(scene->properties[size_t(p.properties)].face)].id != faceId)
            continue;
        const model::Vec3& a = scene->vertices[size_t(p.vertices[0])];
        const model::Vec3& b = scene->vertices[size_t(p.vertices[1])];
        const model::Vec3& c = scene->vertices[size_t(p.vertices[2])];
        const model::Vec3 n = glm::cross(b - a, c - a);
        const bool inside = glm::dot(glm::cross(b - a, point - a), n) >= 0.0 &&
                            glm::dot(glm::cross(c - b, point - b), n) >= 0.0 &&
                            glm::dot(glm::cross(a - c, point - c), n) >= 0.0;
        if (inside)
            return int(i);
        const double d = glm::length(p.centroid - point);
        if (d < bestDistance) {
            bestDistance = d;
            best = int(i);
        }
    }
    return best;
}

void PainterPlayback::stop()
{
    m_timer.stop();
    m_order.reset();
    m_step = 0;
    m_patch = -1;
    if (m_viewport) {
        m_viewport->removeLayer(layerName());
        m_viewport->removeLayer(markerLayerName());
    }
    emit changed();
}

void PainterPlayback::setStep(int step)
{
    step = std::clamp(step, 0, stepCount());
    if (step == m_step)
        return;
    m_step = step;
    updateLayers();
    emit changed();
}

void PainterPlayback::play()
{
    if (!active())
        return;
    if (m_step >= stepCount())
        setStep(0);
    m_timer.start();
    emit changed();
}

void PainterPlayback::pause()
{
    m_timer.stop();
    emit changed();
}

void PainterPlayback::setSpeed(int stepsPerSecond) { m_stepsPerSecond = std::max(0, stepsPerSecond); }

void PainterPlayback::advance()
{
    const int perSecond = m_stepsPerSecond > 0 ? m_stepsPerSecond : std::max(1, stepCount() / 10);
    const int perTick = std::max(1, perSecond * kTickMilliseconds / 1000);
    setStep(m_step + perTick);
    if (m_step >= stepCount())
        pause();
}

void PainterPlayback::updateLayers()
{
    if (!m_order || !m_prepared || !m_viewport)
        return;
    m_viewport->setLayer(layerName(), buildPainterLayer(*m_prepared, *m_order, m_step));
    m_viewport->setLayer(markerLayerName(), buildPainterMarkerLayer(*m_prepared, *m_order, m_step, m_eye));
}

} // namespace regio::editor
