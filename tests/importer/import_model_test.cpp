// Whole imports (importer/import_model.h): model files in, valid scenes out,
// or a clear refusal; never a crash.
#include "importer/import_model.h"

#include "model/geometry/geometry.h"
#include "model/io/scene_json.h"
#include "model/validation/validation.h"
#include "output/png_writer.h"
#include "solver/solver.h"
#include "support/furnished_room.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <atomic>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <string>
#include <tuple>

using namespace regio;
namespace fs = std::filesystem;

namespace {

// A scratch directory per test, removed afterwards.
struct Scratch {
    fs::path dir;
    Scratch()
    {
        dir = fs::temp_directory_path() /
              ("regio-import-test-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "-" +
               ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(dir);
    }
    ~Scratch() { fs::remove_all(dir); }
    std::string write(const std::string& name, const std::string& text) const
    {
        std::ofstream(dir / name, std::ios::binary) << text;
        return (dir / name).string();
    }
};

// The Cornell box as it circulates as OBJ: millimetres, quads, an open
// front, a light with Ke, the back wall's corner 2 mm out of its plane, and
// faces that refer to their vertices by negative (relative) indices.
const char* const kCornellMtl = R"(newmtl white
Kd 0.73 0.73 0.73
newmtl red
Kd 0.63 0.065 0.05
newmtl green
Kd 0.14 0.45 0.091
newmtl light
Kd 0.78 0.78 0.78
Ke 17 12 4
)";

const char* const kCornellObj = R"(mtllib cornell.mtl
o floor
usemtl white
v 552.8 0 0
v 0 0 0
v 0 0 559.2
v 549.6 0 559.2
f -4 -3 -2 -1
o ceiling
v 556 548.8 0
v 556 548.8 559.2
v 0 548.8 559.2
v 0 548.8 0
f -4 -3 -2 -1
o back
v 549.6 0 559.2
v 0 0 559.2
v 0 548.8 559.2
v 556 550.8 559.2
f -4 -3 -2 -1
o right
usemtl green
v 0 0 559.2
v 0 0 0
v 0 548.8 0
v 0 548.8 559.2
f -4 -3 -2 -1
o left
usemtl red
v 552.8 0 0
v 549.6 0 559.2
v 556 548.8 559.2
v 556 548.8 0
f -4 -3 -2 -1
o light
usemtl light
v 343 548.7 227
v 343 548.7 332
v 213 548.7 332
v 213 548.7 227
f -4 -3 -2 -1
)";

} // namespace

TEST(ImportModel, TheCornellBoxAsItCirculatesAsObjImportsChecksAndSolves)
{
    Scratch s;
    s.write("cornell.mtl", kCornellMtl);
    const std::string obj = s.write("cornell.obj", kCornellObj);
    importer::ImportOptions options;
    options.read.scale = 0.001;
    auto imported = importer::importModel(obj, options);
    ASSERT_TRUE(imported) << imported.diagnostics().front().message;
    const model::Scene& scene = imported->scene;
    EXPECT_EQ(imported->report.merge.trianglesIn, 12u);
    // Every quad one face but the back wall: its corner 2 mm out of plane is
    // beyond the 1 mm tolerance, so its two triangles stay two faces.
    EXPECT_EQ(imported->report.merge.faces, 7u);
    EXPECT_EQ(imported->report.build.objects, 6u);
    EXPECT_EQ(imported->report.build.emittingFaces, 1u);
    EXPECT_EQ(imported->report.build.closedParts, 0u) << "walls are open shells";
    std::map<std::string, model::Material> materials;
    for (const model::Material& m : scene.materials)
        materials[m.id] = m;
    ASSERT_EQ(materials.count("light"), 1u);
    EXPECT_EQ(materials["light"].emission, (model::Rgb{17, 12, 4}));
    EXPECT_NEAR(materials["red"].reflectance.r, 0.63, 1e-6);
    EXPECT_FALSE(model::hasErrors(model::validateScene(scene)));

    solver::SolverOptions solve;
    solve.maxIterations = 200;
    auto solver = solver::Solver::create(scene, solve);
    ASSERT_TRUE(solver);
    const std::atomic<bool> cancel{false};
    (*solver)->run({}, cancel);
    double lit = 0.0;
    for (const solver::FaceResult& f : (*solver)->faceResults())
        if (f.id.rfind("floor", 0) == 0)
            lit = f.radiosity.y;
    // The Cornell box sample's floor reads 0.284 under a light of luminance
    // 38; this light's is 12.5 (Ke 17 12 4), and the blocks are missing.
    EXPECT_NEAR(lit, 0.284 * 12.5 / 38.0, 0.02);
}

