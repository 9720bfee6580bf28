#include "output/vertex_radiosity.h"

#include "output/exact_direct.h"
#include "output/point_grid.h"

#include "model/geometry/edge_key.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <unordered_map>
#include <utility>
#include <vector>

namespace regio::output {

using model::edgeKey;
using model::Plane;
using model::undirectedEdgeKey;
using solver::Element;
using solver::InputFace;
using solver::Properties;

namespace {

glm::vec3 toFloat(const Vec3& v)
{
    return glm::vec3(static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z));
}

bool near(const Vec3& a, const Vec3& b, double tolerance)
{
    return std::abs(a.x - b.x) <= tolerance && std::abs(a.y - b.y) <= tolerance && std::abs(a.z - b.z) <= tolerance;
}

// Faces whose pieces may share vertex values: same plane, same side, same
// material. Properties carry the material's values, not its id, so two
// materials with equal values count as one (they look the same anyway).
struct GroupKey {
    Plane plane;
    Rgb reflectance;
    Rgb emission;

    bool matches(const Properties& p) const
    {
        return glm::dot(plane.normal, p.plane.normal) > 1.0 - 1e-9 && std::abs(plane.d - p.plane.d) <= 1e-7 &&
               near(reflectance, p.reflectance, 1e-12) && near(emission, p.emission, 1e-12);
    }
};

// Which group each Properties belongs to, and the elements of every group.
struct Grouping {
    std::vector<GroupKey> keys;
    std::vector<std::vector<int>> elements;
};

Grouping groupElements(const PreparedScene& scene)
{
    Grouping g;
    std::vector<int> groupOfProperties(scene.properties.size(), -1);
    for (size_t i = 0; i < scene.properties.size(); ++i) {
        const Properties& p = scene.properties[i];
        for (size_t k = 0; k < g.keys.size() && groupOfProperties[i] < 0; ++k) {
            if (g.keys[k].matches(p))
                groupOfProperties[i] = static_cast<int>(k);
        }
        if (groupOfProperties[i] < 0) {
            groupOfProperties[i] = static_cast<int>(g.keys.size());
            g.keys.push_back({p.plane, p.reflectance, p.emission});
        }
    }
    g.elements.resize(g.keys.size());
    for (size_t e = 0; e < scene.elements.size(); ++e) {
        const int group = groupOfProperties[static_cast<size_t>(scene.elements[e].properties)];
        g.elements[static_cast<size_t>(group)].push_back(static_cast<int>(e));
    }
    return g;
}

// The points of `grid` (ids into `positions`) that lie on the inside of the
// segment a-b, within `tolerance` of it and farther than that from its ends,
// as (fraction of the way from a, id), sorted along the segment. `cell` is
// the grid's cell size; `candidates` is scratch space.
void pointsOnSegment(const PointGrid& grid, const std::vector<Vec3>& positions, const Vec3& a, const Vec3& b,
                     double cell, double tolerance, std::vector<int>& candidates,
                     std::vector<std::pair<double, int>>& out)
{
    out.clear();
    const Vec3 d = b - a;
    const double length2 = glm::dot(d, d);
    if (length2 <= 0.0)
        return;
    const double length = std::sqrt(length2);
    const int steps = static_cast<int>(std::ceil(length / cell));
    candidates.clear();
    for (int k = 0; k <= steps; ++k)
        grid.forNear(a + d * (static_cast<double>(k) / steps), [&](int id) { candidates.push_back(id); });
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
    const double margin = tolerance / length;
    for (int v : candidates) {
        const Vec3& p = positions[static_cast<size_t>(v)];
        const double t = glm::dot(p - a, d) / length2;
        if (t > margin && t < 1.0 - margin && glm::length(p - (a + d * t)) <= tolerance)
            out.emplace_back(t, v);
    }
    std::sort(out.begin(), out.end());
}

// Triangulates a convex polygon whose sides may hold collinear points (the
// T-vertices) by clipping ears, never a degenerate one: each time the ear of
// best shape (area over the squared side lengths) among those with a real
// area that leave a remainder with an area. CCW order is kept. Returns
// triangles as triples of polygon entries.
void triangulateConvex(std::vector<int> polygon, const std::vector<Vec3>& positions, const Vec3& normal,
                       std::vector<std::array<int, 3>>& out)
{
    while (polygon.size() > 3) {
        const size_t n = polygon.size();
        // An ear may only go if what stays has an area too: cutting the ear
        // opposite a side full of collinear points would leave them flat.
        double twiceTotal = 0.0;
        const Vec3& origin = positions[static_cast<size_t>(polygon[0])];
        for (size_t i = 1; i + 1 < n; ++i)
            twiceTotal += glm::dot(glm::cross(positions[static_cast<size_t>(polygon[i])] - origin,
                                              positions[static_cast<size_t>(polygon[i + 1])] - origin),
                                   normal);
        int best = -1;
        double bestQuality = 0.0;
        for (size_t i = 0; i < n; ++i) {
            const Vec3& a = positions[static_cast<size_t>(polygon[(i + n - 1) % n])];
            const Vec3& b = positions[static_cast<size_t>(polygon[i])];
            const Vec3& c = positions[static_cast<size_t>(polygon[(i + 1) % n])];
            const double twiceArea = glm::dot(glm::cross(b - a, c - a), normal);
            const double sides = glm::dot(b - a, b - a) + glm::dot(c - b, c - b) + glm::dot(a - c, a - c);
            const double quality = twiceArea / sides;
            if (quality > 1e-9 && twiceTotal - twiceArea > 1e-9 * twiceTotal && quality > bestQuality) {
                bestQuality = quality;
                best = static_cast<int>(i);
            }
        }
        if (best < 0)
            break; // numerically flat remainder: fan it below
        const size_t i = static_cast<size_t>(best);
        out.push_back({polygon[(i + n - 1) % n], polygon[i], polygon[(i + 1) % n]});
        polygon.erase(polygon.begin() + static_cast<std::ptrdiff_t>(i));
    }
    for (size_t i = 1; i + 1 < polygon.size(); ++i)
        out.push_back({polygon[0], polygon[i], polygon[i + 1]});
}

} // namespace

