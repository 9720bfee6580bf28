#include "output/exact_direct.h"

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
#include <unordered_map>
#include <utility>
#include <vector>

namespace regio::output {

namespace {

// New corners stay this far from every other corner of their triangles: a
// model file's reader may weld corners closer than a millimetre into one
// (the importer does), which would fold the triangles between them.
constexpr double kMinSeparation = 1.25e-3;

std::uint64_t edgeKey(std::uint32_t a, std::uint32_t b)
{
    return a < b ? (std::uint64_t(a) << 32) | b : (std::uint64_t(b) << 32) | a;
}

// A place of a face: points this close are one place.
constexpr double kPlace = 1e-6; // metres
struct PlaceKey {
    int face;
    long long x, y, z;
    bool operator==(const PlaceKey&) const = default;
};
struct PlaceHash {
    size_t operator()(const PlaceKey& k) const
    {
        std::uint64_t h = static_cast<std::uint32_t>(k.face);
        h *= 0x9E3779B97F4A7C15u;
        for (const long long c : {k.x, k.y, k.z})
            h = (h ^ static_cast<std::uint64_t>(c)) * 0x100000001B3u;
        return size_t(h ^ (h >> 29));
    }
};
using PlaceValues = std::unordered_map<PlaceKey, Rgb, PlaceHash>;

// The points of faces where the direct part is wanted, each place once (an
// element's edge midpoint and the cut's midpoint there, a float's rounding
// apart, are one), evaluated on every core: the contour formula and the
// cutting of the lights by what stands between take nearly all of the time.
class DirectSamples {
public:
    static constexpr size_t kNone = ~size_t(0);

    size_t add(int face, const Vec3& p)
    {
        const PlaceKey key = placeOf(face, p);
        const auto [found, added] = m_index.try_emplace(key, m_points.size());
        if (added)
            m_points.emplace_back(face, p);
        return found->second;
    }

