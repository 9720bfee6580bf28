#include "solver/prepare/bsp_tree.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace regio::solver {

namespace {

class Builder {
public:
    Builder(PreparedScene& scene, int region, std::span<const int> rank, double eps)
        : m_scene(scene), m_region(region), m_rank(rank), m_eps(eps)
    {
    }

    int build(std::vector<FacePolygon> polygons, int depth)
    {
        if (polygons.empty())
            return -1;
        RegionStats& stats = m_scene.regions[size_t(m_region)].stats;
        stats.depth = std::max(stats.depth, depth);
        ++stats.nodes;

        size_t rootIndex = 0;
        for (size_t i = 1; i < polygons.size(); ++i)
            if (rankOf(polygons[i]) < rankOf(polygons[rootIndex]))
                rootIndex = i;
        const Plane plane = m_scene.properties[size_t(polygons[rootIndex].face)].plane;

        std::vector<FacePolygon> on, front, back;
        std::vector<Vec3> frontLoop, backLoop;
        for (size_t i = 0; i < polygons.size(); ++i) {
            FacePolygon& p = polygons[i];
            const model::Side side = i == rootIndex ? model::Side::On : model::classifyPolygon(p.loop, plane, m_eps);
            switch (side) {
            case model::Side::On: on.push_back(std::move(p)); break;
            case model::Side::Front: front.push_back(std::move(p)); break;
            case model::Side::Back: back.push_back(std::move(p)); break;
            case model::Side::Spanning:
                ++stats.splits;
                model::splitPolygon(p.loop, plane, frontLoop, backLoop, m_eps);
                keepPiece(frontLoop, p.face, front);
                keepPiece(backLoop, p.face, back);
                break;
            }
        }
        polygons.clear();
        polygons.shrink_to_fit();

        // Fragments facing along the node plane first (BspNode::forward*).
        std::stable_partition(on.begin(), on.end(), [&](const FacePolygon& p) {
            return glm::dot(m_scene.properties[size_t(p.face)].plane.normal, plane.normal) > 0.0;
        });

        const int index = int(m_scene.nodes.size());
        BspNode node;
        node.plane = plane;
        node.region = m_region;
        node.firstFragment = int(m_scene.fragments.size());
        node.fragmentCount = int(on.size());
        for (const FacePolygon& p : on) {
            if (glm::dot(m_scene.properties[size_t(p.face)].plane.normal, plane.normal) > 0.0)
                ++node.forwardFragments;
            addFragment(p, index);
        }
        m_scene.nodes.push_back(node);
        stats.fragments += int(on.size());
        on.clear();

        const int backChild = build(std::move(back), depth + 1);
        const int frontChild = build(std::move(front), depth + 1);
        m_scene.nodes[size_t(index)].back = backChild;
        m_scene.nodes[size_t(index)].front = frontChild;
        return index;
    }

private:
    int rankOf(const FacePolygon& p) const { return m_rank[size_t(p.face)]; }

    void keepPiece(const std::vector<Vec3>& loop, int face, std::vector<FacePolygon>& into) const
    {
        std::vector<Vec3> clean = cleanConvexLoop(loop, m_eps);
        // Splits within eps of a vertex leave slivers of no area: drop them.
        if (clean.size() >= 3 && model::polygonArea(clean) > model::kAreaEpsilon)
            into.push_back({std::move(clean), face});
    }

    void addFragment(const FacePolygon& p, int node)
    {
        Region& region = m_scene.regions[size_t(m_region)];
        Fragment fragment;
        fragment.properties = p.face;
        fragment.node = node;
        fragment.region = m_region;
        fragment.firstPoint = int(m_scene.fragmentPoints.size());
        fragment.pointCount = int(p.loop.size());
        fragment.area = model::polygonArea(p.loop);
        for (const Vec3& v : p.loop) {
            m_scene.fragmentPoints.push_back(v);
            region.bounds.extend(v);
        }
        m_scene.fragments.push_back(fragment);
    }

    PreparedScene& m_scene;
    int m_region;
    std::span<const int> m_rank;
    double m_eps;
};

} // namespace

void buildRegionBsp(PreparedScene& scene, int region, std::vector<FacePolygon> polygons, std::span<const int> rank,
                    double eps)
{
    Region& r = scene.regions[size_t(region)];
    r.stats = RegionStats{};
    r.stats.inputFaces = int(polygons.size());
    Builder builder(scene, region, rank, eps);
    const int root = builder.build(std::move(polygons), 1);
    scene.regions[size_t(region)].bspRoot = root;
}

} // namespace regio::solver
