#pragma once
// Ctrl-C (SIGINT) and SIGTERM for the commands that solve: the first one
// only raises a flag that the solves poll (Solver::run's cancel), so every
// file is finished or not written at all; the exit code then tells which
// signal stopped the command (128 + its number, as a shell reports it).
#include <atomic>
#include <csignal>

namespace regio::cli {

// Installs the handlers for its lifetime and restores the previous ones.
class InterruptGuard {
public:
    InterruptGuard();
    ~InterruptGuard();
    InterruptGuard(const InterruptGuard&) = delete;
    InterruptGuard& operator=(const InterruptGuard&) = delete;

    // Raised by the first signal; what the solves poll.
    static const std::atomic<bool>& flag();
    static bool interrupted() { return flag().load(); }
    // 130 after SIGINT, 143 after SIGTERM.
    static int exitCode();

private:
    using Handler = void (*)(int);
    Handler m_previousInt;
    Handler m_previousTerm;
};

} // namespace regio::cli
