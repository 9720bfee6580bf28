#include "editor/preview/preview_session.h"

#include "output/vertex_radiosity.h"
#include "solver/shooting/shooting.h"
#include "solver/visibility/hemicube_view.h"

#include <QCoreApplication>

#include <cmath>

namespace regio::editor {

namespace {

double secondsSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

} // namespace

PreviewSession::PreviewSession(Config config, Notify notify)
    : m_config(std::move(config))
    , m_notify(std::move(notify))
    , m_start(std::chrono::steady_clock::now())
{
    m_paused = m_config.startPaused;
    ++s_live;
    m_thread = std::thread([this] { guardedWork(); });
}

PreviewSession::~PreviewSession()
{
    quit();
    if (m_thread.joinable())
        m_thread.join();
    --s_live;
}

void PreviewSession::pause()
{
    std::lock_guard<std::mutex> lock(m_mutex);
    if (m_done)
        return;
    m_paused = true;
    m_cancel.store(true);
    m_wake.notify_all();
}

void PreviewSession::resume()
{
    std::lock_guard<std::mutex> lock(m_mutex);
    m_paused = false;
    m_wake.notify_all();
}

void PreviewSession::stop()
{
    std::lock_guard<std::mutex> lock(m_mutex);
    m_stopRequested = true;
    m_cancel.store(true);
    m_wake.notify_all();
}

bool PreviewSession::refining() const
{
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_solver && m_solver->refining();
}

bool PreviewSession::continueRun()
{
    std::lock_guard<std::mutex> lock(m_mutex);
    if (!m_solver || !m_done || m_quit)
        return false;
    m_solver->extendIterationLimit(m_iterationStep);
    m_done = false;
    m_stopRequested = false;
    m_paused = false;
    // The last frame now shows a solve that runs again. The run's end is
    // announced before its final frame is built (see work()), and that
    // frame can take a while on a mesh the run refined: until it comes, the
    // latest frame must not pass for the final one.
    if (m_latest && !m_latest->running) {
        auto again = std::make_shared<PreviewFrame>(*m_latest);
        again->running = true;
        m_latest = std::move(again);
    }
    m_wake.notify_all();
    return true;
}

void PreviewSession::quit()
{
    std::lock_guard<std::mutex> lock(m_mutex);
    m_quit = true;
    m_stopRequested = true;
    m_cancel.store(true);
    m_wake.notify_all();
}

bool PreviewSession::finished() const
{
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_done;
}

std::shared_ptr<const PreviewFrame> PreviewSession::latestFrame() const
{
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_latest;
}

model::Diagnostics PreviewSession::diagnostics() const
{
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_diagnostics;
}

void PreviewSession::requestHemicube(int patch, int resolution)
{
    std::lock_guard<std::mutex> lock(m_mutex);
    m_hemicubeRequest = std::make_pair(patch, resolution);
    // A running solve serves it after the shot under way; an idle worker wakes up.
    m_wake.notify_all();
}

std::optional<HemicubeImages> PreviewSession::takeHemicube()
{
    std::lock_guard<std::mutex> lock(m_mutex);
    std::optional<HemicubeImages> out = std::move(m_hemicubeResult);
    m_hemicubeResult.reset();
    return out;
}

void PreviewSession::record(const solver::SolverStats& stats)
{
    const solver::EnergyBalance& e = stats.energy;
    const double emitted = solver::luminance(e.emitted);
    ConvergencePoint p;
    p.iteration = stats.iterations;
    if (emitted > 0.0) {
        p.unshot = solver::luminance(e.unshot) / emitted;
        p.absorbed = solver::luminance(e.absorbed) / emitted;
        p.escaped = solver::luminance(e.escaped) / emitted;
        p.balanceError = std::abs(emitted - solver::luminance(e.absorbed) - solver::luminance(e.unshot) -
                                  solver::luminance(e.escaped)) /
                         emitted;
    }
    m_history.push_back(p);
}

void PreviewSession::publish(bool running)
{
    const auto begin = std::chrono::steady_clock::now();
    auto frame = std::make_shared<PreviewFrame>();
    frame->snapshot = m_solver->snapshot();
    frame->settings = m_solver->settings();
    frame->running = running;
    frame->history = m_history;
    frame->elapsedSeconds = secondsSince(m_start);
    // On the worker, between shots, the prepared scene and the snapshot describe
    // the same mesh; if they ever differ (a mesh being regrouped), the flat
    // element mesh of the snapshot itself is shown.
    const solver::PreparedScene& prepared = m_solver->prepared();
    const std::vector<model::Rgb>& radiosity = frame->snapshot.radiosity;
    if (prepared.elements.size() == radiosity.size()) {
        frame->unshot = m_solver->shooting().unshotRadiosity();
        frame->elementPatch.reserve(prepared.elements.size());
        frame->elementRegion.reserve(prepared.elements.size());
        for (const solver::Element& e : prepared.elements) {
            frame->elementPatch.push_back(e.patch);
            frame->elementRegion.push_back(e.node >= 0 ? prepared.nodes[static_cast<size_t>(e.node)].region : -1);
        }
        for (const solver::Region& r : prepared.regions)
            frame->regionIds.push_back(r.id);
        // The outputs' picture in every frame, so the view never switches
        // between two looks: smooth vertex radiosity (§6) with the lights'
        // direct part exact (output/exact_direct.h), of which the share shot
        // so far. The welding, re-triangulation and cutting are done once
        // per mesh, and the direct part once per place: a refinement round
        // computes it only where it adds corners. A frame then only sums
        // each vertex's elements. The mesh only grows (refinement rounds),
        // so its element and vertex counts tell when it changed.
        if (!m_shading || m_shading->elementCount() != prepared.elements.size() ||
            m_shadedVertices != prepared.vertices.size()) {
            m_shading = std::make_unique<output::ExactDirectShading>(prepared, output::SmoothingOptions{},
                                                                     &m_directCache, output::CutFor::Screen);
            m_shadedVertices = prepared.vertices.size();
        }
        frame->lit = std::make_shared<output::LitMesh>(
            m_shading->litMesh(radiosity, output::directShare(prepared, frame->unshot)));
    } else {
        frame->smooth = false;
        frame->lit = std::make_shared<output::LitMesh>(output::litMeshFromSolution(frame->snapshot));
    }
    frame->buildSeconds = secondsSince(begin);
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_latest = std::move(frame);
    }
    // Frames are spaced from the start of the previous one, so the time to
    // make one (tens of ms for large meshes) does not stretch the interval.
    m_lastPublish = begin;
    if (!m_framePending.exchange(true))
        m_notify(SessionEvent::Frame);
}

