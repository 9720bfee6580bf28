#include "editor/bsp/bsp_analysis.h"

#include "editor/document/scene_document.h"
#include "solver/prepare/prepare.h"

#include <QPromise>
#include <QThreadPool>

#include <chrono>

namespace regio::editor {

const solver::RegionBspFigures* BspAnalysis::region(const std::string& regionId) const
{
    if (!authored)
        return nullptr;
    const int index = authored->regionIndex(regionId);
    return index < 0 ? nullptr : &authored->regions[size_t(index)];
}

int BspAnalysis::preparedRegion(const std::string& regionId) const
{
    if (!prepared)
        return -1;
    for (size_t r = 0; r < prepared->regions.size(); ++r)
        if (prepared->regions[r].id == regionId)
            return int(r);
    return -1;
}

BspAnalysis analyseBsp(model::Scene sceneCopy)
{
    const auto start = std::chrono::steady_clock::now();
    BspAnalysis out;
    out.scene = std::make_shared<const model::Scene>(std::move(sceneCopy));
    const model::Scene& scene = *out.scene;
    // The figures come from the very preparation whose trees are drawn, so
    // the tree view, the fragment layer and the numbers never disagree.
    model::Result<solver::PreparedScene> prepared = solver::prepareBsp(scene);
    out.diagnostics = prepared.takeDiagnostics();
    if (prepared) {
        out.authored = solver::bspFiguresOf(*prepared, solver::RegionsMode::Authored);
        out.prepared = std::make_shared<const solver::PreparedScene>(std::move(*prepared));
    }
    if (model::Result<solver::SceneBspFigures> baseline = solver::computeBspFigures(scene, {solver::RegionsMode::None}))
        out.baseline = std::move(*baseline);
    out.milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return out;
}

BspAnalyser::BspAnalyser(SceneDocument* document, QObject* parent)
    : QObject(parent)
    , m_document(document)
{
    m_debounce.setSingleShot(true);
    m_debounce.setInterval(150);
    connect(&m_debounce, &QTimer::timeout, this, &BspAnalyser::start);
    connect(&m_watcher, &QFutureWatcher<BspAnalysis>::finished, this, &BspAnalyser::onFinished);
    for (auto signal : {&SceneDocument::objectsChanged, &SceneDocument::geometryChanged, &SceneDocument::regionsChanged,
                        &SceneDocument::sceneReset})
        connect(document, signal, this, &BspAnalyser::onChanged);
    onChanged();
}

BspAnalyser::~BspAnalyser()
{
    // The pool thread owns its copy of the scene and its promise; the result
    // is simply dropped. Waiting keeps a closing window from outliving its
    // worker by more than one preparation.
    m_watcher.disconnect(this);
    if (m_running)
        m_watcher.waitForFinished();
}

void BspAnalyser::refreshNow()
{
    m_debounce.stop();
    m_current = analyseBsp(m_document->scene());
    m_currentRevision = m_revision;
    m_stale = false;
    emit analysed();
}

void BspAnalyser::onChanged()
{
    ++m_revision;
    if (!m_stale) {
        m_stale = true;
        emit becameStale();
    }
    // A busy run sees the change when it ends (onFinished) and starts again.
    if (!m_running)
        m_debounce.start();
}

void BspAnalyser::start()
{
    if (m_running)
        return;
    m_running = true;
    m_runningRevision = m_revision;
    auto promise = std::make_shared<QPromise<BspAnalysis>>();
    m_watcher.setFuture(promise->future());
    promise->start();
    QThreadPool::globalInstance()->start([promise, scene = m_document->scene()]() mutable {
        promise->addResult(analyseBsp(std::move(scene)));
        promise->finish();
    });
}

void BspAnalyser::onFinished()
{
    m_running = false;
    // refreshNow() may have shown a newer scene meanwhile.
    const bool newer = m_runningRevision >= m_currentRevision;
    if (m_watcher.future().resultCount() > 0 && newer) {
        // result(), not takeResult(): taking resets the future's state to
        // "not finished", and a later waitForFinished() would never return.
        m_current = m_watcher.future().result();
        m_currentRevision = m_runningRevision;
    }
    m_stale = m_currentRevision != m_revision;
    if (m_stale)
        m_debounce.start();
    if (newer)
        emit analysed();
}

} // namespace regio::editor
