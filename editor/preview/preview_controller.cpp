#include "editor/preview/preview_controller.h"

#include "editor/app/image_file.h"

#include "editor/document/scene_document.h"
#include "editor/preview/convergence_plot.h"
#include "editor/preview/hemicube_dialog.h"
#include "editor/preview/preview_export.h"
#include "editor/preview/preview_inspector.h"
#include "editor/preview/solver_dock.h"
#include "editor/preview/solver_presets.h"
#include "editor/viewport/viewport.h"

#include <QAction>
#include <QApplication>
#include <QClipboard>
#include <QFileDialog>
#include <QFileInfo>
#include <QImage>
#include <QInputDialog>
#include <QLabel>
#include <QMainWindow>
#include <QMenu>
#include <QMessageBox>
#include <QProgressBar>
#include <QStatusBar>
#include <QToolBar>

#include <algorithm>

namespace regio::editor {

PreviewController::PreviewController(SceneDocument* document, Viewport* viewport, QMainWindow* window, bool interactive)
    : QObject(window)
    , m_document(document)
    , m_viewport(viewport)
    , m_window(window)
    , m_interactive(interactive)
    , m_runner(new PreviewRunner(this))
{
    m_pool.setMaxThreadCount(1);
    createActions();
    m_dock = new SolverDock(document,
                            {m_actions.run, m_actions.continueSolve, m_actions.pause, m_actions.stop, m_actions.reset,
                             m_actions.live, m_actions.dryRun, m_actions.inspect, m_actions.hemicube},
                            window);
    window->addDockWidget(Qt::RightDockWidgetArea, m_dock);
    m_convergence = new ConvergenceDock(window);
    window->addDockWidget(Qt::BottomDockWidgetArea, m_convergence);
    m_convergence->hide();
    connect(m_convergence, &QDockWidget::visibilityChanged, this, [this](bool visible) {
        if (visible && m_shownFrame)
            m_convergence->setHistory(m_shownFrame->history);
    });

    m_status = new QLabel(window);
    window->statusBar()->addPermanentWidget(m_status);
    // Busy while the scene is prepared, then how far the solve is.
    m_progress = new QProgressBar(window);
    m_progress->setObjectName(QStringLiteral("previewProgress"));
    m_progress->setMaximumWidth(120);
    m_progress->setMaximumHeight(14);
    m_progress->setTextVisible(false);
    m_progress->hide();
    window->statusBar()->addPermanentWidget(m_progress);

    m_inspector = std::make_unique<PreviewInspector>([this] { return m_shownFrame; });
    connect(m_inspector.get(), &PreviewInspector::inspected, this, [this](const Inspection& i) {
        m_dock->setInspection(describeInspection(i));
        m_dock->raise();
        ViewportLayer marker;
        marker.depthTest = false;
        marker.order = 10;
        const glm::vec4 colour(1.0f, 0.2f, 0.9f, 1.0f);
        for (int k = 0; k < 3; ++k)
            marker.lines.add(i.corners[size_t(k)], i.corners[size_t((k + 1) % 3)], colour);
        m_viewport->setLayer(QStringLiteral("preview.inspect"), std::move(marker));
        m_inspectedPatch = i.patch;
        updateActions();
    });
    connect(m_inspector.get(), &PreviewInspector::missed, this,
            [this] { m_dock->setInspection(tr("Nothing of the solution under the cursor.")); });
    connect(m_inspector.get(), &PreviewInspector::dropped, this, [this] {
        m_actions.inspect->setChecked(false);
        m_viewport->removeLayer(QStringLiteral("preview.inspect"));
    });

    m_debounce.setSingleShot(true);
    m_debounce.setInterval(600);
    connect(&m_debounce, &QTimer::timeout, this, [this] {
        if (live() && (m_runner->isStale() || m_runner->state() == PreviewState::Idle ||
                       m_runner->state() == PreviewState::Failed))
            run();
    });
    // Elapsed time keeps counting between frames (and while preparing).
    m_statusTimer.setInterval(250);
    connect(&m_statusTimer, &QTimer::timeout, this, &PreviewController::updateStatus);

    connect(m_runner, &PreviewRunner::frameReady, this, &PreviewController::onFrame);
    connect(m_runner, &PreviewRunner::stateChanged, this, &PreviewController::onState);
    connect(m_runner, &PreviewRunner::staleChanged, this, &PreviewController::updateStatus);
    connect(m_runner, &PreviewRunner::failed, this, [this](const QString& message) {
        m_window->statusBar()->showMessage(tr("The preview cannot solve this scene: %1").arg(message), 10000);
    });
    connect(m_runner, &PreviewRunner::hemicubeReady, this, [this](const HemicubeImages& images) {
        if (!m_hemicubeDialog) {
            m_hemicubeDialog = new HemicubeDialog(m_window);
            m_hemicubeDialog->setAttribute(Qt::WA_DeleteOnClose);
        }
        m_hemicubeDialog->setImages(images);
        m_hemicubeDialog->show();
        m_hemicubeDialog->raise();
    });
    connect(m_dock, &SolverDock::displayChanged, this, [this] { scheduleLayers(); });

    for (auto signal :
         {&SceneDocument::objectsChanged, &SceneDocument::geometryChanged, &SceneDocument::materialsChanged,
          &SceneDocument::regionsChanged, &SceneDocument::settingsChanged})
        connect(m_document, signal, this, &PreviewController::onSceneChanged);
    connect(m_document, &SceneDocument::sceneReset, this, &PreviewController::onSceneReset);
    updateActions();
    updateStatus();
}

PreviewController::~PreviewController()
{
    // The guarded pointer is read once: each read may find the viewport gone.
    if (Viewport* viewport = m_viewport; viewport && viewport->tool() == m_inspector.get())
        viewport->setTool(nullptr);
    // Layer jobs capture nothing of ours but post back to us: let them end.
    m_pool.waitForDone();
}

void PreviewController::createActions()
{
    auto& a = m_actions;
    auto make = [this](const QString& text, const QString& tip) {
        auto* action = new QAction(text, this);
        action->setToolTip(tip);
        action->setStatusTip(tip);
        return action;
    };
    a.run = make(tr("&Run"), tr("Solve the scene as it is now (the preview shows it progressively)"));
    a.run->setShortcut(Qt::Key_F5);
    a.continueSolve = make(tr("&Continue"), tr("Go on from where the solve stopped: its iteration limit or your Stop"));
    a.continueSolve->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_F5));
    a.pause = make(tr("&Pause"), tr("Pause the solve, or resume it"));
    a.pause->setShortcut(Qt::Key_F6);
    a.stop = make(tr("&Stop"), tr("End the solve; the solution stays"));
    a.stop->setShortcut(QKeySequence(Qt::SHIFT | Qt::Key_F5));
    a.reset = make(tr("Rese&t"), tr("Drop the solution and show the materials again"));
    a.live = make(tr("&Live"), tr("Solve again automatically after a pause in editing"));
    a.live->setCheckable(true);
    a.dryRun = make(tr("&Dry Run…"), tr("List the effective settings and the patch and element counts"));
    a.inspect = make(tr("&Inspect"), tr("Click a surface of the solution to see its element"));
    a.inspect->setCheckable(true);
    a.hemicube = make(tr("&Hemicube…"), tr("Show the item buffer of the inspected patch"));
    a.draft = make(tr("Draft"), tr("Coarse and fast: for previews while editing"));
    a.normal = make(tr("Normal"), tr("The default settings"));
    a.final = make(tr("Final"), tr("Fine meshes and a large hemicube: for batch solving"));
    a.exportModel = make(tr("Export Lit &Model…"), tr("Write the shown solution as glTF, PLY or OBJ"));
    a.exportImage = make(tr("Export Viewport &Image…"), tr("Save the viewport as a picture"));
    a.exportBatch = make(tr("Export for &Batch…"),
                         tr("Write a self-contained scene with final settings and the regio-solve command"));

    connect(a.run, &QAction::triggered, this, &PreviewController::run);
    connect(a.pause, &QAction::triggered, this, [this] {
        if (m_runner->state() == PreviewState::Paused)
            m_runner->resume();
        else
            m_runner->pause();
    });
    connect(a.stop, &QAction::triggered, m_runner, &PreviewRunner::stop);
    connect(a.continueSolve, &QAction::triggered, m_runner, &PreviewRunner::continueSolve);
    connect(a.reset, &QAction::triggered, this, [this] {
        m_debounce.stop();
        m_runner->reset();
    });
    connect(a.live, &QAction::toggled, this, [this](bool on) {
        if (on && (m_runner->isStale() || m_runner->state() == PreviewState::Idle))
            m_debounce.start();
        else if (!on)
            m_debounce.stop();
    });
    connect(a.dryRun, &QAction::triggered, this, &PreviewController::showDryRun);
    connect(a.inspect, &QAction::toggled, this, [this](bool on) {
        Viewport* viewport = m_viewport;
        if (!viewport) // the window is closing
            return;
        if (on)
            viewport->setTool(m_inspector.get());
        else if (viewport->tool() == m_inspector.get())
            viewport->setTool(nullptr);
    });
    connect(a.hemicube, &QAction::triggered, this, &PreviewController::showHemicube);
    connect(a.draft, &QAction::triggered, this, [this] { m_dock->applyPreset(SolverPreset::Draft); });
    connect(a.normal, &QAction::triggered, this, [this] { m_dock->applyPreset(SolverPreset::Normal); });
    connect(a.final, &QAction::triggered, this, [this] { m_dock->applyPreset(SolverPreset::Final); });
    connect(a.exportModel, &QAction::triggered, this, &PreviewController::chooseExportModel);
    connect(a.exportImage, &QAction::triggered, this, &PreviewController::chooseExportImage);
    connect(a.exportBatch, &QAction::triggered, this, &PreviewController::chooseExportBatch);
}

