// What a render leaves out of the paint order, and that it changes no pixel:
// the closed parts' back faces (solver/visibility/closed_back_faces.h), from
// a shooter on the empty side of every closed part only, the nodes whose
// pieces all lie behind the shooter (solver/visibility/node_culling.h), and
// what lies in the shadow of the face across a gap
// (solver/visibility/shadow_volume.h). The item buffers are those painted
// from the whole order, pixel for pixel, in both visibility modes.
#include "model/geometry/primitives.h"
#include "solver/prepare/prepare.h"
#include "solver/shooting/shooter_points.h"
#include "solver/visibility/closed_back_faces.h"
#include "solver/visibility/node_culling.h"
#include "solver/visibility/shadow_volume.h"
#include "solver/visibility/traversal.h"
#include "solver/visibility/visibility.h"
#include "support/furnished_room.h"
#include "support/prepared_scenes.h"
#include "support/sample_scenes.h"
#include "support/solver_test_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

using namespace regio;
using namespace regio::solver;

namespace {

ClosedPart partNamed(const PreparedScene& p, const std::string& faceId)
{
    const size_t face = test::faceNamed(p, faceId);
    const std::vector<ClosedPart> parts = closedParts(p);
    for (const ClosedPart& part : parts)
        for (const auto& t : part.triangles)
            if (std::ranges::count(p.faces[face].polygon, t[0]) > 0 &&
                std::ranges::count(p.faces[face].polygon, t[1]) > 0 &&
                std::ranges::count(p.faces[face].polygon, t[2]) > 0)
                return part;
    ADD_FAILURE() << "no closed part holds " << faceId;
    return {};
}

// A room of 4 x 3 x 4 m built as one closed part facing in, a box standing
// on its floor and a shelf against its back wall (z = 0).
model::Scene furnishedShell()
{
    model::Scene scene;
    test::addMaterial(scene, "grey", {0.5, 0.5, 0.5});
    scene.objects.push_back({"room", "", {*model::makeRoom("room.shell", {0, 0, 0}, {4, 3, 4}, "grey")}});
    test::addBox(scene, "box", {1, 0, 1}, {2, 1, 2}, "grey");
    test::addBox(scene, "shelf", {2.5, 0, 0}, {3.5, 2, 0.4}, "grey");
    return scene;
}

// The painter's order (or the z-buffer's node ranges) with every back face
// and every node, the regions behind the shooter left out as a render
// leaves them out.
std::vector<PaintRange> wholeOrder(const PreparedScene& p, const ShooterFrame& frame, model::Visibility mode)
{
    const Plane plane = Plane::fromPointNormal(frame.origin, frame.n);
    const auto accept = [&](int region) { return !boxBehindPlane(p.regions[size_t(region)].bounds, plane); };
    std::vector<PaintRange> order;
    if (mode == model::Visibility::Painter) {
        forEachNodeBackToFront(p, frame.origin, accept, [&](int node, bool eyeInFront) {
            forEachPaintRange(p.nodes[size_t(node)], eyeInFront, true, [&](int begin, int end, bool receives) {
                if (begin < end)
                    order.push_back({begin, end, receives});
            });
        });
        return order;
    }
    for (const BspNode& node : p.nodes)
        if (node.pieceCount > 0 && (node.region < 0 || accept(node.region)))
            order.push_back({node.firstPiece, node.firstPiece + node.pieceCount, true});
    return order;
}

// Renders every `stride`-th patch of `p` both ways; counts in `skipped` how
// many of them left the back faces out.
void expectSameBuffersAsTheWholeOrder(const PreparedScene& p, size_t stride, int& skipped)
{
    const Hemicube h(60);
    const std::vector<ClosedPart> parts = closedParts(p);
    skipped = 0;
    for (model::Visibility mode : {model::Visibility::Painter, model::Visibility::ZBuffer}) {
        SCOPED_TRACE(model::visibilityName(mode));
        Visibility rendered(p, h, mode), full(p, h, mode);
        ItemBuffer a = rendered.makeBuffer(), b = full.makeBuffer();
        for (size_t i = 0; i < p.patches.size(); i += stride) {
            const ShooterFrame frame = shooterFrameOfPatch(p, static_cast<int>(i));
            ASSERT_TRUE(rendered.render(frame, a));
            b.clear();
            ASSERT_TRUE(full.paint(frame, wholeOrder(p, frame, mode), b));
            ASSERT_TRUE(std::ranges::equal(a.all(), b.all())) << "patch " << i;
            skipped += mode == model::Visibility::Painter && closedBackFacesHidden(parts, frame.origin, frame.n);
        }
        // Fewer pieces painted: the furniture's far sides, what lies behind.
        EXPECT_LT(rendered.stats().elementsVisited, full.stats().elementsVisited);
    }
}

} // namespace

