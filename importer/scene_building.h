#pragma once
// Merged faces into a Regio scene: a mesh (a node of the model) becomes an
// object, each connected piece of it a part (a closed solid or an open
// shell), the materials it uses scene materials. Names are kept where the
// file has them and made unique in the scene's one id namespace ("light",
// "light-2"); what has no name gets a stable one from its place. Faces
// wound against their neighbours are turned (the file's majority wins, and a
// closed solid faces out).
#include "importer/face_merging.h"
#include "model/diagnostic.h"
#include "model/scene.h"

#include <cstddef>
#include <string>
#include <vector>

namespace regio::importer {

// Reflectance at or above 1 would never decay; such a diffuse colour is
// scaled down to this and reported.
inline constexpr double kMaxImportedReflectance = 0.95;

struct BuildCounts {
    std::size_t objects = 0;
    std::size_t parts = 0;
    std::size_t closedParts = 0;    // every edge shared by two faces, winding consistent
    std::size_t closedFacingIn = 0; // of those, the ones whose faces look in (a room seen from inside)
    std::size_t materials = 0;
    std::size_t emittingFaces = 0;
    std::size_t turnedFaces = 0; // wound against their neighbours in the file (or a solid turned inside out)
    std::vector<std::string> clampedMaterials;  // ids whose reflectance was scaled down
    std::vector<std::string> texturedMaterials; // ids whose colour came from a texture's mean
};

struct BuiltScene {
    model::Scene scene;
    BuildCounts counts;
    model::Diagnostics warnings;
};

BuiltScene buildScene(const MergedModel& merged, const TriangleSoup& soup);

// `name` as an id: letters, digits and "_-." kept, anything else a '-';
// `fallback` when nothing is left.
std::string idFrom(const std::string& name, const std::string& fallback);

} // namespace regio::importer