    // The values at every place: from `known`, when given, where it has
    // them, the others computed (and added to it).
    std::vector<Rgb> evaluate(const solver::DirectLight& direct, PlaceValues* known) const
    {
        std::vector<Rgb> values(m_points.size());
        std::vector<size_t> missing;
        for (const auto& [key, index] : m_index) {
            if (const auto found = known ? known->find(key) : PlaceValues::iterator{}; known && found != known->end())
                values[index] = found->second;
            else
                missing.push_back(index);
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
        if (known)
            for (const size_t index : missing)
                known->try_emplace(keyOf(index), values[index]);
        return values;
    }

private:
    static PlaceKey placeOf(int face, const Vec3& p)
    {
        return {face, std::llround(p.x / kPlace), std::llround(p.y / kPlace), std::llround(p.z / kPlace)};
    }
    PlaceKey keyOf(size_t index) const { return placeOf(m_points[index].first, m_points[index].second); }

    std::unordered_map<PlaceKey, size_t, PlaceHash> m_index;
    std::vector<std::pair<int, Vec3>> m_points;
};

} // namespace

struct DirectCache::Places {
    PlaceValues values;
};

DirectCache::DirectCache()
    : m_places(std::make_unique<Places>())
{
}

DirectCache::~DirectCache() = default;

size_t DirectCache::size() const { return m_places->values.size(); }

ExactDirectShading::ExactDirectShading(const PreparedScene& scene, const SmoothingOptions& options, DirectCache* cache)
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
    DirectSamples samples;
    std::vector<size_t> elementSamples(3 * scene.elements.size());
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
    struct EdgeState {
        bool cut = true;   // cut at its midpoint
        int triangles = 0; // of the mesh that have it: 1 on a group's outline
    };
    std::unordered_map<std::uint64_t, EdgeState> edges;
    edges.reserve(2 * smooth.indices.size());
    for (size_t t = 0; t < smooth.triangleCount(); ++t)
        for (size_t k = 0; k < 3; ++k) {
            const std::uint32_t a = smooth.indices[3 * t + k], b = smooth.indices[3 * t + (k + 1) % 3];
            const std::uint32_t c = smooth.indices[3 * t + (k + 2) % 3];
            const Vec3 mid = 0.5 * (position(a) + position(b));
            EdgeState& edge = edges[edgeKey(a, b)];
            edge.cut = edge.cut && glm::length(position(b) - position(a)) >= 2.0 * kMinSeparation &&
                       glm::length(position(c) - mid) >= kMinSeparation;
            ++edge.triangles;
        }
    // Nor where its midpoint would come within kMinSeparation of another
    // corner of the mesh without being on it: a corner of another group,
    // where two faces meet or touch, or the midpoint of one of its edges.
    std::vector<Vec3> near;
    PointGrid grid(2.0 * kMinSeparation);
    const auto add = [&](const Vec3& p) {
        grid.insert(p, int(near.size()));
        near.push_back(p);
    };
    for (size_t v = 0; v < smooth.vertexCount(); ++v)
        add(position(std::uint32_t(v)));
    for (size_t t = 0; t < smooth.triangleCount(); ++t)
        for (size_t k = 0; k < 3; ++k) {
            const std::uint32_t a = smooth.indices[3 * t + k], b = smooth.indices[3 * t + (k + 1) % 3];
            EdgeState& edge = edges.at(edgeKey(a, b));
            if (!edge.cut)
                continue;
            const Vec3 mid = 0.5 * (position(a) + position(b));
            grid.forNearest(mid, [&](int other) {
                const double d = glm::length(near[size_t(other)] - mid);
                if (d > 1e-7 && d < kMinSeparation)
                    edge.cut = false;
            });
            if (edge.cut)
                add(mid);
        }
    LitMesh& mesh = m_geometry;
    mesh = smooth;
    mesh.indices.clear();
    mesh.triangleFace.clear();
    mesh.indices.reserve(4 * smooth.indices.size());
    mesh.triangleFace.reserve(4 * smooth.triangleFace.size());
    std::vector<int> faceOf(smooth.vertexCount(), -1);
    std::unordered_map<std::uint64_t, std::uint32_t> midpoints;
    midpoints.reserve(smooth.indices.size());
    const auto midpoint = [&](std::uint32_t a, std::uint32_t b, int face) {
        const auto [found, added] = midpoints.try_emplace(edgeKey(a, b), std::uint32_t(mesh.positions.size()));
        if (added) {
            // In doubles and rounded once: a corner on a face's outline stays
            // on the line to a file's float round-off.
            mesh.positions.push_back(glm::vec3(0.5 * (position(a) + position(b))));
            mesh.normals.push_back(smooth.normals[a]);
            mesh.radiosity.push_back(glm::vec3(0.0f));
            m_ends.push_back(a);
            m_ends.push_back(b);
            mesh.reflectance.push_back(smooth.reflectance[a]);
            faceOf.push_back(face);
        }
        return found->second;
    };
    const auto triangle = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c, int face) {
        mesh.indices.insert(mesh.indices.end(), {a, b, c});
        mesh.triangleFace.push_back(face);
    };
    for (size_t t = 0; t < smooth.triangleCount(); ++t) {
        const int face = smooth.triangleFace[t];
        std::uint32_t v[3] = {smooth.indices[3 * t], smooth.indices[3 * t + 1], smooth.indices[3 * t + 2]};
        for (std::uint32_t corner : v)
            faceOf[corner] = face;
        bool split[3]; // edge k runs from v[k] to v[k + 1]
        int count = 0;
        for (size_t k = 0; k < 3; ++k)
            count += (split[k] = edges.at(edgeKey(v[k], v[(k + 1) % 3])).cut) ? 1 : 0;
        // Turned so that the cut edges come first: edge 0 (one cut), edges 0
        // and 1 (two).
        size_t turn = 0;
        if (count == 1)
            turn = split[0] ? 0 : (split[1] ? 1 : 2);
        else if (count == 2)
            turn = !split[2] ? 0 : (!split[0] ? 1 : 2);
        const std::uint32_t a = v[turn], b = v[(turn + 1) % 3], c = v[(turn + 2) % 3];
        if (count == 0) {
            triangle(a, b, c, face);
        } else if (count == 1) {
            const std::uint32_t ab = midpoint(a, b, face);
            triangle(a, ab, c, face);
            triangle(ab, b, c, face);
        } else if (count == 2) {
            // The corner between the cut edges, then the quad left by the
            // shorter diagonal.
            const std::uint32_t ab = midpoint(a, b, face), bc = midpoint(b, c, face);
            triangle(ab, b, bc, face);
            const auto at = [&](std::uint32_t corner) { return Vec3(mesh.positions[corner]); };
            if (glm::length(at(bc) - at(a)) <= glm::length(at(c) - at(ab))) {
                triangle(a, ab, bc, face);
                triangle(a, bc, c, face);
            } else {
                triangle(a, ab, c, face);
                triangle(ab, bc, c, face);
            }
        } else {
            const std::uint32_t ab = midpoint(a, b, face), bc = midpoint(b, c, face), ca = midpoint(c, a, face);
            triangle(a, ab, ca, face);
            triangle(ab, b, bc, face);
            triangle(ca, bc, c, face);
            triangle(ab, bc, ca, face);
        }
    }
    // The direct part, exact at every vertex: most of the cut's midpoints
    // are the elements' edges' midpoints.
    std::vector<size_t> vertexSamples(mesh.vertexCount(), DirectSamples::kNone);
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
