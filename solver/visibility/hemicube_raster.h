#pragma once
// Projection of element polygons onto the five hemicube faces (§5.6, "in one
// pass for element edges we get the element projection on every hemicube
// wall; projected borders are then scan-line filled").
//
// A polygon given in the shooter's local frame is clipped against each face's
// frustum, projected, snapped to fixed point and scan-converted with ONE rule
// for every path (painter, z-buffer): a pixel belongs to a polygon when its
// centre lies inside, with left/top edges inclusive and right/bottom edges
// exclusive in the half-open sense. Edge positions are computed in exact
// integer arithmetic from the snapped endpoints, taken in a canonical order,
// so two polygons sharing an edge split its pixels between them exactly: no
// cracks and no pixel counted twice. (An inconsistent rule at pixel-centre ties
// double-counts or drops whole rows: errors of several percent.)
//
// The span consumer is a template parameter: no virtual call and no
// allocation per polygon or pixel.
#include "model/types.h"
#include "solver/visibility/hemicube.h"

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

namespace regio::solver {

using model::Vec3;

// The hemicube's coordinate system: origin at the shooter's centre, z along
// its normal, x and y in its plane.
struct ShooterFrame {
    Vec3 origin{0.0};
    Vec3 u{1.0, 0.0, 0.0};
    Vec3 v{0.0, 1.0, 0.0};
    Vec3 n{0.0, 0.0, 1.0};

    // A right-handed frame around `normal` (unit); `tangent` fixes the
    // rotation about the normal when it is not parallel to it.
    static ShooterFrame make(const Vec3& origin, const Vec3& normal, const Vec3& tangent = Vec3{0.0});
    Vec3 toLocal(const Vec3& world) const
    {
        const Vec3 d = world - origin;
        return {d.x * u.x + d.y * u.y + d.z * u.z, d.x * v.x + d.y * v.y + d.z * v.z,
                d.x * n.x + d.y * n.y + d.z * n.z};
    }
    Vec3 directionToLocal(const Vec3& dir) const
    {
        return {dir.x * u.x + dir.y * u.y + dir.z * u.z, dir.x * v.x + dir.y * v.y + dir.z * v.z,
                dir.x * n.x + dir.y * n.y + dir.z * n.z};
    }
};

// Face coordinates (a, b, w) of a local point: w along the face's axis, a its
// horizontal and b its vertical screen coordinate (b = local z on side faces).
inline Vec3 faceCoordinates(HemicubeFace face, const Vec3& p)
{
    switch (face) {
    case HemicubeFace::Top: return {p.x, p.y, p.z};
    case HemicubeFace::PosX: return {p.y, p.z, p.x};
    case HemicubeFace::NegX: return {-p.y, p.z, -p.x};
    case HemicubeFace::PosY: return {-p.x, p.z, p.y};
    case HemicubeFace::NegY: return {p.x, p.z, -p.y};
    }
    return p;
}

// Outcodes: five bits per face (near, a > w, a < -w, b > w, b below the
// face), bit 5f + k. A polygon whose vertices' codes AND to a face bit lies
// wholly outside that face; one whose codes OR to no bit of a face lies wholly
// inside it and needs no clipping there.
inline constexpr double kNearPlane = 1e-9; // metres along a face's axis
inline constexpr std::uint32_t faceOutcodeBits(int face) { return 0x1Fu << (5 * face); }
// Set for points on or below the base plane (z <= kNearPlane): a polygon all
// of whose vertices have it (the shooter's own plane, most often) covers no
// pixel centre and is dropped before any face is tried.
inline constexpr std::uint32_t kBelowBaseBit = 1u << 25;
inline constexpr std::uint32_t kAllOutcodeBits = 0x3FFFFFFu;
std::uint32_t hemicubeOutcode(const Vec3& local);

// A projected vertex: fixed-point pixel coordinates with kSubpixelBits
// fractional bits (x along a face's columns, y along its rows).
struct FixedVertex {
    std::int32_t x = 0;
    std::int32_t y = 0;
};

class HemicubeRaster {
public:
    // Fixed-point precision of projected vertices: 1/65536 pixel. Fine
    // snapping keeps the slivers that T-junctions (BSP splits, region clips)
    // open between snapped edges too thin to hold a pixel centre; coordinates
    // fit 32 bits and the edge arithmetic stays exact in 64 bits up to
    // kMaxHemicubeResolution.
    static constexpr int kSubpixelBits = 16;
    static constexpr int kMaxInputVertices = 16;

    explicit HemicubeRaster(const Hemicube& hemicube);
    int resolution() const { return m_n; }

    // The snapped projection of a point inside a face's frustum (its outcode
    // has no bit of that face). Every path projects through this function, so
    // a vertex cached once per shooter and a vertex projected while clipping
    // land on the same fixed-point position.
    FixedVertex project(HemicubeFace face, const Vec3& local) const;

