#include "solver/visibility/hemicube_renderer.h"

#include <algorithm>

namespace regio::solver {

namespace {

// Face groups of equal pixel count for 1, 2 and 3 threads.
std::vector<HemicubeFaceSet> faceGroups(int threads)
{
    using F = HemicubeFace;
    if (threads <= 1)
        return {kAllHemicubeFaces};
    if (threads == 2)
        return {faceBit(F::Top) | faceBit(F::PosX), faceBit(F::NegX) | faceBit(F::PosY) | faceBit(F::NegY)};
    return {faceBit(F::Top), faceBit(F::PosX) | faceBit(F::NegX), faceBit(F::PosY) | faceBit(F::NegY)};
}

} // namespace

int resolveThreadCount(int threads)
{
    if (threads > 0)
        return threads;
    return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

HemicubeRenderer::HemicubeRenderer(const PreparedScene& scene, const Hemicube& hemicube, model::Visibility mode,
                                   int threads)
{
    for (HemicubeFaceSet faces : faceGroups(resolveThreadCount(threads)))
        m_groups.push_back(std::make_unique<Visibility>(scene, hemicube, mode, faces));
    for (size_t g = 1; g < m_groups.size(); ++g)
        m_threads.emplace_back([this, g] { work(g); });
}

HemicubeRenderer::~HemicubeRenderer()
{
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_quit = true;
    }
    m_wake.notify_all();
    for (std::thread& t : m_threads)
        t.join();
}

void HemicubeRenderer::work(size_t group)
{
    std::uint64_t seen = 0;
    for (;;) {
        const ShooterFrame* frame;
        ItemBuffer* buffer;
        const std::atomic<bool>* cancel;
        {
            std::unique_lock<std::mutex> lock(m_mutex);
            m_wake.wait(lock, [&] { return m_quit || m_shot != seen; });
            if (m_quit)
                return;
            seen = m_shot;
            frame = m_frame;
            buffer = m_buffer;
            cancel = m_cancel;
        }
        const bool done = m_groups[group]->render(*frame, *buffer, cancel);
        {
            std::lock_guard<std::mutex> lock(m_mutex);
            m_cancelled = m_cancelled || !done;
            if (--m_running == 0)
                m_finished.notify_one();
        }
    }
}

bool HemicubeRenderer::render(const ShooterFrame& frame, ItemBuffer& buffer, const std::atomic<bool>* cancel)
{
    if (m_threads.empty())
        return m_groups.front()->render(frame, buffer, cancel);
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_frame = &frame;
        m_buffer = &buffer;
        m_cancel = cancel;
        m_cancelled = false;
        m_running = static_cast<int>(m_threads.size());
        ++m_shot;
    }
    m_wake.notify_all();
    const bool done = m_groups.front()->render(frame, buffer, cancel);
    std::unique_lock<std::mutex> lock(m_mutex);
    m_finished.wait(lock, [&] { return m_running == 0; });
    return done && !m_cancelled;
}

} // namespace regio::solver
