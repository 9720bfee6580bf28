// Parsing the command line of `regio-solve solve` (solve_options.h).
#include "cli/solve_options.h"

#include "cli/commands.h"
#include "cli/number_argument.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <set>
#include <sstream>

namespace regio::cli {

const char* const kSolveUsage =
    "Usage: regio-solve solve [OPTIONS] SCENE.json...\n"
    "\n"
    "Computes the radiosity solution of each scene by progressive shooting\n"
    "with the painter's hemicube over regional BSP trees. Settings not given\n"
    "here come from the scene's own solver settings.\n"
    "\n"
    "Options:\n"
    "  --hemicube N            hemicube resolution (top face N x N), 2..4096\n"
    "  --iterations N          shoot exactly N times (fewer only if no light is\n"
    "                          left); the convergence test is off unless\n"
    "                          --convergence is also given\n"
    "  --convergence X         stop when unshot / emitted power < X (per channel)\n"
    "  --visibility MODE       painter (default) or zbuffer\n"
    "  --regions MODE          authored (default), none (one BSP tree) or auto\n"
    "  --report FILE.json      write the JSON report there ('-': standard output)\n"
    "  --threads N             hemicube render threads, 1..64 (default: every\n"
    "                          core; at most 8 are used; the result is the same\n"
    "                          for any N)\n"
    "  --cache-mb N            memory for kept form-factor rows, which later shots\n"
    "                          of a patch reuse (default 1024; 0: render every shot)\n"
    "\n"
    "Adaptive subdivision of the element mesh (paper section 5.7):\n"
    "  --adaptive on|off       refine the mesh between shots where neighbouring\n"
    "                          elements differ (off: the initial mesh throughout)\n"
    "  --threshold X           relative luminance difference between edge\n"
    "                          neighbours that splits an element, X >= 0\n"
    "                          (0: any difference; 1 or more: never)\n"
    "  --min-edge METRES       shortest element edge a split may make, > 0\n"
    "  --anchoring on|off      keep the mesh conforming and graded 2:1\n"
    "                          (Baum et al. 1991); off only to see what it does\n"
    "\n"
    "Batch: many scenes into one directory:\n"
    "  --out-dir DIR           write each scene's report (NAME.report.json) and\n"
    "                          outputs (NAME.glb, ...) into DIR, NAME being the\n"
    "                          scene file's name without .json; a scene whose\n"
    "                          report there shows the same file content and the\n"
    "                          same options is skipped, so an interrupted batch\n"
    "                          resumes where it stopped\n"
    "  --format LIST           outputs per scene, comma-separated: glb, gltf,\n"
    "                          ply, obj, png (default: the report only)\n"
    "  --jobs N                solve up to N scenes at once, 1..64 (default: one\n"
    "                          per core, or cores / --threads; each solve gets\n"
    "                          cores / N threads, and 1024 / N MB of --cache-mb,\n"
    "                          unless those are given)\n"
    "  --force                 solve every scene, even those already solved\n"
    "  --progress text|json    json: one JSON line per scene event and per\n"
    "                          percent of a solve on standard output, for tools\n"
    "                          to follow (the summary goes to standard error)\n"
    "\n"
    "Output of the lit model (one scene only):\n"
    "  --out FILE              the lit model: .gltf (+ .bin), .glb, .ply or .obj\n"
    "  --image FILE.png        a Gouraud-shaded picture from the scene's camera\n"
    "                          (a view of the whole model when it has none)\n"
    "  --size WxH              picture size in pixels (default 1024x768)\n"
    "  --exposure STOPS        display exposure, +1 doubles (default 0)\n"
    "  --gamma G               display gamma (default 2.2)\n"
    "  --srgb                  encode with the sRGB curve instead of a gamma\n"
    "  --false-colour SCALE    luminance in false colour, log or linear, with a legend\n"
    "  --ambient               add the ambient term (for unconverged solutions)\n"
    "  --flat                  one value per element instead of smooth vertex\n"
    "                          radiosity (paper section 6)\n"
    "  -q, --quiet             no progress line and no summary\n"
    "  -h, --help              show this help\n"
    "\n"
    "Exit status: 0 every scene was solved, 1 some scene has errors (it is not\n"
    "solved; every other scene still is), 2 some file could not be read or\n"
    "written or the command line is wrong, 130 interrupted by Ctrl-C and 143\n"
    "by SIGTERM (finished scenes are kept, the report holds what was done).\n";

const char* extensionOf(BatchFormat format)
{
    switch (format) {
    case BatchFormat::Glb: return ".glb";
    case BatchFormat::Gltf: return ".gltf";
    case BatchFormat::Ply: return ".ply";
    case BatchFormat::Obj: return ".obj";
    case BatchFormat::Png: return ".png";
    }
    return "";
}

int solveUsageError(const std::string& message)
{
    std::cerr << "regio-solve solve: " << message << "\nTry 'regio-solve solve --help'.\n";
    return kExitFailure;
}

namespace {

std::optional<std::vector<BatchFormat>> parseFormats(const std::string& list)
{
    std::vector<BatchFormat> formats;
    std::istringstream in(list);
    std::string name;
    while (std::getline(in, name, ',')) {
        BatchFormat format;
        if (name == "glb")
            format = BatchFormat::Glb;
        else if (name == "gltf")
            format = BatchFormat::Gltf;
        else if (name == "ply")
            format = BatchFormat::Ply;
        else if (name == "obj")
            format = BatchFormat::Obj;
        else if (name == "png")
            format = BatchFormat::Png;
        else
            return std::nullopt;
        if (std::find(formats.begin(), formats.end(), format) == formats.end())
            formats.push_back(format);
    }
    if (formats.empty())
        return std::nullopt;
    return formats;
}

std::optional<bool> parseSwitch(const std::string& text)
{
    if (text == "on")
        return true;
    if (text == "off")
        return false;
    return std::nullopt;
}

// Options that change neither a solution nor its files: a batch does not
// solve a scene again because they differ.
bool affectsResults(const std::string& option)
{
    static const std::set<std::string> kNeutral{"--out-dir",  "--jobs",   "--threads", "--cache-mb", "--force",
                                                "--progress", "--report", "--out",     "--image"};
    return kNeutral.count(option) == 0;
}

} // namespace

std::optional<int> parseSolveOptions(int argc, char** argv, SolveOptions& options)
{
    bool optionsEnded = false;
    for (int i = 1; i < argc; ++i) {
        std::string arg = argv[i];
        if (optionsEnded || arg == "-" || arg.empty() || arg[0] != '-') {
            options.files.push_back(arg);
            continue;
        }
        if (arg == "--") {
            optionsEnded = true;
            continue;
        }
        if (arg == "-h" || arg == "--help") {
            std::cout << kSolveUsage;
            return kExitOk;
        }
        if (arg == "-q" || arg == "--quiet") {
            options.quiet = true;
            continue;
        }
        if (arg == "--force") {
            options.force = true;
            continue;
        }
        if (arg == "--srgb" || arg == "--ambient" || arg == "--flat") {
            options.resultArguments.push_back(arg);
            if (arg == "--srgb")
                options.output.display.toneMap.encoding.transfer = output::Transfer::Srgb;
            else if (arg == "--ambient")
                options.output.includeAmbient = true;
            else
                options.flat = true;
            continue;
        }
        std::string value;
        const size_t eq = arg.find('=');
        if (eq != std::string::npos) {
            value = arg.substr(eq + 1);
            arg = arg.substr(0, eq);
        } else if (arg == "--hemicube" || arg == "--iterations" || arg == "--convergence" || arg == "--visibility" ||
                   arg == "--regions" || arg == "--report" || arg == "--out" || arg == "--image" || arg == "--size" ||
                   arg == "--exposure" || arg == "--gamma" || arg == "--false-colour" || arg == "--adaptive" ||
                   arg == "--threshold" || arg == "--min-edge" || arg == "--anchoring" || arg == "--threads" ||
                   arg == "--cache-mb" || arg == "--out-dir" || arg == "--format" || arg == "--jobs" ||
                   arg == "--progress") {
            if (i + 1 >= argc)
                return solveUsageError(arg + " needs a value");
            value = argv[++i];
        } else {
            return solveUsageError("unknown option '" + arg + "'");
        }
        if (affectsResults(arg))
            options.resultArguments.push_back(arg + "=" + value);

        if (arg == "--hemicube") {
            int n = 0;
            if (!parseNumber(value, n) || n < 2 || n > solver::kMaxHemicubeResolution)
                return solveUsageError("--hemicube expects an integer from 2 to " +
                                       std::to_string(solver::kMaxHemicubeResolution) + ", not '" + value + "'");
            options.solver.hemicube = n;
        } else if (arg == "--iterations") {
            int n = 0;
            if (!parseNumber(value, n) || n < 0)
                return solveUsageError("--iterations expects a non-negative integer, not '" + value + "'");
            options.solver.maxIterations = n;
            options.iterationsGiven = true;
        } else if (arg == "--convergence") {
            double x = 0.0;
            if (!parseNumber(value, x) || !(x >= 0.0) || x > 1.0)
                return solveUsageError("--convergence expects a number from 0 to 1, not '" + value + "'");
            options.solver.convergence = x;
            options.convergenceGiven = true;
        } else if (arg == "--threads") {
            int n = 0;
            if (!parseNumber(value, n) || n < 1 || n > 64)
                return solveUsageError("--threads expects an integer from 1 to 64, not '" + value + "'");
            options.solver.threads = n;
        } else if (arg == "--cache-mb") {
            long long mb = 0;
            if (!parseNumber(value, mb) || mb < 0 || mb > (1LL << 24))
                return solveUsageError("--cache-mb expects megabytes from 0 to 16777216, not '" + value + "'");
            options.solver.formFactorCacheBytes = static_cast<std::size_t>(mb) << 20;
            options.cacheGiven = true;
        } else if (arg == "--visibility") {
            options.solver.visibility = model::parseVisibility(value);
            if (!options.solver.visibility)
                return solveUsageError("--visibility expects painter or zbuffer, not '" + value + "'");
        } else if (arg == "--regions") {
            options.solver.regions = model::parseRegionsMode(value);
            if (!options.solver.regions)
                return solveUsageError("--regions expects authored, none or auto, not '" + value + "'");
        } else if (arg == "--adaptive" || arg == "--anchoring") {
            const std::optional<bool> on = parseSwitch(value);
            if (!on)
                return solveUsageError(arg + " expects on or off, not '" + value + "'");
            (arg == "--adaptive" ? options.solver.adaptive : options.solver.adaptiveAnchoring) = *on;
        } else if (arg == "--threshold") {
            double x = 0.0;
            if (!parseNumber(value, x) || !std::isfinite(x) || x < 0.0)
                return solveUsageError("--threshold expects a relative difference >= 0, not '" + value + "'");
            options.solver.adaptiveThreshold = x;
        } else if (arg == "--min-edge") {
            double metres = 0.0;
            if (!parseNumber(value, metres) || !std::isfinite(metres) || metres <= 0.0)
                return solveUsageError("--min-edge expects a length in metres > 0, not '" + value + "'");
            options.solver.adaptiveMinEdge = metres;
        } else if (arg == "--out-dir") {
            if (value.empty())
                return solveUsageError("--out-dir needs a directory");
            options.outDir = value;
        } else if (arg == "--format") {
            const auto formats = parseFormats(value);
            if (!formats)
                return solveUsageError("--format expects a comma-separated list of glb, gltf, ply, obj and png, not '" +
                                       value + "'");
            options.formats = *formats;
        } else if (arg == "--jobs") {
            int n = 0;
            if (!parseNumber(value, n) || n < 1 || n > 64)
                return solveUsageError("--jobs expects an integer from 1 to 64, not '" + value + "'");
            options.jobs = n;
        } else if (arg == "--progress") {
            if (value == "text")
                options.progress = ProgressStyle::Text;
            else if (value == "json")
                options.progress = ProgressStyle::Json;
            else
                return solveUsageError("--progress expects text or json, not '" + value + "'");
        } else if (arg == "--report") {
            if (value.empty())
                return solveUsageError("--report needs a file name");
            options.reportPath = value;
        } else if (arg == "--out") {
            if (!output::modelFormatForPath(value))
                return solveUsageError("--out expects a .gltf, .glb, .ply or .obj file, not '" + value + "'");
            options.output.modelPath = value;
        } else if (arg == "--image") {
            if (value.empty())
                return solveUsageError("--image needs a file name");
            options.output.imagePath = value;
        } else if (arg == "--size") {
            int w = 0, h = 0;
            char x = 0;
            std::istringstream in(value);
            if (!(in >> w >> x >> h) || x != 'x' || in.peek() != std::char_traits<char>::eof() || w < 1 || h < 1 ||
                w > 16384 || h > 16384)
                return solveUsageError("--size expects WIDTHxHEIGHT from 1x1 to 16384x16384, not '" + value + "'");
            options.output.imageWidth = w;
            options.output.imageHeight = h;
        } else if (arg == "--exposure") {
            double stops = 0.0;
            if (!parseNumber(value, stops) || !std::isfinite(stops) || std::abs(stops) > 64)
                return solveUsageError("--exposure expects a number of stops from -64 to 64, not '" + value + "'");
            options.output.display.toneMap.exposure = stops;
        } else if (arg == "--gamma") {
            double g = 0.0;
            if (!parseNumber(value, g) || !(g >= 0.1 && g <= 10.0))
                return solveUsageError("--gamma expects a number from 0.1 to 10, not '" + value + "'");
            options.output.display.toneMap.encoding.gamma = g;
        } else if (arg == "--false-colour") {
            options.output.display.colours = output::ColourMode::FalseColour;
            if (value == "log")
                options.output.display.falseColour.scale = output::FalseColourScale::Logarithmic;
            else if (value == "linear")
                options.output.display.falseColour.scale = output::FalseColourScale::Linear;
            else
                return solveUsageError("--false-colour expects log or linear, not '" + value + "'");
        } else {
            return solveUsageError("unknown option '" + arg + "'");
        }
    }
    if (options.files.empty())
        return solveUsageError("no scene file given");
    const bool outputs = !options.output.modelPath.empty() || !options.output.imagePath.empty();
    if (options.outDir) {
        if (outputs)
            return solveUsageError(
                "--out-dir writes each scene's outputs itself (--format); --out and --image "
                "take one scene without it");
        for (const std::string& file : options.files)
            if (file == "-")
                return solveUsageError("--out-dir names each scene's files after its file: standard input has none");
    } else {
        if (!options.formats.empty() || options.jobs > 0 || options.force || options.progress == ProgressStyle::Json)
            return solveUsageError("--format, --jobs, --force and --progress work with --out-dir");
        if (outputs && options.files.size() > 1)
            return solveUsageError("--out and --image take one scene at a time");
    }
    // "Exactly N shooting steps": the convergence test only applies when asked for.
    if (options.iterationsGiven && !options.convergenceGiven)
        options.solver.convergence = 0.0;
    return std::nullopt;
}

} // namespace regio::cli
