#include "solver/authoring/bsp_suggest.h"

#include "model/geometry/region_clip.h"
#include "solver/prepare/partition.h"
#include "solver/prepare/regional_tree.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace regio::solver {

namespace {

// The builder's tree, simulated: the same partition rule (partition.h) and,
// where the order already decides, the same root, so the simulated tree is
// the tree buildRegionBsp will build.
class GreedyBuilder {
public:
    GreedyBuilder(const std::vector<Properties>& properties, std::span<const char> listable,
                  const SuggestOptions& options)
        : m_properties(properties)
        , m_listable(listable)
        , m_options(options)
        , m_rank(properties.size(), -1)
    {
    }

    void build(std::vector<FacePolygon> polygons, int depth)
    {
        if (polygons.empty())
            return;
        m_figures.depth = std::max(m_figures.depth, depth);
        ++m_figures.nodes;

        const size_t rootIndex = chooseRoot(polygons);
        const Plane plane = planeOf(polygons[rootIndex]);
        BspPartition parts = partitionAtRoot(std::move(polygons), rootIndex, plane);
        m_figures.fragments += int(parts.on.size());
        m_figures.splits += parts.splits;
        parts.on.clear();
        build(std::move(parts.back), depth + 1);
        build(std::move(parts.front), depth + 1);
    }

    GreedyOrder result() &&
    {
        GreedyOrder out;
        out.faces = std::move(m_order);
        out.figures = m_figures;
        return out;
    }

private:
    const Plane& planeOf(const FacePolygon& p) const { return m_properties[size_t(p.face)].plane; }

    // What the builder will pick (lowest rank; ties: the earlier polygon),
    // where the order already decides; otherwise the greedy choice, which then
    // joins the order.
    size_t chooseRoot(const std::vector<FacePolygon>& polygons)
    {
        size_t listed = polygons.size();
        for (size_t i = 0; i < polygons.size(); ++i) {
            const int rank = m_rank[size_t(polygons[i].face)];
            if (rank >= 0 && (listed == polygons.size() || rank < m_rank[size_t(polygons[listed].face)]))
                listed = i;
        }
        if (listed < polygons.size())
            return listed;

        std::vector<size_t> candidates;
        for (size_t i = 0; i < polygons.size(); ++i)
            if (m_listable[size_t(polygons[i].face)])
                candidates.push_back(i);
        if (candidates.empty()) {
            // Unlisted faces rank in scene order.
            size_t first = 0;
            for (size_t i = 1; i < polygons.size(); ++i)
                if (polygons[i].face < polygons[first].face)
                    first = i;
            return first;
        }
        if (int(candidates.size()) > m_options.exhaustiveLimit && m_options.sampleSize > 0 &&
            int(candidates.size()) > m_options.sampleSize) {
            std::vector<size_t> sample;
            const size_t n = candidates.size(), k = size_t(m_options.sampleSize);
            for (size_t j = 0; j < k; ++j)
                sample.push_back(candidates[j * n / k]);
            candidates = std::move(sample);
        }

        size_t best = candidates.front();
        double bestCost = std::numeric_limits<double>::infinity();
        for (size_t c : candidates) {
            const double cost = costOf(polygons, c, bestCost);
            // Ties keep the earlier face (scene order): stable suggestions.
            if (cost < bestCost || (cost == bestCost && polygons[c].face < polygons[best].face)) {
                bestCost = cost;
                best = c;
            }
        }
        m_rank[size_t(polygons[best].face)] = int(m_order.size());
        m_order.push_back(polygons[best].face);
        return best;
    }

    // Thibault-Naylor cost of `root` over the subset; gives up (returning
    // infinity) once the splits alone cost more than `bound`.
    double costOf(const std::vector<FacePolygon>& polygons, size_t root, double bound) const
    {
        const Plane& plane = planeOf(polygons[root]);
        int splits = 0, front = 0, back = 0;
        for (size_t i = 0; i < polygons.size(); ++i) {
            if (i == root)
                continue;
            switch (model::classifyPolygon(polygons[i].loop, plane)) {
            case model::Side::On: break;
            case model::Side::Front: ++front; break;
            case model::Side::Back: ++back; break;
            case model::Side::Spanning:
                ++splits, ++front, ++back;
                if (m_options.splitWeight * splits > bound)
                    return std::numeric_limits<double>::infinity();
                break;
            }
        }
        return m_options.splitWeight * splits + m_options.balanceWeight * std::abs(front - back);
    }