// One group: weld, find T-vertices, re-triangulate, and note which elements
// each vertex averages (its value is computed by shade()).
void SmoothShading::planGroup(const PreparedScene& scene, const Vec3& planeNormal, const Rgb& reflectance,
                              const std::vector<int>& elements)
{
    const SmoothingOptions& options = m_options;
    // Weld the corners.
    std::vector<Vec3> positions;
    std::vector<std::array<int, 3>> corners(elements.size());
    PointGrid weld(std::max(options.weldTolerance, 1e-12));
    double edgeLengthSum = 0.0;
    for (size_t k = 0; k < elements.size(); ++k) {
        const Element& el = scene.elements[static_cast<size_t>(elements[k])];
        for (int c = 0; c < 3; ++c) {
            const Vec3& p = scene.vertices[static_cast<size_t>(el.vertices[static_cast<size_t>(c)])];
            int found = -1;
            weld.forNear(p, [&](int id) {
                if (found < 0 && near(positions[static_cast<size_t>(id)], p, options.weldTolerance))
                    found = id;
            });
            if (found < 0) {
                found = static_cast<int>(positions.size());
                positions.push_back(p);
                weld.insert(p, found);
            }
            corners[k][static_cast<size_t>(c)] = found;
        }
        for (int c = 0; c < 3; ++c)
            edgeLengthSum +=
                glm::length(scene.vertices[static_cast<size_t>(el.vertices[static_cast<size_t>((c + 1) % 3)])] -
                            scene.vertices[static_cast<size_t>(el.vertices[static_cast<size_t>(c)])]);
    }

    // Directed edges; an edge whose reverse exists is conforming and holds
    // no T-vertex. Only the others are searched.
    std::unordered_map<uint64_t, int> edges;
    for (const auto& t : corners)
        for (size_t c = 0; c < 3; ++c)
            ++edges[edgeKey(t[c], t[(c + 1) % 3])];

    const double cell = std::max(edgeLengthSum / (3.0 * static_cast<double>(elements.size())), 1e-6);
    PointGrid grid(cell);
    for (size_t v = 0; v < positions.size(); ++v)
        grid.insert(positions[v], static_cast<int>(v));

    // Each element's outline: corners and, on each side, the T-vertices in
    // order along it.
    std::vector<std::vector<int>> outlines(elements.size());
    std::vector<int> candidates;
    std::vector<std::pair<double, int>> onEdge;
    for (size_t k = 0; k < elements.size(); ++k) {
        for (size_t c = 0; c < 3; ++c) {
            const int ia = corners[k][c];
            const int ib = corners[k][(c + 1) % 3];
            outlines[k].push_back(ia);
            if (edges.count(edgeKey(ib, ia)) != 0)
                continue;
            pointsOnSegment(grid, positions, positions[static_cast<size_t>(ia)], positions[static_cast<size_t>(ib)],
                            cell, options.edgeTolerance, candidates, onEdge);
            for (const auto& [t, v] : onEdge)
                outlines[k].push_back(v);
        }
    }

    // The output triangles, free of T-vertices.
    std::vector<std::array<int, 3>> triangles;
    std::vector<int> triangleFace;
    std::vector<size_t> triangleElement; // index into `elements`
    for (size_t k = 0; k < elements.size(); ++k) {
        if (outlines[k].size() == 3)
            triangles.push_back({outlines[k][0], outlines[k][1], outlines[k][2]});
        else
            triangulateConvex(outlines[k], positions, planeNormal, triangles);
        const int face =
            scene.properties[static_cast<size_t>(scene.elements[static_cast<size_t>(elements[k])].properties)].face;
        triangleFace.resize(triangles.size(), face);
        triangleElement.resize(triangles.size(), k);
    }

    // The average of the elements touching each vertex (§6), each weighted
    // by its angle at the vertex (pi where the vertex lies on its edge), so
    // that every direction around the vertex counts alike. Weighted by area
    // instead, where a refined part of the mesh meets a coarse one the
    // large elements outweighed the small ones beside the vertex, and their
    // means come from farther away: on the Cornell box's short block a
    // vertex 1.4 cm above the floor, where the elements along the foot meet
    // larger ones, read 13 % too bright (docs/accuracy.md).
    const auto base = static_cast<uint32_t>(m_geometry.positions.size());
    std::vector<std::vector<std::pair<uint32_t, double>>> terms(positions.size());
    for (size_t k = 0; k < elements.size(); ++k) {
        const auto e = static_cast<uint32_t>(elements[k]);
        const bool flat = scene.elements[e].area <= 0.0; // weighs nothing, as before
        const std::vector<int>& outline = outlines[k];
        const size_t n = outline.size();
        for (size_t i = 0; i < n; ++i) {
            const Vec3& p = positions[static_cast<size_t>(outline[i])];
            const Vec3 a = positions[static_cast<size_t>(outline[(i + n - 1) % n])] - p;
            const Vec3 b = positions[static_cast<size_t>(outline[(i + 1) % n])] - p;
            const double angle = flat ? 0.0 : std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
            terms[static_cast<size_t>(outline[i])].emplace_back(e, angle);
        }
    }

    // Boundary vertices (on an edge used by one triangle) and neighbours.
    std::unordered_map<uint64_t, int> undirected;
    for (const auto& t : triangles)
        for (size_t c = 0; c < 3; ++c) {
            const int a = t[c], b = t[(c + 1) % 3];
            ++undirected[undirectedEdgeKey(a, b)];
        }
    std::vector<char> boundary(positions.size(), 0);
    std::vector<std::vector<int>> neighbours(positions.size());
    for (const auto& [edge, uses] : undirected) {
        const int a = static_cast<int>(edge >> 32), b = static_cast<int>(edge & 0xFFFFFFFFu);
        neighbours[static_cast<size_t>(a)].push_back(b);
        neighbours[static_cast<size_t>(b)].push_back(a);
        if (uses == 1)
            boundary[static_cast<size_t>(a)] = boundary[static_cast<size_t>(b)] = 1;
    }

    const std::vector<std::array<int, 3>> welded = triangles;
    // A shadow corner (PreparedScene::shadowCorners) is no one point of the
    // picture: each element there takes its own copy of the vertex, valued
    // by that element alone, never extrapolated.
    std::vector<char> singular(positions.size(), 0);
    for (const Vec3& p : scene.shadowCorners)
        weld.forNear(p, [&](int id) {
            if (near(positions[static_cast<size_t>(id)], p, options.weldTolerance))
                singular[static_cast<size_t>(id)] = 1;
        });
    std::vector<char> claimed(positions.size(), 0);
    for (size_t t = 0; t < triangles.size(); ++t) {
        for (int& v : triangles[t]) {
            const auto original = static_cast<size_t>(v);
            if (!singular[original])
                continue;
            const auto e = static_cast<uint32_t>(elements[triangleElement[t]]);
            const std::vector<std::pair<uint32_t, double>> own{{e, 1.0}};
            if (!claimed[original]) {
                claimed[original] = 1;
                terms[original] = own;
                neighbours[original].clear();
                continue;
            }
            v = static_cast<int>(positions.size());
            positions.push_back(positions[original]);
            terms.push_back(own);
            boundary.push_back(1);
            neighbours.emplace_back();
            singular.push_back(1);
        }
    }

    // The terms in the order shade() sums them, the same for every radiosity.
    for (size_t v = 0; v < positions.size(); ++v) {
        double weight = 0.0;
        for (const auto& [e, w] : terms[v]) {
            m_termElement.push_back(e);
            m_termWeight.push_back(w);
            weight += w;
        }
        m_weight.push_back(weight);
        m_termEnd.push_back(static_cast<uint32_t>(m_termElement.size()));
    }

    // What the options need of the neighbourhood, in output vertex numbers.
    if (options.extrapolateBoundary || options.neighbourPasses > 0) {
        for (size_t v = 0; v < positions.size(); ++v) {
            // A boundary vertex beside a shadow corner is not extrapolated:
            // shadow lines radiate from the corner, so its inner neighbours
            // lie across them, and their difference is the jump from
            // light to umbra, not a gradient towards the edge (the floor
            // 3 mm from the Cornell box's tall block's corner, in its
            // shadow, was carried to a third of its value).
            Outline kind = boundary[v] ? Outline::Extrapolated : Outline::Inner;
            if (kind == Outline::Extrapolated && !singular[v] &&
                std::any_of(neighbours[v].begin(), neighbours[v].end(),
                            [&](int w) { return singular[static_cast<size_t>(w)] != 0; }))
                kind = Outline::Averaged;
            m_boundary.push_back(kind);
            for (int w : neighbours[v])
                m_neighbour.push_back(base + static_cast<uint32_t>(w));
            m_neighbourEnd.push_back(static_cast<uint32_t>(m_neighbour.size()));
        }
    }

    // Emit the group's geometry: its vertices once each, then its triangles.
    const glm::vec3 normal = glm::normalize(toFloat(glm::normalize(planeNormal)));
    const auto group = m_groupOf.empty() ? 0u : m_groupOf.back() + 1u;
    if (options.meanPreservingPasses > 0)
        m_mass.resize(m_mass.size() + positions.size(), 0.0); // summed below; 0 = pinned
    for (size_t v = 0; v < positions.size(); ++v) {
        m_exact.push_back(positions[v]);
        m_groupOf.push_back(group);
        m_geometry.positions.push_back(toFloat(positions[v]));
        m_geometry.normals.push_back(normal);
        m_geometry.reflectance.push_back(toFloat(reflectance));
    }
    for (size_t t = 0; t < triangles.size(); ++t) {
        // The edges on the group's outline, for closeCracksBetweenGroups (the
        // welded corners: copies at shadow corners are no outline).
        for (size_t c = 0; c < 3; ++c) {
            const int a = welded[t][c], b = welded[t][(c + 1) % 3];
            if (undirected[undirectedEdgeKey(a, b)] == 1)
                m_openEdges.push_back(static_cast<uint32_t>(m_geometry.indices.size() + c));
        }
        for (int v : triangles[t])
            m_geometry.indices.push_back(base + static_cast<uint32_t>(v));
        m_geometry.triangleFace.push_back(triangleFace[t]);
        if (options.meanPreservingPasses > 0) {
            const Vec3& a = positions[size_t(triangles[t][0])];
            const Vec3& b = positions[size_t(triangles[t][1])];
            const Vec3& c = positions[size_t(triangles[t][2])];
            const double area = 0.5 * glm::length(glm::cross(b - a, c - a));
            ProjectionTriangle pt{{}, uint32_t(elements[triangleElement[t]]), area};
            for (size_t k = 0; k < 3; ++k) {
                pt.v[k] = base + uint32_t(triangles[t][k]);
                if (!singular[size_t(triangles[t][k])])
                    m_mass[pt.v[k]] += area / 3.0;
            }
            m_projection.push_back(pt);
        }
    }
}

