// `regio-solve solve`: the batch radiosity solve of one or more scene files,
// with a progress line on standard error and an optional JSON report.
#include "cli/commands.h"
#include "cli/number_argument.h"
#include "cli/scene_input.h"

#include "model/io/printable.h"
#include "output/export.h"
#include "output/report.h"
#include "output/vertex_radiosity.h"
#include "solver/solver.h"

#include <nlohmann/json.hpp>

#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace regio::cli {

namespace {

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
    "solved), 2 some file could not be read or the command line is wrong,\n"
    "130 interrupted (the report still holds what was done).\n";

std::atomic<bool> g_interrupted{false};
static_assert(std::atomic<bool>::is_always_lock_free, "set from a signal handler");

extern "C" void onInterrupt(int) { g_interrupted.store(true); }

struct Options {
    solver::SolverOptions solver;
    bool iterationsGiven = false;
    bool convergenceGiven = false;
    std::optional<std::string> reportPath;
    output::OutputRequest output;
    bool flat = false;
    bool quiet = false;
    std::vector<std::string> files;
};

int usageError(const std::string& message)
{
    std::cerr << "regio-solve solve: " << message << "\nTry 'regio-solve solve --help'.\n";
    return kExitFailure;
}

std::optional<bool> parseSwitch(const std::string& text)
{
    if (text == "on")
        return true;
    if (text == "off")
        return false;
    return std::nullopt;
}

// Parses the command line; returns an exit code when the command must stop here.
std::optional<int> parseOptions(int argc, char** argv, Options& options)
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
        if (arg == "--srgb" || arg == "--ambient" || arg == "--flat") {
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
                   arg == "--cache-mb") {
            if (i + 1 >= argc)
                return usageError(arg + " needs a value");
            value = argv[++i];
        } else {
            return usageError("unknown option '" + arg + "'");
        }

        if (arg == "--hemicube") {
            int n = 0;
            if (!parseNumber(value, n) || n < 2 || n > solver::kMaxHemicubeResolution)
                return usageError("--hemicube expects an integer from 2 to " +
                                  std::to_string(solver::kMaxHemicubeResolution) + ", not '" + value + "'");
            options.solver.hemicube = n;
        } else if (arg == "--iterations") {
            int n = 0;
            if (!parseNumber(value, n) || n < 0)
                return usageError("--iterations expects a non-negative integer, not '" + value + "'");
            options.solver.maxIterations = n;
            options.iterationsGiven = true;
        } else if (arg == "--convergence") {
            double x = 0.0;
            if (!parseNumber(value, x) || !(x >= 0.0) || x > 1.0)
                return usageError("--convergence expects a number from 0 to 1, not '" + value + "'");
            options.solver.convergence = x;
            options.convergenceGiven = true;
        } else if (arg == "--threads") {
            int n = 0;
            if (!parseNumber(value, n) || n < 1 || n > 64)
                return usageError("--threads expects an integer from 1 to 64, not '" + value + "'");
            options.solver.threads = n;
        } else if (arg == "--cache-mb") {
            long long mb = 0;
            if (!parseNumber(value, mb) || mb < 0 || mb > (1LL << 24))
                return usageError("--cache-mb expects megabytes from 0 to 16777216, not '" + value + "'");
            options.solver.formFactorCacheBytes = static_cast<std::size_t>(mb) << 20;
        } else if (arg == "--visibility") {
            options.solver.visibility = model::parseVisibility(value);
            if (!options.solver.visibility)
                return usageError("--visibility expects painter or zbuffer, not '" + value + "'");
        } else if (arg == "--regions") {
            options.solver.regions = model::parseRegionsMode(value);
            if (!options.solver.regions)
                return usageError("--regions expects authored, none or auto, not '" + value + "'");
        } else if (arg == "--adaptive" || arg == "--anchoring") {
            const std::optional<bool> on = parseSwitch(value);
            if (!on)
                return usageError(arg + " expects on or off, not '" + value + "'");
            (arg == "--adaptive" ? options.solver.adaptive : options.solver.adaptiveAnchoring) = *on;
        } else if (arg == "--threshold") {
            double x = 0.0;
            if (!parseNumber(value, x) || !std::isfinite(x) || x < 0.0)
                return usageError("--threshold expects a relative difference >= 0, not '" + value + "'");
            options.solver.adaptiveThreshold = x;
        } else if (arg == "--min-edge") {
            double metres = 0.0;
            if (!parseNumber(value, metres) || !std::isfinite(metres) || metres <= 0.0)
                return usageError("--min-edge expects a length in metres > 0, not '" + value + "'");
            options.solver.adaptiveMinEdge = metres;
        } else if (arg == "--report") {
            if (value.empty())
                return usageError("--report needs a file name");
            options.reportPath = value;
        } else if (arg == "--out") {
            if (!output::modelFormatForPath(value))
                return usageError("--out expects a .gltf, .glb, .ply or .obj file, not '" + value + "'");
            options.output.modelPath = value;
        } else if (arg == "--image") {
            if (value.empty())
                return usageError("--image needs a file name");
            options.output.imagePath = value;
        } else if (arg == "--size") {
            int w = 0, h = 0;
            char x = 0;
            std::istringstream in(value);
            if (!(in >> w >> x >> h) || x != 'x' || in.peek() != std::char_traits<char>::eof() || w < 1 || h < 1 ||
                w > 16384 || h > 16384)
                return usageError("--size expects WIDTHxHEIGHT from 1x1 to 16384x16384, not '" + value + "'");
            options.output.imageWidth = w;
            options.output.imageHeight = h;
        } else if (arg == "--exposure") {
            double stops = 0.0;
            if (!parseNumber(value, stops) || !std::isfinite(stops) || std::abs(stops) > 64)
                return usageError("--exposure expects a number of stops from -64 to 64, not '" + value + "'");
            options.output.display.toneMap.exposure = stops;
        } else if (arg == "--gamma") {
            double g = 0.0;
            if (!parseNumber(value, g) || !(g >= 0.1 && g <= 10.0))
                return usageError("--gamma expects a number from 0.1 to 10, not '" + value + "'");
            options.output.display.toneMap.encoding.gamma = g;
        } else if (arg == "--false-colour") {
            options.output.display.colours = output::ColourMode::FalseColour;
            if (value == "log")
                options.output.display.falseColour.scale = output::FalseColourScale::Logarithmic;
            else if (value == "linear")
                options.output.display.falseColour.scale = output::FalseColourScale::Linear;
            else
                return usageError("--false-colour expects log or linear, not '" + value + "'");
        } else {
            return usageError("unknown option '" + arg + "'");
        }
    }
    if (options.files.empty())
        return usageError("no scene file given");
    const bool outputs = !options.output.modelPath.empty() || !options.output.imagePath.empty();
    if (outputs && options.files.size() > 1)
        return usageError("--out and --image take one scene at a time");
    // "Exactly N shooting steps": the convergence test only applies when asked for.
    if (options.iterationsGiven && !options.convergenceGiven)
        options.solver.convergence = 0.0;
    return std::nullopt;
}

