#include "output/export_gltf.h"
#include "output/export_support.h"

#include "model/io/file_io.h"

#include <glm/common.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <bit>
#include <cctype>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <unordered_map>

namespace regio::output {

namespace {

using nlohmann::json;

// glTF enumerations (glTF 2.0 specification, 5.1 and 3.6).
constexpr int kFloat = 5126;
constexpr int kUnsignedShort = 5123;
constexpr int kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;
constexpr int kTriangles = 4;

constexpr uint32_t kGlbMagic = 0x46546C67;     // "glTF"
constexpr uint32_t kGlbJsonChunk = 0x4E4F534A; // "JSON"
constexpr uint32_t kGlbBinChunk = 0x004E4942;  // "BIN\0"

void appendU32(std::string& out, uint32_t v)
{
    for (int i = 0; i < 4; ++i)
        out.push_back(static_cast<char>((v >> (8 * i)) & 0xFF));
}

void appendU16(std::string& out, uint16_t v)
{
    out.push_back(static_cast<char>(v & 0xFF));
    out.push_back(static_cast<char>(v >> 8));
}

void appendFloat(std::string& out, float v) { appendU32(out, std::bit_cast<uint32_t>(v)); }

void padTo4(std::string& out, char fill)
{
    while (out.size() % 4 != 0)
        out.push_back(fill);
}

// Percent-encodes everything but RFC 3986 unreserved characters, so a file
// name with spaces or non-ASCII letters is still a valid URI reference.
std::string uriEncode(const std::string& name)
{
    static const char* hex = "0123456789ABCDEF";
    std::string out;
    for (const char byte : name) {
        const auto c = static_cast<unsigned char>(byte);
        if (std::isalnum(c) != 0 || c == '-' || c == '_' || c == '.' || c == '~') {
            out.push_back(byte);
        } else {
            out.push_back('%');
            out.push_back(hex[c >> 4]);
            out.push_back(hex[c & 0xF]);
        }
    }
    return out;
}

struct GltfParts {
    json document;
    std::string bin;
};

// glTF material of a scene material: an unlit white base (the vertex colours
// are the baked light) with the physical values kept for Regio's importer in
// extras, and the emission as glTF says it (a factor up to 1 times a
// strength) for tools that look for lights.
json materialJson(const LitMaterial& m)
{
    json material = {{"name", m.id.empty() ? std::string("radiosity (unlit vertex colours)") : m.id},
                     {"pbrMetallicRoughness",
                      {{"baseColorFactor", {1.0, 1.0, 1.0, 1.0}}, {"metallicFactor", 0.0}, {"roughnessFactor", 1.0}}},
                     {"extensions", {{"KHR_materials_unlit", json::object()}}},
                     {"extras",
                      {{"regio",
                        {{"reflectance", {m.reflectance.x, m.reflectance.y, m.reflectance.z}},
                         {"emission", {m.emission.x, m.emission.y, m.emission.z}}}}}}};
    const float peak = std::max({m.emission.x, m.emission.y, m.emission.z});
    if (peak > 0.0f) {
        const glm::vec3 factor = m.emission / std::max(peak, 1.0f);
        material["emissiveFactor"] = {factor.x, factor.y, factor.z};
        if (peak > 1.0f)
            material["extensions"]["KHR_materials_emissive_strength"] = {{"emissiveStrength", peak}};
    }
    return material;
}

// Builds the JSON and the binary buffer. `bufferUri` empty = GLB (the buffer
// is the file's BIN chunk). One node and mesh per object of the scene, one
// primitive per input face with the face's material and vertices of its own
// (readers such as Assimp copy a primitive's whole accessors, so shared ones
// would multiply), so that a reader sees the faces apart.
GltfParts buildGltf(const LitMesh& mesh, const DisplayColours& colours, const std::string& bufferUri)
{
    GltfParts parts;
    json& doc = parts.document;
    doc["asset"] = {{"version", "2.0"},
                    {"generator", "Regio"},
                    {"extras", {{"colours", colours.description}, {"radiosityUnit", "W/m^2"}}}};
    doc["scene"] = 0;
    if (mesh.empty()) {
        // Nothing to draw: a valid file with an empty scene.
        doc["scenes"] = json::array({json::object({{"name", "radiosity solution"}})});
        return parts;
    }

    json bufferViews = json::array();
    json accessors = json::array();
    std::string& bin = parts.bin;

    auto addVec3 = [&](const std::vector<uint32_t>& vertices, const std::vector<glm::vec3>& values, bool withBounds,
                       auto transform) {
        const size_t offset = bin.size();
        glm::vec3 lo(std::numeric_limits<float>::max());
        glm::vec3 hi(std::numeric_limits<float>::lowest());
        for (uint32_t i : vertices) {
            const glm::vec3 v = transform(values[i]);
            appendFloat(bin, v.x);
            appendFloat(bin, v.y);
            appendFloat(bin, v.z);
            lo = glm::min(lo, v);
            hi = glm::max(hi, v);
        }
        bufferViews.push_back(
            {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bin.size() - offset}, {"target", kArrayBuffer}});
        json accessor = {{"bufferView", bufferViews.size() - 1},
                         {"componentType", kFloat},
                         {"count", vertices.size()},
                         {"type", "VEC3"}};
        if (withBounds) {
            accessor["min"] = {lo.x, lo.y, lo.z};
            accessor["max"] = {hi.x, hi.y, hi.z};
        }
        accessors.push_back(std::move(accessor));
        return accessors.size() - 1;
    };
    auto same = [](const glm::vec3& v) { return v; };
    // COLOR_0 must stay within [0,1] (unclamped tone mapping is for HDR
    // displays, not for glTF vertex colours).
    auto unit = [](const glm::vec3& v) { return glm::clamp(v, glm::vec3(0.0f), glm::vec3(1.0f)); };