TEST(ClosedBackFaces, TheWindingNumberIsOneInsideASolidMinusOneInsideARoomAndZeroOutsideBoth)
{
    const PreparedScene p = test::prepared(furnishedShell());
    const ClosedPart box = partNamed(p, "box.body.py");
    const ClosedPart room = partNamed(p, "room.shell.ny");
    EXPECT_FALSE(box.inward);
    EXPECT_TRUE(room.inward);
    EXPECT_NEAR(windingNumber(box, {1.5, 0.5, 1.5}), 1.0, 1e-12);
    EXPECT_NEAR(windingNumber(box, {1.2, 0.9, 1.9}), 1.0, 1e-12);
    EXPECT_NEAR(windingNumber(box, {3.0, 0.5, 1.5}), 0.0, 1e-12);
    EXPECT_NEAR(windingNumber(room, {1.5, 0.5, 1.5}), -1.0, 1e-12);
    EXPECT_NEAR(windingNumber(room, {5.0, 0.5, 1.5}), 0.0, 1e-12);
    // On a face: half of the way.
    EXPECT_NEAR(windingNumber(box, {1.5, 1.0, 1.5}), 0.5, 1e-12);
}

TEST(ClosedBackFaces, AreHiddenFromAShooterOnAFaceOfTheFurnitureOrOnTheRoomsWalls)
{
    const PreparedScene p = test::prepared(furnishedShell());
    const std::vector<ClosedPart> parts = closedParts(p);
    ASSERT_EQ(parts.size(), 3u);
    EXPECT_TRUE(closedBackFacesHidden(parts, {1.5, 1.0, 1.5}, {0, 1, 0}));  // the box's top
    EXPECT_TRUE(closedBackFacesHidden(parts, {2.0, 0.5, 1.5}, {1, 0, 0}));  // the box's side
    EXPECT_TRUE(closedBackFacesHidden(parts, {0.5, 0.0, 0.5}, {0, 1, 0}));  // the floor beside the box
    EXPECT_TRUE(closedBackFacesHidden(parts, {1.0, 1.5, 0.0}, {0, 0, 1}));  // the back wall beside the shelf
    EXPECT_TRUE(closedBackFacesHidden(parts, {2.0, 3.0, 2.0}, {0, -1, 0})); // the ceiling
    EXPECT_TRUE(closedBackFacesHidden(parts, {3.0, 2.0, 0.2}, {0, 1, 0}));  // the shelf's top
}

TEST(ClosedBackFaces, ArePaintedFromAShooterBehindAShelfInsideABoxOrOutsideTheRoom)
{
    const PreparedScene p = test::prepared(furnishedShell());
    const std::vector<ClosedPart> parts = closedParts(p);
    // The back wall where the shelf stands against it: the whole shelf faces away.
    EXPECT_FALSE(closedBackFacesHidden(parts, {3.0, 1.0, 0.0}, {0, 0, 1}));
    // The floor under the box, looking up into it.
    EXPECT_FALSE(closedBackFacesHidden(parts, {1.5, 0.0, 1.5}, {0, 1, 0}));
    EXPECT_FALSE(closedBackFacesHidden(parts, {1.5, 0.5, 1.5}, {1, 0, 0}));
    // A wall's outside, looking away from the room: the room's walls face away.
    EXPECT_FALSE(closedBackFacesHidden(parts, {0.0, 1.5, 2.0}, {-1, 0, 0}));
    EXPECT_FALSE(closedBackFacesHidden(parts, {-1.0, 1.5, 2.0}, {1, 0, 0}));
}

