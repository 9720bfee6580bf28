#include "solver/shooting/adaptive_subdivision.h"

#include "model/geometry/edge_key.h"
#include "solver/prepare/pieces.h"
#include "solver/shooting/shooting.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace regio::solver {

AdaptiveMesh::AdaptiveMesh(PreparedScene& scene, std::vector<Rgb> radiosity, std::vector<Rgb> unshot, bool anchoring)
    : m_scene(scene)
    , m_anchoring(anchoring)
    , m_levels(scene.elements.size())
    , m_radiosity(std::move(radiosity))
    , m_unshot(std::move(unshot))
    , m_faces(scene.faces.size())
    , m_shared(sharedOutlines(scene))
    , m_rim(scene.faces.size())
{
    if (m_radiosity.size() != scene.elements.size() || m_unshot.size() != scene.elements.size())
        throw std::invalid_argument("AdaptiveMesh: one radiosity and one unshot value per element expected");
    for (int e = 0; e < int(scene.elements.size()); ++e) {
        addEdges(e);
        const int face = faceOf(e);
        if (onSharedOutline(face, e))
            m_rim[size_t(face)].push_back(e);
    }
}

int AdaptiveMesh::faceOf(int element) const
{
    return m_scene.properties[size_t(m_scene.elements[size_t(element)].properties)].face;
}

void AdaptiveMesh::addEdges(int element)
{
    FaceTopology& t = m_faces[size_t(faceOf(element))];
    const auto& v = m_scene.elements[size_t(element)].vertices;
    for (int k = 0; k < 3; ++k)
        t.sides[model::undirectedEdgeKey(v[size_t(k)], v[size_t((k + 1) % 3)])].push_back(element);
}

void AdaptiveMesh::removeEdges(int element)
{
    FaceTopology& t = m_faces[size_t(faceOf(element))];
    const auto& v = m_scene.elements[size_t(element)].vertices;
    for (int k = 0; k < 3; ++k) {
        auto it = t.sides.find(model::undirectedEdgeKey(v[size_t(k)], v[size_t((k + 1) % 3)]));
        if (it == t.sides.end())
            throw std::logic_error("AdaptiveMesh::removeEdges: a side of the element is not in the mesh");
        std::erase(it->second, element);
        if (it->second.empty())
            t.sides.erase(it);
    }
}

int AdaptiveMesh::midpoint(int face, int a, int b)
{
    FaceTopology& t = m_faces[size_t(face)];
    const EdgeKey k = model::undirectedEdgeKey(a, b);
    if (auto it = t.midpoint.find(k); it != t.midpoint.end())
        return it->second;
    // Computed from the sorted pair, so it is the same point whoever asks.
    const int lo = std::min(a, b), hi = std::max(a, b);
    const int m = int(m_scene.vertices.size());
    m_scene.vertices.push_back(0.5 * (m_scene.vertices[size_t(lo)] + m_scene.vertices[size_t(hi)]));
    t.midpoint[k] = m;
    t.halfOf[model::undirectedEdgeKey(a, m)] = k;
    t.halfOf[model::undirectedEdgeKey(m, b)] = k;
    return m;
}

void AdaptiveMesh::collectFiner(const FaceTopology& t, int a, int b, int exclude, std::vector<int>& out) const
{
    if (auto it = t.sides.find(model::undirectedEdgeKey(a, b)); it != t.sides.end()) {
        bool found = false;
        for (int e : it->second)
            if (e != exclude) {
                out.push_back(e);
                found = true;
            }
        if (found)
            return;
    }
    if (auto it = t.midpoint.find(model::undirectedEdgeKey(a, b)); it != t.midpoint.end()) {
        collectFiner(t, a, it->second, exclude, out);
        collectFiner(t, it->second, b, exclude, out);
    }
}

