// Clipping a part to the region boxes: the one-click fix for validation's
// "straddles region boundaries" warning. The pieces lie in one region each,
// keep the area of the part, and the returned record undoes it exactly.
#include "model/geometry/region_clip.h"

#include "model/edit/edit_regions.h"
#include "model/geometry/primitives.h"
#include "model/geometry/winged_edge.h"
#include "model/validation/validation.h"
#include "support/sample_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace regio::model;

namespace {

Region box(const std::string& id, Vec3 min, Vec3 max)
{
    Region region;
    region.id = id;
    region.min = min;
    region.max = max;
    return region;
}

// Regions "left" [0,2] and "right" [2,4] along x; a slab crossing x = 2 and
// a crate inside "left".
Scene twoRegions()
{
    Scene scene;
    scene.materials.push_back({"white", "", {0.5, 0.5, 0.5}, {1, 1, 1}});
    scene.objects.push_back({"slab", "", {*makeBox("slab.body", {1, 0, 0.5}, {3, 0.5, 1.5}, "white")}});
    scene.objects.push_back({"crate", "", {*makeBox("crate.body", {0.2, 0, 0.2}, {0.6, 0.4, 0.6}, "white")}});
    scene.regions = {box("left", {0, 0, 0}, {2, 2, 2}), box("right", {2, 0, 0}, {4, 2, 2})};
    return scene;
}

double faceArea(const Part& part, const Face& face) { return polygonArea(loopPositions(part.vertices, face.loop)); }

// Area of the faces of these parts that are not caps.
double surfaceArea(const Scene& scene, const std::vector<std::string>& partIds,
                   const std::vector<std::string>& caps = {})
{
    double area = 0.0;
    for (const std::string& id : partIds) {
        const Part* part = scene.findPart(id);
        EXPECT_TRUE(part) << id;
        if (part)
            for (const Face& face : part->faces)
                if (std::find(caps.begin(), caps.end(), face.id) == caps.end())
                    area += faceArea(*part, face);
    }
    return area;
}

std::vector<Diagnostic> straddleWarnings(const Scene& scene)
{
    std::vector<Diagnostic> out;
    for (const Diagnostic& d : validateScene(scene))
        if (d.message.find("straddles") != std::string::npos)
            out.push_back(d);
    return out;
}

bool warnedAbout(const std::vector<Diagnostic>& diagnostics, const std::string& partId)
{
    return std::any_of(diagnostics.begin(), diagnostics.end(), [&](const Diagnostic& d) {
        return std::find(d.idPath.begin(), d.idPath.end(), partId) != d.idPath.end();
    });
}

bool insideBox(const Part& part, const Region& region)
{
    Box3 b;
    b.extend(region.min);
    b.extend(region.max);
    return std::all_of(part.vertices.begin(), part.vertices.end(), [&](const Vec3& v) { return b.contains(v); });
}

} // namespace

TEST(RegionClip, CutsAStraddlingBoxIntoOneClosedPiecePerRegionNamedAfterIt)
{
    Scene scene = twoRegions();
    ASSERT_EQ(straddleWarnings(scene).size(), 1u);
    const double area = surfaceArea(scene, {"slab.body"});

    auto clip = clipPartToRegions(scene, "slab.body");
    ASSERT_TRUE(clip) << clip.error().message;
    EXPECT_EQ(clip->partId, "slab.body");
    EXPECT_EQ(clip->pieces, (std::vector<std::string>{"slab.body-left", "slab.body-right"}));
    EXPECT_EQ(clip->splits.size(), 1u);
    EXPECT_EQ(clip->capFaces.size(), 2u) << "one cap on each side of the cut";
    EXPECT_FALSE(scene.findPart("slab.body"));

    const Part* left = scene.findPart("slab.body-left");
    const Part* right = scene.findPart("slab.body-right");
    ASSERT_TRUE(left && right);
    EXPECT_TRUE(insideBox(*left, scene.regions[0]));
    EXPECT_TRUE(insideBox(*right, scene.regions[1]));
    EXPECT_TRUE(WingedEdgeMesh::build(*left).isClosed());
    EXPECT_TRUE(WingedEdgeMesh::build(*right).isClosed());
    EXPECT_TRUE(scene.findPart("slab.body-left")->faces.size() == 6u);
    EXPECT_NE(scene.locateFace("slab.body-left.py").face, -1) << "face ids follow their part";
    EXPECT_NEAR(surfaceArea(scene, clip->pieces, clip->capFaces), area, 1e-12);
    EXPECT_TRUE(straddleWarnings(scene).empty());
    EXPECT_FALSE(hasErrors(validateScene(scene)));
}

