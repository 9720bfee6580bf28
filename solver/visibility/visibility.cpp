#include "solver/visibility/visibility.h"

#include "solver/visibility/node_culling.h"
#include "solver/visibility/traversal.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

namespace regio::solver {

namespace {
// How often (in elements) a render looks at the cancel flag: a relaxed
// atomic load is cheap, but not per element.
constexpr int kCancelCheckInterval = 256;
// Set in a vertex's outcode when it lies in the occluder's shadow volume
// (shadow_volume.h), beside the rasteriser's bits (hemicube_raster.h): a
// piece whose three corners all have it is left out.
constexpr std::uint32_t kHiddenBit = 1u << 26;
static_assert((kHiddenBit & (kAllOutcodeBits | kBelowBaseBit)) == 0);
// Turns of the hemicube about the normal per metre along each axis (the
// R3 sequence's irrationals over a centimetre): patches a few centimetres
// apart turn by unrelated angles, and a patch moved by a hair turns by one.
constexpr Vec3 kTurnsPerMetre{75.48776662466927, 56.98402909980532, 43.01597090019468};
} // namespace

ShooterFrame shooterFrameOfPatch(const PreparedScene& scene, int patch)
{
    const Patch& p = scene.patches[static_cast<size_t>(patch)];
    return shooterFrameAt(p.centroid, scene.properties[static_cast<size_t>(p.properties)].plane.normal);
}

ShooterFrame shooterFrameAt(const Vec3& point, const Vec3& n)
{
    // A hemicube whose pixel rows run along the patch's edges sees the edges
    // of a room that is built along the same axes (walls, shelves, a grid of
    // lamp patches) line up with its rows, every shooter alike: a face seen
    // edge-on covers one row of pixels or two by luck, and the luck is the
    // same for every patch of a light. Turned by an angle that follows from
    // where the patch lies, the rows cross those edges at other angles from
    // every shooter, and the luck averages out over a light's patches
    // (§5.6, aliasing; docs/accuracy.md, "Turned hemicubes"). The angle
    // depends on the patch's centroid only, not on its numbering or its
    // first corner, so a scene read back from a model file shoots alike.
    const ShooterFrame base = ShooterFrame::make(point, n);
    const double turn = 2.0 * std::numbers::pi * glm::dot(kTurnsPerMetre, point);
    return ShooterFrame::make(point, n, std::cos(turn) * base.u + std::sin(turn) * base.v);
}

Visibility::Visibility(const PreparedScene& scene, const Hemicube& hemicube, model::Visibility mode)
    : m_scene(scene)
    , m_hemicube(hemicube)
    , m_mode(mode)
    , m_raster(hemicube)
{
}

ItemBuffer Visibility::makeBuffer() const { return ItemBuffer(m_hemicube, m_mode == model::Visibility::ZBuffer); }

void Visibility::prepareFrame(const ShooterFrame& frame, HemicubeFaceSet faces, const Occluder& occluder)
{
    m_frame = frame;
    m_hidden = ShadowVolume(frame.origin, occluder, Plane::fromPointNormal(frame.origin, frame.n));
    m_faces = faces & kAllHemicubeFaces;
    m_countsStats = (m_faces & faceBit(HemicubeFace::Top)) != 0;
    m_otherFaceBits = 0;
    for (int f = 0; f < kHemicubeFaceCount; ++f)
        if (!(m_faces & (1u << f)))
            m_otherFaceBits |= faceOutcodeBits(f);
    // Every paint takes a new stamp below, so the cached projections are
    // always those of the faces it paints.
    const size_t count = m_scene.pieceVertices.size();
    if (m_vertices.size() != count) {
        m_vertices.assign(count, TouchedVertex{});
        m_currentStamp = 0;
    }
    if (++m_currentStamp == 0) { // wrapped: forget every stamp
        for (TouchedVertex& v : m_vertices)
            v.stamp = 0;
        m_currentStamp = 1;
    }
}

inline void Visibility::touch(int vertex)
{
    TouchedVertex& v = m_vertices[static_cast<size_t>(vertex)];
    if (v.stamp == m_currentStamp)
        return;
    v.stamp = m_currentStamp;
    const Vec3& world = m_scene.pieceVertices[static_cast<size_t>(vertex)];
    v.local = m_frame.toLocal(world);
    v.outcode = hemicubeOutcode(v.local);
    if (!m_hidden.empty() && m_hidden.hides(world))
        v.outcode |= kHiddenBit;
    // Project once per paint onto the painted faces whose frustum holds the
    // vertex (one, or two on a border): elements inside a face then skip
    // projection.
    for (int f = 0; f < kHemicubeFaceCount; ++f)
        if ((m_faces & (1u << f)) && !(v.outcode & faceOutcodeBits(f)))
            v.projected[f] = m_raster.project(static_cast<HemicubeFace>(f), v.local);
}

bool Visibility::regionCulled(int region, const Plane& shooterPlane) const
{
    return boxBehindPlane(m_scene.regions[static_cast<size_t>(region)].bounds, shooterPlane);
}

template <class Paint>
inline void Visibility::rasterisePiece(int piece, Paint&& paint)
{
    m_stats.elementsVisited += m_countsStats;
    const Piece& e = m_scene.pieces[static_cast<size_t>(piece)];
    touch(e.vertices[0]);
    touch(e.vertices[1]);
    touch(e.vertices[2]);
    const TouchedVertex& v0 = m_vertices[static_cast<size_t>(e.vertices[0])];
    const TouchedVertex& v1 = m_vertices[static_cast<size_t>(e.vertices[1])];
    const TouchedVertex& v2 = m_vertices[static_cast<size_t>(e.vertices[2])];
    const std::uint32_t everyCode = v0.outcode & v1.outcode & v2.outcode;
    // On or below the shooter's plane, in the occluder's shadow, or outside
    // every face (a bit of each face's group is set).
    bool hidden = (everyCode & (kBelowBaseBit | kHiddenBit)) != 0;
    if (hidden)
        return;
    hidden = true;
    for (int f = 0; f < kHemicubeFaceCount && hidden; ++f)
        hidden = (everyCode & faceOutcodeBits(f)) != 0;
    if (hidden)
        return;
    m_stats.elementsRasterised += m_countsStats;
    // Only this visibility's faces from here on.
    const std::uint32_t andCode = everyCode | m_otherFaceBits;
    const std::uint32_t orCode = v0.outcode | v1.outcode | v2.outcode;
    const Vec3* const local[3] = {&v0.local, &v1.local, &v2.local};
    const FixedVertex* const projected[3] = {v0.projected, v1.projected, v2.projected};
    m_raster.rasterizeTriangle(local, projected, orCode, andCode, paint);
}

void Visibility::paintPiece(int piece, ItemId id, ItemBuffer& buffer)
{
    const int n = m_hemicube.resolution();
    rasterisePiece(piece, [&](HemicubeFace f, int row, int x0, int x1) {
        ItemId* ids = buffer.face(f) + row * n;
        std::fill(ids + x0, ids + x1, id);
        buffer.painted(f, row, x0, x1);
    });
}

void Visibility::depthTestPiece(int piece, ItemId id, ItemBuffer& buffer)
{
    // Depth 1/w is affine in the face's screen coordinates and exact from the
    // plane: with p = w (sx, sy, 1) in face coordinates and plane n.p + d = 0,
    // 1/w = -(na sx + nb sy + nw) / d.
    const Piece& p = m_scene.pieces[static_cast<size_t>(piece)];
    const Element& e = m_scene.elements[static_cast<size_t>(p.element)];
    const Vec3 nLocal = m_frame.directionToLocal(e.normal);
    const double dLocal = -glm::dot(nLocal, m_frame.toLocal(m_scene.pieceVertices[static_cast<size_t>(p.vertices[0])]));
    if (dLocal == 0.0)
        return; // the plane contains the shooter's centre: seen edge-on
    const int n = m_hemicube.resolution();
    const double pixel = 2.0 / n;
    // Where a back face meets a front face along a silhouette edge both cover
    // the edge pixels at almost equal depth, and float rounding would pick
    // either. The back face is never in front there (it belongs to the same
    // solid), so it is pushed back by far more than the rounding; a thin
    // two-sided wall then shows its facing side, as in the painter.
    //
    // Unlike the painter, the z-buffer also lets a receiver win over the
    // coplanar back face of a solid it touches (a box standing on a box). The
    // painter's node order tells the two cases apart (Visibility::render); a
    // depth bias cannot without giving silhouette edge pixels to back faces.
    // Such contact areas are seen only from an eye inside a solid (a shooter
    // patch whose centre lies under a box), so item buffers from eyes outside
    // every solid are unaffected.
    const double scale = (id == kBlockerItem ? 1.0 - 1e-5 : 1.0) / -dLocal;
    rasterisePiece(piece, [&](HemicubeFace f, int row, int x0, int x1) {
        const Vec3 nf = faceCoordinates(f, nLocal);
        const double sy = (row + 0.5) * pixel - (f == HemicubeFace::Top ? 1.0 : 0.0);
        const double base = (nf.y * sy + nf.z) * scale;
        const double slope = nf.x * scale;
        ItemId* ids = buffer.face(f) + row * n;
        float* depth = buffer.depth(f) + row * n;
        buffer.painted(f, row, x0, x1);
        const double first = base + slope * (0.5 * pixel - 1.0); // depth at column 0
        const double step = slope * pixel;
        // Branch-free so that the compiler can vectorise the span.
        for (int x = x0; x < x1; ++x) {
            // A covered pixel whose centre ray grazes past the plane (snapping
            // at the horizon) still belongs to the element: never below "far".
            const float inv = std::max(static_cast<float>(first + step * x), std::numeric_limits<float>::min());
            const bool nearer = inv > depth[x];
            depth[x] = nearer ? inv : depth[x];
            ids[x] = nearer ? id : ids[x];
        }
    });
}

void Visibility::paintOrder(const ShooterFrame& frame, std::vector<PaintRange>& order, const Occluder& occluder)
{
    order.clear();
    const Plane shooterPlane = Plane::fromPointNormal(frame.origin, frame.n);
    auto accept = [&](int region) {
        const bool culled = regionCulled(region, shooterPlane);
        m_stats.regionsCulled += culled;
        return !culled;
    };
    if (!m_cachesStamp || *m_cachesStamp != m_scene.piecesStamp || m_nodeBounds.size() != m_scene.nodes.size()) {
        // A new scene, or new pieces.
        m_closedParts = closedParts(m_scene);
        m_nodeBounds = nodePieceBounds(m_scene);
        m_cachesStamp = m_scene.piecesStamp;
    }
    const bool solidBacks = !closedBackFacesHidden(m_closedParts, frame.origin, frame.n);
    const ShadowVolume hidden(frame.origin, occluder, shooterPlane);
    const auto culledNode = [&](size_t node) {
        return piecesBehindShooter(m_nodeBounds[node], shooterPlane) || hidden.hides(m_nodeBounds[node]);
    };
    if (m_mode == model::Visibility::Painter) {
        forEachNodeBackToFront(m_scene, frame.origin, accept, [&](int nodeIndex, bool eyeInFront) {
            if (culledNode(static_cast<size_t>(nodeIndex)))
                return;
            forEachPaintRange(m_scene.nodes[static_cast<size_t>(nodeIndex)], eyeInFront, solidBacks,
                              [&](int begin, int end, bool receives) {
                                  if (begin < end)
                                      order.push_back({begin, end, receives});
                              });
        });
        return;
    }
    // Z-buffer: node array order, regions and nodes culled the same way, and
    // the closed parts' back faces left out when the painter leaves them out.
    std::vector<char>& culled = m_regionCulled;
    culled.resize(m_scene.regions.size());
    for (size_t r = 0; r < culled.size(); ++r)
        culled[r] = !accept(static_cast<int>(r));
    for (size_t n = 0; n < m_scene.nodes.size(); ++n) {
        const BspNode& node = m_scene.nodes[n];
        if (node.pieceCount == 0 || (node.region >= 0 && culled[static_cast<size_t>(node.region)]) || culledNode(n))
            continue;
        int begin = node.firstPiece, end = node.firstPiece + node.pieceCount;
        if (!solidBacks) {
            if (node.plane.signedDistance(frame.origin) > 0.0)
                end -= node.oppositeSolidPieces;
            else
                begin += node.forwardSolidPieces;
        }
        if (begin < end)
            order.push_back({begin, end, true});
    }
}

bool Visibility::paint(const ShooterFrame& frame, std::span<const PaintRange> ranges, ItemBuffer& buffer,
                       const std::atomic<bool>* cancel, HemicubeFaceSet faces, const Occluder& occluder)
{
    if (cancel && cancel->load(std::memory_order_relaxed))
        return false;
    prepareFrame(frame, faces, occluder);
    int sinceCheck = 0;
    const bool painter = m_mode == model::Visibility::Painter;
    for (const PaintRange& range : ranges) {
        for (int i = range.begin; i < range.end; ++i) {
            const Piece& piece = m_scene.pieces[static_cast<size_t>(i)];
            const auto element = static_cast<std::uint32_t>(piece.element);
            if (painter) {
                paintPiece(i, range.receives ? itemOfElement(element) : kBlockerItem, buffer);
                continue;
            }
            const Element& e = m_scene.elements[element];
            const double facing =
                glm::dot(e.normal, frame.origin - m_scene.pieceVertices[static_cast<size_t>(piece.vertices[0])]);
            depthTestPiece(i, facing > 0.0 ? itemOfElement(element) : kBlockerItem, buffer);
        }
        sinceCheck += range.end - range.begin;
        if (cancel && sinceCheck >= kCancelCheckInterval) {
            sinceCheck = 0;
            if (cancel->load(std::memory_order_relaxed))
                return false;
        }
    }
    return true;
}

bool Visibility::render(const ShooterFrame& frame, ItemBuffer& buffer, const std::atomic<bool>* cancel,
                        const Occluder& occluder)
{
    buffer.clear();
    paintOrder(frame, m_order, occluder);
    return paint(frame, m_order, buffer, cancel, kAllHemicubeFaces, occluder);
}

} // namespace regio::solver
