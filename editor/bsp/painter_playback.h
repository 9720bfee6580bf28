#pragma once
// Painter-order playback (paper §5.6, Appendix A): from a point picked in the
// viewport, or from a patch as the solver shoots it, the elements in the
// back-to-front order the painter's hemicube paints them, replayed step by
// step (a slider, or a timer) or shown at once as a colour ramp. The order is
// solver::painterOrder on the scene prepared exactly as the solver prepares
// it (the scene's patch size, elements per patch and regions mode), so the
// sequence is the solver's traversal, element for element, on the mesh
// before adaptive subdivision (§5.7) splits any element; its splits (along
// contact lines before the first shot, at shadow borders later) change the
// elements painted, not the order of the BSP nodes.
#include "solver/prepare/prepared_scene.h"
#include "solver/visibility/painter_order.h"

#include <QObject>
#include <QPointer>
#include <QTimer>

#include <memory>
#include <optional>

namespace regio::editor {

class SceneDocument;
class Viewport;

class PainterPlayback : public QObject {
    Q_OBJECT
public:
    PainterPlayback(SceneDocument* document, Viewport* viewport, QObject* parent = nullptr);
    ~PainterPlayback() override;

    // The solver's preparation of the current scene (made on first use and
    // after every change); nullptr when the scene cannot be prepared.
    std::shared_ptr<const solver::PreparedScene> prepared();

    // Starts a playback from a free point (nothing culled) or from a patch of
    // prepared() (the hemicube at its centroid, regions behind it culled).
    // False when the scene cannot be prepared or the patch does not exist.
    bool startFromPoint(const model::Vec3& eye);
    bool startFromPatch(int patch);
    // The patch of prepared() on `faceId` nearest to `point`, or -1.
    int patchAt(const std::string& faceId, const model::Vec3& point);
    // Ends the playback and removes its layers.
    void stop();

    bool active() const { return m_order.has_value(); }
    const solver::PainterOrder* order() const { return m_order ? &*m_order : nullptr; }
    model::Vec3 eye() const { return m_eye; }
    int patch() const { return m_patch; }
    int stepCount() const { return m_order ? int(m_order->steps.size()) : 0; }
    // Elements painted so far (0..stepCount); the ramp shows them all.
    int step() const { return m_step; }
    void setStep(int step);
    bool playing() const { return m_timer.isActive(); }
    void play();
    void pause();
    // Steps per second while playing; elements per tick grow with the count
    // so a long sequence still plays in about ten seconds.
    void setSpeed(int stepsPerSecond);

    static QString layerName();
    static QString markerLayerName();

signals:
    void changed();

private:
    void advance();
    void updateLayers();

    SceneDocument* m_document;
    QPointer<Viewport> m_viewport; // destroyed first when the window closes
    std::shared_ptr<const solver::PreparedScene> m_prepared;
    bool m_preparedValid = false;
    std::optional<solver::PainterOrder> m_order;
    model::Vec3 m_eye{0.0};
    int m_patch = -1;
    int m_step = 0;
    int m_stepsPerSecond = 0; // 0 = about ten seconds for the whole sequence
    QTimer m_timer;
};

} // namespace regio::editor