TEST(RegionClip, UndoGivesBackTheEqualScene)
{
    Scene scene = twoRegions();
    ASSERT_TRUE(insertBspEntry(scene, "left", "slab.body.py"));
    ASSERT_TRUE(insertBspEntry(scene, "right", "slab.body.px"));
    const Scene before = scene;
    auto clip = clipPartToRegions(scene, "slab.body");
    ASSERT_TRUE(clip);
    ASSERT_NE(scene, before);
    ASSERT_TRUE(unclipPart(scene, *clip));
    EXPECT_EQ(scene, before);
}

TEST(RegionClip, KeepsEachOrderNamingOnlyThePiecesInsideItsRegion)
{
    Scene scene = twoRegions();
    ASSERT_TRUE(insertBspEntry(scene, "left", "crate.body.py"));
    ASSERT_TRUE(insertBspEntry(scene, "left", "slab.body.py"));  // cut in two by x = 2
    ASSERT_TRUE(insertBspEntry(scene, "right", "slab.body.px")); // wholly in "right"
    auto clip = clipPartToRegions(scene, "slab.body");
    ASSERT_TRUE(clip);
    EXPECT_EQ(scene.findRegion("left")->bspOrder, (std::vector<std::string>{"crate.body.py", "slab.body-left.py"}));
    EXPECT_EQ(scene.findRegion("right")->bspOrder, (std::vector<std::string>{"slab.body-right.px"}));
    for (const Diagnostic& d : validateScene(scene))
        EXPECT_EQ(d.pointer.find("bspOrder"), std::string::npos) << d.message;
}

TEST(RegionClip, LeavesOpenPartsOpenAndCutsThemAtEveryBoundary)
{
    // A floor panel under three regions: three panels, no caps.
    Scene scene;
    scene.materials.push_back({"white", "", {0.5, 0.5, 0.5}, {1, 1, 1}});
    Part floor;
    floor.id = "room.floor";
    floor.material = "white";
    floor.vertices = {{0, 0, 0}, {0, 0, 2}, {6, 0, 2}, {6, 0, 0}};
    floor.faces = {{"room.floor.top", {0, 1, 2, 3}, ""}};
    scene.objects.push_back({"room", "", {floor}});
    scene.regions = {box("west", {0, -0.1, 0}, {2, 3, 2}), box("middle", {2, -0.1, 0}, {4, 3, 2}),
                     box("east", {4, -0.1, 0}, {6, 3, 2})};
    const Scene before = scene;

    auto clip = clipPartToRegions(scene, "room.floor");
    ASSERT_TRUE(clip);
    EXPECT_EQ(clip->pieces, (std::vector<std::string>{"room.floor-west", "room.floor-middle", "room.floor-east"}));
    EXPECT_TRUE(clip->capFaces.empty());
    for (const std::string& id : clip->pieces)
        EXPECT_EQ(scene.findPart(id)->faces.size(), 1u) << id;
    EXPECT_NEAR(surfaceArea(scene, clip->pieces), 12.0, 1e-12);
    EXPECT_TRUE(straddleWarnings(scene).empty());
    ASSERT_TRUE(unclipPart(scene, *clip));
    EXPECT_EQ(scene, before);
}

