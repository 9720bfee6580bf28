#pragma once
// What a batch tells while it runs: a line per scene event on standard error
// for people, or (--progress json) one JSON object per line on standard
// output for tools: every scene event and every percent of a solve's work.
// Safe to call from the batch's worker threads.
#include "cli/solve_options.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <map>
#include <mutex>
#include <ostream>
#include <string>

namespace regio::cli {

class BatchProgress {
public:
    BatchProgress(ProgressStyle style, bool quiet, int sceneCount);

    // The scene `index` (0-based) starts; `file` as given on the command line.
    void started(int index, const std::string& scene, const std::string& file);
    // prepare, shoot or write.
    void phase(const std::string& scene, const char* phase);
    // After each shot; prints only when the percent of work done grows.
    void shot(const std::string& scene, int iteration, double unshot, int percent);
    // The scene's end: solved, skipped, failed, interrupted. `line` is what
    // people read after the scene's name; `fields` go into the JSON line.
    void finished(int index, const std::string& scene, const char* status, const std::string& line,
                  nlohmann::json fields);
    // A diagnostic or warning for people: standard error in either style.
    void message(const std::string& text);
    // The batch's last event (JSON only).
    void summary(nlohmann::json fields);

    double elapsed() const;

private:
    void emit(nlohmann::json line);

    ProgressStyle m_style;
    bool m_quiet;
    int m_count;
    std::chrono::steady_clock::time_point m_start;
    std::mutex m_mutex;
    std::map<std::string, int> m_percent;
};

} // namespace regio::cli
