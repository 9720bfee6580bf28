// Hemicube visibility: the painter's back-to-front order (paper §5.6,
// Appendix A) against the z-buffer reference, on scenes with several regions.
#include "solver/prepare/prepare.h"
#include "solver/solver.h"
#include "solver/visibility/visibility.h"
#include "support/prepared_scenes.h"
#include "support/solver_test_scenes.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <set>

using namespace regio;
using namespace regio::solver;

namespace {

// True if the 3 x 3 neighbourhood of (x, y) in `b` holds more than one id.
bool edgePixel(const ItemBuffer& b, HemicubeFace f, int x, int y)
{
    const ItemId id = b.at(f, x, y);
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            const int nx = x + dx, ny = y + dy;
            if (nx < 0 || ny < 0 || nx >= b.width(f) || ny >= b.height(f))
                continue;
            if (b.at(f, nx, ny) != id)
                return true;
        }
    return false;
}

struct Comparison {
    int differing = 0;      // pixels whose ids differ
    int differingInner = 0; // ... and that are not edge pixels of either buffer
    int pixels = 0;
};

Comparison compare(const ItemBuffer& a, const ItemBuffer& b)
{
    Comparison c;
    for (int fi = 0; fi < kHemicubeFaceCount; ++fi) {
        const auto f = static_cast<HemicubeFace>(fi);
        for (int y = 0; y < a.height(f); ++y)
            for (int x = 0; x < a.width(f); ++x) {
                ++c.pixels;
                if (a.at(f, x, y) == b.at(f, x, y))
                    continue;
                ++c.differing;
                if (!edgePixel(a, f, x, y) && !edgePixel(b, f, x, y))
                    ++c.differingInner;
            }
    }
    return c;
}

} // namespace

TEST(Visibility, AFullHemicubeInsideAClosedRoomSumsToOnePerShooter)
{
    model::Scene scene;
    test::addMaterial(scene, "grey", {0.5, 0.5, 0.5});
    test::addBox(scene, "room", {0, 0, 0}, {4, 2.5, 3}, "grey", true);
    test::addBox(scene, "block", {1, 0, 1}, {2, 1.2, 1.8}, "grey");
    test::addBox(scene, "shelf", {2.5, 1.5, 0.5}, {3.5, 1.6, 2.5}, "grey"); // floating
    const PreparedScene p = test::prepared(scene);
    Hemicube h(100);
    for (model::Visibility mode : {model::Visibility::Painter, model::Visibility::ZBuffer}) {
        Visibility vis(p, h, mode);
        ItemBuffer buffer = vis.makeBuffer();
        std::vector<double> perItem;
        for (size_t i = 0; i < p.patches.size(); i += 7) {
            ASSERT_TRUE(vis.render(shooterFrameOfPatch(p, static_cast<int>(i)), buffer));
            perItem.assign(p.elements.size() + kFirstElementItem, 0.0);
            buffer.accumulate(h, perItem);
            double receivers = 0.0;
            for (size_t e = 0; e < p.elements.size(); ++e)
                receivers += perItem[e + kFirstElementItem];
            // Floor patches under the block see only its inside (back faces);
            // the block's bottom looks into the floor's back side: nothing.
            const std::string& face = p.faces[static_cast<size_t>(p.patches[i].properties)].id;
            if (face == "block.body.ny")
                continue;
            const bool covered = face == "room.body.ny" && perItem[kBlockerItem] > 0.5;
            EXPECT_NEAR(receivers, covered ? 0.0 : 1.0, 1e-6) << "patch " << i << " " << model::visibilityName(mode);
            EXPECT_NEAR(perItem[kBlockerItem], covered ? 1.0 : 0.0, 1e-6) << "patch " << i;
            EXPECT_EQ(perItem[kEmptyItem], 0.0) << "patch " << i << " " << model::visibilityName(mode);
        }
    }
}

TEST(Visibility, PainterItemBuffersEqualZBufferItemBuffersExceptOnEdgePixels)
{
    Hemicube h(150);
    for (unsigned seed : {1u, 2u, 3u, 4u}) {
        const model::Scene scene = test::randomRegionScene(seed, 3, 2);
        const PreparedScene p = test::prepared(scene);
        ASSERT_EQ(p.regions.size(), 6u);
        Visibility painter(p, h, model::Visibility::Painter);
        Visibility zbuffer(p, h, model::Visibility::ZBuffer);
        ItemBuffer a = painter.makeBuffer(), b = zbuffer.makeBuffer();
        Comparison total;
        for (size_t i = 0; i < p.patches.size(); i += 11) {
            const ShooterFrame frame = shooterFrameOfPatch(p, static_cast<int>(i));
            painter.render(frame, a);
            zbuffer.render(frame, b);
            const Comparison c = compare(a, b);
            EXPECT_EQ(c.differingInner, 0) << "seed " << seed << " patch " << i;
            total.differing += c.differing;
            total.pixels += c.pixels;
        }
        // Ties along contact lines only: a tiny fraction of all pixels.
        EXPECT_LT(total.differing, total.pixels / 1000) << "seed " << seed;
    }
}

