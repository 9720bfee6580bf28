#include "output/exact_direct.h"

#include "output/flat_index.h"
#include "output/point_grid.h"
#include "solver/picture/direct_light.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace regio::output {

namespace {

// New corners stay this far from every other corner of their triangles: a
// model file's reader may weld corners closer than a millimetre into one
// (the importer does), which would fold the triangles between them.
constexpr double kMinSeparation = 1.25e-3;

// A place of a face: points this close are one place.
constexpr double kPlace = 1e-6; // metres
struct PlaceKey {
    int face = -1;
    long long x = 0, y = 0, z = 0;
    bool operator==(const PlaceKey&) const = default;
};
struct PlaceHash {
    std::uint64_t operator()(const PlaceKey& k) const { return hashIntegers({k.face, k.x, k.y, k.z}); }
};
using PlaceIndex = FlatIndex<PlaceKey, PlaceHash>;

// The direct part at places already computed.
struct PlaceValues {
    PlaceIndex index;
    std::vector<Rgb> values; // by the index's numbers
};

// The points of faces where the direct part is wanted, each place once (an
// element's edge midpoint and the cut's midpoint there, a float's rounding
// apart, are one), evaluated on every core: the contour formula and the
// cutting of the lights by what stands between take nearly all of the time.
class DirectSamples {
public:
    static constexpr std::uint32_t kNone = ~std::uint32_t(0);

    explicit DirectSamples(size_t expected)
        : m_index(expected)
    {
        m_points.reserve(expected);
    }

    std::uint32_t add(int face, const Vec3& p)
    {
        const auto [index, added] =
            m_index.insert({face, std::llround(p.x / kPlace), std::llround(p.y / kPlace), std::llround(p.z / kPlace)});
        if (added)
            m_points.emplace_back(face, p);
        return index;
    }

