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
    const int h = m_n / 2;
    const std::vector<float>& top = hemicube.topQuarter();
    const std::vector<float>& side = hemicube.sideHalf();
    const ItemId* ids = face(HemicubeFace::Top);
    for (int y = 0; y < m_n; ++y)
        accumulateRow(ids + y * m_n, top.data() + hemicube.mirrored(y) * h, h, perItem.data());
    for (int f = 1; f < kHemicubeFaceCount; ++f) {
        ids = face(static_cast<HemicubeFace>(f));
        for (int y = 0; y < h; ++y)
            accumulateRow(ids + y * m_n, side.data() + y * h, h, perItem.data());
    }
}

} // namespace regio::solver
