#pragma once
// The BSP figures and trees the BSP order dock shows (paper §5.3), computed by
// the solver's own preparation off the UI thread. Every document change
// restarts a short debounce; when it runs out the current scene is copied and
// prepared on a pool thread, twice: the author's regions (whose trees the
// dock and the fragment layer draw) and the single-BSP baseline. Changes that
// arrive while a run is busy start one more run when it ends, so a drag that
// edits the scene sixty times a second costs at most two preparations.
#include "model/diagnostic.h"
#include "model/scene.h"
#include "solver/authoring/bsp_figures.h"
#include "solver/prepare/prepared_scene.h"

#include <QFutureWatcher>
#include <QObject>
#include <QTimer>

#include <memory>
#include <optional>

namespace regio::editor {

class SceneDocument;

struct BspAnalysis {
    std::shared_ptr<const model::Scene> scene;       // the scene that was analysed
    std::optional<solver::SceneBspFigures> authored; // the scene's regions and orders
    std::optional<solver::SceneBspFigures> baseline; // one BSP tree, no regions
    // The authored preparation (BSP stage, coarse mesh): regions, trees, fragments.
    std::shared_ptr<const solver::PreparedScene> prepared;
    model::Diagnostics diagnostics; // of the authored preparation
    double milliseconds = 0.0;      // wall time of both preparations

    // The figures of one authored region, if the scene has it.
    const solver::RegionBspFigures* region(const std::string& regionId) const;
    // Index of the region in `prepared`, or -1.
    int preparedRegion(const std::string& regionId) const;
};

// Synchronous: what the worker runs.
BspAnalysis analyseBsp(model::Scene scene);

class BspAnalyser : public QObject {
    Q_OBJECT
public:
    explicit BspAnalyser(SceneDocument* document, QObject* parent = nullptr);
    ~BspAnalyser() override;

    // The newest finished analysis (empty figures before the first one).
    const BspAnalysis& current() const { return m_current; }
    // True while the shown analysis is older than the document.
    bool stale() const { return m_stale; }
    // Milliseconds of quiet before a change is analysed.
    void setDelay(int milliseconds) { m_debounce.setInterval(milliseconds); }
    // Analyses the current scene now, on this thread (first show, tests).
    void refreshNow();

signals:
    // A new analysis is current.
    void analysed();
    // The document changed; the shown figures are out of date until analysed().
    void becameStale();

private:
    void onChanged();
    void start();
    void onFinished();

    SceneDocument* m_document;
    QTimer m_debounce;
    QFutureWatcher<BspAnalysis> m_watcher;
    bool m_running = false;
    bool m_stale = true;
    // Document changes seen, the one the running worker copied, the one m_current shows.
    quint64 m_revision = 0, m_runningRevision = 0, m_currentRevision = 0;
    BspAnalysis m_current;
};

} // namespace regio::editor