TEST(Visibility, PainterAndZBufferSolutionsAgreePerFaceWithinHalfAPercent)
{
    const model::Scene scene = test::randomRegionScene(11, 2, 2);
    std::vector<FaceResult> results[2];
    for (int m = 0; m < 2; ++m) {
        SolverOptions options;
        options.hemicube = 100;
        options.patchSize = 0.75;
        options.elementsPerPatch = 4;
        options.visibility = m == 0 ? model::Visibility::Painter : model::Visibility::ZBuffer;
        options.maxIterations = 100000;
        options.convergence = 2e-3;
        options.adaptive = false; // both on the same mesh
        auto built = Solver::create(scene, options);
        ASSERT_TRUE(built.ok());
        std::atomic<bool> cancel{false};
        ASSERT_EQ((*built)->run({}, cancel), StopReason::Converged);
        results[m] = (*built)->faceResults();
    }
    ASSERT_EQ(results[0].size(), results[1].size());
    for (size_t i = 0; i < results[0].size(); ++i)
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(results[0][i].radiosity[c], results[1][i].radiosity[c], 0.005 * results[1][i].radiosity[c])
                << results[0][i].id << " channel " << c;
}

TEST(Visibility, RegionsBehindTheShooterPlaneAreCulledWhole)
{
    const model::Scene scene = test::randomRegionScene(1, 2, 1);
    const PreparedScene p = test::prepared(scene);
    Hemicube h(50);
    Visibility painter(p, h, model::Visibility::Painter);
    ItemBuffer buffer = painter.makeBuffer();
    // The -x face of the box in the first cell looks away from the second cell.
    const auto it = std::find_if(p.patches.begin(), p.patches.end(), [&](const Patch& patch) {
        return p.faces[static_cast<size_t>(patch.properties)].id == "box00.body.nx";
    });
    ASSERT_NE(it, p.patches.end());
    painter.render(shooterFrameOfPatch(p, static_cast<int>(it - p.patches.begin())), buffer);
    EXPECT_GE(painter.stats().regionsCulled, 1);
}

TEST(Visibility, BackFacingElementsArePaintedAsBlockers)
{
    // Seen from below, a floating box's top is a back face behind its bottom;
    // from inside a bottomless box only back faces are visible.
    model::Scene scene;
    test::addMaterial(scene, "grey", {0.5, 0.5, 0.5});
    test::addBox(scene, "cover", {-1, 0, -1}, {1, 1, 1}, "grey", false, {"ny"});
    test::addPolygon(scene, "floor", {{-0.2, 0, -0.2}, {-0.2, 0, 0.2}, {0.2, 0, 0.2}, {0.2, 0, -0.2}}, "grey");
    const PreparedScene p = test::prepared(scene);
    Hemicube h(40);
    for (model::Visibility mode : {model::Visibility::Painter, model::Visibility::ZBuffer}) {
        Visibility vis(p, h, mode);
        ItemBuffer buffer = vis.makeBuffer();
        const auto it = std::find_if(p.patches.begin(), p.patches.end(), [&](const Patch& patch) {
            return p.faces[static_cast<size_t>(patch.properties)].id == "floor.face";
        });
        ASSERT_NE(it, p.patches.end());
        vis.render(shooterFrameOfPatch(p, static_cast<int>(it - p.patches.begin())), buffer);
        std::set<ItemId> seen(buffer.all().begin(), buffer.all().end());
        EXPECT_EQ(seen, std::set<ItemId>{kBlockerItem}) << model::visibilityName(mode);
    }
}

TEST(Visibility, ACancelledRenderStopsEarly)
{
    const model::Scene scene = test::randomRegionScene(3, 3, 3);
    const PreparedScene p = test::prepared(scene);
    Hemicube h(50);
    for (model::Visibility mode : {model::Visibility::Painter, model::Visibility::ZBuffer}) {
        Visibility vis(p, h, mode);
        ItemBuffer buffer = vis.makeBuffer();
        std::atomic<bool> cancel{true};
        EXPECT_FALSE(vis.render(shooterFrameOfPatch(p, 0), buffer, &cancel));
        EXPECT_LT(vis.stats().elementsVisited, static_cast<std::int64_t>(p.elements.size()));
    }
}
