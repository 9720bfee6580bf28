// glTF 2.0 export: the .gltf + .bin pair and the .glb container, read back
// and checked against the mesh (the Khronos validator runs over the same
// kinds of files in the gltf_validator test).
#include "output/export_gltf.h"

#include "export_test_support.h"
#include "lit_mesh_fixtures.h"
#include "output/vertex_radiosity.h"
#include "support/adaptive_scenes.h"
#include "support/prepared_scenes.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <bit>
#include <cstring>
#include <limits>
#include <numeric>
#include <set>

using namespace regio::output;
using namespace regio::solver;
using nlohmann::json;
using regio::test::freshOutputFolder;
using regio::test::readBytes;
using regio::test::sampleRoom;

namespace {

uint32_t u32(const std::string& bytes, size_t at)
{
    uint32_t v = 0;
    for (int i = 3; i >= 0; --i)
        v = (v << 8) | static_cast<unsigned char>(bytes[at + static_cast<size_t>(i)]);
    return v;
}

float f32(const std::string& bytes, size_t at) { return std::bit_cast<float>(u32(bytes, at)); }

DisplayColours colours(const LitMesh& mesh, double exposure = 0.0)
{
    ToneMapSettings s;
    s.exposure = exposure;
    s.whiteReference = 8.0;
    return toneMappedColours(mesh, ToneMap::forMesh(s, mesh));
}

// The float vec3 accessor `name` of a primitive, read from `bin`.
std::vector<glm::vec3> readVec3(const json& doc, const std::string& bin, const json& primitive, const std::string& name)
{
    const json& accessor = doc["accessors"][primitive["attributes"][name].get<size_t>()];
    EXPECT_EQ(accessor["componentType"], 5126);
    EXPECT_EQ(accessor["type"], "VEC3");
    const json& view = doc["bufferViews"][accessor["bufferView"].get<size_t>()];
    const size_t offset = view["byteOffset"].get<size_t>() + accessor.value("byteOffset", size_t{0});
    std::vector<glm::vec3> out;
    for (size_t i = 0; i < accessor["count"].get<size_t>(); ++i) {
        const size_t at = offset + 12 * i;
        out.push_back({f32(bin, at), f32(bin, at + 4), f32(bin, at + 8)});
    }
    return out;
}

std::vector<uint32_t> readIndices(const json& doc, const std::string& bin, const json& primitive)
{
    const json& accessor = doc["accessors"][primitive["indices"].get<size_t>()];
    const json& view = doc["bufferViews"][accessor["bufferView"].get<size_t>()];
    const size_t offset = view["byteOffset"].get<size_t>();
    const int type = accessor["componentType"];
    std::vector<uint32_t> out;
    for (size_t i = 0; i < accessor["count"].get<size_t>(); ++i) {
        if (type == 5123)
            out.push_back(uint32_t{static_cast<unsigned char>(bin[offset + 2 * i])} |
                          (uint32_t{static_cast<unsigned char>(bin[offset + 2 * i + 1])} << 8u));
        else
            out.push_back(u32(bin, offset + 4 * i));
    }
    return out;
}

// The value of attribute `name` at every triangle corner of the file, in
// file order (meshes, primitives, indices).
std::vector<glm::vec3> readCorners(const json& doc, const std::string& bin, const std::string& name)
{
    std::vector<glm::vec3> out;
    for (const json& m : doc["meshes"])
        for (const json& primitive : m["primitives"]) {
            const std::vector<glm::vec3> values = readVec3(doc, bin, primitive, name);
            for (uint32_t i : readIndices(doc, bin, primitive))
                out.push_back(values.at(i));
        }
    return out;
}

// The same from the mesh: triangles by input face (one object here).
std::vector<glm::vec3> meshCorners(const LitMesh& mesh, const std::vector<glm::vec3>& values)
{
    std::vector<size_t> order(mesh.triangleCount());
    std::iota(order.begin(), order.end(), size_t{0});
    std::stable_sort(order.begin(), order.end(),
                     [&](size_t a, size_t b) { return mesh.triangleFace[a] < mesh.triangleFace[b]; });
    std::vector<glm::vec3> out;
    for (size_t t : order)
        for (size_t k = 0; k < 3; ++k)
            out.push_back(values[mesh.indices[3 * t + k]]);
    return out;
}

// Everything a reader relies on, for either container.
void expectMatchesMesh(const json& doc, const std::string& bin, const LitMesh& mesh, const DisplayColours& c)
{
    EXPECT_EQ(doc["asset"]["version"], "2.0");
    EXPECT_EQ(doc["asset"]["generator"], "Regio");
    ASSERT_EQ(doc["buffers"].size(), 1u);
    EXPECT_EQ(doc["buffers"][0]["byteLength"].get<size_t>(), bin.size());
    for (const json& view : doc["bufferViews"]) {
        EXPECT_EQ(view["byteOffset"].get<size_t>() % 4, 0u) << "buffer views start 4-byte aligned";
        EXPECT_LE(view["byteOffset"].get<size_t>() + view["byteLength"].get<size_t>(), bin.size());
    }
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
    size_t primitives = 0;
    for (const json& m : doc["meshes"])
        for (const json& primitive : m["primitives"]) {
            ++primitives;
            const json& attributes = primitive["attributes"];
            const size_t count = doc["accessors"][attributes["POSITION"].get<size_t>()]["count"].get<size_t>();
            for (const char* name : {"NORMAL", "COLOR_0", "_RADIOSITY"})
                EXPECT_EQ(doc["accessors"][attributes[name].get<size_t>()]["count"].get<size_t>(), count) << name;
            EXPECT_EQ(primitive["mode"], 4);
            const json& position = doc["accessors"][attributes["POSITION"].get<size_t>()];
            for (size_t k = 0; k < 3; ++k) {
                lo[glm::length_t(k)] = std::min(lo[glm::length_t(k)], position["min"][k].get<float>());
                hi[glm::length_t(k)] = std::max(hi[glm::length_t(k)], position["max"][k].get<float>());
            }
            EXPECT_TRUE(primitive["extras"].contains("face")) << "a primitive per input face, named";
        }
    std::set<int32_t> faces(mesh.triangleFace.begin(), mesh.triangleFace.end());
    EXPECT_EQ(primitives, faces.size()) << "one primitive per input face";
    const LitBounds bounds = litMeshBounds(mesh);
    EXPECT_EQ(lo, bounds.min);
    EXPECT_EQ(hi, bounds.max);
    EXPECT_EQ(readCorners(doc, bin, "POSITION"), meshCorners(mesh, mesh.positions));
    EXPECT_EQ(readCorners(doc, bin, "NORMAL"), meshCorners(mesh, mesh.normals));
    EXPECT_EQ(readCorners(doc, bin, "COLOR_0"), meshCorners(mesh, c.linear)) << "linear, tone-mapped colours";
    EXPECT_EQ(readCorners(doc, bin, "_RADIOSITY"), meshCorners(mesh, mesh.radiosity)) << "the raw solution";
    EXPECT_EQ(doc["materials"][0]["extensions"].count("KHR_materials_unlit"), 1u);
    EXPECT_EQ(doc["extensionsUsed"][0], "KHR_materials_unlit");
}

} // namespace