TEST(ClosedBackFaces, AShooterUnderABoxStandingOnItsFaceSeesOnlyTheBoxsInside)
{
    model::Scene scene;
    test::addMaterial(scene, "grey", {0.5, 0.5, 0.5});
    test::addPolygon(scene, "floor", {{-2, 0, -2}, {-2, 0, 2}, {2, 0, 2}, {2, 0, -2}}, "grey");
    test::addBox(scene, "box", {-0.5, 0, -0.5}, {0.5, 1, 0.5}, "grey");
    test::addBox(scene, "far", {1.2, 0, 1.2}, {1.8, 2, 1.8}, "grey");
    const PreparedScene p = test::prepared(scene);
    const Hemicube h(40);
    for (model::Visibility mode : {model::Visibility::Painter, model::Visibility::ZBuffer}) {
        Visibility vis(p, h, mode);
        ItemBuffer buffer = vis.makeBuffer();
        vis.render(ShooterFrame::make({0.1, 0.0, -0.2}, {0, 1, 0}), buffer);
        const std::set<ItemId> seen(buffer.all().begin(), buffer.all().end());
        EXPECT_EQ(seen, std::set<ItemId>{kBlockerItem}) << model::visibilityName(mode);
    }
}

TEST(PaintOrderCulling, ChangesNoPixelOfTheSampleRoom)
{
    const PreparedScene p = test::prepared(test::loadSample("two-lights-room"));
    int skipped = 0;
    expectSameBuffersAsTheWholeOrder(p, 7, skipped);
    EXPECT_GT(skipped, int(p.patches.size() / 7) * 9 / 10);
}

TEST(PaintOrderCulling, ChangesNoPixelOfAFurnishedRoomBuiltAsOneShell)
{
    const PreparedScene p = test::prepared(test::furnishedRoom(3, 12, {8.0, 3.0, 6.0}));
    int skipped = 0;
    expectSameBuffersAsTheWholeOrder(p, 5, skipped);
    EXPECT_GT(skipped, int(p.patches.size() / 5) * 9 / 10);
}

TEST(NodeCulling, ABoxBehindTheShooterOrOnItsPlaneIsCulledOneAHairInFrontIsNot)
{
    const Plane floor = Plane::fromPointNormal({0, 0, 0}, {0, 1, 0});
    Box3 below;
    below.extend({0, -2, 0});
    below.extend({1, -1, 1});
    EXPECT_TRUE(piecesBehindShooter(below, floor));
    Box3 on; // the floor's own pieces: edge-on, they cover nothing
    on.extend({0, 0, 0});
    on.extend({3, 0, 2});
    EXPECT_TRUE(piecesBehindShooter(on, floor));
    Box3 above = on;
    above.extend({1, 1e-9, 1}); // reaches the rasteriser's near plane
    EXPECT_FALSE(piecesBehindShooter(above, floor));
    Box3 wall; // stands on the floor
    wall.extend({0, 0, 0});
    wall.extend({0, 2.5, 3});
    EXPECT_FALSE(piecesBehindShooter(wall, floor));
    EXPECT_FALSE(piecesBehindShooter(Box3{}, floor));
}

