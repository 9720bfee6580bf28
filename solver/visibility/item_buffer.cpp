#include "solver/visibility/item_buffer.h"

#include <algorithm>

namespace regio::solver {

ItemBuffer::ItemBuffer(const Hemicube& hemicube, bool withDepth)
    : m_n(hemicube.resolution())
{
    for (int f = 0; f < kHemicubeFaceCount; ++f)
        m_offset[f] = hemicube.faceOffset(static_cast<HemicubeFace>(f));
    m_ids.assign(static_cast<size_t>(hemicube.totalPixelCount()), kEmptyItem);
    if (withDepth)
        m_depth.assign(m_ids.size(), 0.0f);
}

void ItemBuffer::clear(std::uint32_t faces)
{
    if (!m_spans.empty()) {
        clearStretch();
        return;
    }
    for (int f = 0; f < kHemicubeFaceCount; ++f) {
        if (!(faces & (1u << f)))
            continue;
        const auto begin = static_cast<std::ptrdiff_t>(m_offset[f]);
        const auto end = begin + static_cast<std::ptrdiff_t>(m_n) * height(static_cast<HemicubeFace>(f));
        std::fill(m_ids.begin() + begin, m_ids.begin() + end, kEmptyItem);
        if (!m_depth.empty())
            std::fill(m_depth.begin() + begin, m_depth.begin() + end, 0.0f);
    }
}

ItemBuffer ItemBuffer::forStretch(const Hemicube& hemicube, bool withDepth)
{
    ItemBuffer b(hemicube, withDepth);
    std::fill(b.m_ids.begin(), b.m_ids.end(), kUnpaintedItem);
    b.m_spans.assign(static_cast<size_t>(b.rowCount()), Span{b.m_n, 0});
    return b;
}

void ItemBuffer::clearStretch()
{
    const auto n = static_cast<size_t>(m_n);
    for (size_t r = 0; r < m_spans.size(); ++r) {
        Span& s = m_spans[r];
        if (s.begin >= s.end)
            continue;
        const auto b = r * n + static_cast<size_t>(s.begin), e = r * n + static_cast<size_t>(s.end);
        std::fill(m_ids.begin() + static_cast<std::ptrdiff_t>(b), m_ids.begin() + static_cast<std::ptrdiff_t>(e),
                  kUnpaintedItem);
        if (!m_depth.empty())
            std::fill(m_depth.begin() + static_cast<std::ptrdiff_t>(b),
                      m_depth.begin() + static_cast<std::ptrdiff_t>(e), 0.0f);
        s = Span{m_n, 0};
    }
}

void ItemBuffer::mergeLater(const ItemBuffer& later, int rowBegin, int rowEnd)
{
    const auto n = static_cast<size_t>(m_n);
    for (auto r = static_cast<size_t>(rowBegin); r < static_cast<size_t>(rowEnd); ++r) {
        const Span s = later.m_spans[r];
        const size_t begin = r * n + static_cast<size_t>(s.begin), end = r * n + static_cast<size_t>(s.end);
        ItemId* ids = m_ids.data();
        const ItemId* laterIds = later.m_ids.data();
        // Branch-free loops, so that the compiler vectorises them.
        if (m_depth.empty()) {
            for (size_t i = begin; i < end; ++i)
                ids[i] = laterIds[i] != kUnpaintedItem ? laterIds[i] : ids[i];
            continue;
        }
        float* depth = m_depth.data();
        const float* laterDepth = later.m_depth.data();
        for (size_t i = begin; i < end; ++i) {
            const bool nearer = laterDepth[i] > depth[i];
            ids[i] = nearer ? laterIds[i] : ids[i];
            depth[i] = nearer ? laterDepth[i] : depth[i];
        }
    }
}

namespace {

// One row: the left half mirrors the table row, the right half reads it forwards.
inline void accumulateRow(const ItemId* ids, const float* tableRow, int half, double* perItem)
{
    ItemId run = ids[0];
    double sum = 0.0;
    for (int x = 0; x < 2 * half; ++x) {
        const ItemId id = ids[x];
        const float d = x < half ? tableRow[half - 1 - x] : tableRow[x - half];
        if (id != run) {
            perItem[run] += sum;
            run = id;
            sum = 0.0;
        }
        sum += d;
    }
    perItem[run] += sum;
}

} // namespace

void ItemBuffer::accumulate(const Hemicube& hemicube, std::span<double> perItem) const
{
    accumulateRows(hemicube, perItem, 0, rowCount());
}

void ItemBuffer::accumulateRows(const Hemicube& hemicube, std::span<double> perItem, int rowBegin, int rowEnd) const
{
    const int h = m_n / 2;
    const std::vector<float>& top = hemicube.topQuarter();
    const std::vector<float>& side = hemicube.sideHalf();
    for (int f = 0; f < kHemicubeFaceCount; ++f) {
        const auto face = static_cast<HemicubeFace>(f);
        const int first = rowOf(face, 0);
        const int begin = std::max(rowBegin, first) - first, end = std::min(rowEnd, first + height(face)) - first;
        const ItemId* ids = this->face(face);
        for (int y = begin; y < end; ++y)
            accumulateRow(ids + y * m_n,
                          face == HemicubeFace::Top ? top.data() + hemicube.mirrored(y) * h : side.data() + y * h, h,
                          perItem.data());
    }
}

} // namespace regio::solver