TEST(GltfExport, AGltfFileAndItsBufferHoldTheMesh)
{
    const auto folder = freshOutputFolder();
    const LitMesh mesh = sampleRoom();
    const DisplayColours c = colours(mesh);
    const std::string path = (folder / "room.gltf").string();
    ASSERT_TRUE(writeGltf(path, mesh, c, GltfContainer::Separate));

    const json doc = json::parse(readBytes(path));
    EXPECT_EQ(doc["buffers"][0]["uri"], "room.bin");
    EXPECT_EQ(gltfBufferPath(path), (folder / "room.bin").string());
    const std::string bin = readBytes(folder / "room.bin");
    expectMatchesMesh(doc, bin, mesh, c);
}

TEST(GltfExport, AGlbFileHoldsJsonAndBinaryChunks)
{
    const auto folder = freshOutputFolder();
    const LitMesh mesh = sampleRoom();
    const DisplayColours c = colours(mesh);
    const auto path = folder / "room.glb";
    ASSERT_TRUE(writeGltf(path.string(), mesh, c, GltfContainer::Binary));
    EXPECT_FALSE(std::filesystem::exists(folder / "room.bin")) << "one self-contained file";

    const std::string bytes = readBytes(path);
    ASSERT_GE(bytes.size(), 28u);
    EXPECT_EQ(bytes.substr(0, 4), "glTF");
    EXPECT_EQ(u32(bytes, 4), 2u);
    EXPECT_EQ(u32(bytes, 8), bytes.size());
    const uint32_t jsonLength = u32(bytes, 12);
    EXPECT_EQ(bytes.substr(16, 4), "JSON");
    EXPECT_EQ(jsonLength % 4, 0u);
    const json doc = json::parse(bytes.substr(20, jsonLength));
    EXPECT_FALSE(doc["buffers"][0].contains("uri"));
    const size_t binHeader = 20 + jsonLength;
    const uint32_t binLength = u32(bytes, binHeader);
    EXPECT_EQ(bytes.substr(binHeader + 4, 4), std::string("BIN\0", 4));
    EXPECT_EQ(binHeader + 8 + binLength, bytes.size());
    expectMatchesMesh(doc, bytes.substr(binHeader + 8, doc["buffers"][0]["byteLength"].get<size_t>()), mesh, c);
}

