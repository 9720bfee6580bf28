// One test per validation rule: each starts from a clean scene, changes the
// least that triggers the rule, and expects exactly that rule's diagnostic.
#include "model/validation/validation.h"

#include "model/io/scene_json.h"
#include "support/broken_file_table.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

using namespace regio::model;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A cube [origin, origin + size], faces counter-clockwise seen from outside,
// named <id>.bottom, .top, .front, .back, .left, .right.
Part cubePart(const std::string& id, Vec3 origin, double size)
{
    Part part;
    part.id = id;
    part.material = "white";
    for (int i = 0; i < 8; ++i) {
        Vec3 corner{double((i == 1 || i == 2 || i == 5 || i == 6) ? 1 : 0),
                    double((i == 2 || i == 3 || i == 6 || i == 7) ? 1 : 0), double(i >= 4 ? 1 : 0)};
        part.vertices.push_back(origin + size * corner);
    }
    const char* names[6] = {"bottom", "top", "front", "back", "left", "right"};
    const std::vector<std::vector<int>> loops{{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                              {2, 3, 7, 6}, {0, 4, 7, 3}, {1, 2, 6, 5}};
    for (int f = 0; f < 6; ++f)
        part.faces.push_back(Face{id + "." + names[f], loops[size_t(f)], {}});
    return part;
}

// A square pyramid over the base (0,0,0)-(1,1,0) with its apex at (0.5, 0.5, 1).
// Every side is a triangle, so moving a base corner affects the base alone.
Part pyramidPart(const std::string& id, std::vector<Vec3> base)
{
    Part part;
    part.id = id;
    part.material = "white";
    part.vertices = base;
    part.vertices.push_back({0.5, 0.5, 1.0});
    const int n = int(base.size());
    std::vector<int> bottom;
    for (int i = n - 1; i >= 0; --i)
        bottom.push_back(i);
    part.faces.push_back(Face{id + ".base", bottom, {}});
    for (int i = 0; i < n; ++i)
        part.faces.push_back(Face{id + ".side" + std::to_string(i), {i, (i + 1) % n, n}, {}});
    return part;
}

// A tetrahedron whose face 0 is (a, b, c); d lies above.
Part tetrahedronPart(const std::string& id, Vec3 a, Vec3 b, Vec3 c, Vec3 d)
{
    Part part;
    part.id = id;
    part.material = "white";
    part.vertices = {a, b, c, d};
    part.faces = {Face{id + ".abc", {0, 2, 1}, {}}, Face{id + ".abd", {0, 1, 3}, {}}, Face{id + ".bcd", {1, 2, 3}, {}},
                  Face{id + ".cad", {2, 0, 3}, {}}};
    return part;
}

// A closed 1 m box with a lamp on top, inside one region that names the lamp
// first in its BSP order: nothing to complain about.
Scene cleanScene()
{
    Scene scene;
    scene.materials.push_back(Material{"white", "", {0.7, 0.7, 0.7}, {0, 0, 0}});
    scene.materials.push_back(Material{"lamp", "", {0.5, 0.5, 0.5}, {10, 10, 10}});
    Object box;
    box.id = "box";
    box.parts.push_back(cubePart("box.body", Vec3(0.0), 1.0));
    box.parts[0].faces[1].material = "lamp";
    scene.objects.push_back(box);
    scene.regions.push_back(Region{"room", "", {-1, -1, -1}, {2, 2, 2}, {"box.body.top"}});
    return scene;
}

// The clean scene with its box replaced by another part of object "box".
Scene sceneWith(Part part)
{
    Scene scene = cleanScene();
    part.faces[1].material = "lamp"; // keep something emitting
    scene.objects[0].parts[0] = std::move(part);
    scene.regions[0].bspOrder.clear();
    return scene;
}

std::string dump(const Diagnostics& diagnostics)
{
    std::ostringstream text;
    for (const Diagnostic& d : diagnostics)
        text << (d.isError() ? "error " : "warning ") << d.pointer << ": " << d.message << "\n";
    return text.str();
}

void expectOnly(const Diagnostics& diagnostics, Severity severity, const std::string& pointer,
                const std::vector<std::string>& idPath, const std::string& phrase)
{
    ASSERT_EQ(diagnostics.size(), 1u) << dump(diagnostics);
    const Diagnostic& d = diagnostics.front();
    EXPECT_EQ(d.severity, severity) << d.message;
    EXPECT_EQ(d.pointer, pointer) << d.message;
    EXPECT_EQ(d.idPath, idPath) << d.message;
    EXPECT_NE(d.message.find(phrase), std::string::npos) << d.message;
}

const std::vector<std::string> kBodyPath{"box", "box.body"};
std::vector<std::string> bodyFace(const std::string& name) { return {"box", "box.body", "box.body." + name}; }

} // namespace

