#include "solver/hemicube_raster.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace regio::solver {

ShooterFrame ShooterFrame::make(const Vec3& origin, const Vec3& normal, const Vec3& tangent)
{
    ShooterFrame f;
    f.origin = origin;
    f.n = glm::normalize(normal);
    Vec3 t = tangent - glm::dot(tangent, f.n) * f.n;
    if (glm::dot(t, t) < 1e-20) {
        // Any axis not parallel to the normal.
        const Vec3 a = std::abs(f.n.x) < 0.9 ? Vec3{1.0, 0.0, 0.0} : Vec3{0.0, 1.0, 0.0};
        t = a - glm::dot(a, f.n) * f.n;
    }
    f.u = glm::normalize(t);
    f.v = glm::cross(f.n, f.u);
    return f;
}

namespace {

// Signed distance of face coordinates (a, b, w) to plane k of a face; inside >= 0.
inline double planeDistance(int k, bool top, const Vec3& c)
{
    switch (k) {
    case 0: return c.z - kNearPlane;
    case 1: return c.z - c.x;
    case 2: return c.z + c.x;
    case 3: return c.z - c.y;
    default: return top ? c.z + c.y : c.y;
    }
}

// Puts an intersection exactly on its plane, so projected coordinates of
// clipped vertices land exactly on the face border.
inline void snapToPlane(int k, bool top, Vec3& c)
{
    switch (k) {
    case 0: c.z = kNearPlane; break;
    case 1: c.x = c.z; break;
    case 2: c.x = -c.z; break;
    case 3: c.y = c.z; break;
    default:
        if (top)
            c.y = -c.z;
        else
            c.y = 0.0;
        break;
    }
}

inline bool lexLess(const Vec3& p, const Vec3& q)
{
    if (p.x != q.x)
        return p.x < q.x;
    if (p.y != q.y)
        return p.y < q.y;
    return p.z < q.z;
}

// Sutherland-Hodgman against one plane. The intersection of an edge is
// computed from its endpoints in a canonical order, so the two polygons that
// share an edge get bit-identical clip vertices on it.
int clipAgainst(int k, bool top, const Vec3* in, int count, Vec3* out)
{
    int n = 0;
    for (int i = 0; i < count; ++i) {
        const Vec3& p = in[i];
        const Vec3& q = in[(i + 1) % count];
        const double dp = planeDistance(k, top, p);
        const double dq = planeDistance(k, top, q);
        if (dp >= 0.0)
            out[n++] = p;
        if ((dp >= 0.0) != (dq >= 0.0)) {
            const bool swap = lexLess(q, p);
            const Vec3& s = swap ? q : p;
            const Vec3& e = swap ? p : q;
            const double ds = swap ? dq : dp;
            const double de = swap ? dp : dq;
            const double t = ds / (ds - de);
            Vec3 x = s + t * (e - s);
            snapToPlane(k, top, x);
            out[n++] = x;
        }
    }
    return n;
}

// ceil(num / den) for den > 0 (C++ division truncates towards zero).
inline std::int64_t ceilDiv(std::int64_t num, std::int64_t den)
{
    const std::int64_t q = num / den;
    return q + ((num % den) > 0 ? 1 : 0);
}

} // namespace

std::uint32_t hemicubeOutcode(const Vec3& p)
{
    std::uint32_t code = 0;
    for (int f = 0; f < kHemicubeFaceCount; ++f) {
        const Vec3 c = faceCoordinates(static_cast<HemicubeFace>(f), p);
        const bool top = f == 0;
        std::uint32_t bits = 0;
        if (c.z < kNearPlane)
            bits |= 1u;
        if (c.x > c.z)
            bits |= 2u;
        if (c.x < -c.z)
            bits |= 4u;
        if (c.y > c.z)
            bits |= 8u;
        if (top ? c.y < -c.z : c.y < 0.0)
            bits |= 16u;
        code |= bits << (5 * f);
    }
    return code;
}

HemicubeRaster::HemicubeRaster(const Hemicube& hemicube)
    : m_n(hemicube.resolution())
    , m_left(static_cast<size_t>(m_n))
    , m_right(static_cast<size_t>(m_n))
{
}

