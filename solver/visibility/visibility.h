#pragma once
// Hemicube visibility: fills an item buffer with what a shooter sees.
//
// Painter (the paper's method, §5.6 and Appendix A): the regional tree and the
// regional BSP trees are walked back to front from the shooter's centre and
// every element is painted in that order, as its pieces (solver/prepare/pieces.h)
// node by node; later pieces overwrite earlier ones, no depth is stored or
// interpolated. Regions whose contents lie behind the shooter's plane are
// culled whole, and so are the nodes whose pieces all lie behind that plane
// (solver/visibility/node_culling.h). Pieces facing away from the shooter are painted with
// kBlockerItem: surfaces are opaque from both sides.
//
// Inside a node, coplanar receivers and blockers overlap where two surfaces
// touch; the order decides who wins (forEachPaintRange): back faces of open
// parts first, then the receivers, then back faces of solids. So a thin
// two-sided wall receives on the side that faces the eye, and a face lying on
// a solid (the bottom of a box standing on a box, and the top it stands on)
// receives nothing there: it faces into that solid. From an eye outside
// every solid (and inside every room built as one closed part) the closed
// parts' back faces are hidden behind their own front faces and are not
// painted at all (solver/visibility/closed_back_faces.h). Given a face just
// in front of the eye (the lamp's top under a ceiling patch in a gap), what
// lies in its shadow is not painted either (solver/visibility/shadow_volume.h).
//
// Z-buffer (the reference): the same projection, clipping and pixel rule, any
// order, a depth test per pixel (depth = 1/w, exact from the element plane).
//
// Both share one per-shooter vertex cache: each vertex is transformed into the
// shooter's frame and outcoded once per shooter, whatever number of elements
// share it (docs/performance.md).
//
// A render is two steps: the paint order (the ranges of pieces in the order
// they are painted, culled regions left out) and the painting of a stretch of
// that order. Several Visibility objects can share a render on several
// threads (solver/visibility/hemicube_renderer.h) in two ways: each paints a
// consecutive stretch of the order into a buffer of its own, merged after;
// or each owns some of the five faces (a face set) and paints the whole
// order on those faces only, leaving the others' pixels alone.
#include "model/scene.h"
#include "solver/prepare/prepared_scene.h"
#include "solver/visibility/closed_back_faces.h"
#include "solver/visibility/hemicube.h"
#include "solver/visibility/hemicube_raster.h"
#include "solver/visibility/item_buffer.h"
#include "solver/visibility/shadow_volume.h"

#include <atomic>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace regio::solver {

// The painter's order inside one BSP node: calls op(begin, end, receives)
// for the node's piece ranges in paint order (see the top of this file and
// prepared_scene.h for the groups [F solid | F open | O open | O solid]).
// Without `solidBacks` the closed parts' back faces are left out
// (solver/visibility/closed_back_faces.h says when that changes nothing).
template <class Op>
inline void forEachPaintRange(const BspNode& node, bool eyeInFront, bool solidBacks, Op&& op)
{
    const int begin = node.firstPiece, end = node.firstPiece + node.pieceCount;
    const int forwardEnd = begin + node.forwardPieces;
    const int forwardSolidEnd = begin + node.forwardSolidPieces;
    const int oppositeSolidBegin = end - node.oppositeSolidPieces;
    if (eyeInFront) {
        op(forwardEnd, oppositeSolidBegin, false); // O open: blockers
        op(begin, forwardEnd, true);               // F: receivers
        if (solidBacks)
            op(oppositeSolidBegin, end, false); // O solid: blockers
    } else {
        op(forwardSolidEnd, forwardEnd, false); // F open: blockers
        op(forwardEnd, end, true);              // O: receivers
        if (solidBacks)
            op(begin, forwardSolidEnd, false); // F solid: blockers
    }
}

// A run of consecutive pieces in paint order. The painter paints them as
// receivers or as blockers; the z-buffer decides per piece by its facing.
struct PaintRange {
    std::int32_t begin = 0;
    std::int32_t end = 0;
    bool receives = true;
};

// A set of hemicube faces: bit f is face f.
using HemicubeFaceSet = std::uint32_t;
inline constexpr HemicubeFaceSet kAllHemicubeFaces = (1u << kHemicubeFaceCount) - 1;
inline constexpr HemicubeFaceSet faceBit(HemicubeFace f) { return 1u << static_cast<int>(f); }

// The hemicube frame of a shooting patch (§5.6): at its centroid, on its
// plane, turned about the normal by an angle that follows from where the
// centroid lies (visibility.cpp says why). Every shot, view and order of a
// patch uses this one frame.
ShooterFrame shooterFrameOfPatch(const PreparedScene& scene, int patch);
// The same frame at any point of a plane with unit normal `n` (a patch shot
// from several points: solver/shooting/shooter_points.h).
ShooterFrame shooterFrameAt(const Vec3& point, const Vec3& n);

