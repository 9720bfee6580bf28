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
// cracks and no pixel counted twice (DESIGN.md, "pixel-centre ties").
//
// The span consumer is a template parameter: no virtual call and no
// allocation per polygon or pixel.
#include "model/types.h"
#include "solver/hemicube.h"

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
inline constexpr std::uint32_t kAllOutcodeBits = 0x1FFFFFFu;
std::uint32_t hemicubeOutcode(const Vec3& local);

class HemicubeRaster {
public:
    // Fixed-point precision of projected vertices: 1/256 pixel.
    static constexpr int kSubpixelBits = 8;
    static constexpr int kMaxInputVertices = 16;

    explicit HemicubeRaster(const Hemicube& hemicube);
    int resolution() const { return m_n; }

    // Scan-converts a convex polygon (local frame, at most kMaxInputVertices
    // vertices) on every face it reaches; calls op(face, row, x0, x1) for each
    // covered span [x0, x1) of a row. orCode/andCode are the OR and AND of the
    // vertices' hemicubeOutcode values.
    template <class SpanOp>
    void rasterize(std::span<const Vec3> local, std::uint32_t orCode, std::uint32_t andCode, SpanOp&& op)
    {
        for (int f = 0; f < kHemicubeFaceCount; ++f) {
            const std::uint32_t bits = faceOutcodeBits(f);
            if (andCode & bits)
                continue;
            const auto face = static_cast<HemicubeFace>(f);
            if (!setupFace(face, local, (orCode & bits) >> (5 * f)))
                continue;
            for (int row = m_rowBegin; row < m_rowEnd; ++row) {
                const int x0 = m_left[row] < 0 ? 0 : static_cast<int>(m_left[row]);
                const int x1 = m_right[row] > m_n ? m_n : static_cast<int>(m_right[row]);
                if (x0 < x1)
                    op(face, row, x0, x1);
            }
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

    // The snapped, projected polygon of the last face set up (for tests):
    // fixed-point pixel coordinates, kSubpixelBits fractional bits.
    struct FixedVertex {
        std::int64_t x;
        std::int64_t y;
    };
    std::span<const FixedVertex> lastProjection() const { return {m_fixed, static_cast<size_t>(m_fixedCount)}; }

private:
    // Clips against the planes flagged in `clipMask` (bit k = plane k of the
    // face), projects, snaps and computes the row spans. False if nothing is left.
    bool setupFace(HemicubeFace face, std::span<const Vec3> local, std::uint32_t clipMask);

    int m_n = 0;
    int m_rowBegin = 0;
    int m_rowEnd = 0;
    std::vector<std::int64_t> m_left;  // first covered column per row
    std::vector<std::int64_t> m_right; // one past the last covered column per row
    FixedVertex m_fixed[kMaxInputVertices + 8]{};
    int m_fixedCount = 0;
};

} // namespace regio::solver