void PreviewController::populateMenu(QMenu* menu)
{
    auto& a = m_actions;
    menu->addAction(a.run);
    menu->addAction(a.continueSolve);
    menu->addAction(a.pause);
    menu->addAction(a.stop);
    menu->addAction(a.reset);
    menu->addAction(a.live);
    menu->addSeparator();
    QMenu* presets = menu->addMenu(tr("&Presets"));
    presets->addAction(a.draft);
    presets->addAction(a.normal);
    presets->addAction(a.final);
    menu->addAction(a.dryRun);
    menu->addSeparator();
    menu->addAction(a.inspect);
    menu->addAction(a.hemicube);
    menu->addAction(m_convergence->toggleViewAction());
    menu->addSeparator();
    menu->addAction(a.exportModel);
    menu->addAction(a.exportImage);
    menu->addAction(a.exportBatch);
}

void PreviewController::populateToolBar(QToolBar* toolBar)
{
    toolBar->setToolButtonStyle(Qt::ToolButtonTextOnly);
    for (QAction* action :
         {m_actions.run, m_actions.continueSolve, m_actions.pause, m_actions.stop, m_actions.reset, m_actions.live})
        toolBar->addAction(action);
}

void PreviewController::run()
{
    m_debounce.stop();
    m_runner->start(m_document->scene());
}