    // One primitive: the triangles given (indices into mesh.indices / 3)
    // with their vertices renumbered from 0.
    auto addPrimitive = [&](const std::vector<size_t>& triangles, int material) {
        std::vector<uint32_t> vertices;
        std::unordered_map<uint32_t, uint32_t> local;
        std::vector<uint32_t> indices;
        for (size_t t : triangles) {
            for (size_t k = 0; k < 3; ++k) {
                const uint32_t v = mesh.indices[3 * t + k];
                auto [it, added] = local.try_emplace(v, static_cast<uint32_t>(vertices.size()));
                if (added)
                    vertices.push_back(v);
                indices.push_back(it->second);
            }
        }
        const size_t position = addVec3(vertices, mesh.positions, true, same);
        const size_t normal = addVec3(vertices, mesh.normals, false, same);
        const size_t colour = addVec3(vertices, colours.linear, false, unit);
        const size_t radiosity = addVec3(vertices, mesh.radiosity, false, same);
        // Indices: 16-bit when every index fits below the primitive-restart value.
        const bool shortIndices = vertices.size() <= 0xFFFF;
        const size_t indexOffset = bin.size();
        for (uint32_t i : indices) {
            if (shortIndices)
                appendU16(bin, static_cast<uint16_t>(i));
            else
                appendU32(bin, i);
        }
        const size_t indexLength = bin.size() - indexOffset;
        padTo4(bin, '\0');
        bufferViews.push_back(
            {{"buffer", 0}, {"byteOffset", indexOffset}, {"byteLength", indexLength}, {"target", kElementArrayBuffer}});
        accessors.push_back({{"bufferView", bufferViews.size() - 1},
                             {"componentType", shortIndices ? kUnsignedShort : kUnsignedInt},
                             {"count", indices.size()},
                             {"type", "SCALAR"}});
        return json{{"attributes",
                     {{"POSITION", position}, {"NORMAL", normal}, {"COLOR_0", colour}, {"_RADIOSITY", radiosity}}},
                    {"indices", accessors.size() - 1},
                    {"material", material},
                    {"mode", kTriangles}};
    };