bool HemicubeRaster::setupFace(HemicubeFace face, std::span<const Vec3> local, std::uint32_t clipMask)
{
    const bool top = face == HemicubeFace::Top;
    Vec3 bufA[kMaxInputVertices + 8];
    Vec3 bufB[kMaxInputVertices + 8];
    int count = static_cast<int>(std::min<size_t>(local.size(), kMaxInputVertices));
    for (int i = 0; i < count; ++i)
        bufA[i] = faceCoordinates(face, local[static_cast<size_t>(i)]);
    Vec3* cur = bufA;
    Vec3* other = bufB;
    for (int k = 0; k < 5 && count >= 3; ++k) {
        if (!(clipMask & (1u << k)))
            continue;
        count = clipAgainst(k, top, cur, count, other);
        std::swap(cur, other);
    }
    if (count < 3)
        return false;

    // Project and snap: x = (a/w + 1) N/2, y = (b/w + 1) N/2 on the top face
    // and (b/w) N/2 on a side face, in 1/2^kSubpixelBits pixel units.
    const double scale = 0.5 * m_n * double(1 << kSubpixelBits);
    const std::int64_t maxX = std::int64_t(m_n) << kSubpixelBits;
    const std::int64_t maxY = top ? maxX : (std::int64_t(m_n / 2) << kSubpixelBits);
    const double yOffset = top ? 1.0 : 0.0;
    for (int i = 0; i < count; ++i) {
        const double inv = 1.0 / cur[i].z;
        const auto x = static_cast<std::int64_t>(std::llround((cur[i].x * inv + 1.0) * scale));
        const auto y = static_cast<std::int64_t>(std::llround((cur[i].y * inv + yOffset) * scale));
        m_fixed[i] = {std::clamp<std::int64_t>(x, 0, maxX), std::clamp<std::int64_t>(y, 0, maxY)};
    }
    m_fixedCount = count;

    std::int64_t area2 = 0;
    std::int64_t yMin = m_fixed[0].y, yMax = m_fixed[0].y;
    for (int i = 0; i < count; ++i) {
        const FixedVertex& p = m_fixed[i];
        const FixedVertex& q = m_fixed[(i + 1) % count];
        area2 += p.x * q.y - q.x * p.y;
        yMin = std::min(yMin, p.y);
        yMax = std::max(yMax, p.y);
    }
    if (area2 == 0)
        return false;

    // Rows whose pixel centre (j + 1/2) lies in [yMin, yMax).
    constexpr std::int64_t one = std::int64_t(1) << kSubpixelBits;
    constexpr std::int64_t half = one / 2;
    const int height = top ? m_n : m_n / 2;
    m_rowBegin = static_cast<int>(std::max<std::int64_t>(0, ceilDiv(yMin - half, one)));
    m_rowEnd = static_cast<int>(std::min<std::int64_t>(height, ceilDiv(yMax - half, one)));
    if (m_rowBegin >= m_rowEnd)
        return false;
    for (int j = m_rowBegin; j < m_rowEnd; ++j) {
        m_left[j] = std::numeric_limits<std::int32_t>::min();
        m_right[j] = std::numeric_limits<std::int32_t>::max();
    }

    // Each non-horizontal edge bounds the rows it spans, from the left or the
    // right depending on the polygon's orientation (with positive area the
    // interior lies left of every directed edge, so an upward edge bounds it
    // on the right). The bound for row j is the first pixel whose centre is
    // at or right of the edge: ceil((X - 1/2) / 1) in pixel units, computed as
    // one exact division from the edge taken bottom-up.
    const bool positive = area2 > 0;
    for (int i = 0; i < count; ++i) {
        FixedVertex p = m_fixed[i];
        FixedVertex q = m_fixed[(i + 1) % count];
        if (p.y == q.y)
            continue;
        const bool upward = q.y > p.y;
        const bool rightEdge = upward == positive;
        if (!upward)
            std::swap(p, q);
        const std::int64_t dy = q.y - p.y;
        const std::int64_t dx = q.x - p.x;
        const int j0 = static_cast<int>(std::max<std::int64_t>(m_rowBegin, ceilDiv(p.y - half, one)));
        const int j1 = static_cast<int>(std::min<std::int64_t>(m_rowEnd, ceilDiv(q.y - half, one)));
        const std::int64_t den = dy * one;
        std::int64_t num = (p.x - half) * dy + ((std::int64_t(j0) * one + half) - p.y) * dx;
        const std::int64_t step = one * dx;
        if (rightEdge) {
            for (int j = j0; j < j1; ++j, num += step)
                m_right[j] = std::min(m_right[j], ceilDiv(num, den));
        } else {
            for (int j = j0; j < j1; ++j, num += step)
                m_left[j] = std::max(m_left[j], ceilDiv(num, den));
        }
    }
    return true;
}

} // namespace regio::solver
