#pragma once
// A uniform grid of point ids, to find the points near a point: what the
// smooth shading welds, and where the exact direct shading may put a corner.
#include "solver/prepare/prepared_scene.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace regio::output {

// A grid cell's hash (FNV-1a over its three coordinates).
struct CellHash {
    size_t operator()(const std::array<int64_t, 3>& c) const
    {
        uint64_t h = 1469598103934665603ull;
        for (int64_t v : c)
            h = (h ^ static_cast<uint64_t>(v)) * 1099511628211ull;
        return static_cast<size_t>(h);
    }
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
    void insert(const Vec3& p, int id) { m_cells[cellOf(p)].push_back(id); }

    template <typename F>
    void forNear(const Vec3& p, F&& visit) const
    {
        const auto c = cellOf(p);
        for (int64_t dx = -1; dx <= 1; ++dx)
            for (int64_t dy = -1; dy <= 1; ++dy)
                for (int64_t dz = -1; dz <= 1; ++dz) {
                    const auto it = m_cells.find({c[0] + dx, c[1] + dy, c[2] + dz});
                    if (it != m_cells.end())
                        for (int id : it->second)
                            visit(id);
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
                    const auto it = m_cells.find({low[0] + dx, low[1] + dy, low[2] + dz});
                    if (it != m_cells.end())
                        for (int id : it->second)
                            visit(id);
                }
    }

private:
    double m_cell;
    std::unordered_map<std::array<int64_t, 3>, std::vector<int>, CellHash> m_cells;
};

} // namespace regio::output