TEST(Validation, ClosedLitBoxInsideItsRegionHasNoDiagnostics) { EXPECT_EQ(dump(validateScene(cleanScene())), ""); }

TEST(Validation, SceneWithoutRegionsSkipsTheRegionRules)
{
    Scene scene = cleanScene();
    scene.regions.clear();
    EXPECT_EQ(dump(validateScene(scene)), "");
}

TEST(Validation, InwardFacingClosedRoomIsClean)
{
    Part room = cubePart("box.body", Vec3(0.0), 1.0);
    for (Face& face : room.faces)
        std::reverse(face.loop.begin(), face.loop.end());
    EXPECT_EQ(dump(validateScene(sceneWith(room))), "");
}

// --- ids -------------------------------------------------------------------

TEST(Validation, EmptyIdIsAnError)
{
    Scene scene = cleanScene();
    scene.objects[0].id = "";
    expectOnly(validateScene(scene), Severity::Error, "/objects/0/id", {""}, "empty id");
}

TEST(Validation, DuplicateFaceIdIsAnError)
{
    Scene scene = cleanScene();
    scene.objects[0].parts[0].faces[2].id = "box.body.bottom";
    expectOnly(validateScene(scene), Severity::Error, "/objects/0/parts/0/faces/2/id",
               {"box", "box.body", "box.body.bottom"}, "/objects/0/parts/0/faces/0");
}

TEST(Validation, IdsAreOneNamespaceAcrossKinds)
{
    Scene scene = cleanScene();
    scene.regions[0].id = "white"; // the id of a material
    expectOnly(validateScene(scene), Severity::Error, "/regions/0/id", {"white"},
               "duplicate id \"white\": already used by the material at /materials/0");
}

// --- materials and references ----------------------------------------------

TEST(Validation, UnknownMaterialOnAPartIsAnError)
{
    Scene scene = cleanScene();
    scene.objects[0].parts[0].material = "marble";
    expectOnly(validateScene(scene), Severity::Error, "/objects/0/parts/0/material", kBodyPath,
               "unknown material \"marble\"");
}

TEST(Validation, UnknownMaterialOnAFaceIsAnError)
{
    Scene scene = cleanScene();
    scene.objects[0].parts[0].faces[3].material = "marble";
    expectOnly(validateScene(scene), Severity::Error, "/objects/0/parts/0/faces/3/material", bodyFace("back"),
               "unknown material \"marble\"");
}

TEST(Validation, FaceWithoutAnyMaterialIsAnError)
{
    Scene scene = cleanScene();
    Part& part = scene.objects[0].parts[0];
    part.material.clear();
    for (Face& face : part.faces)
        if (face.material.empty() && face.id != "box.body.left")
            face.material = "white";
    expectOnly(validateScene(scene), Severity::Error, "/objects/0/parts/0/faces/4", bodyFace("left"),
               "has no material");
}

TEST(Validation, ReflectanceOfOneIsAnError)
{
    Scene scene = cleanScene();
    scene.materials[0].reflectance.y = 1.0;
    expectOnly(validateScene(scene), Severity::Error, "/materials/0/reflectance/1", {"white"}, "must be below 1");
}

