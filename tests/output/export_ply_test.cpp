// PLY export: binary little endian with display colours (uchar) and the raw
// radiosity (float), read back by a small PLY reader.
#include "output/export_ply.h"

#include "export_test_support.h"
#include "lit_mesh_fixtures.h"

#include <gtest/gtest.h>

#include <bit>
#include <map>
#include <sstream>

using namespace regio::output;
using namespace regio::solver;
using regio::test::freshOutputFolder;
using regio::test::readBytes;
using regio::test::sampleRoom;

namespace {

struct PlyProperty {
    std::string type;
    std::string name;
    std::string countType; // list properties only
};

struct PlyElement {
    std::string name;
    size_t count = 0;
    std::vector<PlyProperty> properties;
};

struct PlyVertex {
    std::map<std::string, double> values;
};

struct PlyFile {
    std::string format;
    std::vector<std::string> comments;
    std::vector<PlyElement> elements;
    std::vector<PlyVertex> vertices;
    std::vector<std::vector<uint32_t>> faces;
};

// A reader for the subset of PLY a writer of triangle meshes uses: binary
// little endian, scalar properties of the common types, one list per face.
PlyFile readPly(const std::string& bytes)
{
    PlyFile ply;
    const size_t end = bytes.find("end_header\n");
    EXPECT_NE(end, std::string::npos);
    std::istringstream header(bytes.substr(0, end));
    std::string line;
    std::getline(header, line);
    EXPECT_EQ(line, "ply");
    while (std::getline(header, line)) {
        std::istringstream words(line);
        std::string keyword;
        words >> keyword;
        if (keyword == "format") {
            std::string version;
            words >> ply.format >> version;
            EXPECT_EQ(version, "1.0");
        } else if (keyword == "comment") {
            ply.comments.push_back(line.substr(8));
        } else if (keyword == "element") {
            PlyElement e;
            words >> e.name >> e.count;
            ply.elements.push_back(e);
        } else if (keyword == "property") {
            PlyProperty p;
            words >> p.type;
            if (p.type == "list")
                words >> p.countType >> p.type;
            words >> p.name;
            ply.elements.back().properties.push_back(p);
        }
    }
    size_t at = end + std::string("end_header\n").size();
    auto scalar = [&](const std::string& type) -> double {
        auto u = [&](int n) {
            uint64_t v = 0;
            for (int i = n - 1; i >= 0; --i)
                v = (v << 8) | static_cast<unsigned char>(bytes.at(at + static_cast<size_t>(i)));
            at += static_cast<size_t>(n);
            return v;
        };
        if (type == "uchar" || type == "uint8")
            return static_cast<double>(u(1));
        if (type == "uint" || type == "uint32")
            return static_cast<double>(u(4));
        if (type == "int" || type == "int32")
            return static_cast<double>(static_cast<int32_t>(u(4)));
        if (type == "float" || type == "float32")
            return std::bit_cast<float>(static_cast<uint32_t>(u(4)));
        ADD_FAILURE() << "unexpected type " << type;
        return 0.0;
    };
    for (const PlyElement& e : ply.elements) {
        for (size_t i = 0; i < e.count; ++i) {
            if (e.name == "vertex") {
                PlyVertex v;
                for (const PlyProperty& p : e.properties)
                    v.values[p.name] = scalar(p.type);
                ply.vertices.push_back(v);
            } else {
                for (const PlyProperty& p : e.properties) {
                    EXPECT_FALSE(p.countType.empty()) << "face properties are lists";
                    const size_t n = static_cast<size_t>(scalar(p.countType));
                    std::vector<uint32_t> face;
                    for (size_t k = 0; k < n; ++k)
                        face.push_back(static_cast<uint32_t>(scalar(p.type)));
                    ply.faces.push_back(face);
                }
            }
        }
    }
    EXPECT_EQ(at, bytes.size()) << "no bytes after the last element";
    return ply;
}

DisplayColours colours(const LitMesh& mesh)
{
    ToneMapSettings s;
    s.whiteReference = 6.0;
    return toneMappedColours(mesh, ToneMap::forMesh(s, mesh));
}

} // namespace

