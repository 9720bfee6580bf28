#include "solver/prepare/partition.h"

#include "solver/prepare/regional_tree.h"

namespace regio::solver {

bool keepSplitSide(std::vector<Vec3>& loop, double eps)
{
    loop = cleanConvexLoop(loop, eps);
    return loop.size() >= 3 && model::polygonArea(loop) > model::kAreaEpsilon;
}

PlaneSplit splitAcross(const std::vector<Vec3>& loop, const Plane& plane, double eps)
{
    PlaneSplit out;
    model::splitPolygon(loop, plane, out.front, out.back, eps);
    if (!keepSplitSide(out.front, eps))
        out.front.clear();
    if (!keepSplitSide(out.back, eps))
        out.back.clear();
    return out;
}

model::Side routeAtSeparatingPlane(const std::vector<Vec3>& loop, int axis, double position, PlaneSplit& split)
{
    const Plane plane = separatingPlane(axis, position);
    switch (model::classifyPolygon(loop, plane)) {
    case model::Side::Front: return model::Side::Front;
    case model::Side::Back: return model::Side::Back;
    case model::Side::On: return model::polygonNormal(loop)[axis] >= 0.0 ? model::Side::Front : model::Side::Back;
    case model::Side::Spanning: break;
    }
    split = splitAcross(loop, plane);
    return model::Side::Spanning;
}

void partitionAtSeparatingPlane(std::vector<FacePolygon> polygons, int axis, double position,
                                std::vector<FacePolygon>& back, std::vector<FacePolygon>& front)
{
    PlaneSplit split;
    for (FacePolygon& p : polygons) {
        switch (routeAtSeparatingPlane(p.loop, axis, position, split)) {
        case model::Side::Front: front.push_back(std::move(p)); break;
        case model::Side::Back: back.push_back(std::move(p)); break;
        case model::Side::On: break; // never: a polygon on the plane goes to a side
        case model::Side::Spanning:
            if (!split.front.empty())
                front.push_back({std::move(split.front), p.face});
            if (!split.back.empty())
                back.push_back({std::move(split.back), p.face});
            break;
        }
    }
}

size_t lowestRank(const std::vector<FacePolygon>& polygons, std::span<const int> rank)
{
    size_t root = 0;
    for (size_t i = 1; i < polygons.size(); ++i)
        if (rank[size_t(polygons[i].face)] < rank[size_t(polygons[root].face)])
            root = i;
    return root;
}

BspPartition partitionAtRoot(std::vector<FacePolygon> polygons, size_t root, const Plane& plane, double eps)
{
    BspPartition out;
    for (size_t i = 0; i < polygons.size(); ++i) {
        FacePolygon& p = polygons[i];
        const model::Side side = i == root ? model::Side::On : model::classifyPolygon(p.loop, plane, eps);
        switch (side) {
        case model::Side::On: out.on.push_back(std::move(p)); break;
        case model::Side::Front: out.front.push_back(std::move(p)); break;
        case model::Side::Back: out.back.push_back(std::move(p)); break;
        case model::Side::Spanning: {
            ++out.splits;
            PlaneSplit split = splitAcross(p.loop, plane, eps);
            if (!split.front.empty())
                out.front.push_back({std::move(split.front), p.face});
            if (!split.back.empty())
                out.back.push_back({std::move(split.back), p.face});
            break;
        }
        }
    }
    return out;
}

} // namespace regio::solver