TEST(NodeCulling, FromALampsTopUnderTheCeilingMostOfTheRoomIsLeftOut)
{
    const PreparedScene p = test::prepared(test::loadSample("two-lights-room"));
    const size_t top = test::faceNamed(p, "lamp1.panel.py");
    const Patch& patch = p.patches[size_t(p.faces[top].firstPatch)];
    const ShooterFrame frame = shooterFrameOfPatch(p, p.faces[top].firstPatch);
    ASSERT_EQ(patch.properties, int(top));
    const Hemicube h(60);
    Visibility vis(p, h, model::Visibility::Painter);
    ItemBuffer rendered = vis.makeBuffer(), whole = vis.makeBuffer();
    ASSERT_TRUE(vis.render(frame, rendered));
    const std::int64_t visited = vis.stats().elementsVisited;
    whole.clear();
    const std::vector<PaintRange> order = wholeOrder(p, frame, model::Visibility::Painter);
    ASSERT_TRUE(vis.paint(frame, order, whole));
    EXPECT_TRUE(std::ranges::equal(rendered.all(), whole.all()));
    std::int64_t offered = 0;
    for (const PaintRange& r : order)
        offered += r.end - r.begin;
    // Only the ceiling and the walls' top 2 cm lie in front of the lamp's
    // top; the walls' nodes reach up there and are painted whole, the floor,
    // the furniture and the lamps' undersides are left out.
    EXPECT_LT(visited * 2, offered) << visited << " of " << offered;
}

TEST(PaintOrderCulling, FollowsTheScenesNewPiecesAsAFreshVisibilityDoes)
{
    // The solver assigns each refined mesh to the scene its visibility
    // refers to; what the visibility keeps of the old pieces must go.
    PreparedScene s = test::prepared(test::loadSample("two-lights-room"));
    const Hemicube h(40);
    Visibility kept(s, h, model::Visibility::Painter);
    ItemBuffer a = kept.makeBuffer(), b = kept.makeBuffer();
    ASSERT_TRUE(kept.render(shooterFrameOfPatch(s, 0), a));
    s = test::prepared(test::loadSample("cornell-box"));
    for (int patch : {0, 5, int(s.patches.size()) - 1}) {
        Visibility fresh(s, h, model::Visibility::Painter);
        ASSERT_TRUE(kept.render(shooterFrameOfPatch(s, patch), a));
        ASSERT_TRUE(fresh.render(shooterFrameOfPatch(s, patch), b));
        EXPECT_TRUE(std::ranges::equal(a.all(), b.all())) << "patch " << patch;
    }
}

TEST(ShadowVolume, HidesWhatLiesBehindALampsTopSeenFromTheCeilingTwoCentimetresAbove)
{
    // The two-light room's west lamp: its top 0.8 m square at y = 2.98,
    // the eye on the ceiling (y = 3) over its middle, facing down.
    const std::vector<Vec3> top{{0.6, 2.98, 1.6}, {0.6, 2.98, 2.4}, {1.4, 2.98, 2.4}, {1.4, 2.98, 1.6}};
    const Vec3 eye{1.0, 3.0, 2.0};
    const Plane ceiling = Plane::fromPointNormal(eye, {0, -1, 0});
    for (bool reversed : {false, true}) {
        std::vector<Vec3> polygon = top;
        if (reversed)
            std::ranges::reverse(polygon);
        const ShadowVolume volume(eye, {polygon, {0, 1, 0}}, ceiling);
        SCOPED_TRACE(reversed ? "clockwise" : "counter-clockwise");
        ASSERT_FALSE(volume.empty());
        EXPECT_TRUE(volume.hides(Vec3{1.0, 0.0, 2.0}));   // the floor below
        EXPECT_TRUE(volume.hides(Vec3{5.9, 0.0, 0.1}));   // the floor's far corner
        EXPECT_FALSE(volume.hides(Vec3{1.0, 2.99, 2.0})); // in the gap
        EXPECT_FALSE(volume.hides(Vec3{5.0, 2.9, 2.0}));  // through the slit
        // Behind the top's plane by more than its margin of 1e-6 m only.
        EXPECT_FALSE(volume.hides(Vec3{1.0, 2.98 - 1e-7, 2.0}));
        EXPECT_TRUE(volume.hides(Vec3{1.0, 2.98 - 1e-5, 2.0}));
        // The ray past the edge x = 1.4 reaches the floor at x = 61; inside
        // it only by more than 1e-5 radians.
        EXPECT_FALSE(volume.hides(Vec3{61.0, 0.0, 2.0}));
        EXPECT_FALSE(volume.hides(Vec3{60.9995, 0.0, 2.0}));
        EXPECT_TRUE(volume.hides(Vec3{60.9, 0.0, 2.0}));
        // From an eye over the top's edge, 1 mm inside it, rays that cross
        // the top 5 micrometres and 0.1 mm inside that edge, to a point ten
        // times as far: the pieces meet the outline only to within a
        // micrometre, so the first may miss them.
        const Vec3 nearEdge{1.399, 3.0, 2.0};
        const ShadowVolume fromNearEdge(nearEdge, {polygon, {0, 1, 0}}, ceiling);
        for (const auto& [inside, hidden] : {std::pair{5e-6, false}, std::pair{1e-4, true}}) {
            const Vec3 crossing{1.4 - inside, 2.98, 2.0};
            EXPECT_EQ(fromNearEdge.hides(nearEdge + 10.0 * (crossing - nearEdge)), hidden) << inside;
        }
        Box3 floor;
        floor.extend({0, 0, 0});
        floor.extend({6, 0.7, 4});
        EXPECT_TRUE(volume.hides(floor));
        Box3 wall = floor; // up to the ceiling: its top shows through the slit
        wall.extend({0, 3, 0});
        EXPECT_FALSE(volume.hides(wall));
        EXPECT_FALSE(volume.hides(Box3{}));
    }
    // Seen from behind, the top would be a back face the painter may leave
    // out; and a face reaching behind the shooter's plane is not wholly
    // painted. Either way it hides nothing.
    EXPECT_TRUE(ShadowVolume(Vec3{1.0, 2.9, 2.0}, {top, {0, 1, 0}}, Plane::fromPointNormal({1.0, 2.9, 2.0}, {0, 1, 0}))
                    .empty());
    const Plane low = Plane::fromPointNormal({1.0, 2.975, 2.0}, {0, -1, 0});
    EXPECT_TRUE(ShadowVolume(Vec3{1.0, 3.0, 2.0}, {top, {0, 1, 0}}, low).empty());
    EXPECT_TRUE(ShadowVolume(eye, {}, ceiling).empty());
}