std::vector<int> AdaptiveMesh::neighboursAcross(int element, int edge) const
{
    const FaceTopology& t = m_faces[size_t(faceOf(element))];
    const auto& v = m_scene.elements[size_t(element)].vertices;
    const int a = v[size_t(edge)], b = v[size_t((edge + 1) % 3)];
    std::vector<int> out;
    collectFiner(t, a, b, element, out);
    if (!out.empty())
        return out;
    // Coarser neighbour: the edge this one halves (and so on up), whose
    // remaining active owner is the element on the other side.
    EdgeKey k = model::undirectedEdgeKey(a, b);
    for (auto it = t.halfOf.find(k); it != t.halfOf.end(); it = t.halfOf.find(k)) {
        k = it->second;
        if (auto s = t.sides.find(k); s != t.sides.end()) {
            for (int e : s->second)
                if (e != element)
                    out.push_back(e);
            if (!out.empty())
                return out;
        }
    }
    return out;
}

namespace {

// The elements `across(k)` lists for the three edges k, each once.
template <typename Across>
std::vector<int> acrossAllEdges(Across across)
{
    std::vector<int> out;
    for (int k = 0; k < 3; ++k)
        for (int n : across(k))
            if (std::find(out.begin(), out.end(), n) == out.end())
                out.push_back(n);
    return out;
}

} // namespace

std::vector<int> AdaptiveMesh::neighbours(int element) const
{
    return acrossAllEdges([&](int k) { return neighboursAcross(element, k); });
}

std::pair<const Vec3&, const Vec3&> AdaptiveMesh::edgeEnds(int element, int edge) const
{
    const auto& v = m_scene.elements[size_t(element)].vertices;
    return {m_scene.vertices[size_t(v[size_t(edge)])], m_scene.vertices[size_t(v[size_t((edge + 1) % 3)])]};
}

bool AdaptiveMesh::onSharedOutline(int face, int element) const
{
    for (const SharedOutline& shared : m_shared[size_t(face)])
        for (int k = 0; k < 3; ++k) {
            const auto [a, b] = edgeEnds(element, k);
            if (collinearOverlap(shared.a, shared.b, a, b) > 0.0)
                return true;
        }
    return false;
}

template <typename Visit>
void AdaptiveMesh::forEachPartnerEdge(int element, int edge, Visit visit) const
{
    const int face = faceOf(element);
    const auto [a, b] = edgeEnds(element, edge);
    for (const SharedOutline& shared : m_shared[size_t(face)]) {
        if (collinearOverlap(shared.a, shared.b, a, b) <= 0.0)
            continue;
        for (int o : m_rim[size_t(shared.partner)])
            for (int k = 0; k < 3; ++k) {
                const auto [c, d] = edgeEnds(o, k);
                if (collinearOverlap(a, b, c, d) > 0.0)
                    visit(o, c, d);
            }
    }
}

std::vector<int> AdaptiveMesh::partnersAcross(int element, int edge) const
{
    std::vector<int> out;
    forEachPartnerEdge(element, edge, [&](int o, const Vec3&, const Vec3&) {
        if (std::find(out.begin(), out.end(), o) == out.end())
            out.push_back(o);
    });
    return out;
}

std::vector<int> AdaptiveMesh::partners(int element) const
{
    return acrossAllEdges([&](int k) { return partnersAcross(element, k); });
}

std::vector<int> AdaptiveMesh::coarserPartners(int element) const
{
    std::vector<int> out;
    for (int k = 0; k < 3; ++k) {
        const auto [a, b] = edgeEnds(element, k);
        const double length = glm::length(b - a);
        forEachPartnerEdge(element, k, [&](int o, const Vec3& c, const Vec3& d) {
            if (glm::length(d - c) > length * (1.0 + 1e-6) && std::find(out.begin(), out.end(), o) == out.end())
                out.push_back(o);
        });
    }
    return out;
}

void AdaptiveMesh::collectInside(const FaceTopology& t, int a, int b, std::vector<int>& out) const
{
    if (auto it = t.midpoint.find(model::undirectedEdgeKey(a, b)); it != t.midpoint.end()) {
        collectInside(t, a, it->second, out);
        out.push_back(it->second);
        collectInside(t, it->second, b, out);
    }
}

std::vector<int> AdaptiveMesh::tVertices(int element) const
{
    const FaceTopology& t = m_faces[size_t(faceOf(element))];
    const auto& v = m_scene.elements[size_t(element)].vertices;
    std::vector<int> out;
    for (int k = 0; k < 3; ++k)
        collectInside(t, v[size_t(k)], v[size_t((k + 1) % 3)], out);
    return out;
}

