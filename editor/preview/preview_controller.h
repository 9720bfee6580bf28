#pragma once
// The radiosity preview inside the editor: the glue between the
// document, the preview runner, the viewport's layers and the preview's
// docks, menus and status bar. MainWindow creates one and asks it to fill
// the Solve menu and toolbar; everything else lives here and in the files
// it names.
//
//   runner (worker threads)  --frame-->  layer job (pool thread)  --layers-->  viewport
//   document changes  -->  stale, and with "live" a new solve after a pause in editing
#include "editor/preview/preview_display.h"
#include "editor/preview/preview_runner.h"

#include <QObject>
#include <QPointer>
#include <QThreadPool>
#include <QTimer>

#include <memory>
#include <optional>

class QAction;
class QLabel;
class QProgressBar;
class QMainWindow;
class QMenu;
class QToolBar;

namespace regio::editor {

class ConvergenceDock;
class HemicubeDialog;
class PreviewInspector;
class SceneDocument;
class SolverDock;
class Viewport;

class PreviewController : public QObject {
    Q_OBJECT
public:
    PreviewController(SceneDocument* document, Viewport* viewport, QMainWindow* window, bool interactive);
    ~PreviewController() override;

    void populateMenu(QMenu* menu);
    void populateToolBar(QToolBar* toolBar);

    PreviewRunner* runner() const { return m_runner; }
    SolverDock* solverDock() const { return m_dock; }
    // Solve > Continue: enabled when a solve stopped short of convergence.
    QAction* continueAction() const { return m_actions.continueSolve; }
    // How far the solve is, 0..100 (the larger of the shots against the
    // limit and the unshot power's way down to the target, on a log scale);
    // -1 while preparing (no measure yet).
    int progressPercent() const;
    ConvergenceDock* convergenceDock() const { return m_convergence; }
    PreviewInspector* inspector() const { return m_inspector.get(); }

    // Solves the document's scene now (Run).
    void run();
    // Exactly `iterations` shots, as `regio-solve solve --iterations N`
    // (--preview-iterations, tests).
    void runIterations(int iterations);
    bool live() const;
    void setLive(bool on);
    // Milliseconds without edits before a live preview re-solves.
    void setLiveDelay(int ms);
    void setDisplay(const PreviewDisplay& display);
    const PreviewDisplay& display() const;

    // Serial of the frame the viewport layers were last built from (0 = none).
    int layersSerial() const { return m_appliedSerial; }
    // The viewport shows the newest frame (its layers are built and set).
    bool layersCurrent() const { return m_appliedSerial > 0 && m_appliedSerial == m_frameSerial; }
    QString statusText() const;

    // Exports (Solve menu); each returns an error message or nothing.
    std::optional<QString> exportLitModel(const QString& path) const;
    std::optional<QString> exportViewportImage(const QString& path) const;
    // Writes the scene with the final preset's settings; `command` receives
    // the regio-solve command line that solves it like the preview.
    std::optional<QString> exportForBatch(const QString& path, QString* command) const;

signals:
    // The viewport shows the layers of a new frame (or none after reset).
    void layersApplied();
    void statusChanged(const QString& text);

private:
    void createActions();
    void onSceneChanged();
    void onSceneReset();
    void onFrame();
    void onState(PreviewState state);
    void scheduleLayers();
    void applyLayers(int generation, int serial, std::shared_ptr<PreviewLayers> layers);
    void clearLayers();
    void updateStatus();
    void updateActions();
    void showDryRun();
    void showHemicube();
    void chooseExportModel();
    void chooseExportImage();
    void chooseExportBatch();

    SceneDocument* m_document;
    QPointer<Viewport> m_viewport; // destroyed before us when the window closes
    QMainWindow* m_window;
    bool m_interactive;
    PreviewRunner* m_runner;
    SolverDock* m_dock = nullptr;
    ConvergenceDock* m_convergence = nullptr;
    std::unique_ptr<PreviewInspector> m_inspector;
    QPointer<HemicubeDialog> m_hemicubeDialog;
    QLabel* m_status = nullptr;
    QProgressBar* m_progress = nullptr;
    QTimer m_debounce;
    QTimer m_statusTimer;

    // Layer building off the UI thread: one job at a time, the newest wins.
    QThreadPool m_pool;
    bool m_jobRunning = false;
    bool m_jobPending = false;
    int m_generation = 0;
    int m_frameSerial = 0;
    int m_appliedSerial = 0;
    std::shared_ptr<const PreviewFrame> m_shownFrame;
    int m_inspectedPatch = -1;

    struct {
        QAction *run, *continueSolve, *pause, *stop, *reset, *live, *dryRun, *inspect, *hemicube;
        QAction *draft, *normal, *final;
        QAction *exportModel, *exportImage, *exportBatch;
    } m_actions{};
};

} // namespace regio::editor
