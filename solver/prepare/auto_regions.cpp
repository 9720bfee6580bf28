#include "solver/prepare/auto_regions.h"

#include "solver/prepare/partition.h"

#include <algorithm>

namespace regio::solver {

namespace {

constexpr int kMaxDepth = 32;

void split(std::vector<FacePolygon> polygons, const Box3& box, int threshold, double patchSize, int depth,
           std::vector<Box3>& out)
{
    double patches = 0.0;
    for (const FacePolygon& p : polygons)
        patches += estimatedPatches(model::polygonArea(p.loop), patchSize);
    const Vec3 size = box.size();
    const int axis = size.x >= size.y && size.x >= size.z ? 0 : size.y >= size.z ? 1 : 2;
    if (patches <= double(threshold) || polygons.size() <= 1 || size[axis] < 2.0 * patchSize || depth >= kMaxDepth) {
        out.push_back(box);
        return;
    }

    std::vector<double> centres;
    centres.reserve(polygons.size());
    for (const FacePolygon& p : polygons)
        centres.push_back(model::polygonCentroid(p.loop)[axis]);
    auto middle = centres.begin() + std::ptrdiff_t(centres.size() / 2);
    std::nth_element(centres.begin(), middle, centres.end());
    const double position = std::clamp(*middle, box.min[axis] + 0.25 * size[axis], box.max[axis] - 0.25 * size[axis]);

    std::vector<FacePolygon> front, back;
    partitionAtSeparatingPlane(std::move(polygons), axis, position, back, front);
    Box3 backBox = box, frontBox = box;
    backBox.max[axis] = position;
    frontBox.min[axis] = position;
    split(std::move(back), backBox, threshold, patchSize, depth + 1, out);
    split(std::move(front), frontBox, threshold, patchSize, depth + 1, out);
}

} // namespace

double estimatedPatches(double area, double patchSize) { return std::max(1.0, 2.0 * area / (patchSize * patchSize)); }

std::vector<Box3> autoRegionBoxes(const std::vector<FacePolygon>& polygons, const Box3& bounds, int patchThreshold,
                                  double patchSize)
{
    std::vector<Box3> out;
    if (bounds.empty)
        return out;
    split(polygons, bounds, std::max(patchThreshold, 1), patchSize > 0.0 ? patchSize : 1.0, 0, out);
    return out;
}

} // namespace regio::solver
