#pragma once
// Hemicube visibility: fills an item buffer with what a shooter sees.
//
// Painter (the paper's method, §5.6 and Appendix A): the regional tree and the
// regional BSP trees are walked back to front from the shooter's centre and
// every element is painted in that order; later elements overwrite earlier
// ones, no depth is stored or interpolated. Regions whose contents lie behind
// the shooter's plane are culled whole. Elements facing away from the shooter
// are painted with kBlockerItem: surfaces are opaque from both sides.
//
// Z-buffer (the reference): the same projection, clipping and pixel rule, any
// order, a depth test per pixel (depth = 1/w, exact from the element plane).
//
// Both share one per-shooter vertex cache: each vertex is transformed into the
// shooter's frame and outcoded once per shooter, whatever number of elements
// share it (DESIGN.md speed notes).
#include "solver/hemicube.h"
#include "solver/hemicube_raster.h"
#include "solver/item_buffer.h"
#include "solver/prepared_scene.h"

#include <atomic>
#include <cstdint>
#include <vector>

namespace regio::solver {

enum class VisibilityMode { Painter, ZBuffer };

const char* visibilityModeName(VisibilityMode mode);

struct VisibilityStats {
    std::int64_t regionsCulled = 0;  // whole regions skipped (behind the shooter plane)
    std::int64_t elementsVisited = 0;
    std::int64_t elementsRasterised = 0; // not rejected by outcodes
};

class Visibility {
public:
    // Keeps a reference to `scene` and `hemicube`; both must outlive it. The
    // scene may grow (adaptive subdivision): caches follow its vertex count.
    Visibility(const PreparedScene& scene, const Hemicube& hemicube, VisibilityMode mode);

    VisibilityMode mode() const { return m_mode; }
    // The item buffer this visibility writes; it has a depth plane in z-buffer mode.
    ItemBuffer makeBuffer() const;

    // Renders the view of a shooter sitting on the plane `frame.n` through
    // `frame.origin`. When `cancel` becomes true the render stops early and
    // returns false (the buffer is then incomplete).
    bool render(const ShooterFrame& frame, ItemBuffer& buffer, const std::atomic<bool>* cancel = nullptr);

    const VisibilityStats& stats() const { return m_stats; }

private:
    void prepareFrame(const ShooterFrame& frame);
    void touch(int vertex);
    template <class Paint>
    void rasteriseElement(int element, Paint&& paint);
    void paintElement(int element, ItemId id, ItemBuffer& buffer);
    void depthTestElement(int element, ItemId id, ItemBuffer& buffer);
    bool regionCulled(int region) const;

    const PreparedScene& m_scene;
    const Hemicube& m_hemicube;
    VisibilityMode m_mode;
    HemicubeRaster m_raster;
    ShooterFrame m_frame;
    Plane m_shooterPlane;

    // Per-vertex cache, valid for the shooter whose stamp it carries.
    std::vector<Vec3> m_local;
    std::vector<std::uint32_t> m_outcode;
    std::vector<FixedVertex> m_projected; // kHemicubeFaceCount per vertex
    std::vector<std::uint32_t> m_stamp;
    std::uint32_t m_currentStamp = 0;
    std::vector<char> m_regionCulled; // z-buffer: per region, for the current shooter

    VisibilityStats m_stats;
};

} // namespace regio::solver