struct VisibilityStats {
    std::int64_t regionsCulled = 0; // whole regions skipped (behind the shooter plane)
    // Counted per painted piece triangle (solver/prepare/pieces.h); most elements are
    // one piece.
    std::int64_t elementsVisited = 0;
    std::int64_t elementsRasterised = 0; // not rejected by outcodes

    VisibilityStats& operator+=(const VisibilityStats& other)
    {
        regionsCulled += other.regionsCulled;
        elementsVisited += other.elementsVisited;
        elementsRasterised += other.elementsRasterised;
        return *this;
    }
};

class Visibility {
public:
    // Keeps a reference to `scene` and `hemicube`; both must outlive it. The
    // scene may grow (adaptive subdivision): caches follow its vertex count.
    Visibility(const PreparedScene& scene, const Hemicube& hemicube, model::Visibility mode);

    model::Visibility mode() const { return m_mode; }
    // The item buffer this visibility writes; it has a depth plane in z-buffer mode.
    ItemBuffer makeBuffer() const;

    // Renders the view of a shooter sitting on the plane `frame.n` through
    // `frame.origin` into `buffer` (cleared first): paintOrder, then paint.
    // When `cancel` becomes true the render stops early and returns false (the
    // buffer is then incomplete).
    // With an `occluder` (a face standing just in front of the eye), what
    // lies in its shadow volume is left out (shadow_volume.h): the same pixels.
    bool render(const ShooterFrame& frame, ItemBuffer& buffer, const std::atomic<bool>* cancel = nullptr,
                const Occluder& occluder = {});

    // The shooter's paint order: the painter's back-to-front node order
    // (§5.6, Appendix A) split into forEachPaintRange's ranges, or the
    // z-buffer's node array order; regions behind the shooter's plane are
    // left out (and counted in stats().regionsCulled).
    void paintOrder(const ShooterFrame& frame, std::vector<PaintRange>& order, const Occluder& occluder = {});
    // Paints `ranges` (a stretch of the shooter's paint order) on the faces
    // in `faces` over what `buffer` holds, without clearing it, and leaves the
    // other faces' pixels alone; false if cancelled. The pieces count in
    // stats() when `faces` holds the top face (once each in a face split).
    bool paint(const ShooterFrame& frame, std::span<const PaintRange> ranges, ItemBuffer& buffer,
               const std::atomic<bool>* cancel = nullptr, HemicubeFaceSet faces = kAllHemicubeFaces,
               const Occluder& occluder = {});

    const VisibilityStats& stats() const { return m_stats; }

private:
    void prepareFrame(const ShooterFrame& frame, HemicubeFaceSet faces, const Occluder& occluder);
    void touch(int vertex);
    template <class Paint>
    void rasterisePiece(int piece, Paint&& paint);
    void paintPiece(int piece, ItemId id, ItemBuffer& buffer);
    void depthTestPiece(int piece, ItemId id, ItemBuffer& buffer);
    bool regionCulled(int region, const Plane& shooterPlane) const;

    const PreparedScene& m_scene;
    const Hemicube& m_hemicube;
    model::Visibility m_mode;
    // The faces of the paint under way.
    HemicubeFaceSet m_faces = kAllHemicubeFaces;
    // Outcode bits of the faces not painted: OR-ed into a piece's AND code,
    // they make those faces look wholly outside.
    std::uint32_t m_otherFaceBits = 0;
    bool m_countsStats = true;
    HemicubeRaster m_raster;
    ShooterFrame m_frame;
    ShadowVolume m_hidden; // of the paint under way's occluder

    // Per-vertex cache, valid for the shooter whose stamp it carries. One
    // record per vertex, so that a piece's corner costs one or two cache
    // lines, not one per field.
    struct TouchedVertex {
        std::uint32_t stamp = 0;
        std::uint32_t outcode = 0;
        Vec3 local{0.0};
        FixedVertex projected[kHemicubeFaceCount]{}; // valid on the painted faces that hold it
    };
    std::vector<TouchedVertex> m_vertices;
    std::uint32_t m_currentStamp = 0;
    std::vector<PaintRange> m_order;  // render's paint order
    std::vector<char> m_regionCulled; // z-buffer: per region, for the current shooter
    // The closed parts (closed_back_faces.h) and each node's pieces' bounds
    // (node_culling.h), of the scene's pieces with this stamp.
    std::vector<ClosedPart> m_closedParts;
    std::vector<Box3> m_nodeBounds;
    std::optional<std::uint64_t> m_cachesStamp;

    VisibilityStats m_stats;
};

} // namespace regio::solver
