#pragma once
// A uniform grid of point ids, to find the points near a point: what the
// smooth shading welds, and where the exact direct shading may put a corner.
#include "model/types.h"
#include "output/flat_index.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace regio::output {

using model::Vec3;

// A grid cell's hash.
struct CellHash {
    std::uint64_t operator()(const std::array<std::int64_t, 3>& c) const { return hashIntegers({c[0], c[1], c[2]}); }
};

// Lookups visit the 3 x 3 x 3 cells around a point, so everything within
// one cell size of it is found.
class PointGrid {
public:
    explicit PointGrid(double cell)
        : m_cell(cell)
    {
    }

    std::array<int64_t, 3> cellOf(const Vec3& p) const
    {
        return {static_cast<int64_t>(std::floor(p.x / m_cell)), static_cast<int64_t>(std::floor(p.y / m_cell)),
                static_cast<int64_t>(std::floor(p.z / m_cell))};
    }
    void insert(const Vec3& p, int id)
    {
        const int entry = static_cast<int>(m_entries.size());
        m_entries.push_back({id, -1});
        const auto [cell, added] = m_cells.insert(cellOf(p));
        if (added) {
            m_chains.push_back({entry, entry});
        } else {
            m_entries[static_cast<size_t>(m_chains[cell].last)].next = entry;
            m_chains[cell].last = entry;
        }
    }

    template <typename F>
    void forNear(const Vec3& p, F&& visit) const
    {
        const auto c = cellOf(p);
        for (int64_t dx = -1; dx <= 1; ++dx)
            for (int64_t dy = -1; dy <= 1; ++dy)
                for (int64_t dz = -1; dz <= 1; ++dz) {
                    visitCell({c[0] + dx, c[1] + dy, c[2] + dz}, visit);
                }
    }

    // As forNear, for points within half a cell of p only: the 2 x 2 x 2
    // cells nearest to it (on each axis the cell it is in and the
    // neighbour on the side of the cell's middle it lies on).
    template <typename F>
    void forNearest(const Vec3& p, F&& visit) const
    {
        const auto c = cellOf(p);
        std::array<int64_t, 3> low{};
        for (size_t k = 0; k < 3; ++k)
            low[k] = p[static_cast<glm::length_t>(k)] / m_cell - static_cast<double>(c[k]) < 0.5 ? c[k] - 1 : c[k];
        for (int64_t dx = 0; dx <= 1; ++dx)
            for (int64_t dy = 0; dy <= 1; ++dy)
                for (int64_t dz = 0; dz <= 1; ++dz) {
                    visitCell({low[0] + dx, low[1] + dy, low[2] + dz}, visit);
                }
    }

private:
    // A cell's points, in the order they were inserted: a chain of entries.
    struct Chain {
        int first = -1, last = -1;
    };
    struct Entry {
        int id;
        int next;
    };

    template <typename F>
    void visitCell(const std::array<int64_t, 3>& cell, F& visit) const
    {
        if (const uint32_t found = m_cells.find(cell); found != m_cells.kNone)
            for (int e = m_chains[found].first; e >= 0; e = m_entries[static_cast<size_t>(e)].next)
                visit(m_entries[static_cast<size_t>(e)].id);
    }

    double m_cell;
    FlatIndex<std::array<int64_t, 3>, CellHash> m_cells;
    std::vector<Chain> m_chains; // per cell
    std::vector<Entry> m_entries;
};

} // namespace regio::output
