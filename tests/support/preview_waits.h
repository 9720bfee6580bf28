#pragma once
// Waiting for a PreviewRunner in the preview tests (the event loop keeps
// running, so frames and state changes arrive).
#include "editor/preview/preview_runner.h"

#include <QElapsedTimer>
#include <QTest>
#include <QTimer>

#include <algorithm>

namespace regio::test {

// `pollMs` is how finely the state is watched: tests that time a Stop poll
// every 2 ms so the poll does not add to what they measure.
inline bool waitForState(editor::PreviewRunner& runner, editor::PreviewState state, int timeoutMs = 120000,
                         int pollMs = 5)
{
    QElapsedTimer clock;
    clock.start();
    while (runner.state() != state && clock.elapsed() < timeoutMs)
        QTest::qWait(pollMs);
    return runner.state() == state;
}

// Finished, and the final frame (made after the last shot) has arrived.
inline bool waitForFinal(editor::PreviewRunner& runner, int timeoutMs = 120000)
{
    QElapsedTimer clock;
    clock.start();
    auto done = [&] {
        return runner.state() == editor::PreviewState::Finished && runner.frame() && !runner.frame()->running;
    };
    while (!done() && clock.elapsed() < timeoutMs)
        QTest::qWait(5);
    return done();
}

// The longest the UI thread went without serving a 2 ms timer between
// start() and stop(): how long the event loop was blocked.
class UiGapMeter {
public:
    UiGapMeter()
    {
        m_ticker.setInterval(2);
        QObject::connect(&m_ticker, &QTimer::timeout, [this] {
            const qint64 now = m_clock.elapsed();
            m_longest = std::max(m_longest, now - m_last);
            m_last = now;
        });
    }
    void start()
    {
        m_last = 0;
        m_longest = 0;
        m_clock.start();
        m_ticker.start();
    }
    void stop() { m_ticker.stop(); }
    qint64 longestMs() const { return m_longest; }

private:
    QTimer m_ticker;
    QElapsedTimer m_clock;
    qint64 m_last = 0;
    qint64 m_longest = 0;
};

} // namespace regio::test