    // Triangles by face, faces by object (in scene order).
    std::vector<std::vector<size_t>> byFace(mesh.faceIds.size());
    for (size_t t = 0; t < mesh.triangleCount(); ++t)
        byFace[static_cast<size_t>(mesh.triangleFace[t])].push_back(t);
    const bool described = !mesh.faceObjects.empty() && !mesh.faceMaterials.empty();
    std::vector<std::string> objects; // in order of first appearance
    std::vector<std::vector<size_t>> facesOf;
    std::unordered_map<std::string, size_t> objectIndex;
    for (size_t f = 0; f < byFace.size(); ++f) {
        if (byFace[f].empty())
            continue;
        const std::string object = described ? mesh.faceObjects[f] : std::string("radiosity solution");
        auto [it, added] = objectIndex.try_emplace(object, objects.size());
        if (added) {
            objects.push_back(object);
            facesOf.emplace_back();
        }
        facesOf[it->second].push_back(f);
    }
    json meshes = json::array();
    json nodes = json::array();
    json sceneNodes = json::array();
    for (size_t o = 0; o < objects.size(); ++o) {
        json primitives = json::array();
        for (size_t f : facesOf[o]) {
            json primitive = addPrimitive(byFace[f], described ? mesh.faceMaterials[f] : 0);
            primitive["extras"] = {{"face", mesh.faceIds[f]}};
            primitives.push_back(std::move(primitive));
        }
        meshes.push_back({{"name", objects[o]}, {"primitives", std::move(primitives)}});
        nodes.push_back({{"name", objects[o]}, {"mesh", o}});
        sceneNodes.push_back(o);
    }

    json buffer = {{"byteLength", bin.size()}};
    if (!bufferUri.empty())
        buffer["uri"] = bufferUri;
    doc["buffers"] = json::array({buffer});
    doc["bufferViews"] = std::move(bufferViews);
    doc["accessors"] = std::move(accessors);
    json materials = json::array();
    bool strength = false;
    if (described) {
        for (const LitMaterial& m : mesh.materials) {
            materials.push_back(materialJson(m));
            strength = strength || materials.back()["extensions"].contains("KHR_materials_emissive_strength");
        }
    } else {
        materials.push_back(materialJson(LitMaterial{}));
        materials.back().erase("extras");
    }
    doc["materials"] = std::move(materials);
    doc["extensionsUsed"] = json::array({"KHR_materials_unlit"});
    if (strength)
        doc["extensionsUsed"].push_back("KHR_materials_emissive_strength");
    doc["meshes"] = std::move(meshes);
    doc["nodes"] = std::move(nodes);
    doc["scenes"] = json::array({{{"name", "radiosity solution"}, {"nodes", std::move(sceneNodes)}}});
    return parts;
}

std::string glb(const GltfParts& parts)
{
    std::string jsonChunk = parts.document.dump();
    padTo4(jsonChunk, ' ');
    std::string binChunk = parts.bin;
    padTo4(binChunk, '\0');
    const bool hasBin = !binChunk.empty();
    const size_t total = 12 + 8 + jsonChunk.size() + (hasBin ? 8 + binChunk.size() : 0);

    std::string out;
    out.reserve(total);
    appendU32(out, kGlbMagic);
    appendU32(out, 2);
    appendU32(out, static_cast<uint32_t>(total));
    appendU32(out, static_cast<uint32_t>(jsonChunk.size()));
    appendU32(out, kGlbJsonChunk);
    out += jsonChunk;
    if (hasBin) {
        appendU32(out, static_cast<uint32_t>(binChunk.size()));
        appendU32(out, kGlbBinChunk);
        out += binChunk;
    }
    return out;
}

} // namespace

std::string gltfBufferPath(const std::string& gltfPath)
{
    std::filesystem::path p(gltfPath);
    p.replace_extension(".bin");
    return p.string();
}

model::Check writeGltf(const std::string& path, const LitMesh& mesh, const DisplayColours& colours,
                       GltfContainer container)
{
    if (model::Check checked = checkWritable(path, mesh, colours); !checked)
        return checked;

    const FileMesh file = fileMesh(mesh, colours);
    if (container == GltfContainer::Binary) {
        const GltfParts parts = buildGltf(file.mesh, file.colours, "");
        const std::string bytes = glb(parts);
        if (bytes.size() > std::numeric_limits<uint32_t>::max())
            return model::makeError("cannot write " + path +
                                    ": the model is larger than the 4 GiB a .glb file can hold");
        return model::writeFileAtomically(path, bytes);
    }

    const std::string binPath = gltfBufferPath(path);
    const std::string binName = std::filesystem::path(binPath).filename().string();
    const GltfParts parts = buildGltf(file.mesh, file.colours, uriEncode(binName));
    if (!parts.bin.empty()) {
        if (model::Check written = model::writeFileAtomically(binPath, parts.bin); !written)
            return written;
    }
    return model::writeFileAtomically(path, parts.document.dump(2) + "\n");
}

} // namespace regio::output
