#include "solver/shooting/row_arena.h"

#include <algorithm>
#include <cstdlib>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace regio::solver {

namespace {
constexpr std::size_t kHugePage = std::size_t(2) << 20;
constexpr std::size_t kChunkBytes = std::size_t(32) << 20; // a dozen rows of a 100 000-element scene

std::size_t roundUp(std::size_t n, std::size_t to) { return (n + to - 1) / to * to; }
} // namespace

RowArena::~RowArena()
{
    for (const Chunk& c : m_chunks)
        std::free(c.data);
}

void RowArena::reset()
{
    for (Chunk& c : m_chunks)
        c.used = 0;
    m_current = 0;
}

std::size_t RowArena::capacity() const
{
    std::size_t total = 0;
    for (const Chunk& c : m_chunks)
        total += c.size;
    return total;
}

void* RowArena::allocate(std::size_t bytes, std::size_t alignment)
{
    for (; m_current < m_chunks.size(); ++m_current) {
        Chunk& c = m_chunks[m_current];
        const std::size_t start = roundUp(c.used, alignment);
        if (start + bytes <= c.size) {
            c.used = start + bytes;
            return c.data + start;
        }
    }
    // A new chunk, larger when one row needs more.
    Chunk c;
    c.size = roundUp(std::max(bytes, kChunkBytes), kHugePage);
    c.data = static_cast<std::byte*>(std::aligned_alloc(kHugePage, c.size));
    if (!c.data)
        throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    // Advice only: without huge pages the chunk works the same, page by page.
    madvise(c.data, c.size, MADV_HUGEPAGE);
#endif
    c.used = bytes;
    m_chunks.push_back(c);
    m_current = m_chunks.size() - 1;
    return c.data;
}

} // namespace regio::solver