TEST(ImportModel, AGroupAndAMaterialOfOneNameBothImport)
{
    Scratch s;
    s.write("m.mtl", "newmtl light\nKd 0.5 0.5 0.5\nKe 5 5 5\n");
    const std::string obj = s.write("m.obj",
                                    "mtllib m.mtl\no light\nusemtl light\n"
                                    "v 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nf 1 4 3 2\n");
    auto imported = importer::importModel(obj);
    ASSERT_TRUE(imported);
    ASSERT_EQ(imported->scene.materials.size(), 1u);
    ASSERT_EQ(imported->scene.objects.size(), 1u);
    EXPECT_EQ(imported->scene.materials[0].id, "light");
    EXPECT_EQ(imported->scene.objects[0].id, "light-2") << "one namespace: the second 'light' is renamed";
    EXPECT_FALSE(model::hasErrors(model::validateScene(imported->scene)));
}

TEST(ImportModel, AWhiteDiffuseColourIsScaledBelowOneWithAWarning)
{
    Scratch s;
    s.write("m.mtl", "newmtl snow\nKd 1 1 1\n");
    const std::string obj =
        s.write("m.obj", "mtllib m.mtl\no slab\nusemtl snow\nv 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nf 1 4 3 2\n");
    auto imported = importer::importModel(obj);
    ASSERT_TRUE(imported);
    EXPECT_EQ(imported->scene.materials[0].reflectance, (model::Rgb{importer::kMaxImportedReflectance}));
    ASSERT_EQ(imported->report.build.clampedMaterials.size(), 1u);
    bool warned = false;
    for (const model::Diagnostic& d : imported.diagnostics())
        warned = warned || d.message.find("'snow'") != std::string::npos;
    EXPECT_TRUE(warned);
}

TEST(ImportModel, WhatCannotBeReadIsRefusedWithTheReason)
{
    Scratch s;
    auto missing = importer::importModel((s.dir / "nothing.obj").string());
    ASSERT_FALSE(missing);
    EXPECT_NE(missing.diagnostics().front().message.find("not a readable file"), std::string::npos);

    auto garbage = importer::importModel(s.write("noise.glb", std::string("glTF\x02\0\0\0\xff\xff", 10)));
    ASSERT_FALSE(garbage);
    EXPECT_NE(garbage.diagnostics().front().message.find("could not be read"), std::string::npos);

    auto lines = importer::importModel(s.write("lines.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nl 1 2\nl 2 3\n"));
    ASSERT_FALSE(lines);
    EXPECT_FALSE(lines.diagnostics().empty());
}