std::string displayName(const std::string& name) { return name == "-" ? "<stdin>" : name; }

// The \r-updated progress line, at most four times a second.
class ProgressLine {
public:
    ProgressLine(std::string name, int maxIterations, bool enabled)
        : m_name(std::move(name))
        , m_max(maxIterations)
        , m_enabled(enabled)
        , m_start(Clock::now())
    {
    }
    ~ProgressLine() { finish(); }

    void update(const solver::SolverStats& s, bool force = false)
    {
        if (!m_enabled)
            return;
        const auto now = Clock::now();
        if (!force && m_shown && now - m_last < std::chrono::milliseconds(250))
            return;
        m_last = now;
        char line[256];
        std::snprintf(line, sizeof line, "%s: iteration %d/%d, unshot %.3g %% of emitted, %.1f s", m_name.c_str(),
                      s.iterations, m_max, 100.0 * s.unshotRatio, std::chrono::duration<double>(now - m_start).count());
        std::string text = line;
        const size_t width = text.size();
        if (text.size() < m_width)
            text.append(m_width - text.size(), ' ');
        m_width = width;
        std::cerr << '\r' << text << std::flush;
        m_shown = true;
    }
    void finish()
    {
        if (m_shown)
            std::cerr << '\n' << std::flush;
        m_shown = false;
    }

private:
    using Clock = std::chrono::steady_clock;
    std::string m_name;
    int m_max;
    bool m_enabled;
    bool m_shown = false;
    size_t m_width = 0;
    Clock::time_point m_start;
    Clock::time_point m_last;
};

nlohmann::json unsolvedEntry(const SceneInput& input, const model::Diagnostics& diagnostics, const char* status)
{
    nlohmann::json entry;
    entry["scene"] = input.name;
    entry["status"] = status;
    nlohmann::json errors = nlohmann::json::array();
    for (const model::Diagnostic& d : diagnostics)
        if (d.isError())
            errors.push_back(formatDiagnostic(displayName(input.name), d));
    entry["errors"] = std::move(errors);
    return entry;
}

// Standard output ("-"), or a file written atomically: a half-written report
// never replaces a previous one.
bool writeReportTo(const std::string& path, const nlohmann::json& report)
{
    if (path == "-") {
        std::cout << report.dump(2) << "\n" << std::flush;
        return true;
    }
    if (model::Check written = output::writeReport(path, report); !written) {
        std::cerr << "regio-solve solve: " << model::printable(written.error().message) << "\n";
        return false;
    }
    return true;
}

// The lit model and the picture: smooth vertex radiosity (§6)
// unless --flat; display values only ever touch the copies written out.
bool writeSolutionOutputs(const Options& options, const model::Scene& scene, const solver::Solver& s)
{
    if (options.output.modelPath.empty() && options.output.imagePath.empty())
        return true;
    const solver::SolutionSnapshot snapshot = s.snapshot();
    const output::LitMesh mesh = output::litMeshForOutput(s.prepared(), snapshot.radiosity, !options.flat);
    output::OutputRequest request = options.output;
    request.camera = scene.camera;
    if (request.includeAmbient)
        request.display.toneMap.ambient = glm::vec3(snapshot.stats.ambient);
    if (model::Check written = output::writeOutputs(mesh, request); !written) {
        std::cerr << "regio-solve solve: " << model::printable(written.error().message) << "\n";
        return false;
    }
    return true;
}