SmoothShading::SmoothShading(const PreparedScene& scene, const SmoothingOptions& options)
    : m_options(options)
    , m_elements(scene.elements.size())
{
    for (const InputFace& f : scene.faces)
        m_geometry.faceIds.push_back(f.id);
    const Grouping groups = groupElements(scene);
    for (size_t g = 0; g < groups.keys.size(); ++g) {
        if (!groups.elements[g].empty())
            planGroup(scene, groups.keys[g].plane.normal, groups.keys[g].reflectance, groups.elements[g]);
    }
    closeCracksBetweenGroups();
    describeFaces(m_geometry, scene);
    m_exact = {};
    m_groupOf = {};
    m_openEdges = {};
}

void SmoothShading::closeCracksBetweenGroups()
{
    if (m_openEdges.empty())
        return;
    const size_t triangles = m_geometry.indices.size() / 3;
    std::vector<uint8_t> open(triangles, 0); // bit c: edge c is on its group's outline
    double edgeLengthSum = 0.0;
    for (uint32_t i : m_openEdges) {
        open[i / 3] |= uint8_t(1u << (i % 3));
        edgeLengthSum +=
            glm::length(m_exact[m_geometry.indices[i / 3 * 3 + (i % 3 + 1) % 3]] - m_exact[m_geometry.indices[i]]);
    }
    const double cell = std::max(edgeLengthSum / double(m_openEdges.size()), 1e-6);
    PointGrid grid(cell);
    for (size_t v = 0; v < m_exact.size(); ++v)
        grid.insert(m_exact[v], int(v));

    std::vector<uint32_t> indices;
    std::vector<int> triangleFace;
    std::vector<int> candidates;
    std::vector<std::pair<double, int>> onEdge;
    std::vector<int> outline;
    std::vector<std::array<int, 3>> fan;
    const size_t original = m_exact.size();
    for (size_t t = 0; t < triangles; ++t) {
        outline.clear();
        bool added = false;
        for (size_t c = 0; c < 3; ++c) {
            const uint32_t ia = m_geometry.indices[3 * t + c], ib = m_geometry.indices[3 * t + (c + 1) % 3];
            outline.push_back(int(ia));
            if (!(open[t] & (1u << c)))
                continue;
            pointsOnSegment(grid, m_exact, m_exact[ia], m_exact[ib], cell, m_options.edgeTolerance, candidates, onEdge);
            std::optional<Vec3> last;
            for (const auto& [s, v] : onEdge) {
                // Another group's vertex; several groups may have one there.
                const Vec3 p = m_exact[size_t(v)];
                if (m_groupOf[size_t(v)] == m_groupOf[ia] || (last && near(*last, p, m_options.weldTolerance)))
                    continue;
                last = p;
                // A vertex of this group at the very position of the other's.
                const auto vertex = static_cast<uint32_t>(m_exact.size());
                m_exact.push_back(p);
                m_groupOf.push_back(m_groupOf[ia]);
                m_geometry.positions.push_back(m_geometry.positions[size_t(v)]);
                m_geometry.normals.push_back(m_geometry.normals[ia]);
                m_geometry.reflectance.push_back(m_geometry.reflectance[ia]);
                m_onEdge.push_back({vertex, ia, ib, s});
                outline.push_back(int(vertex));
                added = true;
            }
        }
        const int face = m_geometry.triangleFace[t];
        if (!added) {
            for (int v : outline)
                indices.push_back(uint32_t(v));
            triangleFace.push_back(face);
            continue;
        }
        fan.clear();
        const Vec3 normal = glm::cross(m_exact[size_t(outline[1])] - m_exact[size_t(outline[0])],
                                       m_exact[size_t(outline.back())] - m_exact[size_t(outline[0])]);
        triangulateConvex(outline, m_exact, glm::normalize(normal), fan);
        for (const auto& f : fan) {
            for (int v : f)
                indices.push_back(uint32_t(v));
            triangleFace.push_back(face);
        }
    }
    m_geometry.indices = std::move(indices);
    m_geometry.triangleFace = std::move(triangleFace);
    // The new vertices average nothing themselves (shade() sets them from
    // their edge); the per-vertex arrays still need an entry each.
    const bool neighbourhood = m_options.extrapolateBoundary || m_options.neighbourPasses > 0;
    for (size_t v = original; v < m_exact.size(); ++v) {
        if (m_options.meanPreservingPasses > 0)
            m_mass.push_back(0.0); // set from their edge, never corrected
        m_weight.push_back(0.0);
        m_termEnd.push_back(m_termEnd.empty() ? 0u : m_termEnd.back());
        if (neighbourhood) {
            m_boundary.push_back(Outline::Inner);
            m_neighbourEnd.push_back(m_neighbourEnd.empty() ? 0u : m_neighbourEnd.back());
        }
    }
}