bool PreviewSession::refinementMayFollow(const solver::SolverStats& stats) const
{
    // The schedule of solver/shooting/adaptive_refinement.h: a round is due after the
    // shot of an emitting patch and after every roundInterval-th shot, at
    // most maxRounds of them.
    const solver::RefinementPolicy policy;
    if (!m_solver->settings().adaptive.enabled || stats.adaptiveRounds >= policy.maxRounds)
        return false;
    if (policy.roundInterval > 0 && stats.iterations % policy.roundInterval == 0)
        return true;
    const int shooter = m_solver->shooting().lastShooter();
    const solver::PreparedScene& prepared = m_solver->prepared();
    if (shooter < 0 || size_t(shooter) >= prepared.patches.size())
        return false;
    return prepared.properties[static_cast<size_t>(prepared.patches[static_cast<size_t>(shooter)].properties)].emits();
}

void PreviewSession::serveHemicube()
{
    std::optional<std::pair<int, int>> request;
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        request = m_hemicubeRequest;
        m_hemicubeRequest.reset();
    }
    if (!request)
        return;
    const solver::PreparedScene& prepared = m_solver->prepared();
    // A light's shots render a finer hemicube than the others (solver/shooting/shooting.h):
    // show it as the shot sees it, as much finer as the solver's is.
    const solver::Shooting& shooting = m_solver->shooting();
    const int resolution = shooting.shotResolution(request->first) > shooting.hemicubeResolution()
                               ? solver::lightHemicubeResolution(request->second)
                               : request->second;
    const auto view = solver::renderHemicubeView(prepared, request->first, resolution, m_solver->settings().visibility);
    if (!view)
        return;
    HemicubeImages images = hemicubeImages(*view, prepared);
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_hemicubeResult = std::move(images);
    }
    m_notify(SessionEvent::Hemicube);
}

