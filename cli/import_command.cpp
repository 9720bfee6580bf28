// `regio-solve import`: a model file (OBJ, glTF, PLY, 3DS, FBX, Collada, STL,
// ... through Assimp) into a Regio scene file with automatic regions and
// suggested BSP orders, and a report of what happened.
#include "cli/commands.h"
#include "cli/number_argument.h"
#include "cli/scene_input.h"

#include "importer/import_model.h"
#include "model/io/file_io.h"
#include "model/io/scene_json.h"

#include <cstring>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

namespace regio::cli {

namespace {

const char* const kImportUsage =
    "Usage: regio-solve import [OPTIONS] MODEL OUT.json\n"
    "\n"
    "Imports a model (OBJ with MTL, glTF 2.0, PLY, 3DS, FBX, Collada, STL and\n"
    "whatever else Assimp reads) as a Regio scene: triangles merged back into\n"
    "planar convex faces, each node an object, each connected piece a part,\n"
    "diffuse colours as reflectances and emissive colours as emission, and\n"
    "automatic regions with a suggested BSP order, kept only when they cost\n"
    "fewer fragments than one BSP tree.\n"
    "\n"
    "Options:\n"
    "  --scale S                 model units to metres (default 1)\n"
    "  --up y|z                  the model's up axis (default y)\n"
    "  --merge-tolerance DEG,MM  normals within DEG degrees and corners within\n"
    "                            MM millimetres are one plane (default 1,1)\n"
    "  --regions auto|none       automatic regions (default auto)\n"
    "  --report FILE.json        write the import report as JSON\n"
    "  -q, --quiet               no summary, diagnostics only\n"
    "  -h, --help                show this help\n"
    "\n"
    "Exit status: 0 imported (maybe with warnings), 1 the model gives no valid\n"
    "scene, 2 the command line is wrong or a file cannot be read or written.\n";

std::optional<double> number(const std::string& text)
{
    double value = 0.0;
    return parseNumber(text, value) ? std::optional<double>(value) : std::nullopt;
}

int usageError(const std::string& message)
{
    std::cerr << "regio-solve import: " << message << "\nTry 'regio-solve import --help'.\n";
    return kExitFailure;
}

// Names and messages from the model are escaped (formatDiagnostic).
void print(const std::string& file, const model::Diagnostics& diagnostics)
{
    for (const model::Diagnostic& d : diagnostics)
        std::cerr << formatDiagnostic(file, d) << "\n";
}

} // namespace

int runImport(int argc, char** argv)
{
    importer::ImportOptions options;
    std::string reportPath;
    bool quiet = false;
    std::vector<std::string> files;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const auto value = [&]() -> std::optional<std::string> {
            if (i + 1 >= argc)
                return std::nullopt;
            return std::string(argv[++i]);
        };
        if (arg == "-h" || arg == "--help") {
            std::cout << kImportUsage;
            return kExitOk;
        } else if (arg == "-q" || arg == "--quiet") {
            quiet = true;
        } else if (arg == "--scale") {
            const auto text = value();
            const auto s = text ? number(*text) : std::nullopt;
            if (!s || *s <= 0.0)
                return usageError("--scale needs a positive number");
            options.read.scale = *s;
        } else if (arg == "--up") {
            const auto text = value();
            if (!text || (*text != "y" && *text != "z"))
                return usageError("--up takes y or z");
            options.read.up = *text == "z" ? importer::UpAxis::Z : importer::UpAxis::Y;
        } else if (arg == "--merge-tolerance") {
            const auto text = value();
            const auto comma = text ? text->find(',') : std::string::npos;
            const auto degrees = comma != std::string::npos ? number(text->substr(0, comma)) : std::nullopt;
            const auto mm = comma != std::string::npos ? number(text->substr(comma + 1)) : std::nullopt;
            if (!degrees || !mm || *degrees < 0.0 || *degrees >= 90.0 || *mm < 0.0)
                return usageError("--merge-tolerance takes DEG,MM (degrees below 90, millimetres at least 0)");
            options.merge.angleDegrees = *degrees;
            options.merge.distance = *mm / 1000.0;
        } else if (arg == "--regions") {
            const auto text = value();
            if (!text || (*text != "auto" && *text != "none"))
                return usageError("--regions takes auto or none");
            options.autoRegions = *text == "auto";
        } else if (arg == "--report") {
            const auto text = value();
            if (!text)
                return usageError("--report needs a file name");
            reportPath = *text;
        } else if (arg.size() > 1 && arg[0] == '-') {
            return usageError("unknown option '" + arg + "'");
        } else {
            files.push_back(arg);
        }
    }
    if (files.size() != 2)
        return usageError("needs a model file and the scene file to write");

    auto imported = importer::importModel(files[0], options);
    print(files[0], imported.diagnostics());
    if (!imported) {
        std::cerr << files[0] << ": not imported\n";
        // A file that no reader takes is a bad argument; one read but giving no valid scene, an error of the model.
        const bool unreadable = !std::filesystem::is_regular_file(files[0]);
        return unreadable ? kExitFailure : kExitErrors;
    }
    if (const model::Check saved = model::saveSceneFile(imported->scene, files[1]); !saved) {
        print(files[1], saved.diagnostics());
        return kExitFailure;
    }
    if (!reportPath.empty()) {
        if (const model::Check written =
                model::writeFileAtomically(reportPath, importer::reportJson(imported->report), "write report");
            !written) {
            print(reportPath, written.diagnostics());
            return kExitFailure;
        }
    }
    if (!quiet) {
        const importer::ImportReport& r = imported->report;
        std::cout << files[0] << ": " << r.merge.trianglesIn << " triangles -> " << r.merge.faces << " faces, "
                  << r.build.parts << " parts (" << r.build.closedParts << " closed, " << r.build.closedFacingIn
                  << " of them facing in), " << r.build.objects << " objects, " << r.build.materials << " materials, "
                  << r.build.emittingFaces << " emitting faces, " << r.build.turnedFaces << " faces turned; dropped "
                  << r.merge.degenerate << " of no area, " << r.merge.duplicate << " repeated, "
                  << r.read.pointsAndLines << " points or lines";
        if (options.autoRegions)
            std::cout << "; " << r.regions << (r.regions == 1 ? " region, " : " regions, ") << r.fragments
                      << " BSP fragments (one tree: " << r.singleTreeFragments << ")";
        std::cout << " -> " << files[1] << "\n";
    }
    return kExitOk;
}

} // namespace regio::cli
