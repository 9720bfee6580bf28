// Scene preparation end to end: regions in the three modes, the face table,
// the author's root order, diagnostics, and the sample scenes.
#include "solver/prepare/prepare.h"

#include "model/geometry/primitives.h"
#include "support/covered_faces.h"
#include "support/random_scenes.h"
#include "support/sample_scenes.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cstdio>

using namespace regio;
using namespace regio::solver;
using model::Vec3;

namespace {

PreparedScene prepareOk(const model::Scene& scene, RegionsMode mode, int autoThreshold = 60)
{
    PrepareOptions options;
    options.regions = mode;
    options.autoRegionPatchThreshold = autoThreshold;
    model::Result<PreparedScene> result = prepareScene(scene, options);
    for (const model::Diagnostic& d : result.diagnostics())
        ADD_FAILURE() << d.pointer << ": " << d.message;
    EXPECT_TRUE(result.ok());
    return result.ok() ? std::move(*result) : PreparedScene{};
}

double inputArea(const PreparedScene& s)
{
    double area = 0.0;
    for (const InputFace& f : s.faces)
        area += f.area;
    return area;
}

model::Scene twoBoxes()
{
    model::Scene scene;
    scene.materials.push_back({"white", "", {0.5, 0.5, 0.5}, {0, 0, 0}});
    scene.objects.push_back({"a", "", {*model::makeBox("a.body", {0, 0, 0}, {1, 1, 1}, "white")}});
    scene.objects.push_back({"b", "", {*model::makeBox("b.body", {2, 0, 0}, {3, 1, 1}, "white")}});
    return scene;
}

} // namespace

TEST(Prepare, WithoutRegionsBuildsOneClassicBspTreeOverEverything)
{
    PreparedScene s = prepareOk(twoBoxes(), RegionsMode::Authored);
    ASSERT_EQ(s.regions.size(), 1u);
    EXPECT_EQ(s.regions[0].id, "scene");
    EXPECT_TRUE(s.regionalNodes[size_t(s.regionalRoot)].isLeaf());
    EXPECT_EQ(s.regions[0].stats.inputFaces, 12);
    EXPECT_EQ(s.stats.inputFaces, 12);
    EXPECT_EQ(s.faces.size(), 12u);
    EXPECT_EQ(s.faces[0].id, "a.body.nx");
    EXPECT_NEAR(s.stats.area, 12.0, 1e-9);
}

TEST(Prepare, CopiesMaterialsAndPlanesIntoOnePropertiesPerFace)
{
    model::Scene scene = twoBoxes();
    scene.materials.push_back({"lamp", "", {0.1, 0.2, 0.3}, {5, 6, 7}});
    scene.objects[1].parts[0].faces[3].material = "lamp"; // b.body.py, the top
    PreparedScene s = prepareOk(scene, RegionsMode::None);
    ASSERT_EQ(s.properties.size(), s.faces.size());
    const Properties& top = s.properties[9];
    EXPECT_EQ(s.faces[9].id, "b.body.py");
    EXPECT_EQ(top.emission, Vec3(5, 6, 7));
    EXPECT_EQ(top.reflectance, Vec3(0.1, 0.2, 0.3));
    EXPECT_NEAR(top.plane.normal.y, 1.0, 1e-12);
    EXPECT_NEAR(top.plane.signedDistance({2.5, 1, 0.5}), 0.0, 1e-12);
    for (int e : s.faces[9].elements) {
        EXPECT_EQ(s.elements[size_t(e)].properties, 9);
        EXPECT_EQ(s.elements[size_t(e)].normal, top.plane.normal);
    }
}

TEST(Prepare, AllThreeRegionModesMeshTheSameTotalArea)
{
    const model::Scene scene = test::roomWithRegions(21, 3, 2, 3);
    PreparedScene none = prepareOk(scene, RegionsMode::None);
    PreparedScene authored = prepareOk(scene, RegionsMode::Authored);
    PreparedScene automatic = prepareOk(scene, RegionsMode::Auto);
    EXPECT_EQ(none.regions.size(), 1u);
    EXPECT_EQ(authored.regions.size(), 6u);
    EXPECT_GT(automatic.regions.size(), 1u);
    // What the boxes standing on the floor cover is not meshed (the floor
    // under them, their bottoms): the rest is, the same in every mode.
    double area = 0.0;
    for (size_t f = 0; f < none.faces.size(); ++f)
        area += test::uncoveredArea(none, f);
    EXPECT_LT(area, inputArea(none) - 1.0) << "the premise: boxes stand on the floor";
    for (const PreparedScene* s : {&none, &authored, &automatic}) {
        EXPECT_NEAR(s->stats.area, area, 1e-9 * area);
        // Per face too: the elements of every face add up to what no solid covers.
        for (size_t f = 0; f < s->faces.size(); ++f) {
            double sum = 0.0;
            for (int e : s->faces[f].elements)
                sum += s->elements[size_t(e)].area;
            EXPECT_NEAR(sum, test::uncoveredArea(*s, f), 1e-9) << s->faces[f].id;
        }
    }
}

