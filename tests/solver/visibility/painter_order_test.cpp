// Painter-order playback: the sequence of elements equals the order in which
// the solver's painter paints them from the same point (§5.6, Appendix A).
//
// The solver's Visibility has no hook that records its order, so the tests
// check the playback three ways against it: the node sequence equals the
// traversal the painter calls (backToFrontNodes, solver/visibility/traversal.h); the
// number of elements and of culled regions equals the painter's own counts
// for the same shooter; and painting the playback's elements in sequence with
// the solver's rasteriser gives the painter's item buffer pixel for pixel
// (any two overlapping elements in the wrong order would differ).
#include "solver/visibility/painter_order.h"

#include "solver/prepare/prepare.h"
#include "solver/visibility/hemicube_raster.h"
#include "solver/visibility/item_buffer.h"
#include "solver/visibility/traversal.h"
#include "solver/visibility/visibility.h"
#include "support/sample_scenes.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>

using namespace regio;
using namespace regio::solver;

namespace {

PreparedScene preparedSample(RegionsMode mode = RegionsMode::Authored)
{
    PrepareOptions options;
    options.regions = mode;
    model::Result<PreparedScene> prepared = prepareScene(test::loadSample("two-lights-room"), options);
    EXPECT_TRUE(prepared.ok());
    return prepared.ok() ? std::move(*prepared) : PreparedScene{};
}

// Patches spread over the scene (every k-th), always including the emitters.
std::vector<int> shooterSample(const PreparedScene& s, int count)
{
    std::vector<int> out;
    const int step = std::max(1, int(s.patches.size()) / count);
    for (int p = 0; p < int(s.patches.size()); p += step)
        out.push_back(p);
    for (int p = 0; p < int(s.patches.size()); ++p)
        if (s.properties[size_t(s.patches[size_t(p)].properties)].emission.r > 0.0)
            out.push_back(p);
    return out;
}

// The playback painted with the solver's rasteriser, element after element.
ItemBuffer paintPlayback(const PreparedScene& s, const Hemicube& hemicube, const ShooterFrame& frame,
                         const PainterOrder& order)
{
    HemicubeRaster raster(hemicube);
    ItemBuffer buffer(hemicube);
    buffer.clear();
    const int n = hemicube.resolution();
    for (const PaintStep& step : order.steps) {
        const ItemId id = step.receives ? itemOfElement(std::uint32_t(step.element)) : kBlockerItem;
        for (int i = step.firstPiece; i < step.firstPiece + step.pieceCount; ++i) {
            const Piece& p = s.pieces[size_t(i)];
            EXPECT_EQ(p.element, step.element);
            const std::array<Vec3, 3> local{frame.toLocal(s.pieceVertices[size_t(p.vertices[0])]),
                                            frame.toLocal(s.pieceVertices[size_t(p.vertices[1])]),
                                            frame.toLocal(s.pieceVertices[size_t(p.vertices[2])])};
            raster.rasterize(local, [&](HemicubeFace f, int row, int x0, int x1) {
                ItemId* ids = buffer.face(f) + row * n;
                std::fill(ids + x0, ids + x1, id);
            });
        }
    }
    return buffer;
}

} // namespace

TEST(PainterOrder, WalksTheNodesInTheOrderOfTheSolversTraversal)
{
    for (RegionsMode mode : {RegionsMode::Authored, RegionsMode::None, RegionsMode::Auto}) {
        const PreparedScene s = preparedSample(mode);
        for (int patch : shooterSample(s, 40)) {
            const ShooterFrame frame = shooterFrameOfPatch(s, patch);
            const Plane plane = Plane::fromPointNormal(frame.origin, frame.n);
            std::vector<int> expected;
            backToFrontNodes(s, frame.origin, &plane, expected);
            EXPECT_EQ(painterOrderFromPatch(s, patch).nodes, expected) << "patch " << patch;
            backToFrontNodes(s, frame.origin, nullptr, expected);
            EXPECT_EQ(painterOrder(s, frame.origin).nodes, expected) << "patch " << patch;
        }
    }
}

TEST(PainterOrder, PaintsTheSamePiecesAndCullsTheSameRegionsAsThePainter)
{
    const PreparedScene s = preparedSample();
    const Hemicube hemicube(64);
    for (int patch : shooterSample(s, 40)) {
        Visibility painter(s, hemicube, model::Visibility::Painter);
        ItemBuffer buffer = painter.makeBuffer();
        ASSERT_TRUE(painter.render(shooterFrameOfPatch(s, patch), buffer));
        const PainterOrder order = painterOrderFromPatch(s, patch);
        std::int64_t pieces = 0;
        for (const PaintStep& step : order.steps)
            pieces += step.pieceCount;
        EXPECT_EQ(pieces, painter.stats().elementsVisited) << "patch " << patch;
        EXPECT_EQ(std::int64_t(order.culledRegions.size()), painter.stats().regionsCulled) << "patch " << patch;
    }
}

