#include "solver/visibility/hemicube_raster.h"

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

// Exact q = floor(num / den) and r = num - q den in [0, den), den > 0, from a
// floating-point estimate corrected by the remainder: 64-bit idiv is the
// slowest instruction of a triangle setup.
inline void floorDivMod(std::int64_t num, std::int64_t den, std::int64_t& q, std::int64_t& r)
{
    q = static_cast<std::int64_t>(static_cast<double>(num) / static_cast<double>(den));
    r = num - q * den;
    while (r < 0) {
        r += den;
        --q;
    }
    while (r >= den) {
        r -= den;
        ++q;
    }
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
    if (p.z <= kNearPlane)
        code |= kBelowBaseBit;
    return code;
}

HemicubeRaster::HemicubeRaster(const Hemicube& hemicube)
    : m_n(hemicube.resolution())
    , m_scale(0.5 * m_n * double(1 << kSubpixelBits))
    , m_maxX(m_n << kSubpixelBits)
    , m_maxSideY((m_n / 2) << kSubpixelBits)
    , m_left(static_cast<size_t>(m_n))
    , m_right(static_cast<size_t>(m_n))
{
}

namespace {

// Rounds half up; inputs below -0.5 (rounding noise outside the face) end
// up clamped to 0 anyway. A plain conversion: llround is a library call.
inline std::int32_t snap(double v, std::int32_t max)
{
    if (!(v > 0.0))
        return 0;
    const double r = v + 0.5;
    return r >= double(max) ? max : static_cast<std::int32_t>(r);
}

} // namespace

// x = (a/w + 1) N/2, y = (b/w + 1) N/2 on the top face and (b/w) N/2 on a
// side face, in 1/2^kSubpixelBits pixel units, from face coordinates (a, b, w).
static inline FixedVertex projectFace(const Vec3& c, bool top, double scale, std::int32_t maxX, std::int32_t maxY)
{
    const double inv = 1.0 / c.z;
    return {snap((c.x * inv + 1.0) * scale, maxX), snap((c.y * inv + (top ? 1.0 : 0.0)) * scale, maxY)};
}

FixedVertex HemicubeRaster::project(HemicubeFace face, const Vec3& local) const
{
    const bool top = face == HemicubeFace::Top;
    return projectFace(faceCoordinates(face, local), top, m_scale, m_maxX, top ? m_maxX : m_maxSideY);
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
    const std::int32_t maxY = top ? m_maxX : m_maxSideY;
    for (int i = 0; i < count; ++i)
        m_fixed[i] = projectFace(cur[i], top, m_scale, m_maxX, maxY);
    m_fixedCount = count;
    return setupSpans(face);
}

bool HemicubeRaster::setupSpans(HemicubeFace face)
{
    const int count = m_fixedCount;
    std::int32_t yMin = m_fixed[0].y, yMax = m_fixed[0].y;
    for (int i = 1; i < count; ++i) {
        yMin = std::min(yMin, m_fixed[i].y);
        yMax = std::max(yMax, m_fixed[i].y);
    }
    // Rows whose pixel centre (j + 1/2) lies in [yMin, yMax). Small elements
    // often cover no row centre at all: leave before any other work.
    constexpr std::int64_t one = std::int64_t(1) << kSubpixelBits;
    constexpr std::int64_t half = one / 2;
    const int height = face == HemicubeFace::Top ? m_n : m_n / 2;
    m_rowBegin = static_cast<int>(std::max<std::int64_t>(0, firstCentreFrom(yMin)));
    m_rowEnd = static_cast<int>(std::min<std::int64_t>(height, firstCentreFrom(yMax)));
    if (m_rowBegin >= m_rowEnd)
        return false;
    // Likewise when no column centre lies in [xMin, xMax).
    std::int32_t xMin = m_fixed[0].x, xMax = m_fixed[0].x;
    for (int i = 1; i < count; ++i) {
        xMin = std::min(xMin, m_fixed[i].x);
        xMax = std::max(xMax, m_fixed[i].x);
    }
    if (firstCentreFrom(xMin) >= firstCentreFrom(xMax))
        return false;
    std::int64_t area2 = 0;
    for (int i = 0; i < count; ++i) {
        const FixedVertex& p = m_fixed[i];
        const FixedVertex& q = m_fixed[i + 1 == count ? 0 : i + 1];
        area2 += std::int64_t(p.x) * q.y - std::int64_t(q.x) * p.y;
    }
    if (area2 == 0)
        return false;
    for (int j = m_rowBegin; j < m_rowEnd; ++j) {
        m_left[static_cast<size_t>(j)] = std::numeric_limits<std::int32_t>::min();
        m_right[static_cast<size_t>(j)] = std::numeric_limits<std::int32_t>::max();
    }

    // Each non-horizontal edge bounds the rows it spans, from the left or the
    // right depending on the polygon's orientation (with positive area the
    // interior lies left of every directed edge, so an upward edge bounds it
    // on the right). The bound for row j is the first pixel whose centre is
    // at or right of the edge, ceil((X_j - 1/2) / 1) in pixel units, with the
    // edge always taken bottom-up so both polygons sharing it agree exactly.
    // The first row costs one division; the others step the quotient and
    // remainder (an exact integer DDA).
    const bool positive = area2 > 0;
    for (int i = 0; i < count; ++i) {
        FixedVertex p = m_fixed[i];
        FixedVertex q = m_fixed[i + 1 == count ? 0 : i + 1];
        if (p.y == q.y)
            continue;
        const bool upward = q.y > p.y;
        const bool rightEdge = upward == positive;
        if (!upward)
            std::swap(p, q);
        const int j0 = static_cast<int>(std::max<std::int64_t>(m_rowBegin, firstCentreFrom(p.y)));
        const int j1 = static_cast<int>(std::min<std::int64_t>(m_rowEnd, firstCentreFrom(q.y)));
        if (j0 >= j1)
            continue;
        const std::int64_t dy = std::int64_t(q.y) - p.y;
        const std::int64_t dx = std::int64_t(q.x) - p.x;
        const std::int64_t den = dy * one;
        const std::int64_t num = (p.x - half) * dy + ((std::int64_t(j0) * one + half) - p.y) * dx;
        // bound = ceil(num / den) and rem = bound den - num in [0, den).
        std::int64_t bound, rem;
        floorDivMod(num, den, bound, rem);
        if (rem != 0) {
            ++bound;
            rem = den - rem;
        }
        std::int64_t* bounds = rightEdge ? m_right.data() : m_left.data();
        if (j1 - j0 == 1) { // most edges of small elements: no step needed
            if (rightEdge ? bound < bounds[j0] : bound > bounds[j0])
                bounds[j0] = bound;
            continue;
        }
        std::int64_t stepQ, stepR; // one dx = stepQ den + stepR, 0 <= stepR < den
        floorDivMod(one * dx, den, stepQ, stepR);
        for (int j = j0; j < j1; ++j) {
            if (rightEdge ? bound < bounds[j] : bound > bounds[j])
                bounds[j] = bound;
            bound += stepQ;
            rem -= stepR;
            if (rem < 0) {
                rem += den;
                ++bound;
            }
        }
    }
    return true;
}

} // namespace regio::solver
