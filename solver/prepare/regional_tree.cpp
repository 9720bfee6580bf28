#include "solver/prepare/regional_tree.h"

#include "solver/prepare/partition.h"

#include <algorithm>
#include <numeric>

namespace regio::solver {

namespace {

struct Split {
    int axis = -1;
    double position = 0.0;
    int balance = -1; // size of the smaller group
    double gap = 0.0; // free space between the groups (negative: touching within eps)
    std::vector<int> back;
    std::vector<int> front;
};

// Searches the limit list of one axis: regions sorted by their lower limit;
// a plane fits after position i when no box among the first i+1 reaches past
// the lower limit of the next one.
void searchAxis(std::span<const Box3> boxes, const std::vector<int>& set, int axis, double eps, Split& best)
{
    std::vector<int> sorted = set;
    std::stable_sort(sorted.begin(), sorted.end(),
                     [&](int a, int b) { return boxes[size_t(a)].min[axis] < boxes[size_t(b)].min[axis]; });
    double reach = boxes[size_t(sorted[0])].max[axis];
    for (size_t i = 0; i + 1 < sorted.size(); ++i) {
        reach = std::max(reach, boxes[size_t(sorted[i])].max[axis]);
        double next = boxes[size_t(sorted[i + 1])].min[axis];
        if (reach > next + eps)
            continue;
        int balance = int(std::min(i + 1, sorted.size() - i - 1));
        double gap = next - reach;
        if (balance > best.balance || (balance == best.balance && gap > best.gap)) {
            best.axis = axis;
            // A touching pair (gap within eps) gets the plane on the shared face.
            best.position = gap > 0.0 ? 0.5 * (reach + next) : next;
            best.balance = balance;
            best.gap = gap;
            best.back.assign(sorted.begin(), sorted.begin() + std::ptrdiff_t(i + 1));
            best.front.assign(sorted.begin() + std::ptrdiff_t(i + 1), sorted.end());
        }
    }
}

int build(std::span<const Box3> boxes, const std::vector<int>& set, double eps, RegionalTreeBuild& out)
{
    const int index = int(out.tree.nodes.size());
    out.tree.nodes.push_back({});
    if (set.size() == 1) {
        out.tree.nodes[size_t(index)].region = set[0];
        return index;
    }
    Split best;
    for (int axis = 0; axis < 3; ++axis)
        searchAxis(boxes, set, axis, eps, best);
    if (best.axis < 0) {
        // No plane separates this group: stop here and report it, instead of
        // looping or guessing an order the painter would get wrong.
        out.inseparable.insert(out.inseparable.end(), set.begin(), set.end());
        out.tree.nodes[size_t(index)].region = set[0];
        return index;
    }
    int back = build(boxes, best.back, eps, out);
    int front = build(boxes, best.front, eps, out);
    RegionalNode& node = out.tree.nodes[size_t(index)];
    node.axis = best.axis;
    node.position = best.position;
    node.back = back;
    node.front = front;
    return index;
}

void assign(const RegionalTree& tree, int index, std::vector<FacePolygon> polygons,
            std::vector<std::vector<FacePolygon>>& cells)
{
    const RegionalNode& node = tree.nodes[size_t(index)];
    if (node.isLeaf()) {
        auto& cell = cells[size_t(node.region)];
        for (FacePolygon& p : polygons)
            cell.push_back(std::move(p));
        return;
    }
    std::vector<FacePolygon> front, back;
    partitionAtSeparatingPlane(std::move(polygons), node.axis, node.position, back, front);
    assign(tree, node.back, std::move(back), cells);
    assign(tree, node.front, std::move(front), cells);
}

} // namespace

Plane separatingPlane(int axis, double position)
{
    Plane plane;
    plane.normal = Vec3{0.0};
    plane.normal[axis] = 1.0;
    plane.d = -position;
    return plane;
}

RegionalTreeBuild buildRegionalTree(std::span<const Box3> boxes, double eps)
{
    RegionalTreeBuild out;
    if (boxes.empty())
        return out;
    std::vector<int> all(boxes.size());
    std::iota(all.begin(), all.end(), 0);
    out.tree.root = build(boxes, all, eps, out);
    return out;
}

std::vector<std::vector<FacePolygon>> assignToCells(const RegionalTree& tree, std::vector<FacePolygon> polygons,
                                                    int regionCount)
{
    std::vector<std::vector<FacePolygon>> cells(size_t(std::max(regionCount, 0)));
    if (tree.root < 0 || cells.empty())
        return cells;
    assign(tree, tree.root, std::move(polygons), cells);
    return cells;
}

} // namespace regio::solver
