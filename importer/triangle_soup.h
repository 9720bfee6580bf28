#pragma once
// What a model file holds once the file format is gone: triangles with their
// material and the mesh (and node) they came from, positions already in the
// scene's frame (metres, y up). The importer's reader fills it; face merging
// and scene building read it. No file format, no library types.
#include "model/types.h"

#include <array>
#include <string>
#include <vector>

namespace regio::importer {

using model::Rgb;
using model::Vec3;

struct SoupMaterial {
    std::string name;  // as the file names it; may be empty or repeat
    Rgb diffuse{0.5};  // the diffuse colour (a texture's mean colour where there is one)
    Rgb emission{0.0}; // emissive colour times its strength
    bool textured = false;

    bool operator==(const SoupMaterial&) const = default;
};

// A mesh as the file has it: the unit within which triangles merge into
// faces (a modelling tool's separate meshes are separate surfaces). Meshes
// of one node (several materials of one object, say) share `object`.
struct SoupMesh {
    std::string name; // the node's name, else the mesh's; may be empty or repeat
    int object = -1;  // the node it belongs to, counted from 0; -1: a node of its own

    bool operator==(const SoupMesh&) const = default;
};

struct SoupTriangle {
    std::array<int, 3> corners{}; // indices into positions, counter-clockwise seen from the front
    int material = 0;             // index into materials
    int mesh = 0;                 // index into meshes

    bool operator==(const SoupTriangle&) const = default;
};

struct TriangleSoup {
    std::vector<Vec3> positions;
    std::vector<SoupTriangle> triangles;
    std::vector<SoupMaterial> materials;
    std::vector<SoupMesh> meshes;

    bool operator==(const TriangleSoup&) const = default;
};

} // namespace regio::importer
