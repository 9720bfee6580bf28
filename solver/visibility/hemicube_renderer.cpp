#include "solver/visibility/hemicube_renderer.h"

#include <algorithm>
#include <chrono>

namespace regio::solver {

namespace {

using Clock = std::chrono::steady_clock;

// How long a thread spins for the next step before it sleeps, and how long
// the caller spins for the others to finish theirs.
constexpr auto kWorkerSpin = std::chrono::microseconds(300);
constexpr auto kCallerSpin = std::chrono::milliseconds(2);

inline void cpuRelax()
{
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#endif
}

// Spins until done() or the time runs out; true if done.
template <class Done>
bool spinUntil(Done&& done, Clock::duration limit)
{
    const Clock::time_point until = Clock::now() + limit;
    for (unsigned i = 1;; ++i) {
        if (done())
            return true;
        if (i % 64 == 0 && Clock::now() > until)
            return false;
        cpuRelax();
    }
}

// Cuts `order` into consecutive stretches, stretch k ending after piece
// ends[k] of the order (the last at the total); a range may be cut in two.
void cutIntoStretches(const std::vector<PaintRange>& order, const std::vector<std::int64_t>& ends,
                      std::vector<std::vector<PaintRange>>& stretches)
{
    for (auto& s : stretches)
        s.clear();
    std::int64_t done = 0; // pieces of the order handed out so far
    size_t part = 0;
    for (const PaintRange& r : order) {
        PaintRange rest = r;
        while (rest.begin < rest.end) {
            const bool last = part + 1 == stretches.size();
            const std::int64_t room = last ? rest.end - rest.begin : ends[part] - done;
            if (room <= 0) {
                ++part;
                continue;
            }
            const auto take = static_cast<std::int32_t>(std::min<std::int64_t>(room, rest.end - rest.begin));
            stretches[part].push_back({rest.begin, rest.begin + take, rest.receives});
            rest.begin += take;
            done += take;
        }
    }
}

// Face groups of equal pixel count for n threads (none for threads past three).
std::vector<HemicubeFaceSet> faceGroups(int threads)
{
    using F = HemicubeFace;
    if (threads <= 1)
        return {kAllHemicubeFaces};
    std::vector<HemicubeFaceSet> groups;
    if (threads == 2)
        groups = {faceBit(F::Top) | faceBit(F::PosX), faceBit(F::NegX) | faceBit(F::PosY) | faceBit(F::NegY)};
    else
        groups = {faceBit(F::Top), faceBit(F::PosX) | faceBit(F::NegX), faceBit(F::PosY) | faceBit(F::NegY)};
    groups.resize(static_cast<size_t>(threads), 0);
    return groups;
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
    const int n = std::min(resolveThreadCount(threads), kMaxThreads);
    for (int t = 0; t < n; ++t)
        m_painters.push_back(std::make_unique<Visibility>(scene, hemicube, mode));
    for (int t = 1; t < n; ++t)
        m_later.push_back(ItemBuffer::forStretch(hemicube, mode == model::Visibility::ZBuffer));
    m_faceGroups = faceGroups(n);
    m_stretches.resize(static_cast<size_t>(n));
    m_done.resize(static_cast<size_t>(n));
    m_speed.assign(static_cast<size_t>(n), 1.0);
    m_paintSeconds.assign(static_cast<size_t>(n), 0.0);
    for (int t = 1; t < n; ++t)
        m_threads.emplace_back([this, t] { work(t); });
}

HemicubeRenderer::~HemicubeRenderer()
{
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_quit.store(true, std::memory_order_release);
    }
    m_wake.notify_all();
    for (std::thread& t : m_threads)
        t.join();
}

VisibilityStats HemicubeRenderer::stats() const
{
    VisibilityStats sum;
    for (const auto& p : m_painters)
        sum += p->stats();
    return sum;
}

void HemicubeRenderer::work(int thread)
{
    std::uint64_t seen = 0;
    for (;;) {
        const auto ready = [&] {
            return m_quit.load(std::memory_order_acquire) || m_round.load(std::memory_order_acquire) != seen;
        };
        if (!spinUntil(ready, kWorkerSpin)) {
            std::unique_lock<std::mutex> lock(m_mutex);
            m_wake.wait(lock, ready);
        }
        if (m_quit.load(std::memory_order_acquire))
            return;
        seen = m_round.load(std::memory_order_acquire);
        (*m_task)(thread);
        if (m_running.fetch_sub(1, std::memory_order_acq_rel) == 1) {
            std::lock_guard<std::mutex> lock(m_mutex);
            m_finished.notify_one();
        }
    }
}

void HemicubeRenderer::onEveryThread(const std::function<void(int)>& task)
{
    m_task = &task;
    m_running.store(static_cast<int>(m_threads.size()), std::memory_order_relaxed);
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_round.fetch_add(1, std::memory_order_release);
    }
    m_wake.notify_all();
    task(0);
    const auto finished = [&] { return m_running.load(std::memory_order_acquire) == 0; };
    if (!spinUntil(finished, kCallerSpin)) {
        std::unique_lock<std::mutex> lock(m_mutex);
        m_finished.wait(lock, finished);
    }
}

