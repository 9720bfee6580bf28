#include "solver/authoring/region_proposal.h"

#include "model/geometry/region_clip.h"
#include "model/validation/validation.h"
#include "solver/prepare/auto_regions.h"
#include "solver/prepare/prepare.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace regio::solver {

namespace {

// Deeper than any useful tree; a guard against pathological inputs only.
constexpr int kMaxDepth = 32;
// A gap narrower than this is two parts touching: a plane there would lie on
// faces of both and file them by their normals, across each other's regions.
constexpr double kMinGap = 4.0 * model::kDistanceEpsilon;
// Half the thickness given to a scene that is flat along an axis (metres).
constexpr double kMinThickness = 1e-3;

struct Item {
    Box3 box;             // of the part's non-shell faces
    double patches = 0.0; // estimated, of those faces
};

class Proposer {
public:
    Proposer(std::vector<std::vector<Vec3>> shell, const RegionProposalOptions& options, double patchSize)
        : m_shell(std::move(shell))
        , m_threshold(std::max(options.patchThreshold, 1))
        , m_cutParts(options.cutParts)
        , m_patchSize(patchSize)
    {
    }

    void split(const Box3& box, std::vector<Item> items, int depth, std::vector<Box3>& out) const
    {
        const double shell = shellPatches(box);
        double patches = shell;
        for (const Item& item : items)
            patches += item.patches;
        if (items.size() <= 1 || patches <= double(m_threshold) || depth >= kMaxDepth) {
            out.push_back(box);
            return;
        }
        Cut cut = bestGap(box, items, shell, patches);
        if (cut.axis < 0 && m_cutParts)
            cut = fewestCrossings(box, items);
        if (cut.axis < 0) {
            out.push_back(box); // unsplittable without cutting a part
            return;
        }

        std::vector<Item> low, high;
        for (Item& item : items) {
            if (item.box.max[cut.axis] <= cut.position) {
                low.push_back(std::move(item));
            } else if (item.box.min[cut.axis] >= cut.position) {
                high.push_back(std::move(item));
            } else { // crossed: each side gets its share
                const double f = lowFraction(item, cut.axis, cut.position);
                Item a = item, b = item;
                a.box.max[cut.axis] = cut.position;
                a.patches = item.patches * f;
                b.box.min[cut.axis] = cut.position;
                b.patches = item.patches * (1.0 - f);
                low.push_back(a);
                high.push_back(b);
            }
        }
        Box3 lowBox = box, highBox = box;
        lowBox.max[cut.axis] = cut.position;
        highBox.min[cut.axis] = cut.position;
        split(lowBox, std::move(low), depth + 1, out);
        split(highBox, std::move(high), depth + 1, out);
    }

private:
    struct Cut {
        int axis = -1;
        double position = 0.0;
    };

    // Balance of a cut: the smaller side's share of the estimated patches.
    double balance(const Box3& box, int axis, double position, double lowItems, double highItems) const
    {
        Box3 low = box, high = box;
        low.max[axis] = position;
        high.min[axis] = position;
        const double a = lowItems + shellPatches(low), b = highItems + shellPatches(high);
        return std::min(a, b) / std::max(a + b, 1.0);
    }

    static double lowFraction(const Item& item, int axis, double position)
    {
        const double extent = item.box.max[axis] - item.box.min[axis];
        return extent > 0.0 ? std::clamp((position - item.box.min[axis]) / extent, 0.0, 1.0) : 0.5;
    }

    // The most balanced plane in a gap no item reaches across; ties: the
    // wider gap, then the lower axis.
    Cut bestGap(const Box3& box, const std::vector<Item>& items, double shell, double patches) const
    {
        Cut best;
        double bestBalance = -1.0, bestGap = 0.0;
        std::vector<size_t> order(items.size());
        for (int axis = 0; axis < 3; ++axis) {
            std::iota(order.begin(), order.end(), size_t(0));
            std::sort(order.begin(), order.end(),
                      [&](size_t a, size_t b) { return items[a].box.min[axis] < items[b].box.min[axis]; });
            double reach = -INFINITY, below = 0.0;
            for (size_t i = 0; i + 1 < order.size(); ++i) {
                reach = std::max(reach, items[order[i]].box.max[axis]);
                below += items[order[i]].patches;
                const double next = items[order[i + 1]].box.min[axis];
                const double gap = next - reach;
                if (gap <= kMinGap)
                    continue;
                const double position = 0.5 * (reach + next);
                const double b = balance(box, axis, position, below, patches - shell - below);
                if (b > bestBalance + 1e-12 || (b > bestBalance - 1e-12 && gap > bestGap)) {
                    best = {axis, position};
                    bestBalance = b;
                    bestGap = gap;
                }
            }
        }
        return best;
    }

