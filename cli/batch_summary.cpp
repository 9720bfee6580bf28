// The end of a batch in a table and in counts (batch_summary.h).
#include "cli/batch_summary.h"

#include "model/io/printable.h"

#include <algorithm>
#include <cstdio>
#include <map>

namespace regio::cli {

const char* outcomeName(Outcome outcome)
{
    switch (outcome) {
    case Outcome::NotStarted: return "not started";
    case Outcome::Solved: return "solved";
    case Outcome::Skipped: return "skipped";
    case Outcome::Failed: return "failed";
    case Outcome::Interrupted: return "interrupted";
    }
    return "";
}

// The table people read at the end: one row per scene.
void printSummary(std::ostream& out, const std::vector<SceneJob>& jobs, std::optional<double> seconds)
{
    std::size_t width = 5;
    for (const SceneJob& job : jobs)
        width = std::max(width, model::printable(job.name).size());
    char row[512];
    std::snprintf(row, sizeof row, "%-*s  %-11s  %10s  %9s  %9s  %8s\n", static_cast<int>(width), "scene", "status",
                  "iterations", "unshot %", "elements", "seconds");
    out << row;
    std::map<Outcome, int> counts;
    for (const SceneJob& job : jobs) {
        ++counts[job.outcome];
        const nlohmann::json& r = job.report;
        const auto number = [&](const nlohmann::json& value) { return value.is_number() ? value.get<double>() : -1.0; };
        const auto field = [&](const char* key) {
            return r.is_object() && r.contains(key) ? r[key] : nlohmann::json();
        };
        const double iterations = number(field("iterations"));
        const double unshot = number(field("unshotRatio"));
        const double elements = number(field("elements"));
        const nlohmann::json times = field("seconds");
        const double secs = times.is_object() && times.contains("total") ? number(times["total"]) : -1.0;
        const auto cell = [](double value, const char* format) {
            char text[32] = "-";
            if (value >= 0.0)
                std::snprintf(text, sizeof text, format, value);
            return std::string(text);
        };
        std::snprintf(row, sizeof row, "%-*s  %-11s  %10s  %9s  %9s  %8s\n", static_cast<int>(width),
                      model::printable(job.name).c_str(), outcomeName(job.outcome), cell(iterations, "%.0f").c_str(),
                      cell(unshot < 0 ? -1.0 : 100.0 * unshot, "%.3g").c_str(), cell(elements, "%.0f").c_str(),
                      job.outcome == Outcome::Skipped ? "-" : cell(secs, "%.2f").c_str());
        out << row;
        if (job.outcome == Outcome::Failed && !job.error.empty())
            out << "  " << model::printable(job.error) << "\n";
    }
    out << jobs.size() << (jobs.size() == 1 ? " scene: " : " scenes: ") << counts[Outcome::Solved] << " solved, "
        << counts[Outcome::Skipped] << " skipped, " << counts[Outcome::Failed] << " failed";
    if (counts[Outcome::Interrupted] > 0 || counts[Outcome::NotStarted] > 0)
        out << ", " << counts[Outcome::Interrupted] << " interrupted, " << counts[Outcome::NotStarted]
            << " not started";
    if (seconds) {
        char total[64];
        std::snprintf(total, sizeof total, " in %.2f s", *seconds);
        out << total;
    }
    out << "\n" << std::flush;
}

nlohmann::json summaryCounts(const std::vector<SceneJob>& jobs)
{
    nlohmann::json counts{{"scenes", jobs.size()}};
    for (Outcome outcome :
         {Outcome::Solved, Outcome::Skipped, Outcome::Failed, Outcome::Interrupted, Outcome::NotStarted}) {
        const auto n = std::count_if(jobs.begin(), jobs.end(), [&](const SceneJob& j) { return j.outcome == outcome; });
        std::string key = outcomeName(outcome);
        std::replace(key.begin(), key.end(), ' ', '_');
        counts[key] = n;
    }
    return counts;
}

} // namespace regio::cli
