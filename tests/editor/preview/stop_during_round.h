#pragma once
// One Stop pressed while the preview refines its mesh: the trial the Stop
// tests of adaptive subdivision repeat at every round, shared by the test of
// what Stop does there and the test of how soon it does it.
#include "editor/preview/preview_runner.h"
#include "preview_scenes.h"
#include "support/preview_waits.h"

#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <QTest>
#include <QTimer>

#include <memory>

namespace regio::test {

struct StopTrial {
    QString failure;          // empty, or the step that did not happen
    qint64 latencyMs = -1;    // from Stop to the runner's Finished state
    int round = 0;            // the refinement round of the frame Stop followed
    int elements = 0;         // and its element count
    bool insideRound = false; // the Stop cut a refinement round short
};

// Solves bigRoundsRoom() and presses Stop `delayMs` after the first frame that
// shows refinement round `round` and a shot. A frame is published right after
// a light's shot, before the round that shot made due, so the Stop lands in
// round `round` + 1.
inline StopTrial stopDuringRound(int round, int delayMs)
{
    editor::PreviewRunner runner;
    QElapsedTimer clock;
    std::shared_ptr<const editor::PreviewFrame> stoppedAt;
    bool scheduled = false;
    QObject::connect(&runner, &editor::PreviewRunner::frameReady, &runner, [&] {
        const auto f = runner.frame();
        if (scheduled || !f || !f->running || f->snapshot.stats.iterations < 1 ||
            f->snapshot.stats.adaptiveRounds < round)
            return;
        scheduled = true;
        QTimer::singleShot(delayMs, &runner, [&] {
            stoppedAt = runner.frame();
            clock.start();
            runner.stop();
        });
    });
    runner.start(bigRoundsRoom());
    StopTrial trial;
    if (!QTest::qWaitFor([&] { return stoppedAt != nullptr; }, 60000)) {
        trial.failure = QStringLiteral("no frame of round %1 within 60 s").arg(round);
        return trial;
    }
    if (!waitForState(runner, editor::PreviewState::Finished, 5000, /*pollMs*/ 2)) {
        trial.failure = QStringLiteral("the solve did not finish within 5 s of Stop");
        return trial;
    }
    trial.latencyMs = clock.elapsed();
    if (!waitForFinal(runner, 10000)) {
        trial.failure = QStringLiteral("no final frame within 10 s of Stop");
        return trial;
    }
    const solver::SolverStats& at = stoppedAt->snapshot.stats;
    const solver::SolverStats& end = runner.frame()->snapshot.stats;
    trial.round = at.adaptiveRounds;
    trial.elements = at.elements;
    // Time spent refining since that frame and no round completed: the Stop
    // cut a round short (no round here settles unsplit).
    trial.insideRound = end.adaptiveSeconds > at.adaptiveSeconds && end.adaptiveRounds == at.adaptiveRounds;
    return trial;
}

} // namespace regio::test
