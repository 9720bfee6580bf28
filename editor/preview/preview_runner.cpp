#include "editor/preview/preview_runner.h"

#include <QCoreApplication>
#include <QMetaObject>
#include <QStringList>

namespace regio::editor {

PreviewRunner::PreviewRunner(QObject* parent)
    : QObject(parent)
{
    m_reaper.setInterval(100);
    connect(&m_reaper, &QTimer::timeout, this, &PreviewRunner::reap);
}

PreviewRunner::~PreviewRunner()
{
    // Sessions call back into this object from their threads: join them all
    // (each abandons its shot within one partial hemicube render) first.
    if (m_session)
        m_session->quit();
    for (auto& s : m_retired)
        s->quit();
    m_session.reset();
    m_retired.clear();
}

void PreviewRunner::start(const model::Scene& scene, std::optional<int> exactIterations)
{
    retireCurrent();
    PreviewSession::Config config;
    config.scene = scene;
    if (exactIterations) {
        config.options.maxIterations = *exactIterations;
        config.options.convergence = 0.0;
    }
    const int serial = ++m_serial;
    m_frame.reset();
    m_diagnostics.clear();
    setState(PreviewState::Preparing);
    if (m_stale) {
        m_stale = false;
        emit staleChanged(false);
    }
    m_session = std::make_unique<PreviewSession>(std::move(config), [this, serial](SessionEvent event) {
        // From the worker thread: queued onto the UI thread. The runner joins
        // every session before it is destroyed, so `this` outlives the call.
        QMetaObject::invokeMethod(
            this, [this, serial, event] { onEvent(serial, event); }, Qt::QueuedConnection);
    });
}

void PreviewRunner::pause()
{
    if (m_session && m_state == PreviewState::Running)
        m_session->pause();
}

void PreviewRunner::resume()
{
    if (m_session && m_state == PreviewState::Paused) {
        m_session->resume();
        setState(PreviewState::Running);
    }
}

void PreviewRunner::stop()
{
    if (m_session &&
        (m_state == PreviewState::Running || m_state == PreviewState::Paused || m_state == PreviewState::Preparing))
        m_session->stop();
}

void PreviewRunner::continueSolve()
{
    // A stale solution is of a scene that is no longer there: Run solves the
    // new one.
    if (m_session && m_state == PreviewState::Finished && !m_stale && m_session->continueRun())
        setState(PreviewState::Running);
}

void PreviewRunner::reset()
{
    retireCurrent();
    ++m_serial;
    m_frame.reset();
    m_diagnostics.clear();
    setState(PreviewState::Idle);
    emit frameReady();
}

void PreviewRunner::markStale()
{
    if (m_stale || (!m_session && !m_frame))
        return;
    m_stale = true;
    emit staleChanged(true);
}

void PreviewRunner::requestHemicube(int patch, int resolution)
{
    if (m_session)
        m_session->requestHemicube(patch, resolution);
}

void PreviewRunner::onEvent(int serial, SessionEvent event)
{
    if (serial != m_serial || !m_session)
        return; // a dropped session's last words
    switch (event) {
    case SessionEvent::Frame:
        m_session->frameTaken();
        m_frame = m_session->latestFrame();
        if (m_state == PreviewState::Preparing) {
            m_diagnostics = m_session->diagnostics();
            setState(PreviewState::Running); // a Paused or Finished event follows if it is already over
        }
        emit frameReady();
        break;
    case SessionEvent::Paused:
        m_frame = m_session->latestFrame();
        setState(PreviewState::Paused);
        emit frameReady();
        break;
    case SessionEvent::Finished:
        m_frame = m_session->latestFrame();
        setState(PreviewState::Finished);
        emit frameReady();
        break;
    case SessionEvent::Failed: {
        m_diagnostics = m_session->diagnostics();
        QStringList messages;
        for (const model::Diagnostic& d : m_diagnostics)
            if (d.severity == model::Severity::Error)
                messages << QString::fromStdString(d.message);
        setState(PreviewState::Failed);
        emit failed(messages.isEmpty() ? tr("the scene could not be prepared") : messages.join(QStringLiteral("; ")));
        break;
    }
    case SessionEvent::Hemicube:
        if (auto images = m_session->takeHemicube())
            emit hemicubeReady(*images);
        break;
    }
}

void PreviewRunner::setState(PreviewState state)
{
    if (state == m_state)
        return;
    m_state = state;
    emit stateChanged(state);
}

void PreviewRunner::retireCurrent()
{
    if (!m_session)
        return;
    m_session->quit();
    m_retired.push_back(std::move(m_session));
    m_reaper.start();
}

void PreviewRunner::reap()
{
    std::erase_if(m_retired, [](const std::unique_ptr<PreviewSession>& s) { return s->exited(); });
    if (m_retired.empty())
        m_reaper.stop();
}

} // namespace regio::editor
