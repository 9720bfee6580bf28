// The batch of `regio-solve solve --out-dir` (batch.h).
//
// Every file a scene gets is written atomically (model/io/file_io.h), its
// outputs first and its report last: a report in the directory always
// describes outputs that are complete. A scene counts as done when its report
// says "solved", records the SHA-256 of the scene file's bytes and the
// options that shape a result (SolveOptions::resultArguments), and every
// requested output is there; anything else is solved (again).
#include "cli/batch.h"

#include "cli/batch_progress.h"
#include "cli/batch_summary.h"
#include "cli/commands.h"
#include "cli/content_hash.h"
#include "cli/interrupt.h"
#include "cli/scene_input.h"
#include "cli/solve_support.h"

#include "model/io/file_io.h"
#include "model/io/printable.h"
#include "output/report.h"
#include "solver/solver.h"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <sstream>
#include <thread>
#include <vector>

namespace regio::cli {

namespace fs = std::filesystem;

namespace {

class Batch {
public:
    Batch(const SolveOptions& options, std::vector<SceneJob> jobs)
        : m_options(options)
        , m_dir(*options.outDir)
        , m_jobs(std::move(jobs))
        , m_progress(options.progress, options.quiet, static_cast<int>(m_jobs.size()))
    {
    }

    void run(int workers)
    {
        std::vector<std::thread> threads;
        for (int w = 1; w < workers; ++w)
            threads.emplace_back([this] { work(); });
        work();
        for (std::thread& t : threads)
            t.join();
    }

    const std::vector<SceneJob>& jobs() const { return m_jobs; }
    BatchProgress& progress() { return m_progress; }

private:
    void work()
    {
        for (;;) {
            if (InterruptGuard::interrupted())
                return;
            const std::size_t index = m_next.fetch_add(1);
            if (index >= m_jobs.size())
                return;
            solveGuarded(static_cast<int>(index), m_jobs[index]);
        }
    }

    // One scene that runs out of memory (past the estimate that let it
    // start) or meets a fault of the solver fails alone; the batch goes on.
    void solveGuarded(int index, SceneJob& job)
    {
        std::string error;
        try {
            solveOne(index, job);
            return;
        } catch (const std::bad_alloc&) {
            error = "out of memory (try a larger patch size, a lower hemicube resolution or fewer --jobs)";
        } catch (const std::exception& e) {
            error = std::string("the solver failed: ") + e.what();
        }
        fail(job, kExitFailure, error);
        m_progress.finished(index, job.name, "failed", "not solved: " + model::printable(job.error),
                            {{"error", job.error}});
    }

    fs::path reportPath(const SceneJob& job) const { return m_dir / (job.name + ".report.json"); }

    std::vector<fs::path> outputPaths(const SceneJob& job) const
    {
        std::vector<fs::path> paths;
        for (BatchFormat format : m_options.formats)
            paths.push_back(m_dir / (job.name + extensionOf(format)));
        return paths;
    }

    nlohmann::json batchRecord(const std::string& sha256) const
    {
        nlohmann::json formats = nlohmann::json::array();
        for (BatchFormat format : m_options.formats)
            formats.push_back(std::string(extensionOf(format)).substr(1));
        return {{"sceneSha256", sha256}, {"arguments", m_options.resultArguments}, {"formats", formats}};
    }

    // The report already in the directory, when it shows this scene solved
    // with these options and every output is there.
    std::optional<nlohmann::json> solvedBefore(const SceneJob& job, const std::string& sha256) const
    {
        const model::Result<std::string> text = model::readFile(reportPath(job).string(), 1u << 26, "report");
        if (!text)
            return std::nullopt;
        nlohmann::json report = nlohmann::json::parse(*text, nullptr, false);
        if (!report.is_object() || report.value("status", "") != "solved" || !report.contains("batch") ||
            report["batch"] != batchRecord(sha256))
            return std::nullopt;
        for (const fs::path& path : outputPaths(job)) {
            std::error_code ec;
            if (!fs::is_regular_file(path, ec))
                return std::nullopt;
        }
        return report;
    }

    // Temporary files a killed run of this scene left beside its outputs
    // (NAME.glb.tmp-XXXXXX). Only this scene's, which no other process of a
    // batch into the same directory is writing now (a Slurm array gives
    // each scene one task).
    void removeLeftovers(const SceneJob& job) const
    {
        std::error_code ec;
        std::vector<fs::path> leftovers;
        for (const fs::directory_entry& entry : fs::directory_iterator(m_dir, ec)) {
            const std::string file = entry.path().filename().string();
            if (file.starts_with(job.name + ".") && file.find(".tmp-") != std::string::npos)
                leftovers.push_back(entry.path());
        }
        for (const fs::path& path : leftovers)
            fs::remove(path, ec);
    }