void PreviewController::runIterations(int iterations)
{
    m_debounce.stop();
    m_runner->start(m_document->scene(), iterations);
}

bool PreviewController::live() const { return m_actions.live->isChecked(); }
void PreviewController::setLive(bool on) { m_actions.live->setChecked(on); }
void PreviewController::setLiveDelay(int ms) { m_debounce.setInterval(ms); }
void PreviewController::setDisplay(const PreviewDisplay& display)
{
    m_dock->setDisplay(display);
    scheduleLayers();
}
const PreviewDisplay& PreviewController::display() const { return m_dock->display(); }

void PreviewController::onSceneChanged()
{
    m_runner->markStale();
    if (live())
        m_debounce.start(); // restarts: solve after a pause in editing
}

void PreviewController::onSceneReset()
{
    // Another scene: the old solution means nothing for it.
    m_debounce.stop();
    m_runner->reset();
    m_inspectedPatch = -1;
    if (live())
        m_debounce.start();
}

void PreviewController::onFrame()
{
    m_shownFrame = m_runner->frame();
    ++m_frameSerial;
    if (!m_shownFrame) {
        clearLayers();
        return;
    }
    if (m_convergence->isVisible())
        m_convergence->setHistory(m_shownFrame->history);
    scheduleLayers();
    updateStatus();
}

void PreviewController::onState(PreviewState state)
{
    if (state == PreviewState::Preparing || state == PreviewState::Running)
        m_statusTimer.start();
    else
        m_statusTimer.stop();
    if (state == PreviewState::Idle) {
        m_inspectedPatch = -1;
        m_dock->setInspection(QString());
    }
    updateActions();
    updateStatus();
}

void PreviewController::scheduleLayers()
{
    if (!m_shownFrame)
        return;
    if (m_jobRunning) {
        m_jobPending = true;
        return;
    }
    m_jobRunning = true;
    m_jobPending = false;
    const int generation = m_generation;
    const int serial = m_frameSerial;
    std::shared_ptr<const PreviewFrame> frame = m_shownFrame;
    const PreviewDisplay display = m_dock->display();
    QPointer<PreviewController> self(this);
    m_pool.start([self, frame, display, generation, serial] {
        auto layers = std::make_shared<PreviewLayers>(buildPreviewLayers(*frame, display));
        if (self)
            QMetaObject::invokeMethod(
                self.data(),
                [self, generation, serial, layers] {
                    if (self)
                        self->applyLayers(generation, serial, layers);
                },
                Qt::QueuedConnection);
    });
}