std::vector<int> AdaptiveMesh::boundaryLoop(int element) const
{
    const FaceTopology& t = m_faces[size_t(faceOf(element))];
    const auto& v = m_scene.elements[size_t(element)].vertices;
    std::vector<int> out;
    for (int k = 0; k < 3; ++k) {
        out.push_back(v[size_t(k)]);
        collectInside(t, v[size_t(k)], v[size_t((k + 1) % 3)], out);
    }
    return out;
}

std::vector<int> AdaptiveMesh::activeElements() const
{
    std::vector<int> out;
    for (int e = 0; e < int(m_levels.size()); ++e)
        if (m_levels[size_t(e)].active())
            out.push_back(e);
    return out;
}

void AdaptiveMesh::setState(std::vector<Rgb> radiosity, std::vector<Rgb> unshot)
{
    if (radiosity.size() != m_levels.size() || unshot.size() != m_levels.size())
        throw std::invalid_argument("AdaptiveMesh::setState: one value per hierarchy element expected");
    m_radiosity = std::move(radiosity);
    m_unshot = std::move(unshot);
}

void AdaptiveMesh::setActiveState(std::span<const int> sourceElement, std::span<const Rgb> radiosity,
                                  std::span<const Rgb> unshot)
{
    if (radiosity.size() != sourceElement.size() || unshot.size() != sourceElement.size())
        throw std::invalid_argument("AdaptiveMesh::setActiveState: one value per active element expected");
    for (size_t i = 0; i < sourceElement.size(); ++i) {
        const int e = sourceElement[i];
        if (e < 0 || e >= int(m_levels.size()) || !isActive(e))
            throw std::invalid_argument("AdaptiveMesh::setActiveState: not an active element of the hierarchy");
        m_radiosity[size_t(e)] = radiosity[i];
        m_unshot[size_t(e)] = unshot[i];
    }
}

double AdaptiveMesh::smallestEdgeAt(int element, double minEdge) const
{
    const Vec3& c = m_scene.elements[size_t(element)].centroid;
    for (const Vec3& corner : m_scene.shadowCorners)
        if (glm::length(c - corner) < kShadowCornerReach * minEdge)
            return kShadowCornerEdge * minEdge;
    return minEdge;
}

bool AdaptiveMesh::canSplitImpl(int element, double minEdge, int depth) const
{
    if (!isActive(element) || depth > 64)
        return false;
    const double smallest = smallestEdgeAt(element, minEdge);
    for (int k = 0; k < 3; ++k) {
        const auto [a, b] = edgeEnds(element, k);
        if (0.5 * glm::length(b - a) < smallest * (1.0 - 1e-9))
            return false;
    }
    if (m_anchoring) {
        const int level = m_levels[size_t(element)].level;
        for (int n : neighbours(element))
            if (m_levels[size_t(n)].level < level && !canSplitImpl(n, minEdge, depth + 1))
                return false;
        for (int n : coarserPartners(element))
            if (!canSplitImpl(n, minEdge, depth + 1))
                return false;
    }
    return true;
}

bool AdaptiveMesh::canSplit(int element, double minEdge) const
{
    // Without a positive smallest edge a shadow border would be refined
    // without end (the scene settings never allow it: model/edit_settings).
    if (!std::isfinite(minEdge) || minEdge <= 0.0)
        throw std::invalid_argument("adaptive subdivision: minEdge must be a positive length");
    return element >= 0 && element < int(m_levels.size()) && canSplitImpl(element, minEdge, 0);
}

std::vector<int> AdaptiveMesh::split(int element, double minEdge)
{
    std::vector<int> done;
    if (!canSplit(element, minEdge))
        return done;
    if (m_anchoring) {
        // 2:1 grading: a neighbour coarser than this element would end up two
        // levels coarser than the children. canSplit checked these are allowed.
        const int level = m_levels[size_t(element)].level;
        for (int n : neighbours(element))
            if (isActive(n) && m_levels[size_t(n)].level < level) {
                std::vector<int> more = split(n, minEdge);
                done.insert(done.end(), more.begin(), more.end());
            }
        // Across a partner face's outline, by size (see the header).
        for (int n : coarserPartners(element))
            if (isActive(n)) {
                std::vector<int> more = split(n, minEdge);
                done.insert(done.end(), more.begin(), more.end());
            }
        if (!isActive(element))
            return done;
    }
    splitNow(element);
    done.push_back(element);
    return done;
}

