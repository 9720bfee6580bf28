#include "solver/prepare/covered_parts.h"

#include "solver/prepare/divisions.h"
#include "solver/prepare/face_polygon.h"
#include "solver/prepare/shadow_lines.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

namespace regio::solver {

namespace {

using Polygon = std::vector<Vec3>;

// Areas below this (m^2) are rounding: slivers along a contact line.
constexpr double kNegligibleArea = model::kDistanceEpsilon * model::kDistanceEpsilon;

// polygon - cover, as convex pieces: outside each edge of the cover in turn,
// the rest going on to the next edge; what is inside every edge is covered.
// Pieces thinner than the distance tolerance are dropped.
void subtract(const Polygon& polygon, const Polygon& cover, const Vec3& coverNormal, std::vector<Polygon>& out)
{
    Polygon rest = polygon;
    const size_t n = cover.size();
    for (size_t k = 0; k < n && rest.size() >= 3; ++k) {
        const Vec3& a = cover[k];
        const Vec3 inward = glm::normalize(glm::cross(coverNormal, cover[(k + 1) % n] - a));
        Polygon outside = cleanConvexLoop(clipConvex(rest, a, -inward));
        if (outside.size() >= 3 && model::polygonArea(outside) > kNegligibleArea)
            out.push_back(std::move(outside));
        rest = clipConvex(rest, a, inward);
    }
}

struct Box {
    Vec3 lo, hi;
};

Box boxOf(const Polygon& polygon)
{
    Box box{polygon[0], polygon[0]};
    for (const Vec3& p : polygon) {
        box.lo = glm::min(box.lo, p);
        box.hi = glm::max(box.hi, p);
    }
    return box;
}

// Apart by more than the tolerance on some axis: nothing in common.
bool apart(const Box& a, const Box& b)
{
    for (int axis = 0; axis < 3; ++axis)
        if (a.hi[axis] < b.lo[axis] - model::kDistanceEpsilon || b.hi[axis] < a.lo[axis] - model::kDistanceEpsilon)
            return true;
    return false;
}

struct CellPiece {
    Box box;
    Polygon loop;
};

// A face under many solids (a hall's floor under its furniture) is first cut
// into square cells, and each cover cuts only the pieces of the cells it
// reaches. Cut whole, every cover's edge lines would run across the whole
// face: thousands of long thin pieces, each cover tested against all of them.
constexpr size_t kCoversForCells = 8;

// About two covers a cell, and never below two patches.
double cellSize(const Polygon& polygon, size_t covers, double patchSize)
{
    return std::max(2.0 * patchSize, 2.0 * std::sqrt(model::polygonArea(polygon) / double(covers)));
}

class CellGrid {
public:
    // size 0: one cell, the whole polygon.
    CellGrid(const Polygon& polygon, const Vec3& normal, double size)
        : m_origin(polygon[0])
        , m_u(glm::normalize(polygon[1] - polygon[0]))
        , m_v(glm::cross(normal, m_u))
        , m_size(size)
    {
        if (size <= 0.0) {
            m_cells.push_back({{boxOf(polygon), polygon}});
            return;
        }
        const auto [u0, u1, v0, v1] = extentOf(polygon);
        m_u0 = u0;
        m_v0 = v0;
        m_nu = divisionsOf(u1 - u0, size);
        m_nv = divisionsOf(v1 - v0, size);
        m_cells.resize(size_t(m_nu) * size_t(m_nv));
        for (int j = 0; j < m_nv; ++j)
            for (int i = 0; i < m_nu; ++i) {
                Polygon cell = polygon;
                const Vec3 lo = m_origin + m_u * (u0 + i * size) + m_v * (v0 + j * size);
                const Vec3 hi = lo + (m_u + m_v) * size;
                if (i > 0)
                    cell = clipConvex(cell, lo, m_u);
                if (i + 1 < m_nu)
                    cell = clipConvex(cell, hi, -m_u);
                if (j > 0)
                    cell = clipConvex(cell, lo, m_v);
                if (j + 1 < m_nv)
                    cell = clipConvex(cell, hi, -m_v);
                cell = cleanConvexLoop(cell);
                if (cell.size() >= 3 && model::polygonArea(cell) > kNegligibleArea)
                    m_cells[size_t(j) * size_t(m_nu) + size_t(i)].push_back({boxOf(cell), std::move(cell)});
            }
    }