TEST(Prepare, AuthoredRegionsClipTheRoomAtTheSeparatingPlanes)
{
    const model::Scene scene = test::roomWithRegions(22, 2, 1, 2);
    PreparedScene s = prepareOk(scene, RegionsMode::Authored);
    ASSERT_EQ(s.regions.size(), 2u);
    EXPECT_EQ(s.regions[0].id, "cell-0-0");
    // Floor, ceiling and the two long walls cross x = 3 and are cut in two.
    EXPECT_EQ(s.stats.regionPieces,
              s.stats.inputFaces + 4 + 2 /* the lamp's top and bottom */ + 2 /* its long sides */);
    for (const Fragment& f : s.fragments)
        for (int i = 0; i < f.pointCount; ++i) {
            const Vec3& p = s.fragmentPoints[size_t(f.firstPoint + i)];
            EXPECT_TRUE(s.regions[size_t(f.region)].bounds.contains(p));
            if (f.region == 0)
                EXPECT_LE(p.x, 3.0 + 1e-9);
            else
                EXPECT_GE(p.x, 3.0 - 1e-9);
        }
}

TEST(Prepare, HonoursEachRegionsBspOrderForItsRoot)
{
    const model::Scene scene = test::roomWithRegions(23, 2, 2, 3);
    PreparedScene s = prepareOk(scene, RegionsMode::Authored);
    for (size_t r = 0; r < s.regions.size(); ++r) {
        const std::string& first = scene.regions[r].bspOrder.front();
        const BspNode& root = s.nodes[size_t(s.regions[r].bspRoot)];
        bool rootHoldsIt = false;
        for (int i = 0; i < root.fragmentCount; ++i)
            rootHoldsIt |= s.faces[size_t(s.fragments[size_t(root.firstFragment + i)].properties)].id == first;
        EXPECT_TRUE(rootHoldsIt) << s.regions[r].id << " should be rooted at " << first;
    }
}

TEST(Prepare, AutomaticRegionsKeepEachUnderThePatchThresholdWhereSpaceAllows)
{
    const model::Scene scene = test::roomWithRegions(24, 1, 1, 12, {8, 3, 8});
    PreparedScene coarse = prepareOk(scene, RegionsMode::Auto, 100000);
    EXPECT_EQ(coarse.regions.size(), 1u) << "under the threshold: one region";
    PreparedScene fine = prepareOk(scene, RegionsMode::Auto, 80);
    EXPECT_GT(fine.regions.size(), 4u);
    // The boxes tile the scene bounds.
    double volume = 0.0;
    for (const Region& r : fine.regions)
        volume += r.box.size().x * r.box.size().y * r.box.size().z;
    const Vec3 size = fine.bounds.size();
    EXPECT_NEAR(volume, size.x * size.y * size.z, 1e-9);
    EXPECT_EQ(fine.regions[0].id, "auto-1");
}

TEST(Prepare, OptionsOverrideThePatchSizeAndElementRatio)
{
    PrepareOptions options;
    options.patchSize = 0.25;
    options.elementsPerPatch = 1;
    model::Result<PreparedScene> result = prepareScene(twoBoxes(), options);
    ASSERT_TRUE(result.ok());
    EXPECT_EQ(result->patchSize, 0.25);
    EXPECT_EQ(result->elements.size(), result->patches.size());
    EXPECT_EQ(result->patches.size(), 12u * 32u); // a unit square: 4 strips x 8 triangles
}

TEST(Prepare, RefusesRegionsThatNoPlaneSeparatesNamingThem)
{
    model::Scene scene = twoBoxes();
    scene.regions.push_back({"left", "", {0, 0, 0}, {2, 2, 2}, {}});
    scene.regions.push_back({"right", "", {1, 0, 0}, {4, 2, 2}, {}});
    model::Result<PreparedScene> result = prepareScene(scene);
    EXPECT_FALSE(result.ok());
    ASSERT_EQ(result.diagnostics().size(), 1u);
    EXPECT_TRUE(result.diagnostics()[0].isError());
    EXPECT_NE(result.diagnostics()[0].message.find("'left', 'right'"), std::string::npos);
    EXPECT_EQ(result.diagnostics()[0].pointer, "/regions/0");
    // Without regions the same scene prepares fine.
    PrepareOptions none;
    none.regions = RegionsMode::None;
    EXPECT_TRUE(prepareScene(scene, none).ok());
}