namespace {

// Linear function over a triangle through the values at its edge midpoints,
// shifted so that its mean (= its value at the centroid = the mean of the
// three midpoint values) is `mean`. Returned at the four child centroids.
std::array<double, 4> childValues(double mean, std::array<double, 3> mid)
{
    // A parent at zero (or a rounding hair below it) has no gradient worth
    // keeping, and the scaling below needs mean > 0 to stay finite.
    if (!(mean > 0.0))
        return {mean, mean, mean, mean};
    const double shift = mean - (mid[0] + mid[1] + mid[2]) / 3.0;
    for (double& m : mid)
        m += shift;
    // mid[k] is the value on edge k (corner k to corner k+1).
    const double a = mid[0] + mid[2] - mid[1];
    const double b = mid[0] + mid[1] - mid[2];
    const double c = mid[1] + mid[2] - mid[0];
    std::array<double, 4> out{(4 * a + b + c) / 6.0, (a + 4 * b + c) / 6.0, (a + b + 4 * c) / 6.0, mean};
    // Radiosity is never negative: scale the deviations down uniformly (the
    // mean stays) where the gradient would take a child below zero.
    double scale = 1.0;
    for (double x : out)
        if (x < 0.0)
            scale = std::min(scale, mean / (mean - x));
    for (double& x : out)
        x = mean + scale * (x - mean);
    return out;
}

} // namespace

void AdaptiveMesh::splitNow(int element)
{
    const int face = faceOf(element);
    const Element parent = m_scene.elements[size_t(element)];
    const auto v = parent.vertices;

    // Interpolation data first, while the topology still shows the parent.
    std::array<Rgb, 3> edgeValue;
    for (int k = 0; k < 3; ++k) {
        Rgb sum{0.0};
        double area = 0.0;
        std::vector<int> across = neighboursAcross(element, k);
        if (across.empty())
            across = partnersAcross(element, k);
        for (int n : across) {
            sum += m_radiosity[size_t(n)] * m_scene.elements[size_t(n)].area;
            area += m_scene.elements[size_t(n)].area;
        }
        const Rgb mean = area > 0.0 ? sum / area : m_radiosity[size_t(element)];
        edgeValue[size_t(k)] = 0.5 * (m_radiosity[size_t(element)] + mean);
    }
    std::array<Rgb, 4> childRadiosity;
    for (int ch = 0; ch < 3; ++ch) {
        const auto values =
            childValues(m_radiosity[size_t(element)][ch], {edgeValue[0][ch], edgeValue[1][ch], edgeValue[2][ch]});
        for (int i = 0; i < 4; ++i)
            childRadiosity[size_t(i)][ch] = values[size_t(i)];
    }

    const int mab = midpoint(face, v[0], v[1]);
    const int mbc = midpoint(face, v[1], v[2]);
    const int mca = midpoint(face, v[2], v[0]);
    const std::array<std::array<int, 3>, 4> corners{
        {{v[0], mab, mca}, {mab, v[1], mbc}, {mca, mbc, v[2]}, {mab, mbc, mca}}};

    removeEdges(element);
    ElementLevel& node = m_levels[size_t(element)];
    const int level = node.level + 1;
    std::array<int, 4> children{};
    std::vector<int>& faceElements = m_scene.faces[size_t(face)].elements;
    std::erase(faceElements, element);
    for (int i = 0; i < 4; ++i) {
        Element child = parent;
        child.vertices = corners[size_t(i)];
        child.node = -1; // set by buildPieces
        // The 4 midpoint children are congruent: exactly a quarter each (a
        // division by 4 is exact), so the areas sum to the parent's exactly.
        child.area = parent.area / 4.0;
        child.centroid =
            (m_scene.vertices[size_t(corners[size_t(i)][0])] + m_scene.vertices[size_t(corners[size_t(i)][1])] +
             m_scene.vertices[size_t(corners[size_t(i)][2])]) /
            3.0;
        const int index = int(m_scene.elements.size());
        m_scene.elements.push_back(child);
        ElementLevel childLevel;
        childLevel.level = level;
        childLevel.parent = element;
        m_levels.push_back(childLevel);
        m_radiosity.push_back(childRadiosity[size_t(i)]);
        // Unshot radiosity is copied: the children hold exactly the parent's
        // unshot power, so the energy books stay balanced. Shooters already
        // spent are NOT re-shot into the children: what they gave the parent
        // is carried by the interpolated radiosity above (its area-weighted
        // mean is the parent's), so no shot power is lost or counted twice.
        m_unshot.push_back(m_unshot[size_t(element)]);
        faceElements.push_back(index);
        children[size_t(i)] = index;
        addEdges(index);
    }
    m_levels[size_t(element)].children = children;
    if (!m_shared[size_t(face)].empty()) {
        std::vector<int>& rim = m_rim[size_t(face)];
        if (std::erase(rim, element) > 0)
            for (int child : children)
                if (onSharedOutline(face, child))
                    rim.push_back(child);
    }
}

