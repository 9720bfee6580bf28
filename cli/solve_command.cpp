// `regio-solve solve`: the batch radiosity solve of one or more scene files,
// with a progress line on standard error and an optional JSON report.
#include "cli/batch.h"
#include "cli/commands.h"
#include "cli/interrupt.h"
#include "cli/scene_input.h"
#include "cli/solve_options.h"
#include "cli/solve_support.h"

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

} // namespace

int runSolve(int argc, char** argv)
{
    SolveOptions options;
    if (const std::optional<int> code = parseSolveOptions(argc, argv, options))
        return *code;
    if (options.outDir)
        return runBatch(options);

    const InterruptGuard interrupt;
    // With the report on standard output, people read everything else on standard error.
    std::ostream& summary = options.reportPath && *options.reportPath == "-" ? std::cerr : std::cout;

    int exitCode = kExitOk;
    nlohmann::json reports = nlohmann::json::array();
    for (const std::string& file : options.files) {
        if (interrupt.interrupted())
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
        if (const auto warning = idleAdaptiveOptionsWarning(displayName(file), options, s.settings()))
            std::cerr << *warning << "\n";
        solver::StopReason stop;
        {
            ProgressLine progress(displayName(file), s.settings().maxIterations, !options.quiet);
            progress.update(s.stats(), true);
            stop = s.run([&](const solver::SolverStats& stats) { progress.update(stats); }, interrupt.flag());
            progress.update(s.stats(), true);
        }
        const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        nlohmann::json report = output::solveReport(file, s, total);
        report["status"] = stop == solver::StopReason::Cancelled ? "interrupted" : "solved";
        reports.push_back(std::move(report));

        const bool outputs = !options.output.modelPath.empty() || !options.output.imagePath.empty();
        if (outputs) {
            if (model::Check written = writeSolutionOutputs(options, {options.output}, *input.scene, s); !written) {
                std::cerr << "regio-solve solve: " << model::printable(written.error().message) << "\n";
                exitCode = std::max(exitCode, kExitFailure);
            }
        }

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

    if (options.reportPath) {
        const nlohmann::json out = options.files.size() == 1 && reports.size() == 1 ? reports[0] : reports;
        if (!writeReportTo(*options.reportPath, out))
            exitCode = std::max(exitCode, kExitFailure);
    }
    if (interrupt.interrupted()) {
        std::cerr << "regio-solve solve: interrupted\n";
        return InterruptGuard::exitCode();
    }
    return exitCode;
}

} // namespace regio::cli