TEST(RegionClip, NeverCapsARoomSoNoWallAppearsAcrossIt)
{
    // makeRoom is closed but faces inwards: its pieces stay open.
    Scene scene;
    scene.materials.push_back({"white", "", {0.5, 0.5, 0.5}, {1, 1, 1}});
    scene.objects.push_back({"room", "", {*makeRoom("room.shell", {0, 0, 0}, {4, 2, 2}, "white")}});
    scene.regions = {box("left", {0, 0, 0}, {2, 2, 2}), box("right", {2, 0, 0}, {4, 2, 2})};
    const Scene before = scene;
    const double area = surfaceArea(scene, {"room.shell"});
    auto clip = clipPartToRegions(scene, "room.shell");
    ASSERT_TRUE(clip);
    EXPECT_EQ(clip->pieces, (std::vector<std::string>{"room.shell-left", "room.shell-right"}));
    EXPECT_TRUE(clip->capFaces.empty());
    for (const std::string& id : clip->pieces)
        EXPECT_EQ(scene.findPart(id)->faces.size(), 5u) << id << ": floor, ceiling, two long walls, one end";
    EXPECT_NEAR(surfaceArea(scene, clip->pieces), area, 1e-12);
    EXPECT_TRUE(straddleWarnings(scene).empty());
    ASSERT_TRUE(unclipPart(scene, *clip));
    EXPECT_EQ(scene, before);
}

TEST(RegionClip, GivesOnePiecePerRegionOfATiling)
{
    // A 3 x 2 x 2 grid of regions over a room: the shell falls into twelve
    // pieces, one per region, cut along the planes between the regions.
    Scene scene;
    scene.materials.push_back({"white", "", {0.5, 0.5, 0.5}, {1, 1, 1}});
    scene.objects.push_back({"room", "", {*makeRoom("room.shell", {0, 0, 0}, {6, 2, 4}, "white")}});
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 2; ++j)
            for (int k = 0; k < 2; ++k) {
                const std::string id{'r', char('0' + i), char('0' + j), char('0' + k)};
                scene.regions.push_back(box(id, {2.0 * i, 1.0 * j, 2.0 * k}, {2.0 * i + 2, 1.0 * j + 1, 2.0 * k + 2}));
            }
    const double area = surfaceArea(scene, {"room.shell"});
    auto clip = clipPartToRegions(scene, "room.shell");
    ASSERT_TRUE(clip);
    EXPECT_EQ(clip->pieces.size(), 12u);
    EXPECT_NEAR(surfaceArea(scene, clip->pieces), area, 1e-9);
    EXPECT_TRUE(straddleWarnings(scene).empty());
}

TEST(RegionClip, PutsWhatLiesOutsideEveryRegionInAnOutsidePiece)
{
    Scene scene = twoRegions();
    scene.objects[0].parts[0] = *makeBox("slab.body", {1, 0, 0.5}, {5, 0.5, 1.5}, "white");
    const double area = surfaceArea(scene, {"slab.body"});
    auto clip = clipPartToRegions(scene, "slab.body");
    ASSERT_TRUE(clip);
    EXPECT_EQ(clip->pieces, (std::vector<std::string>{"slab.body-left", "slab.body-right", "slab.body-outside"}));
    EXPECT_NEAR(surfaceArea(scene, clip->pieces, clip->capFaces), area, 1e-12);
    const std::vector<Diagnostic> warnings = straddleWarnings(scene);
    EXPECT_FALSE(warnedAbout(warnings, "slab.body-left"));
    EXPECT_FALSE(warnedAbout(warnings, "slab.body-right"));
    // Whatever validation calls it (its cap lies on the face of "right", which
    // validation counts as reaching into the box), it is in no region at all.
    const Part& outside = *scene.findPart("slab.body-outside");
    for (const Region& region : scene.regions)
        EXPECT_FALSE(insideBox(outside, region)) << region.id;
    for (const Vec3& v : outside.vertices)
        EXPECT_GE(v.x, 4.0 - kDistanceEpsilon);
}

