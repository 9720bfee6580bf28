// OBJ export with vertex colours ("v x y z r g b"), normals and one group per
// input face, read back by a small OBJ reader.
#include "output/export_obj.h"

#include "export_test_support.h"
#include "lit_mesh_fixtures.h"
#include "output/vertex_radiosity.h"
#include "support/adaptive_scenes.h"
#include "support/prepared_scenes.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <array>
#include <map>
#include <set>
#include <sstream>

using namespace regio::output;
using namespace regio::solver;
using regio::test::freshOutputFolder;
using regio::test::readBytes;
using regio::test::sampleRoom;

namespace {

struct ObjFile {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> colours;
    std::vector<glm::vec3> normals;
    std::vector<std::array<int, 3>> faces; // 0-based position indices
    std::map<std::string, size_t> facesPerGroup;
    std::map<std::string, double> areaPerGroup;
    std::map<std::string, std::string> materialOfGroup; // the last "usemtl" in the group
    std::string materialLibrary;                        // "mtllib"
};

ObjFile readObj(const std::string& text)
{
    ObjFile obj;
    std::istringstream in(text);
    std::string line;
    std::string group;
    while (std::getline(in, line)) {
        std::istringstream words(line);
        std::string keyword;
        words >> keyword;
        if (keyword == "v") {
            glm::vec3 p, c;
            words >> p.x >> p.y >> p.z >> c.x >> c.y >> c.z;
            EXPECT_FALSE(words.fail()) << "six numbers: " << line;
            obj.positions.push_back(p);
            obj.colours.push_back(c);
        } else if (keyword == "vn") {
            glm::vec3 n;
            words >> n.x >> n.y >> n.z;
            obj.normals.push_back(n);
        } else if (keyword == "g") {
            words >> group;
        } else if (keyword == "usemtl") {
            words >> obj.materialOfGroup[group];
        } else if (keyword == "mtllib") {
            words >> obj.materialLibrary;
        } else if (keyword == "f") {
            std::array<int, 3> f{};
            for (int& i : f) {
                std::string corner;
                words >> corner;
                const size_t slashes = corner.find("//");
                EXPECT_NE(slashes, std::string::npos) << corner;
                i = std::stoi(corner.substr(0, slashes)) - 1;
                EXPECT_EQ(corner.substr(slashes + 2), corner.substr(0, slashes)) << "normal index = position index";
            }
            std::string extra;
            EXPECT_FALSE(words >> extra) << "triangles only";
            obj.faces.push_back(f);
            ++obj.facesPerGroup[group];
            const glm::vec3 a = obj.positions.at(size_t(f[0])), b = obj.positions.at(size_t(f[1])),
                            c = obj.positions.at(size_t(f[2]));
            obj.areaPerGroup[group] += 0.5 * double(glm::length(glm::cross(b - a, c - a)));
        }
    }
    return obj;
}

DisplayColours colours(const LitMesh& mesh)
{
    ToneMapSettings s;
    s.whiteReference = 6.0;
    return toneMappedColours(mesh, ToneMap::forMesh(s, mesh));
}

} // namespace

TEST(ObjExport, ReadsBackWithTheSameVerticesAndColours)
{
    const auto folder = freshOutputFolder();
    const LitMesh mesh = sampleRoom();
    const DisplayColours c = colours(mesh);
    const auto path = folder / "room.obj";
    ASSERT_TRUE(writeObj(path.string(), mesh, c));

    const ObjFile obj = readObj(readBytes(path));
    ASSERT_EQ(obj.positions.size(), mesh.vertexCount());
    ASSERT_EQ(obj.normals.size(), mesh.vertexCount());
    for (size_t v = 0; v < mesh.vertexCount(); ++v) {
        EXPECT_EQ(obj.positions[v], mesh.positions[v]) << "shortest round-trip numbers";
        EXPECT_EQ(obj.normals[v], mesh.normals[v]);
        EXPECT_EQ(obj.colours[v], c.encoded(v)) << "display-encoded colours in [0,1]";
        for (int k = 0; k < 3; ++k) {
            EXPECT_GE(obj.colours[v][k], 0.0f);
            EXPECT_LE(obj.colours[v][k], 1.0f);
        }
    }
    ASSERT_EQ(obj.faces.size(), mesh.triangleCount());
}