TEST(PainterOrder, RepaintedWithTheSolversRasteriserGivesThePaintersItemBuffer)
{
    const PreparedScene s = preparedSample();
    const Hemicube hemicube(100);
    int compared = 0, reversedDiffers = 0;
    for (int patch : shooterSample(s, 25)) {
        const ShooterFrame frame = shooterFrameOfPatch(s, patch);
        Visibility painter(s, hemicube, model::Visibility::Painter);
        ItemBuffer expected = painter.makeBuffer();
        ASSERT_TRUE(painter.render(frame, expected));
        const ItemBuffer replayed = paintPlayback(s, hemicube, frame, painterOrderFromPatch(s, patch));
        ASSERT_EQ(replayed.all().size(), expected.all().size());
        size_t differing = 0;
        for (size_t i = 0; i < expected.all().size(); ++i)
            differing += replayed.all()[i] != expected.all()[i];
        EXPECT_EQ(differing, 0u) << "patch " << patch;
        ++compared;

        // The comparison has teeth: front to back paints a different buffer
        // wherever elements overlap in the view.
        PainterOrder reversed = painterOrderFromPatch(s, patch);
        std::reverse(reversed.steps.begin(), reversed.steps.end());
        const ItemBuffer wrong = paintPlayback(s, hemicube, frame, reversed);
        size_t reversedDiffering = 0;
        for (size_t i = 0; i < expected.all().size(); ++i)
            reversedDiffering += wrong.all()[i] != expected.all()[i];
        reversedDiffers += reversedDiffering > 0;
    }
    EXPECT_GT(compared, 20);
    // (A shooter that sees no element behind another, such as a lamp's top
    // against the ceiling, paints the same either way.)
    EXPECT_GT(reversedDiffers, compared * 3 / 4);
}

TEST(PainterOrder, ListsEveryPieceOnceFromAPointWithNoPlane)
{
    // Every element is painted, once per node holding a piece of it: an
    // element cut by a plane appears in several steps, each of its own node.
    const PreparedScene s = preparedSample();
    const PainterOrder order = painterOrder(s, {3.0, 1.5, 2.0});
    EXPECT_TRUE(order.culledRegions.empty());
    std::vector<int> pieceSeen(s.pieces.size(), 0), elementSeen(s.elements.size(), 0);
    std::vector<int> nodeOfPiece(s.pieces.size(), -1);
    for (size_t n = 0; n < s.nodes.size(); ++n)
        for (int i = s.nodes[n].firstPiece; i < s.nodes[n].firstPiece + s.nodes[n].pieceCount; ++i)
            nodeOfPiece[size_t(i)] = int(n);
    for (const PaintStep& step : order.steps) {
        ++elementSeen[size_t(step.element)];
        EXPECT_GE(step.pieceCount, 1);
        for (int i = step.firstPiece; i < step.firstPiece + step.pieceCount; ++i) {
            ++pieceSeen[size_t(i)];
            EXPECT_EQ(nodeOfPiece[size_t(i)], step.node);
        }
        EXPECT_EQ(s.nodes[size_t(step.node)].region, step.region);
    }
    EXPECT_TRUE(std::all_of(pieceSeen.begin(), pieceSeen.end(), [](int n) { return n == 1; }));
    EXPECT_TRUE(std::all_of(elementSeen.begin(), elementSeen.end(), [](int n) { return n >= 1; }));
    EXPECT_EQ(order.regions.size(), s.regions.size());
}

TEST(PainterOrder, MarksElementsFacingAwayFromTheEyeAsBlockers)
{
    const PreparedScene s = preparedSample();
    const Vec3 eye{1.1, 1.3, 2.7};
    int receivers = 0, blockers = 0;
    for (const PaintStep& step : painterOrder(s, eye).steps) {
        const Element& e = s.elements[size_t(step.element)];
        const double facing = glm::dot(e.normal, eye - s.vertices[size_t(e.vertices[0])]);
        EXPECT_EQ(step.receives, facing > 0.0) << "element " << step.element;
        (step.receives ? receivers : blockers)++;
    }
    EXPECT_GT(receivers, 0);
    EXPECT_GT(blockers, 0) << "the far sides of the furniture face away";
}

TEST(PainterOrder, LeavesOutTheRegionsBehindTheShooter)
{
    const PreparedScene s = preparedSample();
    int shootersWithCulling = 0;
    for (int patch = 0; patch < int(s.patches.size()); ++patch) {
        const PainterOrder order = painterOrderFromPatch(s, patch);
        if (order.culledRegions.empty())
            continue;
        ++shootersWithCulling;
        const ShooterFrame frame = shooterFrameOfPatch(s, patch);
        const Plane plane = Plane::fromPointNormal(frame.origin, frame.n);
        for (int r : order.culledRegions)
            EXPECT_TRUE(boxBehindPlane(s.regions[size_t(r)].bounds, plane));
        for (const PaintStep& step : order.steps)
            EXPECT_EQ(std::count(order.culledRegions.begin(), order.culledRegions.end(), step.region), 0);
        EXPECT_EQ(order.regions.size() + order.culledRegions.size(), s.regions.size());
    }
    EXPECT_GT(shootersWithCulling, 0) << "walls between regions face away from their neighbours";
}