TEST(GltfExport, ExposureScalesTheVertexColours)
{
    const auto folder = freshOutputFolder();
    const LitMesh mesh = sampleRoom();
    ASSERT_TRUE(writeGltf((folder / "base.glb").string(), mesh, colours(mesh, 0.0), GltfContainer::Binary));
    ASSERT_TRUE(writeGltf((folder / "dark.glb").string(), mesh, colours(mesh, -1.0), GltfContainer::Binary));
    auto colour0 = [&](const std::string& name) {
        const std::string bytes = readBytes(folder / name);
        const uint32_t jsonLength = u32(bytes, 12);
        const json doc = json::parse(bytes.substr(20, jsonLength));
        return readCorners(doc, bytes.substr(28 + jsonLength), "COLOR_0");
    };
    const auto base = colour0("base.glb");
    const auto dark = colour0("dark.glb");
    ASSERT_EQ(base.size(), dark.size());
    for (size_t v = 0; v < base.size(); ++v) {
        if (base[v].x < 1.0f) { // unclipped values halve with one stop less
            EXPECT_FLOAT_EQ(dark[v].x, 0.5f * base[v].x);
        }
    }
}

TEST(GltfExport, LargeMeshesUse32BitIndices)
{
    const auto folder = freshOutputFolder();
    LitMesh mesh;
    for (int i = 0; i < 22000; ++i) { // 66 000 vertices: past 16-bit indices
        const float x = static_cast<float>(i % 200), y = static_cast<float>(i / 200);
        regio::test::addTriangle(mesh, {x, y, 0}, {x + 1, y, 0}, {x, y + 1, 0}, glm::vec3(1.0f), "plane");
    }
    const DisplayColours c = colours(mesh);
    const std::string path = (folder / "big.gltf").string();
    ASSERT_TRUE(writeGltf(path, mesh, c, GltfContainer::Separate));
    const json doc = json::parse(readBytes(path));
    const json& indices = doc["accessors"][doc["meshes"][0]["primitives"][0]["indices"].get<size_t>()];
    EXPECT_EQ(indices["componentType"], 5125);
    expectMatchesMesh(doc, readBytes(folder / "big.bin"), mesh, c);
}

TEST(GltfExport, AnEmptySolutionGivesAValidEmptyScene)
{
    const auto folder = freshOutputFolder();
    const std::string path = (folder / "empty.gltf").string();
    ASSERT_TRUE(writeGltf(path, LitMesh{}, DisplayColours{}, GltfContainer::Separate));
    const json doc = json::parse(readBytes(path));
    EXPECT_EQ(doc["asset"]["version"], "2.0");
    EXPECT_FALSE(doc.contains("meshes"));
    EXPECT_FALSE(doc.contains("buffers"));
    EXPECT_EQ(doc["scenes"].size(), 1u);
    EXPECT_FALSE(std::filesystem::exists(folder / "empty.bin"));
}

TEST(GltfExport, ABufferNameWithSpacesIsAValidUri)
{
    const auto folder = freshOutputFolder();
    const LitMesh mesh = sampleRoom();
    const std::string path = (folder / "my room.gltf").string();
    ASSERT_TRUE(writeGltf(path, mesh, colours(mesh), GltfContainer::Separate));
    const json doc = json::parse(readBytes(path));
    EXPECT_EQ(doc["buffers"][0]["uri"], "my%20room.bin");
    EXPECT_TRUE(std::filesystem::exists(folder / "my room.bin"));
}

TEST(GltfExport, AnUnwritablePathIsNamedInTheError)
{
    const auto folder = freshOutputFolder();
    const LitMesh mesh = sampleRoom();
    const std::string path = (folder / "missing-folder" / "room.glb").string();
    const auto error = writeGltf(path, mesh, colours(mesh), GltfContainer::Binary);
    ASSERT_FALSE(error.ok());
    EXPECT_NE(error.error().message.find(path), std::string::npos) << error.error().message;
    EXPECT_TRUE(std::filesystem::is_empty(folder)) << "no temporary file is left behind";
}