    // Calls visit(pieces of the cell) for every cell `cover` may reach.
    template <typename Visit>
    void forCellsNear(const Polygon& cover, Visit visit)
    {
        if (m_size <= 0.0) {
            visit(m_cells[0]);
            return;
        }
        const auto [u0, u1, v0, v1] = extentOf(cover);
        const auto index = [&](double x, double origin, int n) {
            return std::clamp(int(std::floor((x - origin) / m_size)), 0, n - 1);
        };
        const double eps = model::kDistanceEpsilon;
        for (int j = index(v0 - eps, m_v0, m_nv); j <= index(v1 + eps, m_v0, m_nv); ++j)
            for (int i = index(u0 - eps, m_u0, m_nu); i <= index(u1 + eps, m_u0, m_nu); ++i)
                visit(m_cells[size_t(j) * size_t(m_nu) + size_t(i)]);
    }

    std::vector<Polygon> pieces()
    {
        std::vector<Polygon> out;
        for (std::vector<CellPiece>& cell : m_cells)
            for (CellPiece& piece : cell)
                out.push_back(std::move(piece.loop));
        return out;
    }

private:
    // The polygon's extent along u and v from the origin: {u0, u1, v0, v1}.
    std::array<double, 4> extentOf(const Polygon& polygon) const
    {
        std::array<double, 4> e{1e300, -1e300, 1e300, -1e300};
        for (const Vec3& p : polygon) {
            const double u = glm::dot(p - m_origin, m_u), v = glm::dot(p - m_origin, m_v);
            e = {std::min(e[0], u), std::max(e[1], u), std::min(e[2], v), std::max(e[3], v)};
        }
        return e;
    }

