#pragma once
// One embedded solve of the preview runner: a worker thread that owns a
// solver::Solver built from a copy of the scene, shoots on it and publishes
// PreviewFrames. Qt-free: the owner learns about events through a callback
// that may be called from the worker thread (PreviewRunner turns it into a
// queued call on the UI thread).
//
// Everything that reads the solver's PreparedScene (smooth vertex radiosity,
// element -> patch/region tables, hemicube views) runs on the worker thread
// between two shots, because adaptive subdivision may grow the mesh while a
// run is under way: the UI only ever sees finished, self-consistent frames.
#include "editor/preview/hemicube_images.h"
#include "model/diagnostic.h"
#include "model/scene.h"
#include "output/exact_direct.h"
#include "output/lit_mesh.h"
#include "solver/solver.h"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace regio::editor {

// One point of the convergence plot: fractions of the emitted power (by
// luminance) after a shot.
struct ConvergencePoint {
    int iteration = 0;
    double unshot = 0.0;
    double absorbed = 0.0;
    double escaped = 0.0;
    double balanceError = 0.0; // |emitted - absorbed - unshot - escaped| / emitted
};

// What the UI shows of a solve at one moment. Arrays indexed by element
// follow the snapshot's own mesh.
struct PreviewFrame {
    solver::SolutionSnapshot snapshot;
    std::vector<model::Rgb> unshot; // per element, W/m^2 (empty if the mesh moved on)
    std::vector<int> elementPatch;  // per element
    std::vector<int> elementRegion; // per element, index into regionIds
    std::vector<std::string> regionIds;
    std::shared_ptr<const output::LitMesh> lit; // smooth vertex radiosity (§6)
    std::vector<ConvergencePoint> history;
    model::SolverSettings settings;
    double elapsedSeconds = 0.0; // since the session started (preparation included)
    bool running = false;        // false: paused, stopped or finished when it was made
    double buildSeconds = 0.0;   // making this frame on the worker (snapshot, smooth lit mesh)
    bool smooth = true;          // smooth vertex radiosity (§6); false: flat elements
};

enum class SessionEvent { Frame, Paused, Finished, Failed, Hemicube };

class PreviewSession {
public:
    struct Config {
        model::Scene scene;
        solver::SolverOptions options;
        int publishIntervalMs = 100; // frames while shooting: ten a second
        bool startPaused = false;
        // Called on the worker after every shot. Tests throw from it to see
        // the worker survive what may escape a solver (std::bad_alloc and the
        // like): the session fails with the reason and the editor goes on.
        std::function<void(const solver::SolverStats&)> afterShot;
    };
    using Notify = std::function<void(SessionEvent)>;

    // Starts the worker thread at once; `notify` may be called from it.
    PreviewSession(Config config, Notify notify);
    // Cancels the shot under way and joins the worker.
    ~PreviewSession();
    // Sessions alive in the process (their workers included), for leak checks.
    static int liveSessions() { return s_live.load(); }
    PreviewSession(const PreviewSession&) = delete;
    PreviewSession& operator=(const PreviewSession&) = delete;

    void pause();
    void resume();
    // Ends the run (the shot under way is abandoned); the solution stays.
    void stop();
    // Stop and let the worker exit (no further events).
    void quit();
    // After a run that stopped short of convergence (at the iteration limit,
    // or stopped by the user): goes on from there, up to the scene's
    // maxIterations shots more. False when there is nothing to continue.
    bool continueRun();
    // The solver is refining its mesh between two shots (no frames come then).
    bool refining() const;
    // The worker has returned (after quit, or when preparation failed).
    bool exited() const { return m_exited.load(); }
    bool finished() const;

    std::shared_ptr<const PreviewFrame> latestFrame() const;
    // Called by the owner when it handled a Frame event: the next frame
    // notifies again (frames in between are coalesced).
    void frameTaken() { m_framePending.store(false); }

    // Preparation problems (errors when it failed, warnings otherwise).
    model::Diagnostics diagnostics() const;

    // The item buffer of a patch, rendered on the worker between two shots;
    // a Hemicube event follows. A light's patch renders at
    // solver::lightHemicubeResolution(resolution), as its shots do.
    void requestHemicube(int patch, int resolution);
    std::optional<HemicubeImages> takeHemicube();

private:
    // The worker: work() with whatever escapes it turned into a failure.
    void guardedWork();
    void work();
    void fail(const std::string& message);
    void publish(bool running);
    void serveHemicube();
    // Whether a refinement round may run before the next shot (worker thread).
    bool refinementMayFollow(const solver::SolverStats& stats) const;
    void record(const solver::SolverStats& stats);

    Config m_config;
    Notify m_notify;
    std::chrono::steady_clock::time_point m_start;
    std::unique_ptr<solver::Solver> m_solver; // worker thread only (after creation)

    mutable std::mutex m_mutex;
    std::condition_variable m_wake;
    bool m_paused = false;
    bool m_stopRequested = false;
    int m_iterationStep = 0; // the shots a Continue adds: the settings' maxIterations
    bool m_quit = false;
    bool m_done = false;
    std::optional<std::pair<int, int>> m_hemicubeRequest;
    std::optional<HemicubeImages> m_hemicubeResult;
    std::shared_ptr<const PreviewFrame> m_latest;
    model::Diagnostics m_diagnostics;
    std::vector<ConvergencePoint> m_history; // worker thread only

    std::atomic<bool> m_cancel{false};
    std::atomic<bool> m_exited{false};
    std::atomic<bool> m_framePending{false};
    std::chrono::steady_clock::time_point m_lastPublish;
    // The shading of the solver's current mesh, and the lights' direct part
    // at the places of its meshes so far (worker thread only).
    std::unique_ptr<output::ExactDirectShading> m_shading;
    size_t m_shadedVertices = 0;
    output::DirectCache m_directCache;
    static inline std::atomic<int> s_live{0};
    std::thread m_thread; // last member: starts after everything above exists
};

} // namespace regio::editor
