#include "importer/assimp_reader.h"

#include "importer/polygon_triangulation.h"

#include "model/limits.h"

#include "model/io/file_io.h"

#include <assimp/Importer.hpp>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <stb/stb_image.h>

#include <nlohmann/json.hpp>

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>

namespace regio::importer {

namespace {

Rgb rgbOf(const aiColor4D& c) { return {double(c.r), double(c.g), double(c.b)}; }

// The mean colour of the texture `name` (a material's diffuse or base
// colour texture), from the file beside the model or the one embedded in
// it; false when stb cannot read it.
bool textureMean(const aiScene& scene, const aiString& name, const std::string& modelPath, Rgb& mean)
{
    int width = 0, height = 0, channels = 0;
    stbi_uc* pixels = nullptr;
    if (const aiTexture* embedded = scene.GetEmbeddedTexture(name.C_Str())) {
        if (embedded->mHeight != 0)
            return false; // raw texels: rare, left to the diffuse colour
        pixels = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(embedded->pcData), int(embedded->mWidth),
                                       &width, &height, &channels, 3);
    } else {
        const std::filesystem::path file = std::filesystem::path(modelPath).parent_path() / name.C_Str();
        pixels = stbi_load(file.string().c_str(), &width, &height, &channels, 3);
    }
    if (pixels == nullptr)
        return false;
    // Texels are sRGB: the mean of the linear values is the reflectance.
    const auto linear = [](stbi_uc v) {
        const double c = v / 255.0;
        return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
    };
    Rgb sum{0.0};
    const auto count = std::size_t(width) * std::size_t(height);
    for (std::size_t i = 0; i < count; ++i)
        sum += Rgb{linear(pixels[3 * i]), linear(pixels[3 * i + 1]), linear(pixels[3 * i + 2])};
    stbi_image_free(pixels);
    if (count == 0)
        return false;
    mean = sum / double(count);
    return true;
}

SoupMaterial materialOf(const aiScene& scene, const aiMaterial& material, const std::string& modelPath,
                        model::Diagnostics& warnings)
{
    SoupMaterial out;
    aiString name;
    if (material.Get(AI_MATKEY_NAME, name) == AI_SUCCESS)
        out.name = name.C_Str();
    aiColor4D colour;
    if (material.Get(AI_MATKEY_BASE_COLOR, colour) == AI_SUCCESS ||
        material.Get(AI_MATKEY_COLOR_DIFFUSE, colour) == AI_SUCCESS)
        out.diffuse = rgbOf(colour);
    if (material.Get(AI_MATKEY_COLOR_EMISSIVE, colour) == AI_SUCCESS) {
        out.emission = rgbOf(colour);
    }
    aiString texture;
    if (material.GetTexture(aiTextureType_BASE_COLOR, 0, &texture) == AI_SUCCESS ||
        material.GetTexture(aiTextureType_DIFFUSE, 0, &texture) == AI_SUCCESS) {
        Rgb mean{0.0};
        if (textureMean(scene, texture, modelPath, mean)) {
            // A texture multiplies the colour factor (glTF) or stands alone (OBJ: Kd is often white).
            out.diffuse *= mean;
            out.textured = true;
        } else {
            warnings.push_back(model::makeWarning("material '" + out.name + "': texture '" +
                                                  std::string(texture.C_Str()) +
                                                  "' could not be read; its diffuse colour is used"));
        }
    }
    return out;
}

// An OFF file's header says how many vertices and faces follow; Assimp
// believes it and reserves that much before reading a line, so a header
// claiming 3.5e12 vertices in a file of 300 bytes eats the machine. Every
// vertex takes at least six bytes ("0 0 0\n"), every face eight.
std::optional<std::string> implausibleOffHeader(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    std::string magic;
    if (!(in >> magic) || (magic != "OFF" && magic != "COFF" && magic != "NOFF" && magic != "CNOFF"))
        return std::nullopt;
    double vertices = 0.0, faces = 0.0;
    if (!(in >> vertices >> faces))
        return std::nullopt; // let the reader say what is wrong
    const auto size = double(std::filesystem::file_size(path));
    if (vertices * 6.0 + faces * 8.0 <= size)
        return std::nullopt;
    return "'" + path + "' claims " + std::to_string(static_cast<long long>(vertices)) + " vertices and " +
           std::to_string(static_cast<long long>(faces)) + " faces in a file of " +
           std::to_string(static_cast<long long>(size)) + " bytes";
}

// Assimp's PLY reader reads past the end of a file that is cut short, or
// whose header never ends, for ever (it seeks at the end of the file in a
// loop), so such files are refused before Assimp sees them: a header must
// end with an end_header line within its first 64 KiB, and an ASCII file
// must hold at least the element lines its header announces.
std::optional<std::string> plyProblem(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    std::string header(64 * 1024, '\0');
    in.read(header.data(), static_cast<std::streamsize>(header.size()));
    header.resize(static_cast<std::size_t>(in.gcount()));
    // Assimp takes a file for PLY by its extension or by "ply" and any
    // white space at its start ("ply   \n" too).
    std::string extension = std::filesystem::path(path).extension().string();
    for (char& c : extension)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    const bool plyMagic =
        header.starts_with("ply") && header.size() > 3 && std::isspace(static_cast<unsigned char>(header[3])) != 0;
    if (extension != ".ply" && !plyMagic)
        return std::nullopt;
    const auto trimmed = [](std::string line) {
        const std::size_t begin = line.find_first_not_of(" \t\r");
        const std::size_t end = line.find_last_not_of(" \t\r");
        return begin == std::string::npos ? std::string() : line.substr(begin, end + 1 - begin);
    };
    std::istringstream lines(header);
    std::string line;
    bool ascii = false;
    bool ended = false;
    std::uint64_t elements = 0;
    std::size_t headerBytes = 0;
    while (std::getline(lines, line)) {
        headerBytes += line.size() + 1;
        const std::string t = trimmed(line);
        if (t == "end_header") {
            ended = true;
            break;
        }
        std::istringstream words(t);
        std::string keyword, name, count;
        words >> keyword;
        if (keyword == "format") {
            words >> name;
            ascii = name == "ascii";
        } else if (keyword == "element") {
            words >> name >> count;
            std::uint64_t n = 0;
            const auto [rest, error] = std::from_chars(count.data(), count.data() + count.size(), n);
            if (error == std::errc() && rest == count.data() + count.size())
                elements = std::min<std::uint64_t>(elements + n, std::uint64_t{1} << 62);
        }
    }
    if (!ended)
        return "'" + path + "' is a PLY file whose header never ends (it has no end_header line)";
    if (!ascii || elements == 0)
        return std::nullopt;
    // One line an element in an ASCII file: count them, as far as needed.
    in.clear();
    in.seekg(static_cast<std::streamoff>(headerBytes));
    std::uint64_t dataLines = 0;
    while (dataLines < elements && std::getline(in, line))
        if (!trimmed(line).empty())
            ++dataLines;
    if (dataLines < elements)
        return "'" + path + "' is a PLY file cut short: its header announces " + std::to_string(elements) +
               " element lines, the file has " + std::to_string(dataLines);
    return std::nullopt;
}

// What a glTF material says that Debian's Assimp (5.2) does not pass on,
// by material name, read from the file's JSON (a .gltf, or the first chunk
// of a .glb):
//   - KHR_materials_emissive_strength: without it an emitter of strength 5
//     would come in five times too dim;
//   - the scene's reflectance and emission that Regio's own glTF export
//     keeps in the material's extras ("regio"), where the glTF colours are
//     those of an unlit display material.
struct GltfMaterialExtras {
    std::optional<double> emissiveStrength;
    std::optional<Rgb> reflectance;
    std::optional<Rgb> emission;
};

std::optional<Rgb> rgbFromJson(const nlohmann::json* value)
{
    if (value == nullptr || !value->is_array() || value->size() != 3)
        return std::nullopt;
    Rgb out{0.0};
    for (std::size_t k = 0; k < 3; ++k) {
        const nlohmann::json& c = (*value)[k];
        if (!c.is_number() || !std::isfinite(c.get<double>()) || c.get<double>() < 0.0)
            return std::nullopt;
        out[glm::length_t(k)] = c.get<double>();
    }
    return out;
}

// The member `key` of an object, or null (a file may put anything anywhere).
const nlohmann::json* member(const nlohmann::json* object, const char* key)
{
    if (object == nullptr || !object->is_object())
        return nullptr;
    const auto it = object->find(key);
    return it == object->end() ? nullptr : &*it;
}

std::map<std::string, GltfMaterialExtras> gltfMaterialExtras(const std::string& path)
{
    std::map<std::string, GltfMaterialExtras> out;
    const std::string ext = std::filesystem::path(path).extension().string();
    if (ext != ".gltf" && ext != ".glb")
        return out;
    auto read = model::readFile(path, model::kMaxSceneFileBytes, "glTF file");
    if (!read)
        return out; // Assimp will say what is wrong with it
    std::string text = std::move(*read);
    if (ext == ".glb") {
        // 12-byte header, then the JSON chunk: length, type "JSON", bytes.
        if (text.size() < 20 || text.compare(16, 4, "JSON") != 0)
            return out;
        std::uint32_t length = 0;
        std::memcpy(&length, text.data() + 12, 4);
        if (length > text.size() - 20)
            return out;
        text = text.substr(20, length);
    }
    const nlohmann::json gltf = nlohmann::json::parse(text, nullptr, false);
    if (!gltf.is_object() || !gltf.contains("materials") || !gltf["materials"].is_array())
        return out;
    for (const nlohmann::json& m : gltf["materials"]) {
        if (!m.is_object())
            continue;
        const std::string name = m.contains("name") && m["name"].is_string() ? m["name"].get<std::string>() : "";
        GltfMaterialExtras extras;
        const nlohmann::json* strength =
            member(member(member(&m, "extensions"), "KHR_materials_emissive_strength"), "emissiveStrength");
        if (strength && strength->is_number() && std::isfinite(strength->get<double>()) &&
            strength->get<double>() >= 0.0)
            extras.emissiveStrength = strength->get<double>();
        const nlohmann::json* regio = member(member(&m, "extras"), "regio");
        extras.reflectance = rgbFromJson(member(regio, "reflectance"));
        extras.emission = rgbFromJson(member(regio, "emission"));
        out[name] = extras;
    }
    return out;
}

// The objects ("o") of an OBJ file, by the groups ("g") under them.
// Assimp's OBJ reader makes every group an object of its own and forgets
// the "o" lines, so a solid written as one group per face (as Regio's OBJ
// export writes it, to keep its faces apart) would come in as six objects
// and no solid. A line scan, no geometry: group name -> object name, and
// each object name to itself (faces before any group).
std::map<std::string, std::string> objGroupObjects(const std::string& path)
{
    std::map<std::string, std::string> out;
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext)
        c = char(std::tolower(static_cast<unsigned char>(c)));
    if (ext != ".obj")
        return out;
    std::ifstream in(path, std::ios::binary);
    std::string line, object;
    const auto rest = [](const std::string& l) {
        const std::size_t begin = l.find_first_not_of(" \t", 1);
        if (begin == std::string::npos)
            return std::string();
        const std::size_t end = l.find_last_not_of(" \t\r");
        return l.substr(begin, end + 1 - begin);
    };
    while (std::getline(in, line)) {
        if (line.size() < 2 || (line[1] != ' ' && line[1] != '\t'))
            continue;
        if (line[0] == 'o') {
            object = rest(line);
            out.emplace(object, object);
        } else if (line[0] == 'g' && !object.empty()) {
            out.emplace(rest(line), object);
        }
    }
    return out;
}

} // namespace