void PreviewSession::guardedWork()
{
    // An exception that leaves a thread ends the process: the editor, its
    // document and hours of work with it. Whatever escapes the solver ends
    // this session instead; the document is the UI thread's and untouched.
    try {
        work();
    } catch (const std::bad_alloc&) {
        fail(QCoreApplication::translate("regio::editor::PreviewSession",
                                         "the solver ran out of memory (try a larger patch size or a lower "
                                         "hemicube resolution)")
                 .toStdString());
    } catch (const std::exception& e) {
        fail(QCoreApplication::translate("regio::editor::PreviewSession", "the solver failed: %1")
                 .arg(QString::fromLocal8Bit(e.what()))
                 .toStdString());
    } catch (...) {
        fail(QCoreApplication::translate("regio::editor::PreviewSession", "the solver failed").toStdString());
    }
}

void PreviewSession::fail(const std::string& message)
{
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_diagnostics.push_back(model::makeError(message));
        m_done = true;
    }
    m_exited.store(true);
    m_notify(SessionEvent::Failed);
}

void PreviewSession::work()
{
    model::Result<std::unique_ptr<solver::Solver>> built = solver::Solver::create(m_config.scene, m_config.options);
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_diagnostics = built.diagnostics();
    }
    if (!built) {
        m_exited.store(true);
        m_notify(SessionEvent::Failed);
        return;
    }
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_solver = std::move(*built);
        m_iterationStep = m_solver->settings().maxIterations;
    }
    // The scene copy is no longer needed: the solver works on its own PreparedScene.
    m_config.scene = model::Scene{};
    publish(!m_config.startPaused);

    const auto interval = std::chrono::milliseconds(m_config.publishIntervalMs);
    const auto progress = [&](const solver::SolverStats& stats) {
        record(stats);
        if (m_config.afterShot)
            m_config.afterShot(stats);
        serveHemicube();
        // A refinement round (§5.7) reports no progress and may take a few
        // hundred ms on a large mesh: when one may follow this shot, the
        // frame goes out now rather than up to one interval before the round
        // (not closer than a quarter interval to the last one, for lights of
        // many patches whose rounds find nothing to split).
        const auto since = std::chrono::steady_clock::now() - m_lastPublish;
        if (since >= interval || (since >= interval / 4 && refinementMayFollow(stats)))
            publish(true);
    };

    std::unique_lock<std::mutex> lock(m_mutex);
    for (;;) {
        m_wake.wait(lock, [&] { return m_quit || m_hemicubeRequest || (!m_done && (m_stopRequested || !m_paused)); });
        if (m_quit)
            break;
        if (m_hemicubeRequest) {
            lock.unlock();
            serveHemicube();
            lock.lock();
            continue;
        }
        bool done = m_stopRequested; // stopped while paused: nothing to run
        if (!done) {
            m_cancel.store(false);
            lock.unlock();
            const solver::StopReason reason = m_solver->run(progress, m_cancel);
            lock.lock();
            done = reason != solver::StopReason::Cancelled || m_stopRequested;
        }
        m_done = done;
        if (m_quit)
            break;
        lock.unlock();
        // The state first (Stop is seen at once), then the final frame.
        m_notify(done ? SessionEvent::Finished : SessionEvent::Paused);
        publish(false);
        lock.lock();
    }
    lock.unlock();
    m_exited.store(true);
}

} // namespace regio::editor