    bool writeReport(SceneJob& job)
    {
        if (model::Check written = output::writeReport(reportPath(job).string(), job.report); !written) {
            fail(job, kExitFailure, written.error().message);
            return false;
        }
        return true;
    }

    void fail(SceneJob& job, int exitCode, const std::string& error)
    {
        job.outcome = Outcome::Failed;
        job.exitCode = std::max(job.exitCode, exitCode);
        if (job.error.empty())
            job.error = error;
    }

    void solveOne(int index, SceneJob& job);

    const SolveOptions& m_options;
    fs::path m_dir;
    std::vector<SceneJob> m_jobs;
    BatchProgress m_progress;
    std::atomic<std::size_t> m_next{0};
};

void Batch::solveOne(int index, SceneJob& job)
{
    const auto start = std::chrono::steady_clock::now();
    const auto seconds = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    m_progress.started(index, job.name, job.file);

    // One read: the bytes hashed are the bytes solved.
    const model::Result<std::string> bytes = model::readFile(job.file);
    const std::string sha256 = bytes ? sha256Hex(*bytes) : std::string();
    // Whatever a killed run of this scene left, also when it is skipped now.
    removeLeftovers(job);
    if (bytes && !m_options.force) {
        if (std::optional<nlohmann::json> report = solvedBefore(job, sha256)) {
            job.outcome = Outcome::Skipped;
            job.report = std::move(*report);
            m_progress.finished(index, job.name, "skipped", "skipped (solved before with the same content and options)",
                                {});
            return;
        }
    }

    m_progress.phase(job.name, "prepare");
    const SceneInput input = bytes ? sceneInputFromText(job.file, *bytes) : readSceneInput(job.file);
    {
        std::ostringstream diagnostics;
        printDiagnostics(diagnostics, input);
        if (!diagnostics.str().empty())
            m_progress.message(diagnostics.str().substr(0, diagnostics.str().size() - 1));
    }
    if (const int code = exitCodeOf(input); code != kExitOk) {
        const bool unreadable = code == kExitFailure;
        fail(job, code, unreadable ? "unreadable" : "the scene has errors");
        job.report = unsolvedEntry(input, input.diagnostics, unreadable ? "unreadable" : "invalid");
        if (!job.report["errors"].empty())
            job.error = job.report["errors"][0].get<std::string>();
        if (!unreadable)
            writeReport(job);
        m_progress.finished(index, job.name, "failed", "not solved: " + model::printable(job.error),
                            {{"error", job.error}});
        return;
    }

    solver::SolverOptions solverOptions = m_options.solver;
    model::Result<std::unique_ptr<solver::Solver>> built = solver::Solver::create(*input.scene, solverOptions);
    for (const model::Diagnostic& d : built.diagnostics())
        m_progress.message(formatDiagnostic(job.file, d));
    if (!built) {
        fail(job, kExitErrors, "the scene could not be prepared");
        job.report = unsolvedEntry(input, built.diagnostics(), "invalid");
        if (!job.report["errors"].empty())
            job.error = job.report["errors"][0].get<std::string>();
        writeReport(job);
        m_progress.finished(index, job.name, "failed", "not solved: " + model::printable(job.error),
                            {{"error", job.error}});
        return;
    }
    solver::Solver& s = **built;
    if (const auto warning = idleAdaptiveOptionsWarning(job.file, m_options, s.settings()))
        m_progress.message(*warning);

    m_progress.phase(job.name, "shoot");
    const int maxIterations = s.settings().maxIterations;
    const double convergence = s.settings().convergence;
    const solver::StopReason stop = s.run(
        [&](const solver::SolverStats& stats) {
            m_progress.shot(job.name, stats.iterations, stats.unshotRatio,
                            solver::workPercent(stats.iterations, maxIterations, stats.unshotRatio, convergence));
        },
        InterruptGuard::flag());
    const solver::SolverStats stats = s.stats();

    job.report = output::solveReport(job.file, s, seconds());
    job.report["batch"] = batchRecord(sha256);
    const nlohmann::json fields{{"iterations", stats.iterations},
                                {"unshot", stats.unshotRatio},
                                {"elements", stats.elements},
                                {"stop", solver::stopReasonName(stop)},
                                {"seconds", seconds()}};
    if (stop == solver::StopReason::Cancelled) {
        // No outputs of a solve cut short; the report says how far it got.
        job.outcome = Outcome::Interrupted;
        job.report["status"] = "interrupted";
        writeReport(job);
        m_progress.finished(index, job.name, "interrupted", "interrupted", fields);
        return;
    }

    m_progress.phase(job.name, "write");
    std::vector<output::OutputRequest> requests;
    for (BatchFormat format : m_options.formats) {
        output::OutputRequest request = m_options.output;
        (format == BatchFormat::Png ? request.imagePath : request.modelPath) =
            (m_dir / (job.name + extensionOf(format))).string();
        requests.push_back(std::move(request));
    }
    if (model::Check written = writeSolutionOutputs(m_options, requests, *input.scene, s); !written) {
        fail(job, kExitFailure, written.error().message);
        m_progress.finished(index, job.name, "failed", "not written: " + model::printable(job.error),
                            {{"error", job.error}});
        return;
    }
    job.report["status"] = "solved";
    if (!writeReport(job)) {
        m_progress.finished(index, job.name, "failed", "not written: " + model::printable(job.error),
                            {{"error", job.error}});
        return;
    }
    job.outcome = Outcome::Solved;
    char line[200];
    std::snprintf(line, sizeof line, "solved: %d iterations (%s), %d elements, unshot %.3g %% of emitted, %.2f s",
                  stats.iterations, solver::stopReasonName(stop), stats.elements, 100.0 * stats.unshotRatio, seconds());
    m_progress.finished(index, job.name, "solved", line, fields);
}

} // namespace

std::string sceneNameOf(const std::string& file)
{
    std::string name = fs::path(file).filename().string();
    if (name.size() > 5 && name.ends_with(".json"))
        name.resize(name.size() - 5);
    return name;
}

int runBatch(const SolveOptions& given)
{
    SolveOptions options = given;
    std::vector<SceneJob> jobs;
    std::map<std::string, std::string> fileOfName;
    for (const std::string& file : options.files) {
        SceneJob job;
        job.file = file;
        job.name = sceneNameOf(file);
        if (const auto [it, fresh] = fileOfName.emplace(job.name, file); !fresh)
            return solveUsageError("'" + model::printable(it->second) + "' and '" + model::printable(file) +
                                   "' would both write " + model::printable(job.name) +
                                   ".report.json: give scenes of different names");
        jobs.push_back(std::move(job));
    }

    std::error_code ec;
    fs::create_directories(*options.outDir, ec);
    if (ec || !fs::is_directory(*options.outDir)) {
        std::cerr << "regio-solve solve: cannot create the directory " << model::printable(*options.outDir) << ": "
                  << (ec ? ec.message() : "a file of that name is in the way") << "\n";
        return kExitFailure;
    }

    // Scenes at once and threads per solve: the machine's cores shared out.
    // Whole scenes side by side use the cores better than one scene's
    // threads do (its shots wait for one another; docs/batch.md), so a
    // batch of many scenes runs one per core unless told otherwise.
    const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
    const int sceneCount = static_cast<int>(jobs.size());
    int workers = options.jobs;
    if (workers == 0)
        workers = options.solver.threads > 0 ? std::max(1, cores / options.solver.threads) : cores;
    workers = std::min(workers, sceneCount);
    if (options.solver.threads == 0)
        options.solver.threads = std::clamp(cores / workers, 1, 8);
    if (!options.cacheGiven)
        options.solver.formFactorCacheBytes /= static_cast<std::size_t>(workers);

    const InterruptGuard interrupt;
    Batch batch(options, std::move(jobs));
    batch.run(workers);

    std::ostream& table = options.progress == ProgressStyle::Json ? std::cerr : std::cout;
    if (!options.quiet)
        printSummary(table, batch.jobs(), batch.progress().elapsed());

    int exitCode = kExitOk;
    nlohmann::json reports = nlohmann::json::array();
    for (const SceneJob& job : batch.jobs()) {
        exitCode = std::max(exitCode, job.exitCode);
        if (!job.report.is_null())
            reports.push_back(job.report);
    }
    nlohmann::json summary = summaryCounts(batch.jobs());
    batch.progress().summary(std::move(summary));

    if (options.reportPath && !writeReportTo(*options.reportPath, reports))
        exitCode = std::max(exitCode, kExitFailure);
    if (InterruptGuard::interrupted()) {
        std::cerr << "regio-solve solve: interrupted; finished scenes are kept, the rest are solved by running the "
                     "same command again\n";
        return InterruptGuard::exitCode();
    }
    return exitCode;
}

} // namespace regio::cli
