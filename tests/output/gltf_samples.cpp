// The glTF samples for the Khronos validator (gltf_samples.h).
#include "gltf_samples.h"

#include "output/export.h"
#include "output/export_gltf.h"
#include "support/sample_scenes.h"

#include "lit_mesh_fixtures.h"

#include <filesystem>
#include <iostream>

using namespace regio;
using namespace regio::output;
using namespace regio::solver;

namespace {

bool write(const std::filesystem::path& path, const LitMesh& mesh, const DisplaySettings& display = {})
{
    if (model::Check written = writeLitModel(path.string(), mesh, prepareColours(mesh, display).colours); !written) {
        std::cerr << written.error().message << "\n";
        return false;
    }
    return true;
}

LitMesh bigPlane()
{
    LitMesh mesh;
    for (int i = 0; i < 22000; ++i) { // 66 000 vertices: 32-bit indices
        const float x = static_cast<float>(i % 200) * 0.1f, z = static_cast<float>(i / 200) * 0.1f;
        test::addTriangle(mesh, {x, 0, z}, {x, 0, z + 0.1f}, {x + 0.1f, 0, z}, glm::vec3(0.01f * float(i % 100)),
                          "plane");
    }
    return mesh;
}

std::optional<LitMesh> solvedCornellBox()
{
    SolverOptions options;
    options.hemicube = 48;
    options.patchSize = 0.2;
    auto built = Solver::create(test::loadSample("cornell-box"), options);
    if (!built.ok()) {
        std::cerr << test::samplePath("cornell-box").string() << ": the solver refused the sample scene\n";
        return std::nullopt;
    }
    (*built)->step(40);
    return litMeshFromSolution((*built)->snapshot());
}

} // namespace

namespace regio::test {

bool writeGltfSamples(const std::filesystem::path& folder)
{
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);

    const LitMesh room = sampleRoom();
    DisplaySettings falseColour;
    falseColour.colours = ColourMode::FalseColour;
    DisplaySettings srgbBright;
    srgbBright.toneMap.exposure = 2.0;
    srgbBright.toneMap.encoding.transfer = Transfer::Srgb;
    srgbBright.toneMap.clamp = false;

    bool ok = write(folder / "room.gltf", room) && write(folder / "room.glb", room) &&
              write(folder / "room false colour.gltf", room, falseColour) &&
              write(folder / "room-bright.glb", room, srgbBright) && write(folder / "empty.gltf", LitMesh{}) &&
              write(folder / "empty.glb", LitMesh{}) && write(folder / "big.glb", bigPlane());
    const auto cornell = solvedCornellBox();
    ok = ok && cornell && write(folder / "cornell.gltf", *cornell) && write(folder / "cornell.glb", *cornell) &&
         write(folder / "cornell-false-colour.glb", *cornell, falseColour);
    if (ok)
        std::cout << "glTF samples written to " << folder.string() << "\n";
    return ok;
}

} // namespace regio::test
