#include "output/export.h"

#include "output/export_gltf.h"
#include "output/export_obj.h"
#include "output/export_ply.h"
#include "output/legend_overlay.h"
#include "output/png_writer.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <stdexcept>

namespace regio::output {

namespace {

std::string lowerExtension(const std::string& path)
{
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

constexpr int kMaxImageSide = 16384;

} // namespace

std::optional<ModelFormat> modelFormatForPath(const std::string& path)
{
    const std::string ext = lowerExtension(path);
    if (ext == ".gltf")
        return ModelFormat::Gltf;
    if (ext == ".glb")
        return ModelFormat::Glb;
    if (ext == ".ply")
        return ModelFormat::Ply;
    if (ext == ".obj")
        return ModelFormat::Obj;
    return std::nullopt;
}

model::Check writeLitModel(const std::string& path, const LitMesh& mesh, const DisplayColours& colours)
{
    const auto format = modelFormatForPath(path);
    if (!format)
        return model::makeError("cannot write " + path + ": unknown model format \"" + lowerExtension(path) +
                                "\" (use .gltf, .glb, .ply or .obj)");
    switch (*format) {
    case ModelFormat::Gltf: return writeGltf(path, mesh, colours, GltfContainer::Separate);
    case ModelFormat::Glb: return writeGltf(path, mesh, colours, GltfContainer::Binary);
    case ModelFormat::Ply: return writePly(path, mesh, colours);
    case ModelFormat::Obj: return writeObj(path, mesh, colours);
    }
    return model::makeError("cannot write " + path + ": unknown model format");
}

PreparedColours prepareColours(const LitMesh& mesh, const DisplaySettings& settings)
{
    PreparedColours out;
    if (settings.colours == ColourMode::FalseColour) {
        const glm::vec3 ambient = settings.toneMap.ambient;
        out.falseColour = FalseColour::forMesh(settings.falseColour, mesh, ambient);
        out.colours = falseColours(mesh, *out.falseColour, ambient, settings.toneMap.encoding);
    } else {
        out.colours = toneMappedColours(mesh, ToneMap::forMesh(settings.toneMap, mesh));
    }
    return out;
}

model::Check writeOutputs(const LitMesh& mesh, const OutputRequest& request)
{
    if (!request.modelPath.empty() && !modelFormatForPath(request.modelPath))
        return model::makeError("cannot write " + request.modelPath + ": unknown model format \"" +
                                lowerExtension(request.modelPath) + "\" (use .gltf, .glb, .ply or .obj)");
    if (!request.imagePath.empty()) {
        if (lowerExtension(request.imagePath) != ".png")
            return model::makeError("cannot write " + request.imagePath +
                                    ": images are written as PNG (use a .png name)");
        if (request.imageWidth < 1 || request.imageHeight < 1 || request.imageWidth > kMaxImageSide ||
            request.imageHeight > kMaxImageSide)
            return model::makeError("cannot write " + request.imagePath + ": the image size must be between 1 and " +
                                    std::to_string(kMaxImageSide) + " pixels a side");
        if (request.camera) {
            if (model::Check problem = checkCamera(*request.camera); !problem)
                return model::makeError("cannot write " + request.imagePath + ": " + problem.error().message);
        }
    }
    if (model::Check problem = checkLitMesh(mesh); !problem)
        return model::makeError("cannot write the solution: " + problem.error().message);
    if (request.modelPath.empty() && request.imagePath.empty())
        return model::success();

    const PreparedColours prepared = prepareColours(mesh, request.display);
    if (!request.modelPath.empty()) {
        if (model::Check written = writeLitModel(request.modelPath, mesh, prepared.colours); !written)
            return written;
    }
    if (!request.imagePath.empty()) {
        RenderOptions options;
        options.width = request.imageWidth;
        options.height = request.imageHeight;
        options.supersample = request.supersample;
        const double aspect = static_cast<double>(request.imageWidth) / request.imageHeight;
        const model::Camera camera = request.camera ? *request.camera : frameCamera(litMeshBounds(mesh), 45.0, aspect);
        Image image = renderImage(mesh, prepared.colours, camera, options);
        if (prepared.falseColour)
            drawLegend(image, prepared.falseColour->legend());
        if (model::Check written = writePng(request.imagePath, image); !written)
            return written;
    }
    return model::success();
}

model::Check writeOutputs(const SolutionSnapshot& snapshot, const OutputRequest& request)
{
    LitMesh mesh;
    try {
        mesh = litMeshFromSolution(snapshot);
    } catch (const std::invalid_argument& e) {
        return model::makeError(std::string("cannot write the solution: ") + e.what());
    }
    if (!request.includeAmbient)
        return writeOutputs(mesh, request);
    OutputRequest withAmbient = request;
    withAmbient.display.toneMap.ambient = glm::vec3(snapshot.stats.ambient);
    return writeOutputs(mesh, withAmbient);
}

} // namespace regio::output