TEST(PlyExport, ReadsBackWithTheSameVerticesColoursAndRadiosity)
{
    const auto folder = freshOutputFolder();
    const LitMesh mesh = sampleRoom();
    const DisplayColours c = colours(mesh);
    const auto path = folder / "room.ply";
    ASSERT_TRUE(writePly(path.string(), mesh, c));

    const PlyFile ply = readPly(readBytes(path));
    EXPECT_EQ(ply.format, "binary_little_endian");
    ASSERT_EQ(ply.elements.size(), 2u);
    EXPECT_EQ(ply.elements[0].name, "vertex");
    EXPECT_EQ(ply.elements[1].name, "face");
    ASSERT_EQ(ply.vertices.size(), mesh.vertexCount());
    for (size_t v = 0; v < mesh.vertexCount(); ++v) {
        const auto& p = ply.vertices[v].values;
        EXPECT_FLOAT_EQ(static_cast<float>(p.at("x")), mesh.positions[v].x);
        EXPECT_FLOAT_EQ(static_cast<float>(p.at("y")), mesh.positions[v].y);
        EXPECT_FLOAT_EQ(static_cast<float>(p.at("z")), mesh.positions[v].z);
        EXPECT_FLOAT_EQ(static_cast<float>(p.at("ny")), mesh.normals[v].y);
        const auto bytes = toBytes(c.encoded(v));
        EXPECT_EQ(p.at("red"), bytes[0]);
        EXPECT_EQ(p.at("green"), bytes[1]);
        EXPECT_EQ(p.at("blue"), bytes[2]);
        EXPECT_FLOAT_EQ(static_cast<float>(p.at("radiosity_r")), mesh.radiosity[v].x);
        EXPECT_FLOAT_EQ(static_cast<float>(p.at("radiosity_g")), mesh.radiosity[v].y);
        EXPECT_FLOAT_EQ(static_cast<float>(p.at("radiosity_b")), mesh.radiosity[v].z);
    }
    ASSERT_EQ(ply.faces.size(), mesh.triangleCount());
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        ASSERT_EQ(ply.faces[t].size(), 3u);
        for (size_t k = 0; k < 3; ++k)
            EXPECT_EQ(ply.faces[t][k], mesh.indices[3 * t + k]);
    }
}

TEST(PlyExport, ColoursAreTheEncodedDisplayValuesAsBytes)
{
    const auto folder = freshOutputFolder();
    LitMesh mesh;
    regio::test::addTriangle(mesh, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {6.0f, 1.5f, 0.0f}, "tri");
    const auto path = folder / "tri.ply";
    ASSERT_TRUE(writePly(path.string(), mesh, colours(mesh)));
    const PlyFile ply = readPly(readBytes(path));
    ASSERT_EQ(ply.vertices.size(), 3u);
    // White at 6 W/m^2; a quarter of it, gamma 2.2 encoded, is 0.25^(1/2.2) = 0.5325.
    EXPECT_EQ(ply.vertices[0].values.at("red"), 255);
    EXPECT_EQ(ply.vertices[0].values.at("green"), 136);
    EXPECT_EQ(ply.vertices[0].values.at("blue"), 0);
}

TEST(PlyExport, TheHeaderSaysHowTheColoursWereMade)
{
    const auto folder = freshOutputFolder();
    const LitMesh mesh = sampleRoom();
    const auto path = folder / "room.ply";
    ASSERT_TRUE(writePly(path.string(), mesh, colours(mesh)));
    const PlyFile ply = readPly(readBytes(path));
    bool described = false;
    for (const std::string& c : ply.comments)
        described = described || c.find("exposure 0 stops, white 6 W/m^2") != std::string::npos;
    EXPECT_TRUE(described);
}

TEST(PlyExport, AnUnwritablePathIsNamedInTheError)
{
    const auto folder = freshOutputFolder();
    const LitMesh mesh = sampleRoom();
    const std::string path = (folder / "no" / "room.ply").string();
    const auto error = writePly(path, mesh, colours(mesh));
    ASSERT_FALSE(error.ok());
    EXPECT_NE(error.error().message.find(path), std::string::npos) << error.error().message;
}