int AdaptiveMesh::subdivide(std::span<const int> elements, double minEdge)
{
    std::vector<int> pending;
    for (int e : elements)
        if (e >= 0 && e < int(m_levels.size()) && isActive(e)) {
            const std::vector<int> done = split(e, minEdge);
            pending.insert(pending.end(), done.begin(), done.end());
        }
    int splits = int(pending.size());
    if (!m_anchoring)
        return splits;
    // An element with midpoints on all three edges is split: its anchored
    // fan would be as fine as its children, without their own values. Only
    // the neighbours of new children can have gained a midpoint.
    while (!pending.empty()) {
        const int parent = pending.back();
        pending.pop_back();
        // A copy: the splits below grow m_levels and would move the array.
        const std::array<int, 4> children = m_levels[size_t(parent)].children;
        for (int child : children) {
            if (!isActive(child))
                continue; // its own split is pending and covers it
            for (int n : neighbours(child)) {
                if (!isActive(n))
                    continue;
                const FaceTopology& t = m_faces[size_t(faceOf(n))];
                const auto& v = m_scene.elements[size_t(n)].vertices;
                int withMidpoint = 0;
                for (int k = 0; k < 3; ++k)
                    withMidpoint +=
                        t.midpoint.count(model::undirectedEdgeKey(v[size_t(k)], v[size_t((k + 1) % 3)])) ? 1 : 0;
                if (withMidpoint == 3) {
                    const std::vector<int> done = split(n, minEdge);
                    pending.insert(pending.end(), done.begin(), done.end());
                    splits += int(done.size());
                }
            }
        }
    }
    return splits;
}

int AdaptiveMesh::refine(std::span<const Rgb> radiosity, const model::AdaptiveSettings& settings)
{
    const std::vector<int> selected = selectBySubdivisionCriterion(radiosity, settings.threshold, settings.minEdge);
    return subdivide(selected, settings.minEdge);
}

double AdaptiveMesh::contrast(int element, std::span<const Rgb> radiosity) const
{
    const double le = luminance(radiosity[size_t(element)]);
    double largest = 0.0;
    std::vector<int> around = neighbours(element);
    for (int n : partners(element))
        around.push_back(n);
    for (int n : around) {
        const double ln = luminance(radiosity[size_t(n)]);
        const double larger = std::max(std::abs(le), std::abs(ln));
        if (larger > 0.0)
            largest = std::max(largest, std::abs(le - ln) / larger);
    }
    return largest;
}

std::vector<int> AdaptiveMesh::selectBySubdivisionCriterion(std::span<const Rgb> radiosity, double threshold,
                                                            double minEdge) const
{
    if (radiosity.size() != m_levels.size())
        throw std::invalid_argument("selectBySubdivisionCriterion: one radiosity per hierarchy element expected");
    if (!std::isfinite(minEdge) || minEdge <= 0.0)
        throw std::invalid_argument("adaptive subdivision: minEdge must be a positive length");
    std::vector<int> out;
    for (int e : activeElements())
        if (contrast(e, radiosity) > threshold && canSplit(e, minEdge))
            out.push_back(e);
    return out;
}