TEST(PaintOrderCulling, TheFaceAcrossAGapHidesWhatLiesBehindItAndChangesNoPixel)
{
    // Every point of every patch in a gap (the ceiling over the lamps, the
    // lamps' tops), rendered with the face across the gap as the occluder
    // and without: the same item buffers, fewer pieces.
    const PreparedScene p = test::prepared(test::loadSample("two-lights-room"));
    const Hemicube h(60);
    int gapPatches = 0;
    for (model::Visibility mode : {model::Visibility::Painter, model::Visibility::ZBuffer}) {
        SCOPED_TRACE(model::visibilityName(mode));
        Visibility occluded(p, h, mode), whole(p, h, mode);
        ItemBuffer a = occluded.makeBuffer(), b = whole.makeBuffer();
        gapPatches = 0;
        for (int patch = 0; patch < int(p.patches.size()); ++patch) {
            const int across = gapFace(p, patch);
            if (across < 0)
                continue;
            ++gapPatches;
            const Occluder occluder{p.faces[size_t(across)].polygon, p.properties[size_t(across)].plane.normal};
            const Vec3& normal = p.properties[size_t(p.patches[size_t(patch)].properties)].plane.normal;
            for (const Vec3& point : shooterPoints(p, patch)) {
                const ShooterFrame frame = shooterFrameAt(point, normal);
                ASSERT_TRUE(occluded.render(frame, a, nullptr, occluder));
                ASSERT_TRUE(whole.render(frame, b));
                ASSERT_TRUE(std::ranges::equal(a.all(), b.all())) << "patch " << patch;
            }
        }
        // Nodes left out whole (the floor's, the furniture's: 14 % of the
        // pieces walked when written) and pieces in the shadow (37 % of
        // those rasterised).
        const VisibilityStats& with = occluded.stats();
        const VisibilityStats& without = whole.stats();
        EXPECT_LT(with.elementsVisited, without.elementsVisited);
        EXPECT_LT(with.elementsRasterised * 4, without.elementsRasterised * 3)
            << with.elementsRasterised << " of " << without.elementsRasterised;
    }
    EXPECT_GT(gapPatches, 8) << "the premise: the ceiling's patches over both lamps";
}
