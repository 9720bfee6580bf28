#pragma once
// Waiting for a PreviewRunner in the preview tests (the event loop keeps
// running, so frames and state changes arrive).
#include "editor/preview/preview_runner.h"

#include <QElapsedTimer>
#include <QTest>

namespace regio::editor::test {

// `pollMs` is how finely the state is watched: tests that time a Stop poll
// every 2 ms so the poll does not add to what they measure.
inline bool waitForState(PreviewRunner& runner, PreviewState state, int timeoutMs = 120000, int pollMs = 5)
{
    QElapsedTimer clock;
    clock.start();
    while (runner.state() != state && clock.elapsed() < timeoutMs)
        QTest::qWait(pollMs);
    return runner.state() == state;
}

// Finished, and the final frame (made after the last shot) has arrived.
inline bool waitForFinal(PreviewRunner& runner, int timeoutMs = 120000)
{
    QElapsedTimer clock;
    clock.start();
    auto done = [&] { return runner.state() == PreviewState::Finished && runner.frame() && !runner.frame()->running; };
    while (!done() && clock.elapsed() < timeoutMs)
        QTest::qWait(5);
    return done();
}

} // namespace regio::editor::test
