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
constexpr std::size_t kSmallPage = 4096;

std::size_t roundUp(std::size_t n, std::size_t to) { return (n + to - 1) / to * to; }

// A 2 MiB-aligned block offered for huge pages; nullptr when there is no memory.
std::byte* allocateChunk(std::size_t size)
{
    auto* data = static_cast<std::byte*>(std::aligned_alloc(kHugePage, size));
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    // Advice only: without huge pages the chunk works the same, page by page.
    if (data)
        madvise(data, size, MADV_HUGEPAGE);
#endif
    return data;
}
} // namespace

RowArena::RowArena(std::size_t aheadLimit)
    : m_aheadLimit(aheadLimit)
{
}

RowArena::~RowArena()
{
    std::free(takeReadied().data);
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
    std::size_t total = m_readied.size;
    for (const Chunk& c : m_chunks)
        total += c.size;
    return total;
}

RowArena::Chunk RowArena::takeReadied()
{
    if (m_readying.joinable())
        m_readying.join();
    Chunk c = m_readied;
    m_readied = Chunk{};
    return c;
}

void RowArena::readyAhead()
{
    if (m_readying.joinable() || m_readied.size > 0 || capacity() + kChunkBytes > m_aheadLimit)
        return;
    m_readied.size = kChunkBytes;
    m_readying = std::thread([this] {
        std::byte* data = allocateChunk(kChunkBytes);
        if (data)
            for (std::size_t at = 0; at < kChunkBytes; at += kSmallPage)
                data[at] = std::byte{0}; // the first touch maps the page
        m_readied.data = data;           // read only after join()
    });
}

void* RowArena::allocate(std::size_t bytes, std::size_t alignment)
{
    for (; m_current < m_chunks.size(); ++m_current) {
        Chunk& c = m_chunks[m_current];
        const std::size_t start = roundUp(c.used, alignment);
        if (start + bytes <= c.size) {
            c.used = start + bytes;
            // Half way through the last chunk, the next is readied: a
            // small scene, whose rows fit one chunk, never readies one.
            if (2 * c.used > c.size && m_current + 1 == m_chunks.size())
                readyAhead();
            return c.data + start;
        }
    }
    // A new chunk: the one readied ahead when there is one and the bytes
    // fit, else one made now, larger when one row needs more.
    Chunk c;
    if (bytes <= kChunkBytes)
        c = takeReadied();
    if (!c.data) {
        c.size = roundUp(std::max(bytes, kChunkBytes), kHugePage);
        c.data = allocateChunk(c.size);
        if (!c.data)
            throw std::bad_alloc();
    }
    c.used = bytes;
    m_chunks.push_back(c);
    m_current = m_chunks.size() - 1;
    if (2 * c.used > c.size)
        readyAhead();
    return c.data;
}

} // namespace regio::solver