TEST(ObjExport, TrianglesAreGroupedByInputFaceWithTheirWindingKept)
{
    const auto folder = freshOutputFolder();
    const LitMesh mesh = sampleRoom();
    const auto path = folder / "room.obj";
    ASSERT_TRUE(writeObj(path.string(), mesh, colours(mesh)));
    const ObjFile obj = readObj(readBytes(path));
    ASSERT_EQ(obj.facesPerGroup.size(), mesh.faceIds.size());
    for (const std::string& id : mesh.faceIds)
        EXPECT_EQ(obj.facesPerGroup.at(id), 2u) << id;
    // Every written triangle is one of the mesh's, corners in the same order.
    std::set<std::array<int, 3>> triangles;
    for (size_t t = 0; t < mesh.triangleCount(); ++t)
        triangles.insert({static_cast<int>(mesh.indices[3 * t]), static_cast<int>(mesh.indices[3 * t + 1]),
                          static_cast<int>(mesh.indices[3 * t + 2])});
    for (const auto& f : obj.faces)
        EXPECT_EQ(triangles.count(f), 1u);
}

TEST(ObjExport, AnUnwritablePathIsNamedInTheError)
{
    const auto folder = freshOutputFolder();
    const LitMesh mesh = sampleRoom();
    const std::string path = (folder / "no" / "room.obj").string();
    const auto error = writeObj(path, mesh, colours(mesh));
    ASSERT_FALSE(error.ok());
    EXPECT_NE(error.error().message.find(path), std::string::npos) << error.error().message;
}

TEST(ObjExport, TheScenesMaterialsGoToAnMtlFileAndEveryGroupNamesItsOwn)
{
    const auto folder = freshOutputFolder();
    const PreparedScene scene = regio::test::prepared(regio::test::boxUnderLamp());
    const LitMesh mesh = smoothLitMesh(scene, std::vector<regio::model::Rgb>(scene.elements.size(), {1.0, 1.0, 1.0}));
    const auto path = folder / "box.obj";
    ASSERT_TRUE(writeObj(path.string(), mesh, colours(mesh)));
    EXPECT_EQ(mtlPath(path.string()), (folder / "box.mtl").string());
    const ObjFile obj = readObj(readBytes(path));
    EXPECT_EQ(obj.materialLibrary, "box.mtl");
    const std::string mtl = readBytes(folder / "box.mtl");
    EXPECT_NE(mtl.find("newmtl grey\nKd 0.5 0.5 0.5\n"), std::string::npos) << mtl;
    EXPECT_NE(mtl.find("newmtl lamp\nKd 0 0 0\nKs 0 0 0\nKe 40 40 40\n"), std::string::npos) << mtl;
    EXPECT_EQ(obj.materialOfGroup.at("floor.face"), "grey");
    EXPECT_EQ(obj.materialOfGroup.at("lamp.face"), "lamp");
    EXPECT_EQ(obj.materialOfGroup.size(), mesh.faceIds.size()) << "every group names its material";
    EXPECT_NEAR(obj.areaPerGroup.at("floor.face"), 9.0, 1e-4) << "the floor under the box is filled in";
}

TEST(ObjExport, AMeshThatDoesNotKnowItsMaterialsWritesNoMtlFile)
{
    const auto folder = freshOutputFolder();
    const LitMesh mesh = sampleRoom();
    ASSERT_TRUE(writeObj((folder / "room.obj").string(), mesh, colours(mesh)));
    EXPECT_FALSE(std::filesystem::exists(folder / "room.mtl"));
    EXPECT_TRUE(readObj(readBytes(folder / "room.obj")).materialLibrary.empty());
}