TEST(RegionClip, CutsAwayWhatLiesOutsideAllRegionsBeforeCuttingBetweenThem)
{
    // The slab crosses x = 2 and pokes out of the top of both regions: one
    // cut at y = 2, then one at x = 2; three pieces, not four.
    Scene scene = twoRegions();
    scene.objects[0].parts[0] = *makeBox("slab.body", {1, 1.5, 0.5}, {3, 2.5, 1.5}, "white");
    const double area = surfaceArea(scene, {"slab.body"});
    const Scene before = scene;
    auto clip = clipPartToRegions(scene, "slab.body");
    ASSERT_TRUE(clip);
    EXPECT_EQ(clip->pieces, (std::vector<std::string>{"slab.body-left", "slab.body-right", "slab.body-outside"}));
    EXPECT_EQ(clip->splits.size(), 2u);
    EXPECT_TRUE(insideBox(*scene.findPart("slab.body-left"), scene.regions[0]));
    EXPECT_TRUE(insideBox(*scene.findPart("slab.body-right"), scene.regions[1]));
    for (const std::string& id : clip->pieces)
        EXPECT_TRUE(WingedEdgeMesh::build(*scene.findPart(id)).isClosed()) << id;
    EXPECT_NEAR(surfaceArea(scene, clip->pieces, clip->capFaces), area, 1e-12);
    const std::vector<Diagnostic> warnings = straddleWarnings(scene);
    EXPECT_FALSE(warnedAbout(warnings, "slab.body-left"));
    EXPECT_FALSE(warnedAbout(warnings, "slab.body-right"));
    ASSERT_TRUE(unclipPart(scene, *clip));
    EXPECT_EQ(scene, before);
}

TEST(RegionClip, NamesPiecesFreshlyWhenTheRegionNamesAreTaken)
{
    Scene scene = twoRegions();
    scene.objects.push_back({"other", "", {*makeBox("slab.body-left", {0.8, 1, 0.2}, {1.0, 1.2, 0.4}, "white")}});
    auto clip = clipPartToRegions(scene, "slab.body");
    ASSERT_TRUE(clip);
    EXPECT_EQ(clip->pieces, (std::vector<std::string>{"slab.body-left-2", "slab.body-right"}));
    EXPECT_FALSE(hasErrors(validateScene(scene)));
}

TEST(RegionClip, RefusesPartsThatDoNotStraddleAndLeavesTheSceneUnchanged)
{
    Scene scene = twoRegions();
    scene.objects.push_back({"far", "", {*makeBox("far.body", {10, 0, 0}, {11, 1, 1}, "white")}});
    const Scene before = scene;
    for (const char* id : {"crate.body", "far.body", "no.such.part"}) {
        auto clip = clipPartToRegions(scene, id);
        EXPECT_FALSE(clip) << id;
        if (!clip) {
            EXPECT_NE(clip.error().message.find(id), std::string::npos) << clip.error().message;
        }
        EXPECT_EQ(scene, before) << id;
    }
    EXPECT_FALSE(partStraddlesRegions(scene, *scene.findPart("crate.body")));
    EXPECT_FALSE(partStraddlesRegions(scene, *scene.findPart("far.body")));
    EXPECT_TRUE(partStraddlesRegions(scene, *scene.findPart("slab.body")));
}

TEST(RegionClip, FixesACrateStraddlingTwoRegionsOfTheSampleRoom)
{
    Scene scene = regio::test::loadSample("two-lights-room");
    const Diagnostics clean = validateScene(scene);
    scene.objects.push_back({"crate", "", {*makeBox("crate.body", {1.7, 0, 1}, {2.3, 0.5, 1.6}, "wood")}});
    ASSERT_EQ(straddleWarnings(scene).size(), 1u);

    const Scene before = scene;
    auto clip = clipPartToRegions(scene, "crate.body");
    ASSERT_TRUE(clip);
    EXPECT_EQ(clip->pieces, (std::vector<std::string>{"crate.body-west", "crate.body-middle"}));
    EXPECT_EQ(validateScene(scene).size(), clean.size()) << "no new diagnostics";
    ASSERT_TRUE(unclipPart(scene, *clip));
    EXPECT_EQ(scene, before);
}

TEST(RegionClip, MeasuresAreaInsideABoxAsValidationDoes)
{
    const std::vector<Vec3> square{{0, 0, 0}, {2, 0, 0}, {2, 0, 2}, {0, 0, 2}};
    Box3 b;
    b.extend(Vec3{1, -1, 1});
    b.extend(Vec3{3, 1, 3});
    EXPECT_NEAR(polygonAreaInBox(square, b), 1.0, 1e-12);
    EXPECT_TRUE(faceTouchesRegionBox(square, b));
    Box3 touching;
    touching.extend(Vec3{2, -1, 0});
    touching.extend(Vec3{3, 1, 2});
    EXPECT_FALSE(faceTouchesRegionBox(square, touching)) << "sharing an edge is no area";
}