void PreviewController::applyLayers(int generation, int serial, std::shared_ptr<PreviewLayers> layers)
{
    m_jobRunning = false;
    if (generation == m_generation && m_shownFrame) {
        m_viewport->setLayer(QString::fromLatin1(kSolutionLayer), std::move(layers->solution));
        if (layers->mesh)
            m_viewport->setLayer(QString::fromLatin1(kMeshLayer), std::move(*layers->mesh));
        else
            m_viewport->removeLayer(QString::fromLatin1(kMeshLayer));
        m_dock->setLegend(layers->legend, layers->whiteReference);
        m_appliedSerial = serial;
        emit layersApplied();
    }
    if (m_jobPending)
        scheduleLayers();
}

void PreviewController::clearLayers()
{
    ++m_generation; // results of jobs under way are dropped
    m_shownFrame.reset();
    m_viewport->removeLayer(QString::fromLatin1(kSolutionLayer));
    m_viewport->removeLayer(QString::fromLatin1(kMeshLayer));
    m_viewport->removeLayer(QStringLiteral("preview.inspect"));
    m_dock->setLegend(std::nullopt, 1.0);
    m_convergence->setHistory({});
    m_appliedSerial = 0;
    emit layersApplied();
}

QString PreviewController::statusText() const
{
    const PreviewState state = m_runner->state();
    QString text;
    const std::shared_ptr<const PreviewFrame>& f = m_shownFrame;
    auto figures = [&] {
        const solver::SolverStats& s = f->snapshot.stats;
        return tr("iteration %1, unshot %2 %, %3 elements, %4 s")
            .arg(s.iterations)
            .arg(100.0 * s.unshotRatio, 0, 'g', 3)
            .arg(s.elements)
            .arg(f->elapsedSeconds, 0, 'f', 1);
    };
    switch (state) {
    case PreviewState::Idle: return tr("Preview: not solved");
    case PreviewState::Preparing: text = tr("Preview: preparing the scene…"); break;
    case PreviewState::Running:
        text = f ? tr("Solving: %1").arg(figures()) : tr("Solving…");
        if (m_runner->refining())
            text += tr(" (refining the mesh…)");
        break;
    case PreviewState::Paused: text = f ? tr("Paused: %1").arg(figures()) : tr("Paused"); break;
    case PreviewState::Finished:
        if (!f) {
            text = tr("Solved");
            break;
        }
        // Why it stopped: a solve at its iteration limit or stopped by the
        // user has light left to shoot, and says so.
        switch (f->snapshot.stats.stop) {
        case solver::StopReason::MaxIterations:
            // An exact number of shots (--preview-iterations) runs without
            // the convergence test, and may well end below the scene's
            // threshold: that is converged, whatever stopped it.
            if (f->snapshot.stats.unshotRatio < m_document->scene().solver.convergence) {
                text = tr("Converged: %1").arg(figures());
                break;
            }
            text = tr("Stopped at the iteration limit, not converged: %1 (Continue goes on)").arg(figures());
            break;
        case solver::StopReason::Cancelled:
            text = tr("Stopped by you, not converged: %1 (Continue goes on)").arg(figures());
            break;
        default: text = tr("Converged: %1").arg(figures()); break;
        }
        break;
    case PreviewState::Failed: text = tr("Preview: the scene cannot be solved"); break;
    }
    if (m_runner->isStale())
        text += tr(" (stale: the scene changed)");
    return text;
}

void PreviewController::updateStatus()
{
    const QString text = statusText();
    if (text != m_status->text()) {
        m_status->setText(text);
        m_dock->setStatus(text);
        emit statusChanged(text);
    }
    const PreviewState state = m_runner->state();
    const bool working = state == PreviewState::Preparing || state == PreviewState::Running;
    m_progress->setVisible(working);
    if (working) {
        const int percent = progressPercent();
        const bool busy = percent < 0 || m_runner->refining();
        m_progress->setRange(0, busy ? 0 : 100); // 0..0: busy
        if (!busy)
            m_progress->setValue(percent);
    }
    updateActions();
}

int PreviewController::progressPercent() const
{
    const std::shared_ptr<const PreviewFrame>& f = m_shownFrame;
    if (!f || m_runner->state() == PreviewState::Preparing)
        return -1;
    const solver::SolverStats& s = f->snapshot.stats;
    return solver::workPercent(s.iterations, f->settings.maxIterations, s.unshotRatio, f->settings.convergence);
}