TEST(ImportModel, AVertexAtInfinityOrBeyondTheCoordinateLimitIsRefusedNotWelded)
{
    // Found by the importer fuzzer: glTF's BoxWithInfinites (assimp-testmodels)
    // has infinite coordinates, which the welding grid turned into integers.
    const fs::path infinites = "/usr/share/assimp/models/glTF2/BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb";
    if (fs::exists(infinites)) {
        auto read = importer::importModel(infinites.string());
        ASSERT_FALSE(read);
        EXPECT_NE(read.diagnostics().front().message.find("which is not a point"), std::string::npos)
            << read.diagnostics().front().message;
    }
    Scratch s;
    auto far = importer::importModel(s.write("far.obj", "v 0 0 0\nv 1 0 0\nv 0 0 3e6\nf 1 2 3\n"));
    ASSERT_FALSE(far);
    EXPECT_NE(far.diagnostics().front().message.find("beyond 1000000 m from the origin"), std::string::npos)
        << far.diagnostics().front().message;
    // In millimetres it is a 3 km triangle, which is fine.
    importer::ImportOptions millimetres;
    millimetres.read.scale = 0.001;
    EXPECT_TRUE(importer::importModel(s.write("near.obj", "v 0 0 0\nv 3e6 0 0\nv 0 0 3e6\nf 1 2 3\n"), millimetres));
}

TEST(ImportModel, APlyHeaderWithoutItsEndIsRefusedInsteadOfReadForEver)
{
    // Found by the importer fuzzer: Assimp reads such a header for ever.
    Scratch s;
    const std::string header =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
        "property float z\nelement face 1\nproperty list uchar int vertex_index\n";
    const std::string body = "0 0 0\n1 0 0\n0 0 1\n3 0 1 2\n";
    auto unended = importer::importModel(s.write("unended.ply", header + "end0\n" + body));
    ASSERT_FALSE(unended);
    EXPECT_NE(unended.diagnostics().front().message.find("no end_header line"), std::string::npos);
    EXPECT_TRUE(importer::importModel(s.write("ended.ply", header + "end_header\n" + body)));
}

TEST(ImportModel, EveryModelOfAssimpsTestModelsImportsValidOrIsRefusedWithAReason)
{
    // Debian's assimp-testmodels: hundreds of files in every format Assimp
    // reads, none written here. Regions are left out: this is about reading.
    const fs::path root = "/usr/share/assimp/models";
    if (!fs::is_directory(root))
        GTEST_SKIP() << "assimp-testmodels is not installed (scripts/dev.sh installs it)";
    importer::ImportOptions options;
    options.autoRegions = false;
    int imported = 0, refused = 0;
    for (const auto& entry : fs::recursive_directory_iterator(root)) {
        if (!entry.is_regular_file())
            continue;
        const std::string ext = entry.path().extension().string();
        if (ext == ".png" || ext == ".jpg" || ext == ".bmp" || ext == ".tga" || ext == ".dds" || ext == ".mtl" ||
            ext == ".txt" || ext == ".bin" || entry.file_size() > 4'000'000)
            continue; // textures, sidecars and the few huge ones
        auto result = importer::importModel(entry.path().string(), options);
        if (result) {
            ++imported;
            EXPECT_FALSE(model::hasErrors(model::validateScene(result->scene))) << entry.path();
        } else {
            ++refused;
            ASSERT_FALSE(result.diagnostics().empty()) << entry.path();
            EXPECT_FALSE(result.diagnostics().front().message.empty()) << entry.path();
        }
    }
    EXPECT_GT(imported, 150);
    std::printf("assimp-testmodels: %d imported, %d refused with a reason\n", imported, refused);
}