    // The values at every place: from `known`, when given, where it has
    // them, the others computed (and added to it).
    std::vector<Rgb> evaluate(const solver::DirectLight& direct, PlaceValues* known) const
    {
        std::vector<Rgb> values(m_points.size());
        std::vector<size_t> missing;
        for (std::uint32_t i = 0; i < m_points.size(); ++i) {
            if (const std::uint32_t found = known ? known->index.find(m_index.key(i)) : PlaceIndex::kNone;
                found != PlaceIndex::kNone)
                values[i] = known->values[found];
            else
                missing.push_back(i);
        }
        std::atomic<size_t> next{0};
        const auto work = [&] {
            constexpr size_t kBlock = 256;
            for (size_t begin; (begin = next.fetch_add(kBlock)) < missing.size();)
                for (size_t k = begin; k < std::min(begin + kBlock, missing.size()); ++k) {
                    const auto& [face, point] = m_points[missing[k]];
                    values[missing[k]] = direct.radiosity(face, point);
                }
        };
        const unsigned threads = std::clamp(std::thread::hardware_concurrency(), 1u, 8u);
        std::vector<std::thread> helpers;
        for (unsigned t = 1; t < threads && missing.size() > 1024; ++t)
            helpers.emplace_back(work);
        work();
        for (std::thread& helper : helpers)
            helper.join();
        if (known) {
            known->index.reserve(known->index.size() + missing.size());
            for (const size_t i : missing)
                if (known->index.insert(m_index.key(std::uint32_t(i))).second)
                    known->values.push_back(values[i]);
        }
        return values;
    }

private:
    PlaceIndex m_index;
    std::vector<std::pair<int, Vec3>> m_points;
};

// The edges of a triangle mesh, each once: per triangle side (3 t + k, from
// corner k to corner k + 1) the index of its edge. The sides are bucketed
// by their lower vertex; within a vertex's few sides, equal upper vertices
// are one edge.
std::vector<std::uint32_t> edgesOfSides(const std::vector<std::uint32_t>& indices, size_t vertexCount,
                                        size_t& edgeCount)
{
    const size_t sides = indices.size();
    const auto ends = [&](size_t side) {
        const std::uint32_t a = indices[side], b = indices[side - side % 3 + (side % 3 + 1) % 3];
        return std::pair(std::min(a, b), std::max(a, b));
    };
    std::vector<std::uint32_t> start(vertexCount + 1, 0);
    for (size_t side = 0; side < sides; ++side)
        ++start[ends(side).first + 1];
    for (size_t v = 0; v < vertexCount; ++v)
        start[v + 1] += start[v];
    std::vector<std::uint32_t> bucket(sides);
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (size_t side = 0; side < sides; ++side)
        bucket[fill[ends(side).first]++] = std::uint32_t(side);
    std::vector<std::uint32_t> edgeOf(sides);
    edgeCount = 0;
    for (size_t v = 0; v < vertexCount; ++v)
        for (std::uint32_t i = start[v]; i < start[v + 1]; ++i) {
            const std::uint32_t upper = ends(bucket[i]).second;
            std::uint32_t j = start[v];
            while (j < i && ends(bucket[j]).second != upper)
                ++j;
            edgeOf[bucket[i]] = j < i ? edgeOf[bucket[j]] : std::uint32_t(edgeCount++);
        }
    return edgeOf;
}

// A triangle side's successor in its triangle.
size_t nextSide(size_t side) { return side - side % 3 + (side % 3 + 1) % 3; }

// midpointOf per edge: kMayCut (to be cut), kUncut, or the midpoint's vertex.
constexpr std::uint32_t kMayCut = 0; // no midpoint is vertex 0: they follow the mesh's own
constexpr std::uint32_t kUncut = ~std::uint32_t(0);

// Leaves uncut every edge whose midpoint would come within kMinSeparation
// of another corner of the mesh without being on it: a corner of another
// group, where two faces meet or touch, or the midpoint of an edge cut
// before it.
void keepMidpointsApart(const LitMesh& mesh, const std::vector<std::uint32_t>& edgeOf,
                        std::vector<std::uint32_t>& midpointOf)
{
    const std::vector<std::uint32_t>& corner = mesh.indices;
    const auto position = [&](std::uint32_t v) { return Vec3(mesh.positions[v]); };
    std::vector<Vec3> near;
    near.reserve(mesh.vertexCount() + midpointOf.size());
    PointGrid grid(2.0 * kMinSeparation);
    const auto add = [&](const Vec3& p) {
        grid.insert(p, int(near.size()));
        near.push_back(p);
    };
    for (size_t v = 0; v < mesh.vertexCount(); ++v)
        add(position(std::uint32_t(v)));
    std::vector<char> checked(midpointOf.size(), 0);
    for (size_t side = 0; side < corner.size(); ++side) {
        const std::uint32_t edge = edgeOf[side];
        if (midpointOf[edge] == kUncut || checked[edge])
            continue;
        checked[edge] = 1;
        const Vec3 mid = 0.5 * (position(corner[side]) + position(corner[nextSide(side)]));
        grid.forNearest(mid, [&](int other) {
            const double d = glm::length(near[size_t(other)] - mid);
            if (d > 1e-7 && d < kMinSeparation)
                midpointOf[edge] = kUncut;
        });
        if (midpointOf[edge] != kUncut)
            add(mid);
    }
}

} // namespace

struct DirectCache::Places {
    PlaceValues values;
};

DirectCache::DirectCache()
    : m_places(std::make_unique<Places>())
{
}

DirectCache::~DirectCache() = default;

size_t DirectCache::size() const { return m_places->values.values.size(); }