    // No gap: the plane that crosses the fewest items, among those leaving at
    // least a quarter of the patches on either side when there are any
    // (ties: the better balance). Both sides keep at least a patch size.
    Cut fewestCrossings(const Box3& box, const std::vector<Item>& items) const
    {
        Cut best;
        int bestCrossed = 0;
        double bestBalance = -1.0;
        bool bestBalanced = false;
        for (int axis = 0; axis < 3; ++axis) {
            std::vector<double> stops;
            for (const Item& item : items) {
                stops.push_back(item.box.min[axis]);
                stops.push_back(item.box.max[axis]);
            }
            std::sort(stops.begin(), stops.end());
            for (size_t i = 0; i + 1 < stops.size(); ++i) {
                if (stops[i + 1] - stops[i] <= kMinGap)
                    continue;
                const double position = 0.5 * (stops[i] + stops[i + 1]);
                if (position - box.min[axis] < m_patchSize || box.max[axis] - position < m_patchSize)
                    continue;
                int crossed = 0;
                double low = 0.0, high = 0.0;
                for (const Item& item : items) {
                    const double f = item.box.max[axis] <= position   ? 1.0
                                     : item.box.min[axis] >= position ? 0.0
                                                                      : lowFraction(item, axis, position);
                    crossed += f > 0.0 && f < 1.0;
                    low += item.patches * f;
                    high += item.patches * (1.0 - f);
                }
                const double b = balance(box, axis, position, low, high);
                const bool balanced = b >= 0.25;
                const bool better = best.axis < 0 || (balanced && !bestBalanced) ||
                                    (balanced == bestBalanced &&
                                     (crossed < bestCrossed || (crossed == bestCrossed && b > bestBalance + 1e-12)));
                if (better) {
                    best = {axis, position};
                    bestCrossed = crossed;
                    bestBalance = b;
                    bestBalanced = balanced;
                }
            }
        }
        return best;
    }

    double shellPatches(const Box3& box) const
    {
        double sum = 0.0;
        for (const std::vector<Vec3>& loop : m_shell) {
            const double area = model::polygonAreaInBox(loop, box);
            if (area >= model::kMinFaceArea)
                sum += estimatedPatches(area, m_patchSize);
        }
        return sum;
    }

    std::vector<std::vector<Vec3>> m_shell;
    int m_threshold;
    bool m_cutParts;
    double m_patchSize;
};

// The face lies in one of the six planes of the bounds.
bool onBoundary(const std::vector<Vec3>& loop, const Box3& bounds)
{
    for (int axis = 0; axis < 3; ++axis)
        for (double plane : {bounds.min[axis], bounds.max[axis]})
            if (std::all_of(loop.begin(), loop.end(),
                            [&](const Vec3& v) { return std::abs(v[axis] - plane) <= model::kDistanceEpsilon; }))
                return true;
    return false;
}

} // namespace

model::Scene withRegions(const model::Scene& scene, std::vector<model::Region> regions)
{
    model::Scene out = scene;
    out.regions = std::move(regions);
    return out;
}