TEST(GltfExport, AnInconsistentMeshIsRefusedWithoutWritingAnything)
{
    const auto folder = freshOutputFolder();
    LitMesh mesh = sampleRoom();
    const DisplayColours c = colours(mesh);
    mesh.indices.back() = 12345;
    const std::string path = (folder / "broken.gltf").string();
    const auto error = writeGltf(path, mesh, c, GltfContainer::Separate);
    ASSERT_FALSE(error.ok());
    EXPECT_NE(error.error().message.find(path), std::string::npos);
    EXPECT_TRUE(std::filesystem::is_empty(folder));
}

TEST(GltfExport, RewritingReplacesThePreviousFileWhole)
{
    const auto folder = freshOutputFolder();
    const std::string path = (folder / "room.glb").string();
    LitMesh big = sampleRoom();
    ASSERT_TRUE(writeGltf(path, big, colours(big), GltfContainer::Binary));
    LitMesh small;
    regio::test::addTriangle(small, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, glm::vec3(1.0f), "one");
    ASSERT_TRUE(writeGltf(path, small, colours(small), GltfContainer::Binary));
    const std::string bytes = readBytes(path);
    EXPECT_EQ(u32(bytes, 8), bytes.size());
    size_t files = 0;
    for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(folder))
        ++files;
    EXPECT_EQ(files, 1u);
}

TEST(GltfExport, EveryObjectIsANodeAndEveryFaceAPrimitiveWithItsSceneMaterial)
{
    const auto folder = freshOutputFolder();
    const PreparedScene scene = regio::test::prepared(regio::test::boxUnderLamp());
    const LitMesh mesh = smoothLitMesh(scene, std::vector<regio::model::Rgb>(scene.elements.size(), {1.0, 1.0, 1.0}));
    const DisplayColours c = colours(mesh);
    const std::string path = (folder / "box.gltf").string();
    ASSERT_TRUE(writeGltf(path, mesh, c, GltfContainer::Separate));
    const json doc = json::parse(readBytes(path));
    const std::string bin = readBytes(folder / "box.bin");

    std::vector<std::string> nodes;
    for (const json& node : doc["nodes"])
        nodes.push_back(node["name"]);
    EXPECT_EQ(nodes, (std::vector<std::string>{"floor", "box", "lamp"}));
    ASSERT_EQ(doc["meshes"][1]["primitives"].size(), 6u) << "the box's six faces";
    EXPECT_EQ(doc["meshes"][1]["primitives"][0]["extras"]["face"], mesh.faceIds[1]);

    ASSERT_EQ(doc["materials"].size(), 2u);
    const json& grey = doc["materials"][0];
    EXPECT_EQ(grey["name"], "grey");
    EXPECT_EQ(grey["extras"]["regio"]["reflectance"], json::array({0.5, 0.5, 0.5}));
    EXPECT_EQ(grey["pbrMetallicRoughness"]["baseColorFactor"], json::array({1.0, 1.0, 1.0, 1.0}))
        << "unlit: the vertex colours are the light";
    const json& lamp = doc["materials"][1];
    EXPECT_EQ(lamp["emissiveFactor"], json::array({1.0, 1.0, 1.0}));
    EXPECT_EQ(lamp["extensions"]["KHR_materials_emissive_strength"]["emissiveStrength"], 40.0);
    EXPECT_EQ(lamp["extras"]["regio"]["emission"], json::array({40.0, 40.0, 40.0}));
    EXPECT_EQ(doc["extensionsUsed"], json::array({"KHR_materials_unlit", "KHR_materials_emissive_strength"}));

    // The floor's primitive is whole: the part under the box is filled in.
    const json& floor = doc["meshes"][0]["primitives"][0];
    EXPECT_EQ(floor["material"], 0);
    const std::vector<glm::vec3> p = readVec3(doc, bin, floor, "POSITION");
    const std::vector<uint32_t> indices = readIndices(doc, bin, floor);
    double area = 0.0;
    for (size_t t = 0; t + 2 < indices.size(); t += 3)
        area +=
            0.5 * double(glm::length(glm::cross(p[indices[t + 1]] - p[indices[t]], p[indices[t + 2]] - p[indices[t]])));
    EXPECT_NEAR(area, 9.0, 1e-4);
}