void SmoothShading::shade(std::span<const Rgb> elementRadiosity, std::vector<glm::vec3>& radiosity) const
{
    if (elementRadiosity.size() != m_elements)
        throw std::invalid_argument("smooth shading: " + std::to_string(elementRadiosity.size()) +
                                    " radiosity values for " + std::to_string(m_elements) + " elements");
    const size_t vertices = m_weight.size();
    std::vector<Rgb> value(vertices, Rgb(0.0));
    uint32_t begin = 0;
    for (size_t v = 0; v < vertices; ++v) {
        const uint32_t end = m_termEnd[v];
        if (m_weight[v] > 0.0) {
            Rgb sum(0.0);
            for (uint32_t t = begin; t < end; ++t)
                sum += elementRadiosity[m_termElement[t]] * m_termWeight[t];
            value[v] = sum / m_weight[v];
        } else if (end > begin) { // only elements of no area touch it
            Rgb sum(0.0);
            for (uint32_t t = begin; t < end; ++t)
                sum += elementRadiosity[m_termElement[t]];
            value[v] = sum / static_cast<double>(end - begin);
        }
        begin = end;
    }
    const auto neighboursOf = [&](size_t v) {
        const uint32_t first = v == 0 ? 0 : m_neighbourEnd[v - 1];
        return std::span<const uint32_t>(m_neighbour.data() + first, m_neighbourEnd[v] - first);
    };
    if (m_options.extrapolateBoundary) {
        const std::vector<Rgb> average = value;
        for (size_t v = 0; v < vertices; ++v) {
            if (m_boundary[v] != Outline::Extrapolated)
                continue;
            Rgb inner(0.0);
            int n = 0;
            for (uint32_t w : neighboursOf(v)) {
                if (m_boundary[w] == Outline::Inner) {
                    inner += average[w];
                    ++n;
                }
            }
            if (n > 0)
                value[v] = glm::max(2.0 * average[v] - inner / static_cast<double>(n), Rgb(0.0));
        }
    }
    for (int pass = 0; pass < m_options.meanPreservingPasses; ++pass)
        preserveMeans(elementRadiosity, value);
    for (int pass = 0; pass < m_options.neighbourPasses; ++pass) {
        const std::vector<Rgb> previous = value;
        for (size_t v = 0; v < vertices; ++v) {
            const std::span<const uint32_t> around = neighboursOf(v);
            if (around.empty())
                continue;
            Rgb mean(0.0);
            for (uint32_t w : around)
                mean += previous[w];
            mean /= static_cast<double>(around.size());
            value[v] = previous[v] + m_options.neighbourWeight * (mean - previous[v]);
        }
    }
    for (const OnEdge& e : m_onEdge)
        value[e.vertex] = value[e.a] * (1.0 - e.s) + value[e.b] * e.s;
    radiosity.resize(vertices);
    for (size_t v = 0; v < vertices; ++v)
        radiosity[v] = toFloat(value[v]);
}