void HemicubeRenderer::parallelFor(size_t count, const std::function<void(size_t begin, size_t end)>& body)
{
    const size_t n = m_painters.size();
    if (n == 1 || count < 2) {
        body(0, count);
        return;
    }
    // Indices handed out one at a time to whichever thread is free: the
    // near field's receivers differ in cost by an order of magnitude (a
    // facing receiver against one polygon, a close one against each of the
    // shooter's elements at four points), and halves fixed in advance left
    // one thread waiting for the other most of the time.
    std::atomic<size_t> next{0};
    onEveryThread([&](int) {
        for (size_t i = next.fetch_add(1, std::memory_order_relaxed); i < count;
             i = next.fetch_add(1, std::memory_order_relaxed))
            body(i, i + 1);
    });
}

RenderSplit HemicubeRenderer::split() const
{
    if (m_forced)
        return *m_forced;
    if (timing())
        return m_timed[0].size() <= m_timed[1].size() ? RenderSplit::Order : RenderSplit::Faces;
    return m_kept;
}

bool HemicubeRenderer::timing() const
{
    return !m_forced && (m_timed[0].size() < kTimedShots || m_timed[1].size() < kTimedShots);
}

bool HemicubeRenderer::render(const ShooterFrame& frame, ItemBuffer& buffer, const std::atomic<bool>* cancel,
                              const Occluder& occluder)
{
    if (m_threads.empty())
        return m_painters.front()->render(frame, buffer, cancel, occluder);
    const RenderSplit s = split();
    const bool timed = timing();
    const Clock::time_point start = Clock::now();
    const bool done = s == RenderSplit::Order ? renderOrderSplit(frame, buffer, cancel, occluder)
                                              : renderFaceSplit(frame, buffer, cancel, occluder);
    if (timed && done) {
        m_timed[static_cast<size_t>(s)].push_back(std::chrono::duration<double>(Clock::now() - start).count());
        if (!timing()) {
            for (std::vector<double>& t : m_timed)
                std::ranges::nth_element(t, t.begin() + kTimedShots / 2);
            m_kept =
                m_timed[0][kTimedShots / 2] <= m_timed[1][kTimedShots / 2] ? RenderSplit::Order : RenderSplit::Faces;
        }
    }
    return done;
}

bool HemicubeRenderer::renderFaceSplit(const ShooterFrame& frame, ItemBuffer& buffer, const std::atomic<bool>* cancel,
                                       const Occluder& occluder)
{
    m_painters.front()->paintOrder(frame, m_order, occluder);
    onEveryThread([&](int t) {
        const auto i = static_cast<size_t>(t);
        m_done[i] = true;
        if (m_faceGroups[i] == 0)
            return;
        buffer.clear(m_faceGroups[i]);
        m_done[i] = m_painters[i]->paint(frame, m_order, buffer, cancel, m_faceGroups[i], occluder);
    });
    return std::ranges::count(m_done, 0) == 0;
}

bool HemicubeRenderer::renderOrderSplit(const ShooterFrame& frame, ItemBuffer& buffer, const std::atomic<bool>* cancel,
                                        const Occluder& occluder)
{
    m_painters.front()->paintOrder(frame, m_order, occluder);
    std::int64_t total = 0;
    for (const PaintRange& r : m_order)
        total += r.end - r.begin;
    // Each thread's share of the pieces in proportion to its speed so far.
    const size_t n = m_painters.size();
    double speedSum = 0.0;
    for (double v : m_speed)
        speedSum += v;
    m_ends.resize(n);
    double before = 0.0;
    for (size_t t = 0; t < n; ++t) {
        before += m_speed[t];
        m_ends[t] = t + 1 == n ? total : static_cast<std::int64_t>(static_cast<double>(total) * before / speedSum);
    }
    cutIntoStretches(m_order, m_ends, m_stretches);
    onEveryThread([&](int t) {
        const auto i = static_cast<size_t>(t);
        const Clock::time_point start = Clock::now();
        ItemBuffer& target = t == 0 ? buffer : m_later[i - 1];
        target.clear();
        m_done[i] = m_painters[i]->paint(frame, m_stretches[i], target, cancel, kAllHemicubeFaces, occluder);
        m_paintSeconds[i] = std::chrono::duration<double>(Clock::now() - start).count();
    });
    if (std::ranges::count(m_done, 0) > 0)
        return false;
    for (size_t t = 0; t < n; ++t) {
        const std::int64_t pieces = m_ends[t] - (t == 0 ? 0 : m_ends[t - 1]);
        if (pieces > 0 && m_paintSeconds[t] > 0.0)
            m_speed[t] = 0.75 * m_speed[t] + 0.25 * static_cast<double>(pieces) / m_paintSeconds[t];
    }
    onEveryThread([&](int t) {
        const int rows = buffer.rowCount(), threads = static_cast<int>(n);
        for (const ItemBuffer& later : m_later)
            buffer.mergeLater(later, t * rows / threads, (t + 1) * rows / threads);
    });
    return true;
}

} // namespace regio::solver
