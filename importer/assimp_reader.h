#pragma once
// Model files into a triangle soup through Assimp (Debian's libassimp): OBJ
// with MTL, glTF 2.0, PLY, 3DS, FBX, Collada, STL and whatever else the
// library reads. Node transforms are applied, polygons triangulated; points
// and lines are left out (counted); the scale and the up axis bring the
// model into the scene's frame (metres, y up).
#include "importer/triangle_soup.h"
#include "model/result.h"

#include <cstddef>
#include <string>

namespace regio::importer {

enum class UpAxis { Y, Z };

struct ReadOptions {
    double scale = 1.0; // model units to metres
    UpAxis up = UpAxis::Y;
    // importModel reads through readModelFileIsolated (a child process,
    // isolated_read.h) unless this is false: the fuzz harness reads in its
    // own process, where the fuzzer sees Assimp's code.
    bool separateProcess = true;
};

struct ReadCounts {
    std::size_t meshes = 0;
    std::size_t pointsAndLines = 0; // primitives that are not triangles, left out

    bool operator==(const ReadCounts&) const = default;
};

struct ReadModel {
    TriangleSoup soup;
    ReadCounts counts;

    bool operator==(const ReadModel&) const = default;
};

// Refused (with Assimp's reason) when the file cannot be read or holds no
// triangle; textures that cannot be read are warnings (the diffuse colour
// stands in).
model::Result<ReadModel> readModelFile(const std::string& path, const ReadOptions& options = {});

} // namespace regio::importer