void SmoothShading::preserveMeans(std::span<const Rgb> elementRadiosity, std::vector<Rgb>& value) const
{
    // Per vertex v: the integral of its hat function phi_v times (element
    // value - Gouraud value) over its triangles, where a triangle of area A
    // with corner values a, b, c gives A (B / 3 - (2 a + b + c) / 12) to
    // corner a; divided by the lumped mass (A / 3 summed), one Jacobi step of
    // the L2 projection of the element values onto the Gouraud mesh.
    std::vector<Rgb> residual(value.size(), Rgb(0.0));
    for (const ProjectionTriangle& t : m_projection) {
        const Rgb third = elementRadiosity[t.element] / 3.0;
        const Rgb sum = value[t.v[0]] + value[t.v[1]] + value[t.v[2]];
        for (uint32_t v : t.v)
            residual[v] += t.area * (third - (value[v] + sum) / 12.0);
    }
    for (size_t v = 0; v < value.size(); ++v)
        if (m_mass[v] > 0.0)
            value[v] = glm::max(value[v] + residual[v] / m_mass[v], Rgb(0.0));
}

LitMesh SmoothShading::litMesh(std::span<const Rgb> elementRadiosity) const
{
    LitMesh mesh = m_geometry;
    shade(elementRadiosity, mesh.radiosity);
    return mesh;
}

LitMesh smoothLitMesh(const PreparedScene& scene, std::span<const Rgb> elementRadiosity,
                      const SmoothingOptions& options)
{
    if (elementRadiosity.size() != scene.elements.size())
        throw std::invalid_argument("smoothLitMesh: " + std::to_string(elementRadiosity.size()) +
                                    " radiosity values for " + std::to_string(scene.elements.size()) + " elements");
    return SmoothShading(scene, options).litMesh(elementRadiosity);
}

LitMesh litMeshForOutput(const PreparedScene& scene, std::span<const Rgb> elementRadiosity, bool smooth,
                         double directShare)
{
    if (smooth) {
        if (elementRadiosity.size() != scene.elements.size())
            throw std::invalid_argument("litMeshForOutput: " + std::to_string(elementRadiosity.size()) +
                                        " radiosity values for " + std::to_string(scene.elements.size()) + " elements");
        return ExactDirectShading(scene).litMesh(elementRadiosity, directShare);
    }
    return litMeshFromSolution(scene, std::vector<Rgb>(elementRadiosity.begin(), elementRadiosity.end()));
}

} // namespace regio::output