ExactDirectShading::ExactDirectShading(const PreparedScene& scene, const SmoothingOptions& options, DirectCache* cache,
                                       CutFor cutFor)
    : m_smooth(scene, options)
{
    const LitMesh smooth = m_smooth.litMesh(std::vector<Rgb>(scene.elements.size(), Rgb(0.0)));
    m_smoothVertices = smooth.vertexCount();
    const solver::DirectLight direct(scene);
    m_hasLights = direct.any();
    if (!m_hasLights) {
        m_geometry = smooth;
        return;
    }
    // Each element's direct part will be the mean of the exact values at
    // its edges' midpoints.
    DirectSamples samples(2 * (scene.elements.size() + smooth.vertexCount()));
    std::vector<std::uint32_t> elementSamples(3 * scene.elements.size());
    for (size_t e = 0; e < scene.elements.size(); ++e) {
        const solver::Element& element = scene.elements[e];
        for (size_t k = 0; k < 3; ++k)
            elementSamples[3 * e + k] =
                samples.add(element.properties, 0.5 * (scene.vertices[size_t(element.vertices[k])] +
                                                       scene.vertices[size_t(element.vertices[(k + 1) % 3])]));
    }

    // Every triangle cut at its edges' midpoints, each midpoint shared by
    // the triangles that share the edge. An edge is cut only where the
    // pieces stay apart by kMinSeparation (see the header). The lit mesh's
    // faces are the scene's input faces, in order.
    const auto position = [&](std::uint32_t v) { return Vec3(smooth.positions[v]); };
    const std::vector<std::uint32_t>& corner = smooth.indices;
    const auto next = nextSide;
    size_t edgeCount = 0;
    const std::vector<std::uint32_t> edgeOf = edgesOfSides(corner, smooth.vertexCount(), edgeCount);
    std::vector<std::uint32_t> midpointOf(edgeCount, kMayCut);
    for (size_t side = 0; side < corner.size(); ++side) {
        const std::uint32_t a = corner[side], b = corner[next(side)], c = corner[next(next(side))];
        const Vec3 mid = 0.5 * (position(a) + position(b));
        if (glm::length(position(b) - position(a)) < 2.0 * kMinSeparation ||
            glm::length(position(c) - mid) < kMinSeparation)
            midpointOf[edgeOf[side]] = kUncut;
    }
    // For files, nor where its midpoint would come within kMinSeparation of
    // another corner of the mesh without being on it: a corner of another
    // group, where two faces meet or touch, or the midpoint of one of its
    // edges.
    if (cutFor == CutFor::Files)
        keepMidpointsApart(smooth, edgeOf, midpointOf);
    LitMesh& mesh = m_geometry;
    mesh = smooth;
    mesh.indices.clear();
    mesh.triangleFace.clear();
    mesh.indices.reserve(4 * smooth.indices.size());
    mesh.triangleFace.reserve(4 * smooth.triangleFace.size());
    std::vector<int> faceOf(smooth.vertexCount(), -1);
    const auto midpoint = [&](size_t side, int face) {
        std::uint32_t& vertex = midpointOf[edgeOf[side]];
        if (vertex == kMayCut) {
            // In doubles and rounded once: a corner on a face's outline stays
            // on the line to a file's float round-off.
            const std::uint32_t a = corner[side], b = corner[next(side)];
            vertex = std::uint32_t(mesh.positions.size());
            mesh.positions.push_back(glm::vec3(0.5 * (position(a) + position(b))));
            mesh.normals.push_back(smooth.normals[a]);
            mesh.radiosity.push_back(glm::vec3(0.0f));
            m_ends.push_back(a);
            m_ends.push_back(b);
            mesh.reflectance.push_back(smooth.reflectance[a]);
            faceOf.push_back(face);
        }
        return vertex;
    };
    const auto triangle = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c, int face) {
        mesh.indices.insert(mesh.indices.end(), {a, b, c});
        mesh.triangleFace.push_back(face);
    };
    for (size_t t = 0; t < smooth.triangleCount(); ++t) {
        const int face = smooth.triangleFace[t];
        bool split[3]; // side k runs from corner k to corner k + 1
        int count = 0;
        for (size_t k = 0; k < 3; ++k) {
            faceOf[corner[3 * t + k]] = face;
            count += (split[k] = midpointOf[edgeOf[3 * t + k]] != kUncut) ? 1 : 0;
        }
        // Turned so that the cut sides come first: side 0 (one cut), sides
        // 0 and 1 (two).
        size_t turn = 0;
        if (count == 1)
            turn = split[0] ? 0 : (split[1] ? 1 : 2);
        else if (count == 2)
            turn = !split[2] ? 0 : (!split[0] ? 1 : 2);
        const size_t sa = 3 * t + turn, sb = next(sa), sc = next(sb); // the sides from a, b and c
        const std::uint32_t a = corner[sa], b = corner[sb], c = corner[sc];
        if (count == 0) {
            triangle(a, b, c, face);
        } else if (count == 1) {
            const std::uint32_t ab = midpoint(sa, face);
            triangle(a, ab, c, face);
            triangle(ab, b, c, face);
        } else if (count == 2) {
            // The corner between the cut sides, then the quad left by the
            // shorter diagonal.
            const std::uint32_t ab = midpoint(sa, face), bc = midpoint(sb, face);
            triangle(ab, b, bc, face);
            const auto at = [&](std::uint32_t v) { return Vec3(mesh.positions[v]); };
            if (glm::length(at(bc) - at(a)) <= glm::length(at(c) - at(ab))) {
                triangle(a, ab, bc, face);
                triangle(a, bc, c, face);
            } else {
                triangle(a, ab, c, face);
                triangle(ab, bc, c, face);
            }
        } else {
            const std::uint32_t ab = midpoint(sa, face), bc = midpoint(sb, face), ca = midpoint(sc, face);
            triangle(a, ab, ca, face);
            triangle(ab, b, bc, face);
            triangle(ca, bc, c, face);
            triangle(ab, bc, ca, face);
        }
    }
    // The direct part, exact at every vertex: most of the cut's midpoints
    // are the elements' edges' midpoints.
    std::vector<std::uint32_t> vertexSamples(mesh.vertexCount(), DirectSamples::kNone);
    for (size_t v = 0; v < mesh.vertexCount(); ++v)
        if (faceOf[v] >= 0)
            vertexSamples[v] = samples.add(faceOf[v], Vec3(mesh.positions[v]));
    const std::vector<Rgb> values = samples.evaluate(direct, cache ? &cache->m_places->values : nullptr);
    m_elementDirect.resize(scene.elements.size());
    for (size_t e = 0; e < scene.elements.size(); ++e)
        m_elementDirect[e] =
            (values[elementSamples[3 * e]] + values[elementSamples[3 * e + 1]] + values[elementSamples[3 * e + 2]]) /
            3.0;
    m_vertexDirect.resize(mesh.vertexCount(), Rgb(0.0));
    for (size_t v = 0; v < mesh.vertexCount(); ++v)
        if (vertexSamples[v] != DirectSamples::kNone)
            m_vertexDirect[v] = values[vertexSamples[v]];
}