std::vector<OutputTriangle> AdaptiveMesh::outputTriangles() const
{
    std::vector<OutputTriangle> out;
    for (int e : activeElements()) {
        const auto& v = m_scene.elements[size_t(e)].vertices;
        if (!m_anchoring) {
            out.push_back({v, e});
            continue;
        }
        const FaceTopology& t = m_faces[size_t(faceOf(e))];
        // The polygon around the element with its T-vertices; cornerAt[k] is
        // the position of corner k in it.
        std::vector<int> polygon;
        std::array<int, 4> cornerAt{};
        for (int k = 0; k < 3; ++k) {
            cornerAt[size_t(k)] = int(polygon.size());
            polygon.push_back(v[size_t(k)]);
            collectInside(t, v[size_t(k)], v[size_t((k + 1) % 3)], polygon);
        }
        cornerAt[3] = int(polygon.size());
        if (polygon.size() == 3) {
            out.push_back({v, e});
            continue;
        }
        // Anchored fan from the first T-vertex (on edge k, between
        // cornerAt[k] and cornerAt[k+1]): the triangles through the points of
        // its own edge would be degenerate and are left out.
        int k = 0;
        while (cornerAt[size_t(k + 1)] - cornerAt[size_t(k)] == 1)
            ++k;
        const int n = int(polygon.size());
        const int apex = cornerAt[size_t(k)] + 1;
        const int first = cornerAt[size_t(k + 1)] % n; // the corner ending the apex's edge
        const int last = cornerAt[size_t(k)];          // the corner starting it
        for (int i = first; i != last; i = (i + 1) % n)
            out.push_back({{polygon[size_t(apex)], polygon[size_t(i)], polygon[size_t((i + 1) % n)]}, e});
    }
    return out;
}

ActiveScene AdaptiveMesh::activeScene() const
{
    ActiveScene result;
    PreparedScene& s = result.scene;
    // Everything but the element arrays, which are rebuilt below: copying the
    // hierarchy's elements, pieces and piece vertices only to drop them would
    // cost as much as the rebuild.
    s.faces = m_scene.faces;
    s.properties = m_scene.properties;
    s.regionalNodes = m_scene.regionalNodes;
    s.regionalRoot = m_scene.regionalRoot;
    s.regions = m_scene.regions;
    s.nodes = m_scene.nodes;
    s.fragments = m_scene.fragments;
    s.fragmentPoints = m_scene.fragmentPoints;
    s.vertices = m_scene.vertices;
    s.patches = m_scene.patches;
    s.bounds = m_scene.bounds;
    s.patchSize = m_scene.patchSize;
    s.shadowCorners = m_scene.shadowCorners;
    s.elementsPerPatch = m_scene.elementsPerPatch;
    s.stats = m_scene.stats;
    const std::vector<int> active = activeElements();
    std::vector<std::vector<int>> byPatch(s.patches.size());
    for (int e : active)
        byPatch[size_t(m_scene.elements[size_t(e)].patch)].push_back(e);
    s.elements.reserve(active.size());
    result.sourceElement.reserve(active.size());
    result.radiosity.reserve(active.size());
    result.unshot.reserve(active.size());
    for (InputFace& f : s.faces)
        f.elements.clear();
    for (size_t p = 0; p < s.patches.size(); ++p) {
        s.patches[p].firstElement = int(s.elements.size());
        s.patches[p].elementCount = int(byPatch[p].size());
        for (int e : byPatch[p]) {
            s.faces[size_t(faceOf(e))].elements.push_back(int(s.elements.size()));
            s.elements.push_back(m_scene.elements[size_t(e)]);
            result.sourceElement.push_back(e);
            result.radiosity.push_back(m_radiosity[size_t(e)]);
            result.unshot.push_back(m_unshot[size_t(e)]);
        }
    }
    s.stats.elements = int(s.elements.size());
    // Elements with T-vertices are painted through them (pieces.h), so the
    // hemicube sees no crack between a coarse element and its finer neighbours.
    std::vector<std::vector<int>> loops(s.elements.size());
    for (size_t i = 0; i < s.elements.size(); ++i)
        if (std::vector<int> loop = boundaryLoop(result.sourceElement[i]); loop.size() > 3)
            loops[i] = std::move(loop);
    buildPieces(s, loops);
    return result;
}

} // namespace regio::solver