    // Scan-converts a convex polygon (local frame, at most kMaxInputVertices
    // vertices) on every face it reaches; calls op(face, row, x0, x1) for each
    // covered span [x0, x1) of a row. orCode/andCode are the OR and AND of the
    // vertices' hemicubeOutcode values.
    template <class SpanOp>
    void rasterize(std::span<const Vec3> local, std::uint32_t orCode, std::uint32_t andCode, SpanOp&& op)
    {
        if (andCode & kBelowBaseBit)
            return;
        for (int f = 0; f < kHemicubeFaceCount; ++f) {
            const std::uint32_t bits = faceOutcodeBits(f);
            if (andCode & bits)
                continue;
            const auto face = static_cast<HemicubeFace>(f);
            if (setupFace(face, local, (orCode & bits) >> (5 * f)))
                emitSpans(face, op);
        }
    }
    // Same, computing the outcodes itself.
    template <class SpanOp>
    void rasterize(std::span<const Vec3> local, SpanOp&& op)
    {
        std::uint32_t orCode = 0, andCode = kAllOutcodeBits;
        for (const Vec3& p : local) {
            const std::uint32_t c = hemicubeOutcode(p);
            orCode |= c;
            andCode &= c;
        }
        rasterize(local, orCode, andCode, op);
    }
    // A triangle whose vertices were projected beforehand: projected[k][f] is
    // project(face f, local[k]), valid for every face the vertex lies inside.
    // Faces the triangle lies wholly inside skip clipping and projection; the
    // others take the clipping path. The pixels are the same either way.
    template <class SpanOp>
    void rasterizeTriangle(const Vec3* const local[3], const FixedVertex* const projected[3], std::uint32_t orCode,
                           std::uint32_t andCode, SpanOp&& op)
    {
        if (andCode & kBelowBaseBit)
            return;
        for (int f = 0; f < kHemicubeFaceCount; ++f) {
            const std::uint32_t bits = faceOutcodeBits(f);
            if (andCode & bits)
                continue;
            const auto face = static_cast<HemicubeFace>(f);
            bool any;
            if (orCode & bits) {
                const Vec3 polygon[3] = {*local[0], *local[1], *local[2]};
                any = setupFace(face, polygon, (orCode & bits) >> (5 * f));
            } else {
                const FixedVertex& a = projected[0][f];
                const FixedVertex& b = projected[1][f];
                const FixedVertex& c = projected[2][f];
                // Most pieces far from the eye hold no pixel centre: tell
                // those here, before the call and the copy.
                if (!mayHoldPixelCentre(a, b, c))
                    continue;
                m_fixed[0] = a;
                m_fixed[1] = b;
                m_fixed[2] = c;
                m_fixedCount = 3;
                any = setupSpans(face);
            }
            if (any)
                emitSpans(face, op);
        }
    }

    // The snapped, projected polygon of the last face set up (for tests).
    std::span<const FixedVertex> lastProjection() const { return {m_fixed, static_cast<size_t>(m_fixedCount)}; }

private:
    // The first pixel (row or column) whose centre j + 1/2 lies at or after
    // the fixed-point coordinate v: ceil(v - 1/2) in pixels, as an
    // arithmetic shift.
    static constexpr std::int64_t firstCentreFrom(std::int64_t v)
    {
        return -(((std::int64_t(1) << (kSubpixelBits - 1)) - v) >> kSubpixelBits);
    }
    // False when no row centre or no column centre lies between the
    // triangle's lowest and highest vertex (as setupSpans decides it).
    static bool mayHoldPixelCentre(const FixedVertex& a, const FixedVertex& b, const FixedVertex& c)
    {
        const auto centresBetween = [](std::int64_t lo, std::int64_t hi) {
            return firstCentreFrom(lo) < firstCentreFrom(hi);
        };
        return centresBetween(std::min({a.y, b.y, c.y}), std::max({a.y, b.y, c.y})) &&
               centresBetween(std::min({a.x, b.x, c.x}), std::max({a.x, b.x, c.x}));
    }
    // Clips against the planes flagged in `clipMask` (bit k = plane k of the
    // face), projects, snaps and computes the row spans. False if nothing is left.
    bool setupFace(HemicubeFace face, std::span<const Vec3> local, std::uint32_t clipMask);
    // Row spans of the snapped polygon in m_fixed. False if it covers no pixel centre.
    bool setupSpans(HemicubeFace face);

    template <class SpanOp>
    void emitSpans(HemicubeFace face, SpanOp& op)
    {
        for (int row = m_rowBegin; row < m_rowEnd; ++row) {
            const auto r = static_cast<size_t>(row);
            const int x0 = m_left[r] < 0 ? 0 : static_cast<int>(m_left[r]);
            const int x1 = m_right[r] > m_n ? m_n : static_cast<int>(m_right[r]);
            if (x0 < x1)
                op(face, row, x0, x1);
        }
    }

    int m_n = 0;
    double m_scale = 0.0; // pixels per unit of a/w, times 2^kSubpixelBits
    std::int32_t m_maxX = 0;
    std::int32_t m_maxSideY = 0;
    int m_rowBegin = 0;
    int m_rowEnd = 0;
    std::vector<std::int64_t> m_left;  // first covered column per row
    std::vector<std::int64_t> m_right; // one past the last covered column per row
    FixedVertex m_fixed[kMaxInputVertices + 8]{};
    int m_fixedCount = 0;
};

} // namespace regio::solver