TEST(ImportModel, AFaceWoundAgainstItsNeighboursIsTurnedAndARoomKeepsFacingIn)
{
    // A unit cube whose top is written clockwise comes in as a closed solid
    // facing out; the same cube wound inwards throughout is a room seen
    // from inside and keeps its winding.
    Scratch s;
    const std::string cube = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n";
    const std::string topWrong = "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 7 8 4\nf 4 1 5 8\n";
    const std::string inward = "f 1 2 3 4\nf 5 8 7 6\nf 1 5 6 2\nf 2 6 7 3\nf 3 7 8 4\nf 4 8 5 1\n";
    for (const auto& [faces, turned, out] : {std::tuple{topWrong, 1u, true}, std::tuple{inward, 0u, false}}) {
        auto imported = importer::importModel(s.write("cube.obj", "o cube\n" + cube + faces));
        ASSERT_TRUE(imported) << imported.diagnostics().front().message;
        EXPECT_EQ(imported->report.build.turnedFaces, turned);
        EXPECT_EQ(imported->report.build.closedParts, 1u);
        EXPECT_EQ(imported->report.build.closedFacingIn, out ? 0u : 1u);
        EXPECT_FALSE(model::hasErrors(model::validateScene(imported->scene)));
        const model::Part& part = imported->scene.objects.at(0).parts.at(0);
        for (const model::Face& f : part.faces) {
            const auto corners = model::loopPositions(part.vertices, f.loop);
            const double outward =
                glm::dot(model::polygonNormal(corners), model::polygonCentroid(corners) - model::Vec3{0.5});
            EXPECT_EQ(outward > 0.0, out) << f.id;
        }
    }
}

TEST(ImportModel, NamesInAnOldCodePageBecomeValidUtf8AndTheSceneSaves)
{
    // "café" in Latin-1, as an old tool writes it: the id keeps what is
    // safe, the name keeps the rest with a replacement character.
    Scratch s;
    const std::string obj = s.write("m.obj", "o caf\xe9\nv 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nf 1 4 3 2\n");
    auto imported = importer::importModel(obj);
    ASSERT_TRUE(imported);
    const model::Object& object = imported->scene.objects.at(0);
    EXPECT_EQ(object.id, "caf");
    EXPECT_EQ(object.name, "caf\xEF\xBF\xBD");
    EXPECT_TRUE(model::saveSceneFile(imported->scene, (s.dir / "m.json").string()));
}

