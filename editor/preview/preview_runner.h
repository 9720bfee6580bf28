#pragma once
// The preview runner: starts, pauses, stops and drops embedded
// solves (PreviewSession, one worker thread each) and hands the newest frame
// to the UI thread. It never waits on a solver: dropped sessions finish
// their shot on their own thread and are joined once they have exited.
#include "editor/preview/preview_session.h"

#include <QObject>
#include <QString>
#include <QTimer>

#include <memory>
#include <optional>
#include <vector>

namespace regio::editor {

enum class PreviewState {
    Idle,      // nothing solved (or reset)
    Preparing, // building the regional tree, BSP trees and meshes
    Running,
    Paused,
    Finished, // converged, maximum iterations or stopped: the solution stays
    Failed    // the scene could not be prepared (diagnostics say why)
};

class PreviewRunner : public QObject {
    Q_OBJECT
public:
    explicit PreviewRunner(QObject* parent = nullptr);
    ~PreviewRunner() override;

    // Solves a copy of `scene` with its own solver settings, dropping any
    // solve under way. `exactIterations`: exactly N shots and no convergence
    // test, as `regio-solve solve --iterations N`.
    void start(const model::Scene& scene, std::optional<int> exactIterations = std::nullopt);
    void pause();
    void resume();
    void stop();
    // Goes on with a finished solve that stopped short of convergence.
    void continueSolve();
    // A refinement round of the running solve is under way.
    bool refining() const { return m_session && m_state == PreviewState::Running && m_session->refining(); }
    // Drops the solve and its solution.
    void reset();

    PreviewState state() const { return m_state; }
    bool busy() const { return m_state == PreviewState::Preparing || m_state == PreviewState::Running; }
    // The newest frame of the current solve (empty after reset).
    std::shared_ptr<const PreviewFrame> frame() const { return m_frame; }
    model::Diagnostics diagnostics() const { return m_diagnostics; }

    // The scene changed since the shown solve was started.
    bool isStale() const { return m_stale; }
    void markStale();

    void requestHemicube(int patch, int resolution);
    // Sessions dropped but still finishing their shot (for tests).
    int retiredSessions() const { return int(m_retired.size()); }

signals:
    void frameReady();
    void stateChanged(regio::editor::PreviewState state);
    void staleChanged(bool stale);
    void failed(const QString& message);
    void hemicubeReady(const regio::editor::HemicubeImages& images);

private:
    void onEvent(int serial, SessionEvent event);
    void setState(PreviewState state);
    void retireCurrent();
    void reap();

    std::unique_ptr<PreviewSession> m_session;
    int m_serial = 0;
    std::vector<std::unique_ptr<PreviewSession>> m_retired;
    QTimer m_reaper;
    std::shared_ptr<const PreviewFrame> m_frame;
    model::Diagnostics m_diagnostics;
    PreviewState m_state = PreviewState::Idle;
    bool m_stale = false;
};

} // namespace regio::editor

Q_DECLARE_METATYPE(regio::editor::PreviewState)
Q_DECLARE_METATYPE(regio::editor::HemicubeImages)