TEST(Prepare, RefusesUnknownMaterialsAndNonConvexFacesWithTheirPointers)
{
    model::Scene scene = twoBoxes();
    scene.objects[0].parts[0].faces[2].material = "nowhere";
    model::Result<PreparedScene> result = prepareScene(scene);
    EXPECT_FALSE(result.ok());
    ASSERT_FALSE(result.diagnostics().empty());
    EXPECT_EQ(result.diagnostics()[0].pointer, "/objects/0/parts/0/faces/2/material");

    model::Scene arrow;
    arrow.materials.push_back({"white", "", {0.5, 0.5, 0.5}, {0, 0, 0}});
    model::Part part{
        "p", "", "white", {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {1, 0.5, 0}, {0, 2, 0}}, {{"p.f", {0, 1, 2, 3, 4}, ""}}};
    arrow.objects.push_back({"o", "", {part}});
    result = prepareScene(arrow);
    EXPECT_FALSE(result.ok());
    ASSERT_EQ(result.diagnostics().size(), 1u);
    EXPECT_EQ(result.diagnostics()[0].pointer, "/objects/0/parts/0/faces/0/loop");
    EXPECT_EQ(result.diagnostics()[0].idPath, (std::vector<std::string>{"o", "p", "p.f"}));
}

TEST(Prepare, KeepsAZeroAreaFaceInTheTableWithAWarningAndNoElements)
{
    model::Scene scene = twoBoxes();
    model::Part flat{"flat", "", "white", {{5, 0, 0}, {6, 0, 0}, {7, 0, 0}}, {{"flat.f", {0, 1, 2}, ""}}};
    scene.objects.push_back({"line", "", {flat}});
    model::Result<PreparedScene> result = prepareScene(scene);
    ASSERT_TRUE(result.ok());
    ASSERT_EQ(result.diagnostics().size(), 1u);
    EXPECT_FALSE(result.diagnostics()[0].isError());
    EXPECT_EQ(result->faces.back().id, "flat.f");
    EXPECT_EQ(result->faces.back().area, 0.0);
    EXPECT_TRUE(result->faces.back().elements.empty());
    EXPECT_EQ(result->stats.inputFaces, 12);
}

TEST(Prepare, AnEmptySceneIsOneEmptyRegion)
{
    model::Result<PreparedScene> result = prepareScene(model::Scene{});
    ASSERT_TRUE(result.ok());
    EXPECT_EQ(result->regions.size(), 1u);
    EXPECT_EQ(result->regions[0].bspRoot, -1);
    EXPECT_TRUE(result->elements.empty());
}

TEST(Prepare, PreparesTheSampleScenesInEveryRegionMode)
{
    int scenes = 0;
    for (const char* name : {"cornell-box", "two-lights-room"}) {
        const model::Scene scene = test::loadSample(name);
        ++scenes;
        double area = -1.0;
        for (RegionsMode mode : {RegionsMode::None, RegionsMode::Authored, RegionsMode::Auto}) {
            PrepareOptions options;
            options.regions = mode;
            model::Result<PreparedScene> result = prepareScene(scene, options);
            ASSERT_TRUE(result.ok()) << name;
            const PrepareStats& st = result->stats;
            if (area < 0.0)
                area = st.area;
            EXPECT_NEAR(st.area, area, 1e-9 * area);
            std::printf(
                "%-22s %-8s regions %3zu  faces %4d  pieces %4d  fragments %4d  splits %4d  depth %3d  "
                "patches %5d  elements %6d\n",
                name,
                mode == RegionsMode::None       ? "none"
                : mode == RegionsMode::Authored ? "authored"
                                                : "auto",
                result->regions.size(), st.inputFaces, st.regionPieces, st.fragments, st.splits, st.maxDepth,
                st.patches, st.elements);
        }
    }
    EXPECT_EQ(scenes, 2);
}

TEST(Prepare, MeshesTheSampleScenesAlikeWithTheirCoordinatesRoundedToFloats)
{
    // Model files hold 32-bit floats: a scene that went through one must be
    // cut into the same patches, elements and pieces, face by face, or its
    // light changes with the rounding (solver/prepare/divisions.h). The
    // two-light room's shelves are whole multiples of its 0.5 m patches.
    for (const char* name : {"cornell-box", "two-lights-room"}) {
        const model::Scene authored = test::loadSample(name);
        model::Scene rounded = authored;
        test::roundToFloats(rounded);
        const model::Result<PreparedScene> a = prepareScene(authored);
        const model::Result<PreparedScene> b = prepareScene(rounded);
        ASSERT_TRUE(a.ok() && b.ok()) << name;
        EXPECT_EQ(b->patches.size(), a->patches.size()) << name;
        // And painted alike: the corners of faces that meet along a line
        // are found on each other's edges (solver/prepare/pieces.cpp).
        EXPECT_EQ(b->stats.pieces, a->stats.pieces) << name;
        ASSERT_EQ(b->faces.size(), a->faces.size()) << name;
        for (size_t f = 0; f < a->faces.size(); ++f)
            EXPECT_EQ(b->faces[f].elements.size(), a->faces[f].elements.size()) << name << " " << a->faces[f].id;
    }
}

