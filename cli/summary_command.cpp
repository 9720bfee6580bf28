// `regio-solve summary DIR [SCENES...]`: the table of a batch from the
// reports it left in DIR, for batches that ran as many processes (a Slurm
// job array, xargs over ssh) and so printed no table of their own.
#include "cli/batch.h"
#include "cli/batch_summary.h"
#include "cli/commands.h"

#include "model/io/file_io.h"
#include "model/io/printable.h"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

namespace regio::cli {

namespace {

namespace fs = std::filesystem;

const char* const kSummaryUsage =
    "Usage: regio-solve summary [OPTIONS] DIR [SCENE.json...]\n"
    "\n"
    "Prints the table of a batch from the reports in DIR (NAME.report.json,\n"
    "as 'regio-solve solve --out-dir DIR' writes them): a row per scene with\n"
    "its status, iterations, unshot power, elements and time. Given the\n"
    "batch's scene files, a scene with no report counts as not started;\n"
    "otherwise every report in DIR is listed.\n"
    "\n"
    "Options:\n"
    "  --json FILE   also write the rows and the counts as JSON ('-': standard\n"
    "                output, the table then going to standard error)\n"
    "  -h, --help    show this help\n"
    "\n"
    "Exit status: 0 every scene is solved, 1 some scene failed, was\n"
    "interrupted or not started, 2 usage error or unreadable directory.\n";

int usageError(const std::string& message)
{
    std::cerr << "regio-solve summary: " << message << "\nTry 'regio-solve summary --help'.\n";
    return kExitFailure;
}

SceneJob fromReport(const fs::path& dir, const std::string& file, const std::string& name)
{
    SceneJob job;
    job.file = file;
    job.name = name;
    const model::Result<std::string> text =
        model::readFile((dir / (name + ".report.json")).string(), 1u << 26, "report");
    if (!text)
        return job; // not started
    job.report = nlohmann::json::parse(*text, nullptr, false);
    const std::string status =
        job.report.is_object() && job.report.contains("status") && job.report["status"].is_string()
            ? job.report["status"].get<std::string>()
            : "";
    if (status == "solved") {
        job.outcome = Outcome::Solved;
    } else if (status == "interrupted") {
        job.outcome = Outcome::Interrupted;
    } else {
        job.outcome = Outcome::Failed;
        job.exitCode = kExitErrors;
        const nlohmann::json errors = job.report.is_object() ? job.report.value("errors", nlohmann::json()) : nullptr;
        job.error = errors.is_array() && !errors.empty() && errors[0].is_string() ? errors[0].get<std::string>()
                                                                                  : "not a report of regio-solve";
    }
    return job;
}

} // namespace

int runSummary(int argc, char** argv)
{
    std::optional<std::string> jsonPath;
    std::vector<std::string> positional;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "-h" || arg == "--help") {
            std::cout << kSummaryUsage;
            return kExitOk;
        }
        if (arg == "--json") {
            if (i + 1 >= argc)
                return usageError("--json needs a file name");
            jsonPath = argv[++i];
        } else if (!arg.empty() && arg[0] == '-') {
            return usageError("unknown option '" + model::printable(arg) + "'");
        } else {
            positional.push_back(arg);
        }
    }
    if (positional.empty())
        return usageError("no directory given");
    const fs::path dir = positional.front();
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) {
        std::cerr << "regio-solve summary: " << model::printable(dir.string()) << " is not a directory\n";
        return kExitFailure;
    }

    std::vector<SceneJob> jobs;
    if (positional.size() > 1) {
        for (std::size_t i = 1; i < positional.size(); ++i)
            jobs.push_back(fromReport(dir, positional[i], sceneNameOf(positional[i])));
    } else {
        std::vector<std::string> names;
        for (const fs::directory_entry& entry : fs::directory_iterator(dir, ec)) {
            const std::string file = entry.path().filename().string();
            const std::string suffix = ".report.json";
            if (file.size() > suffix.size() && file.ends_with(suffix))
                names.push_back(file.substr(0, file.size() - suffix.size()));
        }
        std::sort(names.begin(), names.end());
        for (const std::string& name : names)
            jobs.push_back(fromReport(dir, name + ".json", name));
    }

    std::ostream& table = jsonPath && *jsonPath == "-" ? std::cerr : std::cout;
    printSummary(table, jobs, std::nullopt);
    int exitCode = kExitOk;
    nlohmann::json rows = nlohmann::json::array();
    for (const SceneJob& job : jobs) {
        if (job.outcome != Outcome::Solved)
            exitCode = kExitErrors;
        nlohmann::json row{{"scene", job.name}, {"status", outcomeName(job.outcome)}};
        for (const char* key : {"iterations", "unshotRatio", "elements", "stop"})
            if (job.report.is_object() && job.report.contains(key))
                row[key] = job.report[key];
        if (!job.error.empty())
            row["error"] = job.error;
        rows.push_back(std::move(row));
    }
    if (jsonPath) {
        const nlohmann::json summary{{"counts", summaryCounts(jobs)}, {"scenes", rows}};
        const std::string text = summary.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
        if (*jsonPath == "-") {
            std::cout << text << std::flush;
        } else if (model::Check written = model::writeFileAtomically(*jsonPath, text); !written) {
            std::cerr << "regio-solve summary: " << model::printable(written.error().message) << "\n";
            return kExitFailure;
        }
    }
    return exitCode;
}

} // namespace regio::cli