model::Result<ReadModel> readModelFile(const std::string& path, const ReadOptions& options)
{
    if (!std::filesystem::is_regular_file(path))
        return model::makeError("'" + path + "' is not a readable file");
    if (const auto claim = implausibleOffHeader(path))
        return model::makeError(*claim);
    if (const auto broken = plyProblem(path))
        return model::makeError(*broken);
    Assimp::Importer importer;
    // No post-processing beyond the check of Assimp's own output: its
    // triangulation step aborts the process on some broken files (a failed
    // assertion), so polygons are triangulated here (triangulatePolygon),
    // and points and lines are counted and left out face by face.
    const aiScene* scene = importer.ReadFile(path, aiProcess_ValidateDataStructure);
    if (scene == nullptr) {
        // Assimp turns an exception of its readers into this string; a
        // std::bad_alloc is a broken file claiming more than any memory.
        const std::string reason = importer.GetErrorString();
        return model::makeError("'" + path + "' could not be read: " +
                                (reason.find("bad_alloc") != std::string::npos
                                     ? "it asks for more memory than there is (a broken or truncated file)"
                                     : reason));
    }
    if ((scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) != 0)
        return model::makeError("'" + path + "' is incomplete (the reader gave up part way)");

    ReadModel out;
    model::Diagnostics warnings;
    for (unsigned m = 0; scene->mMaterials && m < scene->mNumMaterials; ++m)
        out.soup.materials.push_back(scene->mMaterials[m] ? materialOf(*scene, *scene->mMaterials[m], path, warnings)
                                                          : SoupMaterial{});
    if (out.soup.materials.empty())
        out.soup.materials.push_back({});
    for (const auto& [name, extras] : gltfMaterialExtras(path))
        for (SoupMaterial& m : out.soup.materials) {
            if (m.name != name)
                continue;
            if (extras.emissiveStrength)
                m.emission *= *extras.emissiveStrength;
            if (extras.reflectance)
                m.diffuse = *extras.reflectance;
            if (extras.emission)
                m.emission = *extras.emission;
        }

    const auto frame = [&](const aiVector3D& p) {
        const Vec3 v = Vec3{double(p.x), double(p.y), double(p.z)} * options.scale;
        return options.up == UpAxis::Z ? Vec3{v.x, v.z, -v.y} : v;
    };
    // Depth first through the node tree, every mesh instance with its node's
    // whole transform: a model's object is a node with meshes.
    struct Visit {
        const aiNode* node;
        aiMatrix4x4 transform;
    };
    std::vector<Visit> todo{{scene->mRootNode, scene->mRootNode ? scene->mRootNode->mTransformation : aiMatrix4x4()}};
    int objects = 0; // nodes with meshes so far
    while (!todo.empty()) {
        const Visit visit = todo.back();
        todo.pop_back();
        if (visit.node == nullptr)
            continue;
        // Whatever a reader left dangling is stepped over, never followed.
        for (unsigned c = visit.node->mChildren ? visit.node->mNumChildren : 0; c-- > 0;)
            if (const aiNode* child = visit.node->mChildren[c])
                todo.push_back({child, visit.transform * child->mTransformation});
        bool anyMesh = false;
        for (unsigned k = 0; visit.node->mMeshes && k < visit.node->mNumMeshes; ++k) {
            if (visit.node->mMeshes[k] >= scene->mNumMeshes || scene->mMeshes[visit.node->mMeshes[k]] == nullptr ||
                scene->mMeshes[visit.node->mMeshes[k]]->mVertices == nullptr)
                continue;
            const aiMesh& mesh = *scene->mMeshes[visit.node->mMeshes[k]];
            const std::string nodeName = visit.node->mName.C_Str();
            const int meshIndex = int(out.soup.meshes.size());
            out.soup.meshes.push_back(
                {nodeName.empty() || nodeName == "RootNode" ? mesh.mName.C_Str() : nodeName, objects});
            anyMesh = true;
            ++out.counts.meshes;
            const auto base = int(out.soup.positions.size());
            for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
                const Vec3 p = frame(visit.transform * mesh.mVertices[v]);
                // Scenes keep within model::kMaxCoordinate of the origin; a
                // vertex beyond it (or not a number) is a broken file or
                // another unit, never geometry to weld.
                if (!(std::abs(p.x) <= model::kMaxCoordinate && std::abs(p.y) <= model::kMaxCoordinate &&
                      std::abs(p.z) <= model::kMaxCoordinate)) {
                    char where[160];
                    std::snprintf(where, sizeof where, "(%g, %g, %g)", p.x, p.y, p.z);
                    const bool finite = std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
                    return model::makeError(
                        "'" + path + "': mesh '" + std::string(mesh.mName.C_Str()) + "' has a vertex at " + where +
                        (finite ? " m, beyond " + std::to_string(static_cast<long>(model::kMaxCoordinate)) +
                                      " m from the origin (a model in another unit needs a --scale)"
                                : ", which is not a point"));
                }
                out.soup.positions.push_back(p);
            }
            // A transform that mirrors (negative determinant) turns the winding.
            const bool mirrored = visit.transform.Determinant() < 0.0f;
            std::vector<Vec3> polygon;
            for (unsigned f = 0; mesh.mFaces && f < mesh.mNumFaces; ++f) {
                const aiFace& face = mesh.mFaces[f];
                if (face.mNumIndices < 3 || face.mIndices == nullptr) {
                    ++out.counts.pointsAndLines;
                    continue;
                }
                polygon.clear();
                for (unsigned i = 0; i < face.mNumIndices; ++i) {
                    if (face.mIndices[i] >= mesh.mNumVertices)
                        return model::makeError("'" + path + "': mesh '" + std::string(mesh.mName.C_Str()) +
                                                "' has a face with a vertex index out of range");
                    polygon.push_back(out.soup.positions[std::size_t(base) + face.mIndices[i]]);
                }
                for (const auto& corner : triangulatePolygon(polygon)) {
                    SoupTriangle t;
                    t.corners = {base + int(face.mIndices[corner[0]]),
                                 base + int(face.mIndices[corner[mirrored ? 2 : 1]]),
                                 base + int(face.mIndices[corner[mirrored ? 1 : 2]])};
                    t.material = mesh.mMaterialIndex < out.soup.materials.size() ? int(mesh.mMaterialIndex) : 0;
                    t.mesh = meshIndex;
                    out.soup.triangles.push_back(t);
                }
            }
        }
        if (anyMesh)
            ++objects;
    }
    // An OBJ file's groups back under their "o" objects.
    if (const auto groups = objGroupObjects(path); !groups.empty()) {
        std::map<std::string, int> objectOf;
        for (SoupMesh& mesh : out.soup.meshes) {
            const auto it = groups.find(mesh.name);
            const std::string key = it != groups.end() ? "o " + it->second : "n " + std::to_string(mesh.object);
            mesh.object = objectOf.emplace(key, int(objectOf.size())).first->second;
            if (it != groups.end())
                mesh.name = it->second;
        }
    }
    if (out.soup.triangles.empty())
        return model::makeError("'" + path + "' holds no triangles (" + std::to_string(out.counts.pointsAndLines) +
                                " points or lines, " + std::to_string(out.counts.meshes) + " meshes)");
    return {std::move(out), std::move(warnings)};
}

} // namespace regio::importer