// --- The stages (prepare.h) --------------------------------------------------

TEST(PrepareStages, PrepareBspIsPrepareSceneWithoutTheMesh)
{
    const model::Scene room = test::loadSample("two-lights-room");
    for (RegionsMode mode : {RegionsMode::Authored, RegionsMode::None, RegionsMode::Auto}) {
        PrepareOptions options;
        options.regions = mode;
        model::Result<PreparedScene> full = prepareScene(room, options);
        model::Result<PreparedScene> bsp = prepareBsp(room, options);
        ASSERT_TRUE(full.ok() && bsp.ok()) << model::regionsModeName(mode);
        EXPECT_TRUE(bsp->patches.empty() && bsp->elements.empty() && bsp->pieces.empty());
        ASSERT_EQ(bsp->regions.size(), full->regions.size());
        for (size_t r = 0; r < bsp->regions.size(); ++r) {
            EXPECT_EQ(bsp->regions[r].id, full->regions[r].id);
            EXPECT_EQ(bsp->regions[r].stats.fragments, full->regions[r].stats.fragments);
            EXPECT_EQ(bsp->regions[r].stats.splits, full->regions[r].stats.splits);
            EXPECT_EQ(bsp->regions[r].stats.depth, full->regions[r].stats.depth);
            EXPECT_EQ(bsp->regions[r].bspRoot, full->regions[r].bspRoot);
        }
        EXPECT_EQ(bsp->nodes.size(), full->nodes.size());
        EXPECT_EQ(bsp->fragmentPoints, full->fragmentPoints);
        EXPECT_EQ(bsp->stats.inputFaces, full->stats.inputFaces);
        EXPECT_EQ(bsp->stats.regionPieces, full->stats.regionPieces);
        EXPECT_EQ(bsp->stats.fragments, full->stats.fragments);
    }
}

TEST(PrepareStages, CollectFacesProjectsEveryFaceOntoItsPlaneAndKeepsFacesWithoutArea)
{
    model::Scene scene = test::loadSample("cornell-box");
    // A face of no area: kept in the table (so every id of the file has a
    // result), with a warning and without a polygon.
    model::Part& part = scene.objects[0].parts[0];
    part.vertices.push_back(part.vertices[0]);
    part.faces.push_back({"flat", {0, int(part.vertices.size()) - 1, 0}, ""});
    model::Result<FaceSet> faces = collectFaces(scene);
    ASSERT_TRUE(faces.ok());
    ASSERT_EQ(faces.diagnostics().size(), 1u);
    EXPECT_FALSE(faces.diagnostics()[0].isError());
    EXPECT_EQ(faces.diagnostics()[0].idPath.back(), "flat");
    EXPECT_EQ(faces->faces.size(), faces->properties.size());
    EXPECT_EQ(faces->polygons.size() + 1, faces->faces.size());
    for (const FacePolygon& p : faces->polygons) {
        const Plane& plane = faces->properties[size_t(p.face)].plane;
        for (const Vec3& v : p.loop) {
            EXPECT_NEAR(plane.signedDistance(v), 0.0, 1e-12);
            EXPECT_TRUE(faces->bounds.contains(v));
        }
    }
}

TEST(PrepareStages, LayOutRegionsRefusesBoxesNoPlaneSeparatesAndNamesThem)
{
    model::Scene scene = test::loadSample("two-lights-room");
    scene.regions[1].min = scene.regions[0].min; // now it overlaps region 0
    model::Result<FaceSet> faces = collectFaces(scene);
    ASSERT_TRUE(faces.ok());
    model::Result<RegionLayout> layout = layOutRegions(scene, *faces, RegionsMode::Authored, 0.5);
    ASSERT_FALSE(layout.ok());
    EXPECT_NE(layout.error().message.find("'" + scene.regions[0].id + "'"), std::string::npos);
    EXPECT_NE(layout.error().message.find("'" + scene.regions[1].id + "'"), std::string::npos);
    EXPECT_EQ(layout.error().pointer.rfind("/regions/", 0), 0u);

    model::Result<RegionLayout> none = layOutRegions(scene, *faces, RegionsMode::None, 0.5);
    ASSERT_TRUE(none.ok());
    ASSERT_EQ(none->regions.size(), 1u);
    EXPECT_EQ(none->regions[0].id, "scene");
}
