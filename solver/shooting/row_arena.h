#pragma once
// Memory for the kept form-factor rows (shooting.h): a few large chunks
// handed out front to back and all taken back at once when the mesh changes.
//
// Why not a vector per row: a row of a 20 000-element room is a few hundred
// kilobytes, fresh memory that the kernel maps page by page on first touch,
// and a solve keeps a row per patch; on the Cornell box those page faults
// took a tenth of the solve. Chunks are 2 MiB-aligned and offered to the
// kernel for huge pages (madvise, Linux), so one fault maps 2 MiB; and they
// outlive reset(), so the pages faulted in for one mesh serve the next.
//
// Even so, the first touch of fresh memory costs the kernel its zeroing
// (and, in a virtual machine, the host its backing): about 0.9 s per
// 320 MB on the machine of docs/performance.md. So once the last chunk is
// half full, the arena readies the next one, allocated and touched on a
// thread of its own while the solve goes on: the solve's threads are idle
// for part of every shot, and there the faults cost nothing. It never
// readies a chunk that would take its capacity over the limit it is given.
#include <cstddef>
#include <cstring>
#include <span>
#include <thread>
#include <type_traits>
#include <vector>

namespace regio::solver {

class RowArena {
public:
    // `aheadLimit`: the capacity up to which the arena readies chunks ahead
    // (the rows' budget; 0 readies none).
    explicit RowArena(std::size_t aheadLimit = 0);
    RowArena(const RowArena&) = delete;
    RowArena& operator=(const RowArena&) = delete;
    ~RowArena();

    // A copy of `values` in the arena, valid until reset().
    template <class T>
    std::span<const T> keep(std::span<const T> values)
    {
        static_assert(std::is_trivially_copyable_v<T>);
        if (values.empty())
            return {};
        void* memory = allocate(values.size_bytes(), alignof(T));
        std::memcpy(memory, values.data(), values.size_bytes());
        return {static_cast<const T*>(memory), values.size()};
    }
    // Takes back everything kept; the chunks stay for what comes next.
    void reset();
    // Bytes of chunk memory held (kept, free, or readied ahead).
    std::size_t capacity() const;

private:
    struct Chunk {
        std::byte* data = nullptr;
        std::size_t size = 0;
        std::size_t used = 0;
    };
    void* allocate(std::size_t bytes, std::size_t alignment);
    // Starts readying the next chunk when the limit allows one more.
    void readyAhead();
    // The chunk readied ahead, waiting for its thread; none when there is none.
    Chunk takeReadied();

    std::vector<Chunk> m_chunks;
    std::size_t m_current = 0; // the chunk being filled
    std::size_t m_aheadLimit = 0;
    std::thread m_readying; // allocates and touches m_readied
    Chunk m_readied;
};

} // namespace regio::solver
