#include "importer/scene_building.h"

#include "model/edit/edit_support.h"
#include "model/geometry/geometry.h"
#include "model/io/printable.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <map>
#include <numeric>
#include <set>
#include <utility>

namespace regio::importer {

namespace {

int findRoot(std::vector<int>& parent, int i)
{
    while (parent[std::size_t(i)] != i) {
        parent[std::size_t(i)] = parent[std::size_t(parent[std::size_t(i)])];
        i = parent[std::size_t(i)];
    }
    return i;
}

// Closed: every edge runs once each way (two faces, consistent winding).
bool closed(const model::Part& part)
{
    std::map<std::pair<int, int>, int> directed;
    for (const model::Face& f : part.faces)
        for (std::size_t i = 0; i < f.loop.size(); ++i)
            ++directed[{f.loop[i], f.loop[(i + 1) % f.loop.size()]}];
    return std::all_of(directed.begin(), directed.end(), [&](const auto& e) {
        const auto back = directed.find({e.first.second, e.first.first});
        return e.second == 1 && back != directed.end() && back->second == 1;
    });
}

// The volume a closed part encloses (divergence theorem): negative when its
// faces look in.
double signedVolume(const model::Part& part)
{
    double six = 0.0;
    for (const model::Face& face : part.faces)
        for (std::size_t i = 1; i + 1 < face.loop.size(); ++i)
            six += glm::dot(
                part.vertices[std::size_t(face.loop[0])],
                glm::cross(part.vertices[std::size_t(face.loop[i])], part.vertices[std::size_t(face.loop[i + 1])]));
    return six / 6.0;
}

// Faces of one surface wound alike: across an edge two faces share, the edge
// must run opposite ways. Within each edge-connected patch of faces, the
// orientation most of its area has in the file wins. Nothing else turns a
// face: a closed part wound consistently inwards is a room seen from inside
// (the commonest radiosity scene), not a solid inside out. Returns the faces
// turned.
std::size_t orientConsistently(model::Part& part)
{
    const std::size_t n = part.faces.size();
    std::map<std::pair<int, int>, std::vector<std::pair<std::size_t, bool>>>
        edges; // (low, high) -> (face, runs low->high)
    for (std::size_t f = 0; f < n; ++f) {
        const auto& loop = part.faces[f].loop;
        for (std::size_t i = 0; i < loop.size(); ++i) {
            const int a = loop[i], b = loop[(i + 1) % loop.size()];
            edges[{std::min(a, b), std::max(a, b)}].push_back({f, a < b});
        }
    }
    std::vector<std::vector<std::pair<std::size_t, bool>>> neighbours(n); // (face, same direction)
    for (const auto& [edge, uses] : edges)
        if (uses.size() == 2 && uses[0].first != uses[1].first) {
            const bool same = uses[0].second == uses[1].second;
            neighbours[uses[0].first].push_back({uses[1].first, same});
            neighbours[uses[1].first].push_back({uses[0].first, same});
        }
    const auto area = [&](std::size_t f) {
        return model::polygonArea(model::loopPositions(part.vertices, part.faces[f].loop));
    };
    std::vector<int> flip(n, -1);
    for (std::size_t seed = 0; seed < n; ++seed) {
        if (flip[seed] >= 0)
            continue;
        std::vector<std::size_t> patch{seed};
        flip[seed] = 0;
        for (std::size_t k = 0; k < patch.size(); ++k)
            for (const auto& [other, same] : neighbours[patch[k]])
                if (flip[other] < 0) {
                    flip[other] = flip[patch[k]] ^ int(same);
                    patch.push_back(other);
                }
        double turned = 0.0, kept = 0.0;
        for (const std::size_t f : patch)
            (flip[f] ? turned : kept) += area(f);
        if (turned > kept)
            for (const std::size_t f : patch)
                flip[f] ^= 1;
    }
    for (std::size_t f = 0; f < n; ++f)
        if (flip[f])
            std::reverse(part.faces[f].loop.begin(), part.faces[f].loop.end());
    return std::size_t(std::count(flip.begin(), flip.end(), 1));
}

// The faces (indices, ascending) that share an edge with another face
// running the same way: one of each such pair. Empty when the part is wound
// alike.
std::vector<std::size_t> facesAtOdds(const model::Part& part)
{
    std::map<std::pair<int, int>, std::vector<std::size_t>> directed;
    for (std::size_t f = 0; f < part.faces.size(); ++f) {
        const auto& loop = part.faces[f].loop;
        for (std::size_t i = 0; i < loop.size(); ++i)
            directed[{loop[i], loop[(i + 1) % loop.size()]}].push_back(f);
    }
    std::set<std::size_t> odd;
    for (const auto& [edge, faces] : directed)
        if (faces.size() > 1)
            odd.insert(faces.back());
    return {odd.begin(), odd.end()};
}

} // namespace

std::string idFrom(const std::string& name, const std::string& fallback)
{
    std::string id;
    for (const char c : name) {
        const bool keep = std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
        if (keep)
            id += c;
        else if (!id.empty() && id.back() != '-')
            id += '-';
    }
    while (!id.empty() && (id.back() == '-' || id.back() == '.'))
        id.pop_back();
    return id.empty() ? fallback : id;
}

BuiltScene buildScene(const MergedModel& merged, const TriangleSoup& soup)
{
    BuiltScene out;
    // Ids of every kind share one namespace: the second "light" is "light-2".
    const model::Scene none;
    model::edit::IdAllocator ids(none);

    // Materials, in the file's order, those that some face uses.
    std::vector<int> usedMaterial(soup.materials.size(), 0);
    for (const MergedFace& f : merged.faces)
        usedMaterial[std::size_t(f.material)] = 1;
    std::vector<std::string> materialId(soup.materials.size());
    for (std::size_t m = 0; m < soup.materials.size(); ++m) {
        if (!usedMaterial[m])
            continue;
        const SoupMaterial& from = soup.materials[m];
        model::Material material;
        material.id = ids.fresh(idFrom(from.name, "material-" + std::to_string(m + 1)));
        material.name = model::validUtf8(from.name);
        Rgb reflectance = glm::max(from.diffuse, Rgb{0.0});
        const double top = std::max({reflectance.r, reflectance.g, reflectance.b});
        if (top > kMaxImportedReflectance) {
            reflectance *= kMaxImportedReflectance / top;
            out.counts.clampedMaterials.push_back(material.id);
            out.warnings.push_back(model::makeWarning("material '" + material.id + "': diffuse colour " +
                                                      "at or near 1 scaled down to a reflectance of at most 0.95"));
        }
        material.reflectance = reflectance;
        material.emission = glm::max(from.emission, Rgb{0.0});
        if (from.textured)
            out.counts.texturedMaterials.push_back(material.id);
        materialId[m] = material.id;
        out.scene.materials.push_back(std::move(material));
    }
    out.counts.materials = out.scene.materials.size();

    // Faces by object (a node of the file, whatever meshes it has), then by
    // connected piece (below). A mesh of no known node is
    // an object of its own, after the nodes.
    std::map<int, std::vector<std::size_t>> byObject;
    std::map<int, int> meshOfObject; // the first mesh of each, for its name
    for (std::size_t f = 0; f < merged.faces.size(); ++f) {
        const int mesh = merged.faces[f].mesh;
        const int node = soup.meshes[std::size_t(mesh)].object;
        const int object = node >= 0 ? node : int(soup.meshes.size()) + mesh;
        byObject[object].push_back(f);
        meshOfObject.emplace(object, mesh);
    }
    for (const auto& [objectKey, faces] : byObject) {
        const int mesh = meshOfObject.at(objectKey);
        // Connected through edges that exactly two faces share: where more
        // meet (a board standing flush against a shelf's side, two boxes
        // touching along an edge), the solids stay apart, and so do faces
        // that only touch at a corner.
        std::vector<int> parent(faces.size());
        std::iota(parent.begin(), parent.end(), 0);
        std::map<std::pair<int, int>, std::vector<int>> facesOfEdge;
        for (std::size_t k = 0; k < faces.size(); ++k) {
            const auto& loop = merged.faces[faces[k]].loop;
            for (std::size_t i = 0; i < loop.size(); ++i) {
                const int a = loop[i], b = loop[(i + 1) % loop.size()];
                facesOfEdge[{std::min(a, b), std::max(a, b)}].push_back(int(k));
            }
        }
        for (const auto& [edge, users] : facesOfEdge)
            if (users.size() == 2)
                parent[std::size_t(findRoot(parent, users[0]))] = findRoot(parent, users[1]);
        std::map<int, std::vector<std::size_t>> connected; // root -> faces, in file order
        for (std::size_t k = 0; k < faces.size(); ++k)
            connected[findRoot(parent, int(k))].push_back(faces[k]);
        // An edge bounds at most two faces of a part: where a model has
        // three (fins, touching boxes), a face that would be the third goes
        // to the next part of the piece it fits in.
        std::vector<std::vector<std::size_t>> pieces;
        for (const auto& [root, members] : connected) {
            std::vector<std::map<std::pair<int, int>, int>> edgeUses;
            const std::size_t first = pieces.size();
            for (const std::size_t f : members) {
                const auto& loop = merged.faces[f].loop;
                std::vector<std::pair<int, int>> edges;
                for (std::size_t i = 0; i < loop.size(); ++i)
                    edges.push_back({std::min(loop[i], loop[(i + 1) % loop.size()]),
                                     std::max(loop[i], loop[(i + 1) % loop.size()])});
                std::size_t into = 0;
                while (into < edgeUses.size() && std::any_of(edges.begin(), edges.end(), [&](const auto& e) {
                           const auto it = edgeUses[into].find(e);
                           return it != edgeUses[into].end() && it->second >= 2;
                       }))
                    ++into;
                if (into == edgeUses.size()) {
                    edgeUses.emplace_back();
                    pieces.emplace_back();
                }
                for (const auto& e : edges)
                    ++edgeUses[into][e];
                pieces[first + into].push_back(f);
            }
        }

        const std::string meshName = soup.meshes[std::size_t(mesh)].name;
        model::Object object;
        object.id = ids.fresh(idFrom(meshName, "object-" + std::to_string(mesh + 1)));
        object.name = model::validUtf8(meshName);
        // The faces of a piece as a part: vertices and loops, wound alike.
        const auto partOf = [&](const std::vector<std::size_t>& members, std::size_t& turned) {
            model::Part part;
            std::map<int, int> local;
            for (const std::size_t f : members) {
                model::Face face;
                for (const int v : merged.faces[f].loop) {
                    const auto [it, fresh] = local.emplace(v, int(part.vertices.size()));
                    if (fresh)
                        part.vertices.push_back(merged.positions[std::size_t(v)]);
                    face.loop.push_back(it->second);
                }
                part.faces.push_back(std::move(face));
            }
            turned = orientConsistently(part);
            return part;
        };
        // Where no winding makes a piece consistent (a surface that meets
        // itself the wrong way round), the faces still at odds go to a part
        // of their own, and so on until every part can be wound alike.
        std::vector<model::Part> parts;
        std::vector<std::vector<std::size_t>> partFaces;
        for (std::size_t p = 0; p < pieces.size(); ++p) {
            std::vector<std::size_t> members = pieces[p];
            std::size_t turned = 0;
            model::Part part = partOf(members, turned);
            const std::vector<std::size_t> odd = facesAtOdds(part);
            if (!odd.empty() && odd.size() < members.size()) {
                std::vector<std::size_t> kept, moved;
                for (std::size_t k = 0; k < members.size(); ++k)
                    (std::binary_search(odd.begin(), odd.end(), k) ? moved : kept).push_back(members[k]);
                pieces.push_back(moved);
                members = kept;
                part = partOf(members, turned);
            }
            out.counts.turnedFaces += turned;
            parts.push_back(std::move(part));
            partFaces.push_back(std::move(members));
        }
        for (std::size_t p = 0; p < parts.size(); ++p) {
            model::Part& part = parts[p];
            const std::vector<std::size_t>& members = partFaces[p];
            part.id = ids.fresh(parts.size() == 1 ? object.id + ".body" : object.id + ".part" + std::to_string(p + 1));
            // The part's material: the one most of its faces use.
            std::map<int, int> votes;
            for (const std::size_t f : members)
                ++votes[merged.faces[f].material];
            const int common = std::max_element(votes.begin(), votes.end(), [](auto& a, auto& b) {
                                   return a.second < b.second;
                               })->first;
            part.material = materialId[std::size_t(common)];
            for (std::size_t k = 0; k < members.size(); ++k) {
                const MergedFace& from = merged.faces[members[k]];
                part.faces[k].id = ids.fresh(part.id + ".f" + std::to_string(k + 1));
                if (from.material != common)
                    part.faces[k].material = materialId[std::size_t(from.material)];
                const Rgb emission = soup.materials[std::size_t(from.material)].emission;
                if (emission.r > 0.0 || emission.g > 0.0 || emission.b > 0.0)
                    ++out.counts.emittingFaces;
            }
            if (closed(part)) {
                ++out.counts.closedParts;
                if (signedVolume(part) < 0.0)
                    ++out.counts.closedFacingIn;
            }
            object.parts.push_back(std::move(part));
        }
        out.counts.parts += object.parts.size();
        out.scene.objects.push_back(std::move(object));
    }
    out.counts.objects = out.scene.objects.size();
    return out;
}

} // namespace regio::importer