LitMesh ExactDirectShading::litMesh(std::span<const Rgb> elementRadiosity, double share) const
{
    if (!m_hasLights)
        return m_smooth.litMesh(elementRadiosity);
    if (elementRadiosity.size() != m_elementDirect.size())
        throw std::invalid_argument("exact direct shading: " + std::to_string(elementRadiosity.size()) +
                                    " radiosity values for " + std::to_string(m_elementDirect.size()) + " elements");
    // What is left of each element without the lights' direct part,
    // smoothed; the direct part added back exact at every vertex.
    std::vector<Rgb> rest(elementRadiosity.begin(), elementRadiosity.end());
    for (size_t e = 0; e < rest.size(); ++e)
        rest[e] -= share * m_elementDirect[e];
    std::vector<glm::vec3> smooth;
    m_smooth.shade(rest, smooth);
    LitMesh mesh = m_geometry;
    for (size_t v = 0; v < mesh.vertexCount(); ++v) {
        const glm::vec3 left =
            v < m_smoothVertices
                ? smooth[v]
                : 0.5f * (smooth[m_ends[2 * (v - m_smoothVertices)]] + smooth[m_ends[2 * (v - m_smoothVertices) + 1]]);
        mesh.radiosity[v] = glm::max(left + glm::vec3(share * m_vertexDirect[v]), glm::vec3(0.0f));
    }
    return mesh;
}

double directShare(const PreparedScene& scene, std::span<const Rgb> unshot)
{
    double emitted = 0.0, left = 0.0;
    for (size_t e = 0; e < scene.elements.size() && e < unshot.size(); ++e) {
        const solver::Element& element = scene.elements[e];
        const Rgb& emission = scene.properties[size_t(element.properties)].emission;
        const double sum = emission.x + emission.y + emission.z;
        if (sum <= 0.0)
            continue;
        const Rgb unshotEmission = glm::min(glm::max(unshot[e], Rgb(0.0)), emission);
        emitted += element.area * sum;
        left += element.area * (unshotEmission.x + unshotEmission.y + unshotEmission.z);
    }
    return emitted > 0.0 ? std::clamp(1.0 - left / emitted, 0.0, 1.0) : 1.0;
}

LitMesh exactDirectLitMesh(const PreparedScene& scene, std::span<const Rgb> elementRadiosity,
                           const SmoothingOptions& options)
{
    if (elementRadiosity.size() != scene.elements.size())
        throw std::invalid_argument("exactDirectLitMesh: " + std::to_string(elementRadiosity.size()) +
                                    " radiosity values for " + std::to_string(scene.elements.size()) + " elements");
    return ExactDirectShading(scene, options).litMesh(elementRadiosity);
}

} // namespace regio::output
