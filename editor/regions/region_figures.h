#pragma once
// What each region holds and what it costs, for the Regions dock. Contents
// (parts and faces in a box) follow validation's rule for "a face is in the
// region" (model/geometry/region_clip.h); fragments are the solver's own figures
// (solver/authoring/bsp_figures.h, equal to `regio-solve solve --report`), computed on
// a worker thread from a snapshot of the scene, a short pause after the
// last edit, so dragging a box never waits for the BSP build.
#include "model/scene.h"
#include "solver/authoring/bsp_figures.h"

#include <QObject>
#include <QTimer>

#include <optional>
#include <vector>

class QThread;

namespace regio::editor {

class SceneDocument;

struct RegionContents {
    int parts = 0; // parts with at least one face in the box
    int faces = 0; // faces with area inside the box
    bool operator==(const RegionContents&) const = default;
};
// One entry per region of the scene, in scene order.
std::vector<RegionContents> regionContents(const model::Scene& scene);

class RegionFiguresWatcher : public QObject {
    Q_OBJECT
public:
    explicit RegionFiguresWatcher(SceneDocument* document, QObject* parent = nullptr);
    ~RegionFiguresWatcher() override;

    // The newest figures: the authored regions beside the single-BSP
    // baseline. Empty before the first computation finished.
    const std::optional<solver::BspComparison>& comparison() const { return m_comparison; }
    // True while an edit has not been reflected yet (waiting or computing).
    bool stale() const;
    // Starts a computation now instead of after the pause.
    void recomputeNow();
    // Tests: runs the event loop until the figures are current.
    bool waitUntilCurrent(int timeoutMs = 30000);
    void setDelay(int milliseconds) { m_debounce.setInterval(milliseconds); }

signals:
    void figuresChanged();
    void staleChanged(bool stale);

private:
    void schedule();
    void start();

    SceneDocument* m_document;
    QTimer m_debounce;
    QThread* m_thread = nullptr;
    bool m_rerun = false;
    std::optional<solver::BspComparison> m_comparison;
};

} // namespace regio::editor
