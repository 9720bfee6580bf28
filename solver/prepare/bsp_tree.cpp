#include "solver/prepare/bsp_tree.h"

#include "solver/prepare/partition.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace regio::solver {

namespace {

class Builder {
public:
    Builder(PreparedScene& scene, int region, std::span<const int> rank, double eps)
        : m_scene(scene)
        , m_region(region)
        , m_rank(rank)
        , m_eps(eps)
    {
    }

    int build(std::vector<FacePolygon> polygons, int depth)
    {
        if (polygons.empty())
            return -1;
        RegionStats& stats = m_scene.regions[size_t(m_region)].stats;
        stats.depth = std::max(stats.depth, depth);
        ++stats.nodes;

        const size_t rootIndex = lowestRank(polygons, m_rank);
        const Plane plane = m_scene.properties[size_t(polygons[rootIndex].face)].plane;
        BspPartition parts = partitionAtRoot(std::move(polygons), rootIndex, plane, m_eps);
        stats.splits += parts.splits;
        std::vector<FacePolygon>& on = parts.on;

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

        const int backChild = build(std::move(parts.back), depth + 1);
        const int frontChild = build(std::move(parts.front), depth + 1);
        m_scene.nodes[size_t(index)].back = backChild;
        m_scene.nodes[size_t(index)].front = frontChild;
        return index;
    }

private:
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
