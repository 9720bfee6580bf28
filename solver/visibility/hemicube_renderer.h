#pragma once
// A shooter's hemicube rendered on one or more threads, in one of two ways.
//
// Order split: the shooter's paint order (Visibility::paintOrder: back to
// front for the painter, §5.6) is cut into as many consecutive stretches as
// there are threads. Each thread paints its stretch on all five faces into a
// buffer of its own with its own Visibility (its own vertex cache and
// rasteriser); the first paints into the caller's buffer. The buffers are
// then merged, every thread taking a share of the rows: a painted pixel of a
// later stretch wins in the painter (it is what one thread would have painted
// last), a strictly nearer one in the z-buffer. The stretches are cut by the
// pieces each thread painted per second in the shots before (pieces near the
// eye, late in the order, cover more pixels): the cut moves work, never
// pixels. Each piece is set up once; the cost is the merge, which grows with
// the pixels.
//
// Face split: the five faces are split into groups of equal pixel count (the
// top face holds N^2 pixels, each side N^2/2): two threads paint {top, +x}
// and {-x, +y, -y}; three or more paint {top}, {+x, -x}, {+y, -y}. Each
// group paints the whole order on its own faces of the one buffer. Nothing is
// merged, but every thread sets up the pieces that reach its faces, so the
// per-piece work is repeated.
//
// Which pays depends on the pixels per piece (the mode, the resolution, the
// scene): the renderer times both on its first shots, alternately, and keeps
// the one with the shorter median render (a median, because other programs
// on a busy machine make single renders slow). Either way every pixel ends up as one thread paints it, so the
// item buffer, and every form factor summed from it, is bit-identical for
// any thread count and either split.
//
// The calling thread does the first share of each step; the others run on
// threads the renderer keeps for its lifetime, woken once or twice per shot.
// A step lasts a fraction of a millisecond, less than waking a sleeping
// thread can take, so the threads spin a little while before they sleep.
#include "solver/prepare/prepared_scene.h"
#include "solver/visibility/hemicube.h"
#include "solver/visibility/item_buffer.h"
#include "solver/visibility/visibility.h"

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

namespace regio::solver {

// The number of threads a `threads` setting asks for: itself when positive,
// else every core the machine reports (at least 1).
int resolveThreadCount(int threads);

enum class RenderSplit { Order, Faces };

class HemicubeRenderer {
public:
    // Each thread past the first adds a whole buffer to clear and merge per
    // shot; more than this many cannot pay on hemicubes of a few hundred pixels.
    static constexpr int kMaxThreads = 8;

    // Keeps references to `scene` and `hemicube`, which must outlive it. Uses
    // min(threads, kMaxThreads) threads; 0 = all cores.
    HemicubeRenderer(const PreparedScene& scene, const Hemicube& hemicube, model::Visibility mode, int threads);
    ~HemicubeRenderer();
    HemicubeRenderer(const HemicubeRenderer&) = delete;
    HemicubeRenderer& operator=(const HemicubeRenderer&) = delete;

    int threads() const { return static_cast<int>(m_painters.size()); }
    ItemBuffer makeBuffer() const { return m_painters.front()->makeBuffer(); }

    // As Visibility::render: false if cancelled.
    bool render(const ShooterFrame& frame, ItemBuffer& buffer, const std::atomic<bool>* cancel = nullptr,
                const Occluder& occluder = {});

    // The split in use: while timing, the one the next shot takes.
    RenderSplit split() const;
    // Uses `split` from now on instead of timing both (tests, benchmarks).
    void forceSplit(RenderSplit split) { m_forced = split; }
    // The renders each split is timed on before the renderer keeps one.
    static constexpr size_t kTimedShots = 16;

    // Summed over the threads: each piece and region is counted once.
    VisibilityStats stats() const;

    // Runs body(i, i + 1) for every i of [0, count) on the renderer's
    // threads, each index once, handed out in increasing order to whichever
    // thread is free, and returns when all are done: other work of a shot
    // (the near field's contour formula) uses the threads the render keeps.
    void parallelFor(size_t count, const std::function<void(size_t begin, size_t end)>& body);

private:
    // Runs task(thread) on every thread, the caller being thread 0, and
    // returns when all have finished.
    void onEveryThread(const std::function<void(int)>& task);
    void work(int thread);
    bool renderOrderSplit(const ShooterFrame& frame, ItemBuffer& buffer, const std::atomic<bool>* cancel,
                          const Occluder& occluder);
    bool renderFaceSplit(const ShooterFrame& frame, ItemBuffer& buffer, const std::atomic<bool>* cancel,
                         const Occluder& occluder);

    std::vector<std::unique_ptr<Visibility>> m_painters; // one per thread
    std::vector<ItemBuffer> m_later;                     // threads 1..n-1 paint here
    std::vector<PaintRange> m_order;
    std::vector<std::vector<PaintRange>> m_stretches; // one per thread
    std::vector<char> m_done;                         // per thread: painted to the end
    std::vector<double> m_speed;                      // per thread: pieces per second, smoothed
    std::vector<double> m_paintSeconds;               // per thread: the last stretch's time
    std::vector<std::int64_t> m_ends;                 // per thread: its stretch ends after this piece
    std::vector<std::thread> m_threads;               // threads 1..n-1
    std::vector<HemicubeFaceSet> m_faceGroups;        // face split: per thread (none past the groups)

    std::optional<RenderSplit> m_forced;
    bool timing() const;
    std::vector<double> m_timed[2]; // seconds of the renders timed, per split
    RenderSplit m_kept = RenderSplit::Order;

    // The task handed to the threads: m_task is written before m_round is
    // raised. m_mutex and the condition variables serve threads that stopped
    // spinning.
    std::mutex m_mutex;
    std::condition_variable m_wake;
    std::condition_variable m_finished;
    std::atomic<std::uint64_t> m_round{0};
    std::atomic<int> m_running{0};
    std::atomic<bool> m_quit{false};
    const std::function<void(int)>* m_task = nullptr;
};

} // namespace regio::solver