    const std::vector<Properties>& m_properties;
    std::span<const char> m_listable;
    const SuggestOptions& m_options;
    std::vector<int> m_rank; // per face: position in m_order, -1 = not listed
    std::vector<int> m_order;
    BspFigures m_figures;
};

model::Box3 authoredBox(const model::Region& region)
{
    model::Box3 box;
    box.extend(glm::min(region.min, region.max));
    box.extend(glm::max(region.min, region.max));
    return box;
}

// Suggestions for the regions `wanted` (indices into scene.regions).
model::Result<std::vector<BspOrderSuggestion>> suggestFor(const model::Scene& scene, const std::vector<int>& wanted,
                                                          const SuggestOptions& options)
{
    std::vector<BspOrderSuggestion> out;
    if (wanted.empty())
        return out;
    model::Result<BspInput> input = prepareBspInput(scene);
    if (!input)
        return model::Result<std::vector<BspOrderSuggestion>>::failureOf(input);
    // The greedy simulation starts from the same cells the builder gets.
    std::vector<std::vector<FacePolygon>> cells = input->cells;
    const PreparedScene s = buildBsps(std::move(*input));
    std::vector<char> listable(s.faces.size(), 0);
    std::vector<Vec3> positions;
    for (int r : wanted) {
        const model::Region& region = scene.regions[size_t(r)];
        const Box3 box = authoredBox(region);
        std::fill(listable.begin(), listable.end(), 0);
        for (const FacePolygon& p : cells[size_t(r)]) {
            const InputFace& info = s.faces[size_t(p.face)];
            const model::Part& part = scene.objects[size_t(info.object)].parts[size_t(info.part)];
            positions = model::loopPositions(part.vertices, part.faces[size_t(info.faceInPart)].loop);
            listable[size_t(p.face)] = model::faceTouchesRegionBox(positions, box);
        }
        GreedyOrder greedy = greedyBspOrder(s.properties, std::move(cells[size_t(r)]), listable, options);
        BspOrderSuggestion suggestion;
        suggestion.regionId = region.id;
        for (int face : greedy.faces)
            suggestion.order.push_back(s.faces[size_t(face)].id);
        suggestion.suggested = greedy.figures;
        suggestion.current = figuresOf(s.regions[size_t(r)].stats);
        out.push_back(std::move(suggestion));
    }
    return out;
}

} // namespace

GreedyOrder greedyBspOrder(const std::vector<Properties>& properties, std::vector<FacePolygon> polygons,
                           std::span<const char> listable, const SuggestOptions& options)
{
    GreedyBuilder builder(properties, listable, options);
    const int inputFaces = int(polygons.size());
    builder.build(std::move(polygons), 1);
    GreedyOrder out = std::move(builder).result();
    out.figures.inputFaces = inputFaces;
    return out;
}

model::Result<BspOrderSuggestion> suggestBspOrder(const model::Scene& scene, const std::string& regionId,
                                                  const SuggestOptions& options)
{
    for (size_t r = 0; r < scene.regions.size(); ++r) {
        if (scene.regions[r].id != regionId)
            continue;
        auto all = suggestFor(scene, {int(r)}, options);
        if (!all)
            return all.error();
        return std::move(all->front());
    }
    return model::makeError("there is no region '" + regionId + "'", "", {regionId});
}

model::Result<std::vector<BspOrderSuggestion>> suggestBspOrders(const model::Scene& scene,
                                                                const SuggestOptions& options)
{
    std::vector<int> all(scene.regions.size());
    for (size_t r = 0; r < all.size(); ++r)
        all[r] = int(r);
    return suggestFor(scene, all, options);
}

} // namespace regio::solver