// --threshold, --min-edge and --anchoring tune a subdivision that a scene
// with adaptive.enabled = false (or --adaptive off) never does: say so
// rather than let the user believe they had an effect.
void warnAboutIdleAdaptiveOptions(const std::string& name, const Options& options,
                                  const model::SolverSettings& settings)
{
    if (settings.adaptive.enabled)
        return;
    std::string given;
    int count = 0;
    for (const auto& [set, option] : {std::pair{options.solver.adaptiveThreshold.has_value(), "--threshold"},
                                      std::pair{options.solver.adaptiveMinEdge.has_value(), "--min-edge"},
                                      std::pair{options.solver.adaptiveAnchoring.has_value(), "--anchoring"}})
        if (set) {
            given += (given.empty() ? "" : ", ") + std::string(option);
            ++count;
        }
    if (count > 0)
        std::cerr << name << ": warning: " << given << (count == 1 ? " has" : " have")
                  << " no effect: adaptive subdivision is off"
                  << (options.solver.adaptive ? "" : " in the scene (--adaptive on turns it on)") << "\n";
}

} // namespace

int runSolve(int argc, char** argv)
{
    Options options;
    if (const std::optional<int> code = parseOptions(argc, argv, options))
        return *code;

    g_interrupted = false;
    const auto previousHandler = std::signal(SIGINT, onInterrupt);
    // With the report on standard output, people read everything else on standard error.
    std::ostream& summary = options.reportPath && *options.reportPath == "-" ? std::cerr : std::cout;

    int exitCode = kExitOk;
    nlohmann::json reports = nlohmann::json::array();
    for (const std::string& file : options.files) {
        if (g_interrupted)
            break;
        const auto start = std::chrono::steady_clock::now();
        const SceneInput input = readSceneInput(file);
        printDiagnostics(std::cerr, input);
        const int inputCode = exitCodeOf(input);
        if (inputCode != kExitOk) {
            exitCode = std::max(exitCode, inputCode);
            reports.push_back(
                unsolvedEntry(input, input.diagnostics, inputCode == kExitFailure ? "unreadable" : "invalid"));
            if (!options.quiet)
                summary << displayName(file) << ": not solved (the scene has errors)\n";
            continue;
        }

        model::Result<std::unique_ptr<solver::Solver>> built = solver::Solver::create(*input.scene, options.solver);
        for (const model::Diagnostic& d : built.diagnostics())
            std::cerr << formatDiagnostic(displayName(file), d) << "\n";
        if (!built) {
            exitCode = std::max(exitCode, kExitErrors);
            reports.push_back(unsolvedEntry(input, built.diagnostics(), "invalid"));
            if (!options.quiet)
                summary << displayName(file) << ": not solved (the scene could not be prepared)\n";
            continue;
        }

        solver::Solver& s = **built;
        warnAboutIdleAdaptiveOptions(displayName(file), options, s.settings());
        solver::StopReason stop;
        {
            ProgressLine progress(displayName(file), s.settings().maxIterations, !options.quiet);
            progress.update(s.stats(), true);
            stop = s.run([&](const solver::SolverStats& stats) { progress.update(stats); }, g_interrupted);
            progress.update(s.stats(), true);
        }
        const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        nlohmann::json report = output::solveReport(file, s, total);
        report["status"] = stop == solver::StopReason::Cancelled ? "interrupted" : "solved";
        reports.push_back(std::move(report));

        if (!writeSolutionOutputs(options, *input.scene, s))
            exitCode = std::max(exitCode, kExitFailure);

        if (!options.quiet) {
            const solver::SolverStats st = s.stats();
            char rounds[64] = "";
            if (s.settings().adaptive.enabled)
                std::snprintf(rounds, sizeof rounds, " (%d adaptive round%s)", st.adaptiveRounds,
                              st.adaptiveRounds == 1 ? "" : "s");
            char line[320];
            std::snprintf(line, sizeof line,
                          ": %d iterations (%s), %d patches, %d elements%s, unshot %.3g %% of emitted, %.2f s",
                          st.iterations, solver::stopReasonName(stop), st.patches, st.elements, rounds,
                          100.0 * st.unshotRatio, total);
            summary << displayName(file) << line << "\n";
        }
    }
    std::signal(SIGINT, previousHandler == SIG_ERR ? SIG_DFL : previousHandler);

    if (options.reportPath) {
        const nlohmann::json out = options.files.size() == 1 && reports.size() == 1 ? reports[0] : reports;
        if (!writeReportTo(*options.reportPath, out))
            exitCode = std::max(exitCode, kExitFailure);
    }
    if (g_interrupted) {
        std::cerr << "regio-solve solve: interrupted\n";
        return 130;
    }
    return exitCode;
}

} // namespace regio::cli
