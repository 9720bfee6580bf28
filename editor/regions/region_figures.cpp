#include "editor/regions/region_figures.h"

#include "editor/document/scene_document.h"
#include "editor/regions/region_layers.h"
#include "model/geometry/region_clip.h"

#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QThread>

#include <algorithm>
#include <memory>

namespace regio::editor {

namespace {
constexpr int kDelayMs = 300;
}

std::vector<RegionContents> regionContents(const model::Scene& scene)
{
    std::vector<RegionContents> contents(scene.regions.size());
    std::vector<model::Box3> boxes;
    for (const model::Region& region : scene.regions)
        boxes.push_back(boxOf(region));
    std::vector<model::Vec3> loop;
    std::vector<char> partCounted(boxes.size());
    for (const model::Object& object : scene.objects)
        for (const model::Part& part : object.parts) {
            std::fill(partCounted.begin(), partCounted.end(), 0);
            for (const model::Face& face : part.faces) {
                loop.clear();
                for (int v : face.loop)
                    if (v >= 0 && size_t(v) < part.vertices.size())
                        loop.push_back(part.vertices[size_t(v)]);
                if (loop.size() < 3)
                    continue;
                model::Box3 bounds;
                for (const model::Vec3& p : loop)
                    bounds.extend(p);
                for (size_t r = 0; r < boxes.size(); ++r) {
                    // Cheap rejection before clipping the polygon by the box.
                    if (bounds.max.x < boxes[r].min.x || bounds.min.x > boxes[r].max.x ||
                        bounds.max.y < boxes[r].min.y || bounds.min.y > boxes[r].max.y ||
                        bounds.max.z < boxes[r].min.z || bounds.min.z > boxes[r].max.z)
                        continue;
                    if (!model::faceTouchesRegionBox(loop, boxes[r]))
                        continue;
                    ++contents[r].faces;
                    if (!partCounted[r]) {
                        partCounted[r] = 1;
                        ++contents[r].parts;
                    }
                }
            }
        }
    return contents;
}

RegionFiguresWatcher::RegionFiguresWatcher(SceneDocument* document, QObject* parent)
    : QObject(parent)
    , m_document(document)
{
    m_debounce.setSingleShot(true);
    m_debounce.setInterval(kDelayMs);
    connect(&m_debounce, &QTimer::timeout, this, &RegionFiguresWatcher::start);
    // Every change that can move a fragment: geometry, regions and their orders.
    connect(document, &SceneDocument::objectsChanged, this, &RegionFiguresWatcher::schedule);
    connect(document, &SceneDocument::geometryChanged, this, &RegionFiguresWatcher::schedule);
    connect(document, &SceneDocument::regionsChanged, this, &RegionFiguresWatcher::schedule);
    connect(document, &SceneDocument::sceneReset, this, &RegionFiguresWatcher::schedule);
    schedule();
}

RegionFiguresWatcher::~RegionFiguresWatcher()
{
    if (m_thread) {
        m_thread->wait();
        delete m_thread;
    }
}

bool RegionFiguresWatcher::stale() const { return m_debounce.isActive() || m_thread || m_rerun; }

void RegionFiguresWatcher::schedule()
{
    const bool wasStale = stale();
    m_debounce.start();
    if (!wasStale)
        emit staleChanged(true);
}

void RegionFiguresWatcher::recomputeNow()
{
    m_debounce.stop();
    start();
}

void RegionFiguresWatcher::start()
{
    if (m_thread) {
        m_rerun = true; // the running one is already out of date
        return;
    }
    auto result = std::make_shared<solver::BspComparison>();
    m_thread =
        QThread::create([scene = m_document->scene(), result] { *result = solver::compareWithSingleBsp(scene); });
    connect(m_thread, &QThread::finished, this, [this, result] {
        m_thread->deleteLater();
        m_thread = nullptr;
        if (m_rerun) {
            m_rerun = false;
            start();
            return;
        }
        m_comparison = std::move(*result);
        emit figuresChanged();
        if (!stale())
            emit staleChanged(false);
    });
    m_thread->start(QThread::LowPriority);
}

bool RegionFiguresWatcher::waitUntilCurrent(int timeoutMs)
{
    QDeadlineTimer deadline(timeoutMs);
    if (m_debounce.isActive())
        recomputeNow();
    while (stale() && !deadline.hasExpired())
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
    return !stale();
}

} // namespace regio::editor