TEST(ImportModel, AGltfEmitterKeepsItsEmissiveStrength)
{
    // A 1 m square lamp (two triangles facing up), emissiveFactor 1 0.5 0.25
    // at KHR_materials_emissive_strength 8, base colour 0.8.
    Scratch s;
    const std::string gltf = s.write("lamp.gltf", R"({
  "asset": {"version": "2.0"},
  "extensionsUsed": ["KHR_materials_emissive_strength"],
  "scene": 0, "scenes": [{"nodes": [0]}],
  "nodes": [{"name": "lamp", "mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "material": 0}]}],
  "materials": [{"name": "panel", "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.8, 0.8, 1]},
                 "emissiveFactor": [1, 0.5, 0.25],
                 "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 8}}}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 6, "type": "VEC3",
                 "min": [0, 0, 0], "max": [1, 0, 1]}],
  "bufferViews": [{"buffer": 0, "byteLength": 72}],
  "buffers": [{"byteLength": 72, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAAAAAAAAAAAAAIA/AACAPwAAAAAAAIA/AAAAAAAAAAAAAAAAAACAPwAAAAAAAIA/AACAPwAAAAAAAAAA"}]
})");
    auto imported = importer::importModel(gltf);
    ASSERT_TRUE(imported) << imported.diagnostics().front().message;
    ASSERT_EQ(imported->scene.materials.size(), 1u);
    const model::Material& panel = imported->scene.materials[0];
    EXPECT_EQ(panel.id, "panel");
    EXPECT_NEAR(panel.emission.r, 8.0, 1e-6);
    EXPECT_NEAR(panel.emission.g, 4.0, 1e-6);
    EXPECT_NEAR(panel.emission.b, 2.0, 1e-6);
    EXPECT_NEAR(panel.reflectance.g, 0.8, 1e-6);
    EXPECT_EQ(imported->report.merge.faces, 1u);
    EXPECT_EQ(imported->report.build.emittingFaces, 1u);
}

TEST(ImportModel, ATexturedMaterialTakesItsTexturesMeanColour)
{
    // A 2 x 2 texture: white, black, and two mid-grey (sRGB 188, linear
    // 0.5) texels, its mean in linear light 0.5; the MTL's Kd of 0.8 0.6 0.4
    // multiplies it.
    Scratch s;
    output::Image texture(2, 2);
    const std::uint8_t texels[] = {255, 0, 188, 188};
    for (std::size_t i = 0; i < 4; ++i)
        for (std::size_t c = 0; c < 3; ++c)
            texture.rgb[3 * i + c] = texels[i];
    ASSERT_TRUE(output::writePng((s.dir / "wood.png").string(), texture));
    s.write("m.mtl", "newmtl wood\nKd 0.8 0.6 0.4\nmap_Kd wood.png\n");
    const std::string obj = s.write("m.obj",
                                    "mtllib m.mtl\no slab\nusemtl wood\nvt 0 0\n"
                                    "v 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nf 1/1 4/1 3/1 2/1\n");
    auto imported = importer::importModel(obj);
    ASSERT_TRUE(imported) << imported.diagnostics().front().message;
    const model::Material& wood = imported->scene.materials.at(0);
    const double mean = (1.0 + 0.0 + 2.0 * std::pow((188 / 255.0 + 0.055) / 1.055, 2.4)) / 4.0;
    EXPECT_NEAR(mean, 0.5, 0.01) << "the premise: sRGB 188 is about half in linear light";
    EXPECT_NEAR(wood.reflectance.r, 0.8 * mean, 1e-6);
    EXPECT_NEAR(wood.reflectance.b, 0.4 * mean, 1e-6);
    EXPECT_EQ(imported->report.build.texturedMaterials, std::vector<std::string>{"wood"});

    // Without its texture file the colour stands in, with a warning.
    fs::remove(s.dir / "wood.png");
    auto missing = importer::importModel(obj);
    ASSERT_TRUE(missing);
    EXPECT_NEAR(missing->scene.materials.at(0).reflectance.r, 0.8, 1e-6);
    bool warned = false;
    for (const model::Diagnostic& d : missing.diagnostics())
        warned = warned || d.message.find("wood.png") != std::string::npos;
    EXPECT_TRUE(warned);
}

TEST(ImportModel, ASurfaceNoWindingMakesConsistentIsSplitIntoPartsThatAre)
{
    // A Moebius band of 24 quads: one-sided, so no choice of windings makes
    // it one consistent part; the faces at odds go to a part of their own.
    Scratch s;
    std::string obj = "o band\n";
    constexpr int n = 24;
    for (int i = 0; i < n; ++i) {
        const double a = 2.0 * std::numbers::pi * i / n, twist = a / 2.0;
        for (const double w : {-0.2, 0.2}) {
            const double r = 1.0 + w * std::cos(twist);
            obj += "v " + std::to_string(r * std::cos(a)) + " " + std::to_string(w * std::sin(twist)) + " " +
                   std::to_string(r * std::sin(a)) + "\n";
        }
    }
    for (int i = 0; i < n; ++i) {
        const int a0 = 2 * i + 1, a1 = 2 * i + 2;
        // The last quad joins the first edge the other way round: the twist.
        const int b0 = i + 1 < n ? 2 * (i + 1) + 1 : 2, b1 = i + 1 < n ? 2 * (i + 1) + 2 : 1;
        obj += "f " + std::to_string(a0) + " " + std::to_string(a1) + " " + std::to_string(b1) + " " +
               std::to_string(b0) + "\n";
    }
    auto imported = importer::importModel(s.write("band.obj", obj));
    ASSERT_TRUE(imported) << imported.diagnostics().front().message;
    EXPECT_GE(imported->scene.objects.at(0).parts.size(), 2u);
    EXPECT_FALSE(model::hasErrors(model::validateScene(imported->scene)));
}

TEST(ImportModel, TheGroupsOfAnObjObjectComeBackAsOneObject)
{
    // A cube written one group per face under one "o" (as Regio's own OBJ
    // export writes a solid): one object, one closed part, six faces.
    Scratch s;
    std::string obj = "o cube\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n";
    const char* faces[] = {"f 1 4 3 2", "f 5 6 7 8", "f 1 2 6 5", "f 2 3 7 6", "f 3 4 8 7", "f 4 1 5 8"};
    for (int k = 0; k < 6; ++k)
        obj += "g side" + std::to_string(k) + "\n" + faces[k] + "\n";
    obj += "o slab\ng top\nv 3 0 0\nv 4 0 0\nv 4 0 1\nv 3 0 1\nf 9 12 11 10\n";
    auto imported = importer::importModel(s.write("cube.obj", obj));
    ASSERT_TRUE(imported) << imported.diagnostics().front().message;
    const model::Scene& scene = imported->scene;
    ASSERT_EQ(scene.objects.size(), 2u);
    EXPECT_EQ(scene.objects[0].id, "cube");
    ASSERT_EQ(scene.objects[0].parts.size(), 1u);
    EXPECT_EQ(scene.objects[0].parts[0].faces.size(), 6u) << "the groups keep the faces apart";
    EXPECT_EQ(imported->report.build.closedParts, 1u);
    EXPECT_EQ(scene.objects[1].id, "slab");
}

TEST(ImportModel, ATriangulatedFurnishedRoomComesBackAsFewerFacesInRegionsThatBeatOneBspTree)
{
    // The generated room of 100 objects written as a modelling tool writes
    // it: every face a fan of triangles, each object under its "o", the
    // materials in an .mtl.
    const model::Scene room = test::furnishedRoom(1, 100);
    Scratch s;
    std::string mtl;
    for (const model::Material& m : room.materials)
        mtl += "newmtl " + m.id + "\nKd " + std::to_string(m.reflectance.r) + " " + std::to_string(m.reflectance.g) +
               " " + std::to_string(m.reflectance.b) + "\nKe " + std::to_string(m.emission.r) + " " +
               std::to_string(m.emission.g) + " " + std::to_string(m.emission.b) + "\n";
    s.write("room.mtl", mtl);
    std::string obj = "mtllib room.mtl\n";
    std::size_t vertices = 0, triangles = 0, faces = 0;
    for (const model::Object& object : room.objects) {
        obj += "o " + object.id + "\n";
        for (const model::Part& part : object.parts)
            for (const model::Face& face : part.faces) {
                ++faces;
                obj += "usemtl " + (face.material.empty() ? part.material : face.material) + "\n";
                for (const int v : face.loop) {
                    const model::Vec3& p = part.vertices[std::size_t(v)];
                    obj += "v " + std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
                }
                for (std::size_t k = 1; k + 1 < face.loop.size(); ++k, ++triangles)
                    obj += "f " + std::to_string(vertices + 1) + " " + std::to_string(vertices + k + 1) + " " +
                           std::to_string(vertices + k + 2) + "\n";
                vertices += face.loop.size();
            }
    }
    auto imported = importer::importModel(s.write("room.obj", obj));
    ASSERT_TRUE(imported) << imported.diagnostics().front().message;
    const importer::ImportReport& r = imported->report;
    EXPECT_EQ(r.merge.trianglesIn, triangles);
    EXPECT_LT(r.merge.faces, triangles);
    EXPECT_EQ(r.merge.faces, faces) << "every face of the room back as it was";
    EXPECT_EQ(r.build.objects, room.objects.size());
    EXPECT_GT(r.regions, 1);
    EXPECT_LT(r.fragments, r.singleTreeFragments) << "the regions beat one BSP tree with its suggested order";
    EXPECT_FALSE(model::hasErrors(model::validateScene(imported->scene)));
    std::printf("furnished room: %zu triangles -> %zu faces, %d regions, %d BSP fragments (one tree: %d)\n", triangles,
                r.merge.faces, r.regions, r.fragments, r.singleTreeFragments);
}
