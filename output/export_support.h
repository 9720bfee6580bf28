#pragma once
// What every lit-model writer (glTF, PLY, OBJ) checks and needs alike.
#include "output/lit_mesh.h"
#include "output/tone_map.h"

#include <optional>
#include <string>

namespace regio::output {

// Refuses a malformed mesh, or colours that are not one per vertex, with a
// message that names the file about to be written.
inline model::Check checkWritable(const std::string& path, const LitMesh& mesh, const DisplayColours& colours)
{
    if (model::Check problem = checkLitMesh(mesh); !problem)
        return model::makeError("cannot write " + path + ": " + problem.error().message);
    if (colours.linear.size() != mesh.vertexCount())
        return model::makeError("cannot write " + path + ": the colours do not match the mesh's vertices");
    return model::success();
}

// What a model file holds: the lit mesh with the parts of faces that solids
// cover filled in (withCoveredParts), their vertices black, so that a floor
// under a block comes out whole.
struct FileMesh {
    LitMesh mesh;
    DisplayColours colours;
};

inline FileMesh fileMesh(const LitMesh& mesh, const DisplayColours& colours)
{
    FileMesh out{withCoveredParts(mesh), colours};
    out.colours.linear.resize(out.mesh.vertexCount(), glm::vec3(0.0f));
    return out;
}

// Header comments of PLY and OBJ end at the line: keep descriptions on one.
inline std::string oneLine(std::string s)
{
    for (char& c : s)
        if (c == '\n' || c == '\r')
            c = ' ';
    return s;
}

} // namespace regio::output
