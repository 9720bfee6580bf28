// The batch's running commentary (batch_progress.h).
#include "cli/batch_progress.h"

#include "model/io/printable.h"

#include <iostream>

namespace regio::cli {

BatchProgress::BatchProgress(ProgressStyle style, bool quiet, int sceneCount)
    : m_style(style)
    , m_quiet(quiet)
    , m_count(sceneCount)
    , m_start(std::chrono::steady_clock::now())
{
}

double BatchProgress::elapsed() const
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
}

void BatchProgress::emit(nlohmann::json line)
{
    line["elapsed"] = std::round(elapsed() * 1000.0) / 1000.0;
    // Names come from file names: keep the line valid UTF-8 whatever they hold.
    std::cout << line.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << "\n" << std::flush;
}

void BatchProgress::started(int index, const std::string& scene, const std::string& file)
{
    const std::lock_guard lock(m_mutex);
    m_percent[scene] = -1;
    if (m_style == ProgressStyle::Json)
        emit({{"event", "start"}, {"scene", scene}, {"file", file}, {"index", index + 1}, {"total", m_count}});
    else if (!m_quiet)
        std::cerr << "[" << index + 1 << "/" << m_count << "] " << model::printable(scene) << ": started\n";
}

void BatchProgress::phase(const std::string& scene, const char* phase)
{
    const std::lock_guard lock(m_mutex);
    if (m_style == ProgressStyle::Json)
        emit({{"event", "phase"}, {"scene", scene}, {"phase", phase}});
}

void BatchProgress::shot(const std::string& scene, int iteration, double unshot, int percent)
{
    const std::lock_guard lock(m_mutex);
    int& last = m_percent[scene];
    if (percent <= last)
        return;
    last = percent;
    if (m_style == ProgressStyle::Json)
        emit({{"event", "progress"},
              {"scene", scene},
              {"phase", "shoot"},
              {"iteration", iteration},
              {"unshot", unshot},
              {"percent", percent}});
}

void BatchProgress::finished(int index, const std::string& scene, const char* status, const std::string& line,
                             nlohmann::json fields)
{
    const std::lock_guard lock(m_mutex);
    m_percent.erase(scene);
    if (m_style == ProgressStyle::Json) {
        fields["event"] = status;
        fields["scene"] = scene;
        emit(std::move(fields));
    } else if (!m_quiet) {
        std::cerr << "[" << index + 1 << "/" << m_count << "] " << model::printable(scene) << ": " << line << "\n";
    }
}

void BatchProgress::message(const std::string& text)
{
    const std::lock_guard lock(m_mutex);
    std::cerr << text << "\n";
}

void BatchProgress::summary(nlohmann::json fields)
{
    const std::lock_guard lock(m_mutex);
    if (m_style == ProgressStyle::Json) {
        fields["event"] = "summary";
        emit(std::move(fields));
    }
}

} // namespace regio::cli