namespace {

// The sweep alone (the header's heuristic), without the comparison.
model::Result<RegionProposal> proposeBySweep(const model::Scene& scene, const RegionProposalOptions& options)
{
    RegionProposal proposal;
    double patchSize = options.patchSize.value_or(scene.solver.patchSize);
    if (!(patchSize > 0.0) || !std::isfinite(patchSize))
        patchSize = 1.0; // preparation below reports the bad setting

    // The faces as preparation sees them, by part; then shell and items.
    model::Result<FaceSet> faces = collectFaces(scene);
    if (!faces)
        return model::Result<RegionProposal>::failureOf(faces);
    const Box3& bounds = faces->bounds;
    if (bounds.empty)
        return proposal;
    struct PartFaces {
        int object = -1, part = -1;
        std::vector<std::vector<Vec3>> loops;
    };
    std::vector<PartFaces> parts;
    for (FacePolygon& polygon : faces->polygons) {
        const InputFace& face = faces->faces[size_t(polygon.face)];
        if (parts.empty() || parts.back().object != face.object || parts.back().part != face.part)
            parts.push_back({face.object, face.part, {}});
        parts.back().loops.push_back(std::move(polygon.loop));
    }

    std::vector<std::vector<Vec3>> shell;
    std::vector<Item> items;
    for (PartFaces& part : parts) {
        Item item;
        for (std::vector<Vec3>& loop : part.loops) {
            if (onBoundary(loop, bounds)) {
                shell.push_back(std::move(loop));
                continue;
            }
            for (const Vec3& v : loop)
                item.box.extend(v);
            item.patches += estimatedPatches(model::polygonArea(loop), patchSize);
        }
        if (!item.box.empty)
            items.push_back(item);
    }

    // A flat scene (one floor panel) still needs boxes with a thickness:
    // a region's min must lie below its max on every axis.
    Box3 space = bounds;
    for (int axis = 0; axis < 3; ++axis)
        if (space.max[axis] - space.min[axis] <= kMinThickness) {
            space.min[axis] -= kMinThickness;
            space.max[axis] += kMinThickness;
        }
    std::vector<Box3> boxes;
    Proposer(std::move(shell), options, patchSize).split(space, std::move(items), 0, boxes);

    model::Scene proposed = withRegions(scene, {});
    for (size_t i = 0; i < boxes.size(); ++i) {
        model::Region region;
        region.id = proposed.uniqueId("region-" + std::to_string(i + 1));
        region.min = boxes[i].min;
        region.max = boxes[i].max;
        proposed.regions.push_back(region);
    }
    if (options.suggestOrders) {
        auto suggestions = suggestBspOrders(proposed, options.suggest);
        if (!suggestions)
            return model::Result<RegionProposal>::failureOf(suggestions);
        for (size_t r = 0; r < proposed.regions.size(); ++r)
            proposed.regions[r].bspOrder = (*suggestions)[r].order;
    }
    for (const model::Object& object : proposed.objects)
        for (const model::Part& part : object.parts)
            if (model::partStraddlesRegions(proposed, part))
                proposal.straddlingParts.push_back(part.id);
    model::Result<SceneBspFigures> figures = computeBspFigures(proposed);
    if (!figures)
        return model::Result<RegionProposal>::failureOf(figures);
    model::Diagnostics warnings = figures.takeDiagnostics();
    proposal.figures = std::move(*figures);
    proposal.regions = std::move(proposed.regions);
    return {std::move(proposal), std::move(warnings)};
}

} // namespace

model::Result<RegionProposal> proposeRegions(const model::Scene& scene, const RegionProposalOptions& options)
{
    model::Result<RegionProposal> swept = proposeBySweep(scene, options);
    if (!swept || !options.neverWorseThanOneRegion || swept->regions.size() <= 1)
        return swept;
    // The planes are placed by counting patches, blind to what they do to
    // the BSP trees: a plane through a room of many small things can cost
    // more fragments than it saves (the two-light room: 155 against 137).
    // So the sweep competes with the same sweep cutting no part but the
    // shell and with one region around everything (each with its suggested
    // orders), and the fewest fragments win; ties go to fewer regions.
    std::vector<model::Result<RegionProposal>> candidates;
    candidates.push_back(std::move(swept));
    if (options.cutParts) {
        RegionProposalOptions whole = options;
        whole.cutParts = false;
        candidates.push_back(proposeBySweep(scene, whole));
    }
    RegionProposalOptions one = options;
    one.patchThreshold = std::numeric_limits<int>::max();
    candidates.push_back(proposeBySweep(scene, one));
    const int oneRegion = candidates.back() ? candidates.back()->figures.fragments : -1;
    size_t best = 0;
    for (size_t c = 1; c < candidates.size(); ++c) {
        if (!candidates[c])
            continue;
        const RegionProposal& a = *candidates[c];
        const RegionProposal& b = *candidates[best];
        if (a.figures.fragments < b.figures.fragments ||
            (a.figures.fragments == b.figures.fragments && a.regions.size() < b.regions.size()))
            best = c;
    }
    model::Result<RegionProposal> chosen = std::move(candidates[best]);
    chosen->singleRegionFragments = oneRegion;
    return chosen;
}

} // namespace regio::solver