    Vec3 m_origin, m_u, m_v;
    double m_size = 0.0, m_u0 = 0.0, m_v0 = 0.0;
    int m_nu = 1, m_nv = 1;
    std::vector<std::vector<CellPiece>> m_cells;
};

// What polygon and cover have in common (inside every edge of the cover).
Polygon commonPart(const Polygon& polygon, const Polygon& cover, const Vec3& coverNormal)
{
    Polygon common = polygon;
    const size_t n = cover.size();
    for (size_t k = 0; k < n && common.size() >= 3; ++k) {
        const Vec3& a = cover[k];
        common = clipConvex(common, a, glm::normalize(glm::cross(coverNormal, cover[(k + 1) % n] - a)));
    }
    return common;
}

double commonArea(const Polygon& polygon, const Polygon& cover, const Vec3& coverNormal)
{
    const Polygon common = commonPart(polygon, cover, coverNormal);
    return common.size() >= 3 ? model::polygonArea(common) : 0.0;
}

// A plane and its opposite share a key: the normal and offset rounded, then
// turned so that the first non-zero component of the normal is positive
// (rounding first, so that a normal a rounding away from an axis cannot turn
// one copy and not the other).
using PlaneKey = std::array<long long, 4>;
PlaneKey keyOf(const Plane& plane, bool& flipped)
{
    PlaneKey key{std::llround(plane.normal.x * 1e6), std::llround(plane.normal.y * 1e6),
                 std::llround(plane.normal.z * 1e6), std::llround(plane.d * 1e6)};
    flipped = key[0] < 0 || (key[0] == 0 && (key[1] < 0 || (key[1] == 0 && key[2] < 0)));
    if (flipped)
        for (long long& k : key)
            k = -k;
    return key;
}

} // namespace

std::vector<std::vector<size_t>> coversOfFaces(const PreparedScene& scene)
{
    const size_t count = scene.faces.size();
    // Faces by plane, each side apart: solids' faces are the covers.
    std::map<PlaneKey, std::array<std::vector<size_t>, 2>> byPlane;
    std::vector<PlaneKey> keys(count);
    std::vector<char> flippedOf(count, 0);
    for (size_t f = 0; f < count; ++f) {
        bool flipped = false;
        keys[f] = keyOf(scene.properties[f].plane, flipped);
        flippedOf[f] = flipped;
        if (scene.faces[f].polygon.size() >= 3)
            byPlane[keys[f]][flipped ? 1 : 0].push_back(f);
    }
    std::vector<std::vector<size_t>> covers(count);
    for (size_t f = 0; f < count; ++f) {
        const Polygon& polygon = scene.faces[f].polygon;
        if (polygon.size() < 3)
            continue;
        const auto it = byPlane.find(keys[f]);
        if (it == byPlane.end())
            continue;
        const Box face = boxOf(polygon);
        for (size_t g : it->second[flippedOf[f] ? 0 : 1])
            if (scene.properties[g].solid && !apart(face, boxOf(scene.faces[g].polygon)))
                covers[f].push_back(g);
    }
    return covers;
}

std::vector<std::vector<std::vector<Vec3>>> uncoveredPieces(const PreparedScene& scene,
                                                            std::vector<Vec3>* shadowCorners)
{
    const size_t count = scene.faces.size();
    std::vector<std::vector<Polygon>> pieces(count);
    const std::vector<std::vector<size_t>> coversOf = coversOfFaces(scene);
    const std::vector<size_t> lights = lightFaces(scene);
    for (size_t f = 0; f < count; ++f) {
        const Polygon& polygon = scene.faces[f].polygon;
        if (polygon.size() < 3)
            continue;
        const std::vector<size_t>& covers = coversOf[f];
        if (covers.empty()) {
            pieces[f].push_back(polygon);
            continue;
        }
        const Vec3& normal = scene.properties[f].plane.normal;
        CellGrid grid(polygon, normal,
                      covers.size() > kCoversForCells ? cellSize(polygon, covers.size(), scene.patchSize) : 0.0);
        for (size_t g : covers) {
            const Polygon& cover = scene.faces[g].polygon;
            const Vec3& coverNormal = scene.properties[g].plane.normal;
            const Box coverBox = boxOf(cover);
            grid.forCellsNear(cover, [&](std::vector<CellPiece>& cell) {
                std::vector<CellPiece> next;
                std::vector<Polygon> cut;
                for (CellPiece& piece : cell) {
                    // Pieces it does not cover stay as they are, to the bit.
                    if (apart(piece.box, coverBox) || commonArea(piece.loop, cover, coverNormal) <= kNegligibleArea) {
                        next.push_back(std::move(piece));
                        continue;
                    }
                    cut.clear();
                    subtract(piece.loop, cover, coverNormal, cut);
                    for (Polygon& loop : cut)
                        next.push_back({boxOf(loop), std::move(loop)});
                }
                cell = std::move(next);
            });
        }
        pieces[f] = grid.pieces();
        // Where few solids stand on the face, its pieces are also cut along
        // the lines where the solids' shadows begin at their feet
        // (solver/prepare/shadow_lines.h). Under many, the lines would cut
        // the face into slivers; there the cells and adaptive subdivision
        // have to do.
        if (covers.size() <= kCoversForCells && !lights.empty()) {
            const ShadowLineLimits limits;
            for (const ShadowLine& line :
                 footShadowLines(scene, f, covers, lights, limits.solidMinWidth * scene.patchSize, limits.maxLines)) {
                cutAlong(pieces[f], line, normal, limits.cutMinWidth * scene.patchSize, limits.cutMinAngle);
                if (shadowCorners &&
                    std::find(shadowCorners->begin(), shadowCorners->end(), line.origin) == shadowCorners->end())
                    shadowCorners->push_back(line.origin);
            }
        }
    }
    return pieces;
}

std::vector<std::vector<std::vector<Vec3>>> coveredPieces(const PreparedScene& scene)
{
    const std::vector<std::vector<size_t>> coversOf = coversOfFaces(scene);
    std::vector<std::vector<Polygon>> covered(scene.faces.size());
    for (size_t f = 0; f < scene.faces.size(); ++f) {
        // What one cover leaves goes on to the next, so that two solids
        // standing on one spot do not cover it twice.
        std::vector<Polygon> rest{scene.faces[f].polygon};
        for (size_t g : coversOf[f]) {
            const Polygon& cover = scene.faces[g].polygon;
            const Vec3& coverNormal = scene.properties[g].plane.normal;
            std::vector<Polygon> next;
            for (Polygon& piece : rest) {
                Polygon common = cleanConvexLoop(commonPart(piece, cover, coverNormal));
                if (common.size() < 3 || model::polygonArea(common) <= kNegligibleArea) {
                    next.push_back(std::move(piece));
                    continue;
                }
                covered[f].push_back(std::move(common));
                subtract(piece, cover, coverNormal, next);
            }
            rest = std::move(next);
        }
    }
    return covered;
}

} // namespace regio::solver
