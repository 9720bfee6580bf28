#pragma once
// The sample scenes of resources/scenes/, which tests of every library load,
// solve or hand to regio-solve: where they are and how to load one, in one
// place. Names are given without the extension: loadSample("cornell-box").
#include "model/io/scene_json.h"
#include "model/scene.h"

#include <glm/vec3.hpp>

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace regio::test {

// resources/scenes/ of the source tree.
inline std::filesystem::path samplesFolder()
{
    return std::filesystem::path(REGIO_SOURCE_DIR) / "resources" / "scenes";
}

// The file of the sample scene `name`.
inline std::filesystem::path samplePath(const std::string& name) { return samplesFolder() / (name + ".json"); }

// Every sample scene file, sorted by name.
inline std::vector<std::filesystem::path> sampleFiles()
{
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(samplesFolder()))
        if (entry.path().extension() == ".json")
            files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

// The sample scene `name` as the reader gives it. The samples are part of the
// product: one that does not load throws, which fails the test that wanted it
// with the reader's first diagnostic.
inline model::Scene loadSample(const std::string& name)
{
    const std::filesystem::path path = samplePath(name);
    model::Result<model::Scene> read = model::loadSceneFile(path.string());
    if (!read.ok())
        throw std::runtime_error(
            "cannot load the sample scene " + path.string() + ": " +
            (read.diagnostics().empty() ? std::string("no diagnostic") : read.diagnostics().front().message));
    return std::move(*read);
}

// Every vertex rounded to a 32-bit float, as a model file (OBJ, glTF, PLY)
// holds it.
inline void roundToFloats(model::Scene& scene)
{
    for (model::Object& object : scene.objects)
        for (model::Part& part : object.parts)
            for (model::Vec3& v : part.vertices)
                v = model::Vec3(glm::vec3(v));
}

} // namespace regio::test