TEST(Validation, NegativeReflectanceIsAnError)
{
    Scene scene = cleanScene();
    scene.materials[0].reflectance.z = -0.1;
    expectOnly(validateScene(scene), Severity::Error, "/materials/0/reflectance/2", {"white"}, "negative");
}

TEST(Validation, NegativeEmissionIsAnError)
{
    Scene scene = cleanScene();
    scene.materials[1].emission.x = -1.0;
    expectOnly(validateScene(scene), Severity::Error, "/materials/1/emission/0", {"lamp"}, "negative");
}

TEST(Validation, NonFiniteMaterialValuesAreErrors)
{
    Scene scene = cleanScene();
    scene.materials[0].emission.y = kNaN;
    expectOnly(validateScene(scene), Severity::Error, "/materials/0/emission/1", {"white"}, "not a finite");
}

TEST(Validation, SceneWithoutEmittingFacesIsAWarning)
{
    Scene scene = cleanScene();
    scene.materials[1].emission = Rgb(0.0);
    expectOnly(validateScene(scene), Severity::Warning, "", {}, "nothing to solve");
}

TEST(Validation, AnEmittingMaterialNoFaceUsesDoesNotCount)
{
    Scene scene = cleanScene();
    scene.objects[0].parts[0].faces[1].material.clear();
    expectOnly(validateScene(scene), Severity::Warning, "", {}, "no face emits light");
}

// --- loops and vertices -----------------------------------------------------

TEST(Validation, LoopWithFewerThanThreeVerticesIsAnError)
{
    Scene scene = cleanScene();
    scene.objects[0].parts[0].faces[0].loop = {0, 3};
    expectOnly(validateScene(scene), Severity::Error, "/objects/0/parts/0/faces/0/loop", bodyFace("bottom"),
               "at least 3");
}

TEST(Validation, LoopIndexOutOfRangeIsAnError)
{
    Scene scene = cleanScene();
    scene.objects[0].parts[0].faces[0].loop[2] = 42;
    expectOnly(validateScene(scene), Severity::Error, "/objects/0/parts/0/faces/0/loop/2", bodyFace("bottom"),
               "loop entry 42 is not a vertex");
}

TEST(Validation, RepeatedLoopVertexIsAnError)
{
    Scene scene = cleanScene();
    scene.objects[0].parts[0].faces[0].loop = {0, 3, 2, 3};
    expectOnly(validateScene(scene), Severity::Error, "/objects/0/parts/0/faces/0/loop/3", bodyFace("bottom"),
               "vertex 3 appears twice");
}

TEST(Validation, NonFiniteVertexIsAnError)
{
    Scene scene = cleanScene();
    scene.objects[0].parts[0].vertices[0].y = std::numeric_limits<double>::infinity();
    expectOnly(validateScene(scene), Severity::Error, "/objects/0/parts/0/vertices/0", kBodyPath,
               "not a finite number");
}

// --- face geometry -----------------------------------------------------------

