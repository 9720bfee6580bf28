// The signal handlers of interrupt.h: async-signal-safe, they only store.
#include "cli/interrupt.h"

namespace regio::cli {

namespace {

std::atomic<bool> g_interrupted{false};
std::atomic<int> g_signal{0};
static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<int>::is_always_lock_free,
              "set from a signal handler");

extern "C" void onInterruptSignal(int number)
{
    g_signal.store(number);
    g_interrupted.store(true);
}

} // namespace

InterruptGuard::InterruptGuard()
{
    g_interrupted = false;
    g_signal = 0;
    m_previousInt = std::signal(SIGINT, onInterruptSignal);
    m_previousTerm = std::signal(SIGTERM, onInterruptSignal);
}

InterruptGuard::~InterruptGuard()
{
    std::signal(SIGINT, m_previousInt == SIG_ERR ? SIG_DFL : m_previousInt);
    std::signal(SIGTERM, m_previousTerm == SIG_ERR ? SIG_DFL : m_previousTerm);
}

const std::atomic<bool>& InterruptGuard::flag() { return g_interrupted; }

int InterruptGuard::exitCode() { return 128 + (g_signal.load() == 0 ? SIGINT : g_signal.load()); }

} // namespace regio::cli
