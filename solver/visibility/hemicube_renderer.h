#pragma once
// A shooter's hemicube rendered on one or more threads.
//
// The five faces are split into groups of equal pixel count (the top face
// holds N^2 pixels, each side N^2/2): one thread paints everything; two paint
// {top, +x} and {-x, +y, -y}; three or more paint {top}, {+x, -x}, {+y, -y}.
// Each group has its own Visibility (its own vertex cache and rasteriser)
// that walks the same back-to-front order (§5.6) and paints its own faces of
// the one item buffer. A face is painted by the same code in the same order
// whatever the split, so the item buffer, and every form factor summed from
// it, is bit-identical for any thread count.
//
// The calling thread renders the first group; the others run on threads the
// renderer keeps for its lifetime, woken once per shot.
#include "solver/prepare/prepared_scene.h"
#include "solver/visibility/hemicube.h"
#include "solver/visibility/item_buffer.h"
#include "solver/visibility/visibility.h"

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace regio::solver {

// The number of threads a `threads` setting asks for: itself when positive,
// else every core the machine reports (at least 1).
int resolveThreadCount(int threads);

class HemicubeRenderer {
public:
    // Keeps references to `scene` and `hemicube`, which must outlive it. Uses
    // min(threads, 3) threads (more cannot split five faces evenly); 0 = all cores.
    HemicubeRenderer(const PreparedScene& scene, const Hemicube& hemicube, model::Visibility mode, int threads);
    ~HemicubeRenderer();
    HemicubeRenderer(const HemicubeRenderer&) = delete;
    HemicubeRenderer& operator=(const HemicubeRenderer&) = delete;

    int threads() const { return static_cast<int>(m_groups.size()); }
    ItemBuffer makeBuffer() const { return m_groups.front()->makeBuffer(); }

    // As Visibility::render, over all five faces: false if cancelled.
    bool render(const ShooterFrame& frame, ItemBuffer& buffer, const std::atomic<bool>* cancel = nullptr);

    // Counted once per piece (by the group that owns the top face).
    const VisibilityStats& stats() const { return m_groups.front()->stats(); }

private:
    void work(size_t group);

    std::vector<std::unique_ptr<Visibility>> m_groups;
    std::vector<std::thread> m_threads; // for groups 1..n-1

    // The shot handed to the threads, guarded by m_mutex.
    std::mutex m_mutex;
    std::condition_variable m_wake;
    std::condition_variable m_finished;
    std::uint64_t m_shot = 0;
    int m_running = 0;
    bool m_quit = false;
    const ShooterFrame* m_frame = nullptr;
    ItemBuffer* m_buffer = nullptr;
    const std::atomic<bool>* m_cancel = nullptr;
    bool m_cancelled = false;
};

} // namespace regio::solver