TEST(Validation, WarpedFaceIsAnError)
{
    // The base corner lifted by 0.1 m: the base leaves its plane by ~2.5 cm,
    // beyond 1 % of its 1.41 m diagonal.
    Part pyramid = pyramidPart("box.body", {{0, 0, 0.1}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
    expectOnly(validateScene(sceneWith(pyramid)), Severity::Error, "/objects/0/parts/0/faces/0", bodyFace("base"),
               "is not planar");
}

TEST(Validation, SlightlyNonPlanarFaceIsAWarning)
{
    // Lifted by 1 mm: 0.25 mm off the plane, above 1e-4 of the diagonal.
    Part pyramid = pyramidPart("box.body", {{0, 0, 0.001}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
    expectOnly(validateScene(sceneWith(pyramid)), Severity::Warning, "/objects/0/parts/0/faces/0", bodyFace("base"),
               "slightly non-planar");
}

TEST(Validation, PlanarityWithinToleranceIsAccepted)
{
    // Lifted by 0.1 mm: 25 um off the plane, below 1e-4 of the 1.41 m diagonal.
    Part pyramid = pyramidPart("box.body", {{0, 0, 1e-4}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
    EXPECT_EQ(dump(validateScene(sceneWith(pyramid))), "");
}

TEST(Validation, NonConvexFaceIsAnError)
{
    // A dart: the fourth corner points into the base.
    Part pyramid = pyramidPart("box.body", {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0.6, 0.4, 0}});
    expectOnly(validateScene(sceneWith(pyramid)), Severity::Error, "/objects/0/parts/0/faces/0", bodyFace("base"),
               "not convex");
}

TEST(Validation, ZeroAreaFaceIsAnError)
{
    // c lies on the segment ab: the face abc is a line.
    Part tetra = tetrahedronPart("box.body", {0, 0, 0}, {1, 0, 0}, {0.5, 0, 0}, {0.5, 0.5, 1});
    expectOnly(validateScene(sceneWith(tetra)), Severity::Error, "/objects/0/parts/0/faces/0", bodyFace("abc"),
               "zero area");
}

TEST(Validation, ZeroAreaFaceInABspOrderIsNotAlsoCalledOutside)
{
    Part tetra = tetrahedronPart("box.body", {0, 0, 0}, {1, 0, 0}, {0.5, 0, 0}, {0.5, 0.5, 1});
    Scene scene = sceneWith(tetra);
    scene.regions[0].bspOrder = {"box.body.abc"};
    expectOnly(validateScene(scene), Severity::Error, "/objects/0/parts/0/faces/0", bodyFace("abc"), "zero area");
}

TEST(Validation, SliverFaceIsAWarning)
{
    // abc is 1 m long and 10 um wide.
    Part tetra = tetrahedronPart("box.body", {0, 0, 0}, {1, 0, 0}, {0.5, 1e-5, 0}, {0.5, 0.5, 1});
    expectOnly(validateScene(sceneWith(tetra)), Severity::Warning, "/objects/0/parts/0/faces/0", bodyFace("abc"),
               "sliver");
}

// --- topology ------------------------------------------------------------------

TEST(Validation, MisWoundFaceIsAnErrorOnThatFace)
{
    Scene scene = cleanScene();
    auto& loop = scene.objects[0].parts[0].faces[5].loop;
    std::reverse(loop.begin(), loop.end());
    expectOnly(validateScene(scene), Severity::Error, "/objects/0/parts/0/faces/5", bodyFace("right"),
               "wound opposite to its neighbours");
}

TEST(Validation, EdgeSharedByMoreThanTwoFacesIsAnError)
{
    // Two cubes in one part touching along the edge x = y = 1.
    Part part = cubePart("box.body", Vec3(0.0), 1.0);
    Part other = cubePart("box.other", Vec3(1, 1, 0), 1.0);
    const int base = int(part.vertices.size());
    part.vertices.insert(part.vertices.end(), other.vertices.begin(), other.vertices.end());
    for (Face face : other.faces) {
        for (int& v : face.loop)
            v = v == 0 ? 2 : v == 4 ? 6 : v + base; // share (1,1,0) and (1,1,1)
        part.faces.push_back(face);
    }
    Diagnostics diagnostics = validateScene(sceneWith(part));
    // Faces on the edge: box.body.back, .right, box.other.front, .left; the
    // third one in face order is reported.
    expectOnly(diagnostics, Severity::Error, "/objects/0/parts/0/faces/8", {"box", "box.body", "box.other.front"},
               "shared by 4 faces");
}

TEST(Validation, OpenPartIsAWarningThatNamesWalls)
{
    Scene scene = cleanScene();
    scene.objects[0].parts[0].faces.erase(scene.objects[0].parts[0].faces.begin()); // no bottom
    expectOnly(validateScene(scene), Severity::Warning, "/objects/0/parts/0", kBodyPath, "walls");
}

TEST(Validation, FlatOpenPanelIsNotWarnedAbout)
{
    // A lone quad (a wall, a lamp panel) is open by nature.
    Part panel;
    panel.id = "box.body";
    panel.material = "white";
    panel.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 0}, {2, 1, 0}};
    panel.faces = {Face{"box.body.a", {0, 1, 2, 3}, {}}, Face{"box.body.b", {1, 4, 5, 2}, {}}};
    EXPECT_EQ(dump(validateScene(sceneWith(panel))), "");
}

// --- regions ---------------------------------------------------------------------

TEST(Validation, RegionWithMinNotBelowMaxIsAnError)
{
    Scene scene = cleanScene();
    scene.regions[0].max.y = scene.regions[0].min.y;
    expectOnly(validateScene(scene), Severity::Error, "/regions/0", {"room"}, "is empty");
}

TEST(Validation, RegionWithNonFiniteCornerIsAnError)
{
    Scene scene = cleanScene();
    scene.regions[0].min.z = kNaN;
    expectOnly(validateScene(scene), Severity::Error, "/regions/0/min", {"room"}, "not a finite point");
}

TEST(Validation, OverlappingRegionsAreAnError)
{
    Scene scene = cleanScene();
    scene.regions.push_back(Region{"annex", "", {1.5, -1, -1}, {4, 2, 2}, {}});
    expectOnly(validateScene(scene), Severity::Error, "/regions/1", {"annex"}, "overlaps region \"room\"");
}

TEST(Validation, TouchingRegionsAreFine)
{
    Scene scene = cleanScene();
    scene.regions.push_back(Region{"annex", "", {2, -1, -1}, {4, 2, 2}, {}});
    EXPECT_EQ(dump(validateScene(scene)), "");
}

TEST(Validation, InterlockingRegionsAreAnError)
{
    // A pinwheel of four boxes around a centre one that holds the box: no two
    // overlap, but no axis-aligned plane cuts the set in two.
    Scene scene = cleanScene();
    const double z0 = -1, z1 = 2;
    scene.regions = {Region{"a", "", {-1, -1, z0}, {1, 0, z1}, {}}, Region{"b", "", {1, -1, z0}, {2, 1, z1}, {}},
                     Region{"c", "", {0, 1, z0}, {2, 2, z1}, {}}, Region{"d", "", {-1, 0, z0}, {0, 2, z1}, {}},
                     Region{"centre", "", {0, 0, z0}, {1, 1, z1}, {"box.body.top"}}};
    expectOnly(validateScene(scene), Severity::Error, "/regions/0", {"a"}, "interlock");
}

TEST(Validation, PartStraddlingARegionBoundaryIsAWarning)
{
    Scene scene = cleanScene();
    scene.regions = {Region{"west", "", {-1, -1, -1}, {0.5, 2, 2}, {"box.body.top"}},
                     Region{"east", "", {0.5, -1, -1}, {2, 2, 2}, {}}};
    expectOnly(validateScene(scene), Severity::Warning, "/objects/0/parts/0", kBodyPath,
               "straddles the boundaries of regions \"west\" and \"east\": the solver will clip it");
}

TEST(Validation, PartReachingOutOfItsOnlyRegionIsAStraddleWarning)
{
    Scene scene = cleanScene();
    scene.regions[0].max.x = 0.5;
    expectOnly(validateScene(scene), Severity::Warning, "/objects/0/parts/0", kBodyPath,
               "partly lies outside every region");
}

TEST(Validation, PartOnARegionBoundaryBelongsToIt)
{
    Scene scene = cleanScene();
    scene.regions[0].min = Vec3(0.0); // the box's faces lie on the region's faces
    scene.regions[0].max = Vec3(1.0);
    EXPECT_EQ(dump(validateScene(scene)), "");
}

TEST(Validation, PartOutsideEveryRegionIsAWarning)
{
    Scene scene = cleanScene();
    scene.regions[0] = Region{"far", "", {5, 5, 5}, {6, 6, 6}, {}};
    expectOnly(validateScene(scene), Severity::Warning, "/objects/0/parts/0", kBodyPath, "lies outside every region");
}

TEST(Validation, BspOrderNamingAnUnknownFaceIsAnError)
{
    Scene scene = cleanScene();
    scene.regions[0].bspOrder.push_back("box.body.ghost");
    expectOnly(validateScene(scene), Severity::Error, "/regions/0/bspOrder/1", {"room"},
               "\"box.body.ghost\", which is not a face");
}

TEST(Validation, BspOrderNamingAPartInsteadOfAFaceIsAnError)
{
    Scene scene = cleanScene();
    scene.regions[0].bspOrder = {"box.body"};
    expectOnly(validateScene(scene), Severity::Error, "/regions/0/bspOrder/0", {"room"}, "not a face");
}

TEST(Validation, BspOrderNamingAFaceOutsideTheRegionIsAnError)
{
    Scene scene = cleanScene();
    scene.regions.push_back(Region{"attic", "", {-1, -1, 2}, {2, 2, 3}, {"box.body.top"}});
    expectOnly(validateScene(scene), Severity::Error, "/regions/1/bspOrder/0", {"attic"}, "lies outside the region");
}

TEST(Validation, BspOrderMayNameAFaceThatCrossesIntoTheRegion)
{
    Scene scene = cleanScene();
    scene.regions = {Region{"west", "", {-1, -1, -1}, {0.5, 2, 2}, {"box.body.top", "box.body.front"}},
                     Region{"east", "", {0.5, -1, -1}, {2, 2, 2}, {"box.body.top", "box.body.right"}}};
    Diagnostics diagnostics = validateScene(scene);
    ASSERT_EQ(diagnostics.size(), 1u) << dump(diagnostics); // only the straddle warning
    EXPECT_NE(diagnostics[0].message.find("straddles"), std::string::npos);
}

TEST(Validation, FaceMeetingTheRegionOnlyAlongALineIsOutsideIt)
{
    // The box's right face (x = 1, 0 <= y <= 1) meets this region (y >= 1)
    // only in the line y = 1: no area of it lies inside.
    Scene scene = cleanScene();
    scene.regions[0].max.x = 1.0;
    scene.regions.push_back(Region{"side", "", {1, 1, -1}, {2, 2, 2}, {"box.body.right"}});
    expectOnly(validateScene(scene), Severity::Error, "/regions/1/bspOrder/0", {"side"}, "lies outside the region");
}

TEST(Validation, FaceListedTwiceInABspOrderIsAWarning)
{
    Scene scene = cleanScene();
    scene.regions[0].bspOrder = {"box.body.top", "box.body.left", "box.body.top"};
    expectOnly(validateScene(scene), Severity::Warning, "/regions/0/bspOrder/2", {"room"}, "listed twice");
}

// --- scale -----------------------------------------------------------------------

TEST(Validation, HundredThousandFacesValidateCleanly)
{
    Scene scene = cleanScene();
    Object& object = scene.objects[0];
    const int cubes = 17000; // 102 000 faces
    for (int i = 1; i < cubes; ++i) {
        Vec3 origin{double(i % 100) * 0.01, double((i / 100) % 100) * 0.01, double(i / 10000) * 0.01};
        object.parts.push_back(cubePart("box.c" + std::to_string(i), origin, 0.005));
        scene.regions[0].bspOrder.push_back("box.c" + std::to_string(i) + ".top");
    }
    auto start = std::chrono::steady_clock::now();
    std::clock_t cpuStart = std::clock();
    Diagnostics diagnostics = validateScene(scene);
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    double cpuSeconds = double(std::clock() - cpuStart) / CLOCKS_PER_SEC;
    std::printf("validated %d faces in %.3f s (%.3f s of CPU)\n", cubes * 6, seconds, cpuSeconds);
    RecordProperty("validate_seconds", std::to_string(seconds));
    EXPECT_EQ(diagnostics.size(), 0u) << dump(diagnostics).substr(0, 2000);
}

// --- the scene files of tests/data/bad (validation.tsv) -----------------------------------------

namespace {

struct InvalidFile {
    std::string name;
    Severity severity = Severity::Error;
    std::string pointer;
    std::vector<std::string> idPath;
    std::string message;
};

void PrintTo(const InvalidFile& file, std::ostream* out) { *out << file.name; }

std::string invalidDataDir() { return std::string(REGIO_TEST_DATA) + "/bad"; }

// validation.tsv: file, severity, pointer ("-" = document), id path (each id in
// double quotes, "-" = none), a part of the message.
std::vector<InvalidFile> loadInvalidFileTable()
{
    std::vector<InvalidFile> table;
    std::ifstream in(invalidDataDir() + "/validation.tsv");
    for (std::string row; std::getline(in, row);) {
        if (row.empty() || row[0] == '#')
            continue;
        std::vector<std::string> cells;
        std::stringstream split(row);
        for (std::string cell; std::getline(split, cell, '\t');)
            cells.push_back(cell);
        if (cells.size() != 5)
            continue;
        InvalidFile file{cells[0],
                         cells[1] == "warning" ? Severity::Warning : Severity::Error,
                         cells[2] == "-" ? "" : cells[2],
                         {},
                         cells[4]};
        if (cells[3] != "-") {
            for (size_t open = cells[3].find('"'); open != std::string::npos;) {
                size_t close = cells[3].find('"', open + 1);
                // "\xHH" stands for the byte HH (ids with control characters).
                std::string id = cells[3].substr(open + 1, close - open - 1);
                for (size_t at = 0; (at = id.find("\\x", at)) != std::string::npos && at + 4 <= id.size(); ++at)
                    id.replace(at, 4, 1, static_cast<char>(std::stoi(id.substr(at + 2, 2), nullptr, 16)));
                file.idPath.push_back(id);
                open = cells[3].find('"', close + 1);
            }
        }
        table.push_back(std::move(file));
    }
    return table;
}

class InvalidSceneFile : public testing::TestWithParam<InvalidFile> { };

} // namespace

TEST(InvalidSceneFiles, EveryFileHasARowAndTheRulesAreCovered)
{
    const std::vector<InvalidFile> table = loadInvalidFileTable();
    ASSERT_GE(table.size(), 10u);
    for (const auto& entry : std::filesystem::directory_iterator(invalidDataDir())) {
        const std::string name = entry.path().filename().string();
        if (name.ends_with(".tsv") || name == "README.md")
            continue;
        const std::vector<std::string> listed = regio::test::catalogueFileNames();
        EXPECT_NE(std::find(listed.begin(), listed.end(), name), listed.end())
            << name << " has no row in format.tsv or validation.tsv";
    }
}

TEST_P(InvalidSceneFile, ReadsCleanlyAndBreaksExactlyItsRule)
{
    const InvalidFile& file = GetParam();
    Result<Scene> read = loadSceneFile(invalidDataDir() + "/" + file.name);
    ASSERT_TRUE(read.ok()) << dump(read.diagnostics());
    EXPECT_TRUE(read.diagnostics().empty()) << dump(read.diagnostics());
    expectOnly(validateScene(*read), file.severity, file.pointer, file.idPath, file.message);
}

INSTANTIATE_TEST_SUITE_P(Rules, InvalidSceneFile, testing::ValuesIn(loadInvalidFileTable()),
                         [](const testing::TestParamInfo<InvalidFile>& test) {
                             std::string name = test.param.name.substr(0, test.param.name.find('.'));
                             std::replace(name.begin(), name.end(), '-', '_');
                             return name;
                         });
