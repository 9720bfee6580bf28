// glTF 2.0 export: the .gltf + .bin pair and the .glb container, read back
// and checked against the mesh (the Khronos validator runs over the same
// kinds of files in the gltf_validator test).
#include "output/export_gltf.h"

#include "export_test_support.h"
#include "lit_mesh_fixtures.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <bit>
#include <cstring>

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

// The float vec3 accessor `name` of the first primitive, read from `bin`.
std::vector<glm::vec3> readVec3(const json& doc, const std::string& bin, const std::string& name)
{
    const size_t a = doc["meshes"][0]["primitives"][0]["attributes"][name].get<size_t>();
    const json& accessor = doc["accessors"][a];
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

std::vector<uint32_t> readIndices(const json& doc, const std::string& bin)
{
    const json& accessor = doc["accessors"][doc["meshes"][0]["primitives"][0]["indices"].get<size_t>()];
    const json& view = doc["bufferViews"][accessor["bufferView"].get<size_t>()];
    const size_t offset = view["byteOffset"].get<size_t>();
    const int type = accessor["componentType"];
    std::vector<uint32_t> out;
    for (size_t i = 0; i < accessor["count"].get<size_t>(); ++i) {
        if (type == 5123)
            out.push_back(static_cast<unsigned char>(bin[offset + 2 * i]) |
                          (static_cast<unsigned char>(bin[offset + 2 * i + 1]) << 8));
        else
            out.push_back(u32(bin, offset + 4 * i));
    }
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
    const json& attributes = doc["meshes"][0]["primitives"][0]["attributes"];
    for (const char* name : {"POSITION", "NORMAL", "COLOR_0", "_RADIOSITY"})
        EXPECT_EQ(doc["accessors"][attributes[name].get<size_t>()]["count"].get<size_t>(), mesh.vertexCount()) << name;
    EXPECT_EQ(doc["meshes"][0]["primitives"][0]["mode"], 4);

    const json& position = doc["accessors"][attributes["POSITION"].get<size_t>()];
    const LitBounds bounds = litMeshBounds(mesh);
    for (glm::length_t k = 0; k < 3; ++k) {
        EXPECT_EQ(position["min"][size_t(k)].get<float>(), bounds.min[k]);
        EXPECT_EQ(position["max"][size_t(k)].get<float>(), bounds.max[k]);
    }
    EXPECT_EQ(readVec3(doc, bin, "POSITION"), mesh.positions);
    EXPECT_EQ(readVec3(doc, bin, "NORMAL"), mesh.normals);
    EXPECT_EQ(readVec3(doc, bin, "COLOR_0"), c.linear) << "linear, tone-mapped colours";
    EXPECT_EQ(readVec3(doc, bin, "_RADIOSITY"), mesh.radiosity) << "the raw solution";
    EXPECT_EQ(readIndices(doc, bin), mesh.indices);
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
        return readVec3(doc, bytes.substr(28 + jsonLength), "COLOR_0");
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
