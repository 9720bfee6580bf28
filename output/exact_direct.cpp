#include "output/exact_direct.h"

#include "output/flat_index.h"
#include "output/midpoint_cut.h"
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

    const Rgb& value(std::uint32_t place) const { return m_values[place]; }

    // The values at the places added since the last call: from `known`,
    // when given, where it has them, the others computed (and added to it).
    void evaluate(const solver::DirectLight& direct, PlaceValues* known)
    {
        const size_t first = m_values.size();
        m_values.resize(m_points.size());
        std::vector<size_t> missing;
        for (size_t i = first; i < m_points.size(); ++i) {
            if (const std::uint32_t found =
                    known ? known->index.find(m_index.key(std::uint32_t(i))) : PlaceIndex::kNone;
                found != PlaceIndex::kNone)
                m_values[i] = known->values[found];
            else
                missing.push_back(i);
        }
        std::atomic<size_t> next{0};
        const auto work = [&] {
            constexpr size_t kBlock = 256;
            for (size_t begin; (begin = next.fetch_add(kBlock)) < missing.size();)
                for (size_t k = begin; k < std::min(begin + kBlock, missing.size()); ++k) {
                    const auto& [face, point] = m_points[missing[k]];
                    m_values[missing[k]] = direct.radiosity(face, point);
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
                    known->values.push_back(m_values[i]);
        }
    }

private:
    PlaceIndex m_index;
    std::vector<std::pair<int, Vec3>> m_points;
    std::vector<Rgb> m_values; // of the places evaluated so far
};

// Rounds of cutting after the first (which cuts every edge), each cutting
// the edges across which the direct part changes by more than kBend of the
// larger of its two ends' values (plus kFloor of the brightest corner's, so
// that the faint tail of a light's reach is left alone): where a lamp's
// light falls from half to a twentieth within a few centimetres (a ceiling
// over a lamp hung just under it), a straight line between corners an
// element apart cannot follow it. Each round halves the edges it cuts.
constexpr int kBendRounds = 4;
constexpr double kBend = 0.25;
constexpr double kFloor = 0.01;

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
    LitMesh smooth = m_smooth.litMesh(std::vector<Rgb>(scene.elements.size(), Rgb(0.0)));
    m_smoothVertices = smooth.vertexCount();
    const solver::DirectLight direct(scene);
    m_hasLights = direct.any();
    if (!m_hasLights) {
        m_geometry = std::move(smooth);
        return;
    }
    PlaceValues* known = cache ? &cache->m_places->values : nullptr;
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
    // The lit mesh's faces are the scene's input faces, in order. Every
    // triangle is cut at its edges' midpoints, so that a straight line
    // between two corners spans half an element; most of the new corners
    // are the elements' edges' midpoints.
    MidpointCut cut(std::move(smooth), cutFor);
    cut.cut([](std::uint32_t, std::uint32_t) { return true; });
    std::vector<std::uint32_t> vertexSamples;
    const auto sampleNewVertices = [&] {
        const LitMesh& mesh = cut.mesh();
        for (size_t v = vertexSamples.size(); v < mesh.vertexCount(); ++v)
            vertexSamples.push_back(cut.faceOf()[v] >= 0 ? samples.add(cut.faceOf()[v], Vec3(mesh.positions[v]))
                                                         : DirectSamples::kNone);
        samples.evaluate(direct, known);
    };
    sampleNewVertices();
    // Then again where the direct part bends (kBendRounds).
    const auto luminance = [&](std::uint32_t v) {
        if (vertexSamples[v] == DirectSamples::kNone)
            return 0.0;
        const Rgb& value = samples.value(vertexSamples[v]);
        return value.x + value.y + value.z;
    };
    double brightest = 0.0;
    for (std::uint32_t v = 0; v < vertexSamples.size(); ++v)
        brightest = std::max(brightest, luminance(v));
    const double floor = kFloor * brightest;
    for (int round = 0; round < kBendRounds; ++round) {
        const size_t added = cut.cut([&](std::uint32_t a, std::uint32_t b) {
            const double la = luminance(a), lb = luminance(b);
            return std::abs(la - lb) > kBend * (std::max(la, lb) + floor);
        });
        if (added == 0)
            break;
        sampleNewVertices();
    }
    m_ends = cut.ends();
    m_geometry = cut.takeMesh();
    m_elementDirect.resize(scene.elements.size());
    for (size_t e = 0; e < scene.elements.size(); ++e)
        m_elementDirect[e] = (samples.value(elementSamples[3 * e]) + samples.value(elementSamples[3 * e + 1]) +
                              samples.value(elementSamples[3 * e + 2])) /
                             3.0;
    m_vertexDirect.resize(m_geometry.vertexCount(), Rgb(0.0));
    for (size_t v = 0; v < m_geometry.vertexCount(); ++v)
        if (vertexSamples[v] != DirectSamples::kNone)
            m_vertexDirect[v] = samples.value(vertexSamples[v]);
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
    // A cut's corner takes the mean of its edge's ends, which come before it.
    std::vector<glm::vec3> left;
    m_smooth.shade(rest, left);
    LitMesh mesh = m_geometry;
    left.resize(mesh.vertexCount());
    for (size_t v = m_smoothVertices; v < mesh.vertexCount(); ++v) {
        const size_t k = v - m_smoothVertices;
        left[v] = 0.5f * (left[m_ends[2 * k]] + left[m_ends[2 * k + 1]]);
    }
    for (size_t v = 0; v < mesh.vertexCount(); ++v)
        mesh.radiosity[v] = glm::max(left[v] + glm::vec3(share * m_vertexDirect[v]), glm::vec3(0.0f));
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