void PreviewController::updateActions()
{
    const PreviewState s = m_runner->state();
    auto& a = m_actions;
    a.pause->setEnabled(s == PreviewState::Running || s == PreviewState::Paused);
    a.pause->setText(s == PreviewState::Paused ? tr("Res&ume") : tr("&Pause"));
    a.stop->setEnabled(s == PreviewState::Running || s == PreviewState::Paused || s == PreviewState::Preparing);
    const solver::StopReason stop = m_shownFrame ? m_shownFrame->snapshot.stats.stop : solver::StopReason::None;
    a.continueSolve->setEnabled(s == PreviewState::Finished && !m_runner->isStale() &&
                                (stop == solver::StopReason::MaxIterations || stop == solver::StopReason::Cancelled));
    a.reset->setEnabled(s != PreviewState::Idle);
    a.hemicube->setEnabled(s != PreviewState::Idle && s != PreviewState::Failed && s != PreviewState::Preparing);
    a.exportModel->setEnabled(s != PreviewState::Idle && s != PreviewState::Failed);
}

void PreviewController::showDryRun()
{
    const DryRun result = dryRun(m_document->scene());
    const QString text = describeDryRun(result);
    if (m_interactive)
        QMessageBox::information(m_window, tr("Dry Run"), text);
    else
        m_window->statusBar()->showMessage(text.section(QLatin1Char('\n'), 0, 0), 5000);
}

void PreviewController::showHemicube()
{
    const std::shared_ptr<const PreviewFrame>& f = m_shownFrame;
    if (!f)
        return;
    int patch = m_inspectedPatch;
    if (patch < 0) {
        if (!m_interactive)
            return;
        bool ok = false;
        patch = QInputDialog::getInt(m_window, tr("Hemicube"), tr("Patch (or inspect a surface first):"), 0, 0,
                                     std::max(0, f->snapshot.stats.patches - 1), 1, &ok);
        if (!ok)
            return;
    }
    m_runner->requestHemicube(patch, std::min(f->settings.hemicube, 512));
}

std::optional<QString> PreviewController::exportLitModel(const QString& path) const
{
    if (!m_shownFrame)
        return tr("there is no solution to export");
    return writePreviewModel(path, *m_shownFrame, display());
}

std::optional<QString> PreviewController::exportViewportImage(const QString& path) const
{
    const QImage image = m_viewport->grabFramebuffer();
    if (image.isNull())
        return tr("the viewport could not be read");
    return writeImageFile(path, image);
}

std::optional<QString> PreviewController::exportForBatch(const QString& path, QString* command) const
{
    if (auto error = writeBatchScene(path, m_document->scene()))
        return error;
    if (command)
        *command = batchCommand(path, display());
    return std::nullopt;
}

void PreviewController::chooseExportModel()
{
    const QString path =
        QFileDialog::getSaveFileName(m_window, tr("Export Lit Model"), QString(),
                                     tr("glTF binary (*.glb);;glTF (*.gltf);;PLY (*.ply);;OBJ (*.obj)"));
    if (path.isEmpty())
        return;
    if (auto error = exportLitModel(path))
        QMessageBox::warning(m_window, tr("Export Lit Model"), *error);
    else
        m_window->statusBar()->showMessage(tr("Exported %1").arg(path), 5000);
}

void PreviewController::chooseExportImage()
{
    const QString path = QFileDialog::getSaveFileName(m_window, tr("Export Viewport Image"), QString(),
                                                      tr("PNG image (*.png);;JPEG image (*.jpg)"));
    if (path.isEmpty())
        return;
    if (auto error = exportViewportImage(path))
        QMessageBox::warning(m_window, tr("Export Viewport Image"), *error);
    else
        m_window->statusBar()->showMessage(tr("Exported %1").arg(path), 5000);
}

void PreviewController::chooseExportBatch()
{
    QString suggestion;
    if (!m_document->filePath().isEmpty()) {
        const QFileInfo info(m_document->filePath());
        suggestion = info.path() + QLatin1Char('/') + info.completeBaseName() + QStringLiteral("-batch.json");
    }
    const QString path =
        QFileDialog::getSaveFileName(m_window, tr("Export for Batch"), suggestion, tr("Regio scene (*.json)"));
    if (path.isEmpty())
        return;
    QString command;
    if (auto error = exportForBatch(path, &command)) {
        QMessageBox::warning(m_window, tr("Export for Batch"), *error);
        return;
    }
    QApplication::clipboard()->setText(command);
    QMessageBox::information(m_window, tr("Export for Batch"),
                             tr("Wrote %1 with the final preset's settings. This command, now on the clipboard, "
                                "solves it and writes the report, the lit model and a picture:\n\n%2")
                                 .arg(path, command));
}

} // namespace regio::editor
