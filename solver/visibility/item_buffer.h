#pragma once
// The item buffer of one hemicube: for every pixel of the five faces, the id
// of the element seen through it (§5.6, "scan-line filled with the element
// identifier"). Two ids are reserved: nothing seen (the sky of an open scene)
// and a blocker that receives nothing (a back-facing surface, Appendix A's
// skipped nodes, which Regio paints: traversal.h). Element e is stored as e + 2,
// so summing delta form factors per id needs no branch: slots 0 and 1 of the
// result collect what escaped and what hit back faces.
#include "solver/visibility/hemicube.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace regio::solver {

using ItemId = std::uint32_t;
inline constexpr ItemId kEmptyItem = 0;
inline constexpr ItemId kBlockerItem = 1;
inline constexpr ItemId kFirstElementItem = 2;
// Marks the pixels that a stretch of the paint order left alone, in the
// buffers a multi-threaded render merges (never in a finished buffer).
inline constexpr ItemId kUnpaintedItem = 0xFFFFFFFFu;
inline constexpr ItemId itemOfElement(std::uint32_t element) { return element + kFirstElementItem; }

class ItemBuffer {
public:
    ItemBuffer() = default;
    // Buffers for a hemicube; `withDepth` adds the z-buffer's depth plane.
    explicit ItemBuffer(const Hemicube& hemicube, bool withDepth = false);

    int resolution() const { return m_n; }
    bool hasDepth() const { return !m_depth.empty(); }

    // Resets every pixel of the faces in `faces` (bit f = face f; all five
    // by default) to kEmptyItem, and their depth to "infinitely far". A
    // stretch buffer resets all its painted pixels to kUnpaintedItem.
    void clear(std::uint32_t faces = 0x1Fu);

    // A buffer for a stretch of a paint order painted apart (HemicubeRenderer):
    // its pixels start as kUnpaintedItem, it records the span of columns
    // painted in every row (painted()), and clear() resets only those.
    static ItemBuffer forStretch(const Hemicube& hemicube, bool withDepth);
    // Records that [x0, x1) of a row was painted; only a stretch buffer keeps it.
    void painted(HemicubeFace f, int row, int x0, int x1)
    {
        if (m_spans.empty())
            return;
        Span& s = m_spans[static_cast<size_t>(rowOf(f, row))];
        s.begin = x0 < s.begin ? x0 : s.begin;
        s.end = x1 > s.end ? x1 : s.end;
    }

    // All faces' rows, top face first: row r holds pixels [r n, (r + 1) n) of all().
    int rowCount() const { return m_n + (kHemicubeFaceCount - 1) * (m_n / 2); }
    // Merges rows [rowBegin, rowEnd) of a stretch buffer painted by the
    // stretch of the same paint order that follows this buffer's: painter
    // buffers take its painted pixels (later paints win); z-buffers take its
    // pixels that are strictly nearer (equal depth keeps the earlier piece,
    // as one depth test over the whole order does). The result is the buffer
    // one render of both stretches paints, pixel for pixel.
    void mergeLater(const ItemBuffer& later, int rowBegin, int rowEnd);

    ItemId* face(HemicubeFace f) { return m_ids.data() + m_offset[static_cast<int>(f)]; }
    const ItemId* face(HemicubeFace f) const { return m_ids.data() + m_offset[static_cast<int>(f)]; }
    // Depth stored as 1/w (w = distance along the face's axis): larger is nearer.
    float* depth(HemicubeFace f) { return m_depth.data() + m_offset[static_cast<int>(f)]; }
    int width(HemicubeFace) const { return m_n; }
    int height(HemicubeFace f) const { return f == HemicubeFace::Top ? m_n : m_n / 2; }
    ItemId at(HemicubeFace f, int x, int y) const { return face(f)[y * m_n + x]; }
    std::span<const ItemId> all() const { return m_ids; }

    // Adds each pixel's delta form factor to perItem[id]; perItem must hold
    // every id painted. Consecutive pixels of one id are summed before the
    // scattered add: runs are long, and the add is the random access.
    void accumulate(const Hemicube& hemicube, std::span<double> perItem) const;
    // The same for the buffer's rows [rowBegin, rowEnd) only (rows as in
    // mergeLater: the top face's, then each side face's in turn).
    void accumulateRows(const Hemicube& hemicube, std::span<double> perItem, int rowBegin, int rowEnd) const;

private:
    struct Span {
        int begin = 0;
        int end = 0;
    };
    void clearStretch();
    int rowOf(HemicubeFace f, int row) const { return (m_offset[static_cast<int>(f)] / m_n) + row; }

    int m_n = 0;
    int m_offset[kHemicubeFaceCount]{};
    std::vector<ItemId> m_ids;
    std::vector<float> m_depth;
    std::vector<Span> m_spans; // stretch buffers: per row, the columns painted since clear()
};

} // namespace regio::solver
