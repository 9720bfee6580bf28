// The radiosity preview's runner and controller without a GL context:
// equality with regio-solve, stop/pause/reset, the layers the viewport gets
// while solving, the inspector, the hemicube view, exports. How fast they
// answer while solving: preview_runner_timing_test.cpp.
#include "editor/app/main_window.h"
#include "editor/document/commands/solver_settings_commands.h"
#include "editor/document/scene_document.h"
#include "editor/preview/convergence_plot.h"
#include "editor/preview/preview_controller.h"
#include "editor/preview/preview_display.h"
#include "editor/preview/preview_export.h"
#include "editor/preview/preview_inspector.h"
#include "editor/preview/preview_runner.h"
#include "editor/preview/solver_dock.h"
#include "editor/preview/solver_presets.h"
#include "editor/viewport/viewport.h"
#include "model/io/scene_json.h"
#include "output/exact_direct.h"
#include "preview_scenes.h"
#include "support/command_run.h"
#include "support/editor_documents.h"
#include "support/editor_windows.h"
#include "support/preview_waits.h"
#include "support/qt_test_registry.h"

#include <QElapsedTimer>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProgressBar>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTimer>

#include <glm/geometric.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <memory>
#include <thread>

using namespace regio;
using namespace regio::editor;

namespace {

std::unique_ptr<MainWindow> makeWindow() { return test::quietWindow(); }

using test::longSample;
using test::waitForFinal;
using test::waitForState;

// The draft preset on a sample: seconds to solve, thousands of elements.
model::Scene draftSample(const char* name)
{
    model::Scene scene = test::loadSample(name);
    scene.solver = applyPreset(scene.solver, SolverPreset::Draft);
    return scene;
}

} // namespace

class PreviewRunnerTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { test::initTestEnvironment(); }

    void previewAfterNStepsEqualsRegioSolveIterationsN_data()
    {
        QTest::addColumn<QString>("sample");
        QTest::addColumn<int>("iterations");
        QTest::addColumn<bool>("adaptive");
        QTest::addColumn<bool>("anchoring");
        QTest::newRow("cornell-box") << QStringLiteral("cornell-box") << 40 << true << true;
        QTest::newRow("two-lights-room") << QStringLiteral("two-lights-room") << 25 << true << true;
        QTest::newRow("cornell-box, adaptive subdivision without anchoring")
            << QStringLiteral("cornell-box") << 40 << true << false;
        QTest::newRow("two-lights-room, adaptive subdivision without anchoring")
            << QStringLiteral("two-lights-room") << 25 << true << false;
        QTest::newRow("cornell-box, no adaptive subdivision") << QStringLiteral("cornell-box") << 40 << false << true;
        QTest::newRow("two-lights-room, no adaptive subdivision")
            << QStringLiteral("two-lights-room") << 25 << false << true;
    }
    void previewAfterNStepsEqualsRegioSolveIterationsN()
    {
        QFETCH(QString, sample);
        QFETCH(int, iterations);
        QFETCH(bool, adaptive);
        QFETCH(bool, anchoring);
        test::ScratchDir scratch;
        model::Scene scene = test::loadSample(sample.toStdString());
        scene.solver.adaptive.enabled = adaptive; // the samples' own thresholds and minimum edges
        scene.solver.adaptive.anchoring = anchoring;
        // Both solve the same file.
        const std::string path = (scratch / "scene.json").string();
        QVERIFY(model::saveSceneFile(scene, path).ok());
        PreviewRunner runner;
        runner.start(scene, iterations);
        QVERIFY(waitForFinal(runner));
        QVERIFY(runner.frame());
        if (runner.frame()->snapshot.stats.iterations != iterations)
            qWarning("history %d points, stop %s, %d elements", int(runner.frame()->history.size()),
                     solver::stopReasonName(runner.frame()->snapshot.stats.stop),
                     runner.frame()->snapshot.stats.elements);
        QCOMPARE(runner.frame()->snapshot.stats.iterations, iterations);
        const std::vector<solver::FaceResult> preview = faceMeans(runner.frame()->snapshot);

        const std::string report = (scratch / "report.json").string();
        const test::CommandRun run = test::runRegioSolve(
            {"solve", path, "--iterations", std::to_string(iterations), "--report", report, "--quiet"});
        QVERIFY2(run.exited && run.exitCode == 0, run.err.c_str());
        QFile file(QString::fromStdString(report));
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QJsonDocument json = QJsonDocument::fromJson(file.readAll());
        QJsonObject entry = json.object();
        if (entry.contains(QStringLiteral("scenes")))
            entry = entry.value(QStringLiteral("scenes")).toArray().first().toObject();
        QCOMPARE(entry.value(QStringLiteral("stats")).toObject().value(QStringLiteral("iterations")).toInt(iterations),
                 iterations);
        // With adaptive subdivision on, the row proves something only if the
        // mesh was refined (a round runs before the shot after a light's shot).
        const int rounds = entry.value(QStringLiteral("adaptive")).toObject().value(QStringLiteral("rounds")).toInt(-1);
        QCOMPARE(runner.frame()->snapshot.stats.adaptiveRounds, adaptive ? rounds : 0);
        if (adaptive)
            QVERIFY2(rounds > 0, "regio-solve refined the mesh");
        const QJsonArray faces = entry.value(QStringLiteral("faces")).toArray();
        QCOMPARE(qsizetype(preview.size()), faces.size());
        int compared = 0;
        for (qsizetype i = 0; i < faces.size(); ++i) {
            const QJsonObject f = faces[i].toObject();
            QCOMPARE(f.value(QStringLiteral("id")).toString().toStdString(), preview[size_t(i)].id);
            const QJsonArray b = f.value(QStringLiteral("radiosity")).toArray();
            for (int c = 0; c < 3; ++c) {
                const double expected = b[c].toDouble();
                const double got = preview[size_t(i)].radiosity[c];
                // 0.1 % of the value, and a floor far below anything visible for unlit faces.
                QVERIFY2(std::abs(got - expected) <= 1e-3 * std::abs(expected) + 1e-9,
                         qPrintable(QStringLiteral("%1 channel %2: preview %3, regio-solve %4")
                                        .arg(f.value(QStringLiteral("id")).toString())
                                        .arg(c)
                                        .arg(got, 0, 'g', 10)
                                        .arg(expected, 0, 'g', 10)));
                ++compared;
            }
        }
        QVERIFY(compared > 30);
    }

    void stopFinishesTheSolveAndKeepsTheSolution()
    {
        PreviewRunner runner;
        runner.start(longSample());
        QVERIFY(waitForState(runner, PreviewState::Running));
        QTRY_VERIFY_WITH_TIMEOUT(runner.frame() && runner.frame()->snapshot.stats.iterations > 5, 60000);
        runner.stop();
        QVERIFY(waitForState(runner, PreviewState::Finished, 5000));
        QTRY_VERIFY(runner.frame() && !runner.frame()->running);
        const int iterations = runner.frame()->snapshot.stats.iterations;
        QTest::qWait(200);
        QCOMPARE(runner.frame()->snapshot.stats.iterations, iterations); // nothing shoots any more
        QVERIFY(!runner.frame()->snapshot.radiosity.empty());
    }

    void everyFrameWhileSolvingIsSmoothLikeTheFinalOne()
    {
        // Through refinement rounds that grow the mesh: each frame is the smooth
        // picture of its own mesh (welded: triangles share their corners, where
        // the flat element mesh has three of its own for every triangle).
        PreviewRunner runner;
        int frames = 0, meshes = 0, lastElements = -1;
        bool allSmooth = true;
        connect(&runner, &PreviewRunner::frameReady, this, [&] {
            const std::shared_ptr<const PreviewFrame> f = runner.frame();
            if (!f || !f->running)
                return;
            ++frames;
            const int elements = f->snapshot.stats.elements;
            meshes += elements != lastElements;
            lastElements = elements;
            allSmooth = allSmooth && f->smooth && f->lit->vertexCount() < 2 * f->lit->triangleCount() &&
                        f->lit->triangleCount() >= f->snapshot.radiosity.size();
        });
        runner.start(longSample());
        QVERIFY(waitForState(runner, PreviewState::Running));
        QTRY_VERIFY_WITH_TIMEOUT(meshes >= 3 && frames >= 10, 60000);
        runner.stop();
        QVERIFY(waitForState(runner, PreviewState::Finished, 5000));
        QVERIFY(allSmooth);
        QTRY_VERIFY(runner.frame() && !runner.frame()->running);
        QVERIFY(runner.frame()->smooth);
    }

    void theFinalFrameIsThePictureTheOutputsDraw()
    {
        // The preview shows what the exports and regio-solve --image draw:
        // smooth vertex radiosity with the lights' direct part exact, on
        // triangles cut at their edges' midpoints. Without adaptive
        // subdivision the preview's mesh is the one a fresh preparation
        // makes, so the picture can be made again here.
        model::Scene scene = test::loadSample("cornell-box");
        scene.solver.adaptive.enabled = false;
        PreviewRunner runner;
        runner.start(scene);
        QVERIFY(waitForFinal(runner));
        const std::shared_ptr<const PreviewFrame> frame = runner.frame();
        QVERIFY(frame && frame->smooth && frame->lit);
        auto solver = solver::Solver::create(scene);
        QVERIFY(solver.ok());
        const solver::PreparedScene& prepared = (*solver)->prepared();
        QCOMPARE(prepared.elements.size(), frame->snapshot.radiosity.size());
        const double share = output::directShare(prepared, frame->unshot);
        QVERIFY(share > 0.999); // the light has shot all it emits
        const output::LitMesh expected = output::ExactDirectShading(prepared, {}, nullptr, output::CutFor::Screen)
                                             .litMesh(frame->snapshot.radiosity, share);
        const output::LitMesh smooth = output::smoothLitMesh(prepared, frame->snapshot.radiosity);
        QVERIFY(expected.vertexCount() > smooth.vertexCount()); // the cut's midpoints
        QCOMPARE(frame->lit->vertexCount(), expected.vertexCount());
        QCOMPARE(frame->lit->indices, expected.indices);
        float largest = 0.0f;
        for (size_t v = 0; v < expected.vertexCount(); ++v) {
            largest = std::max(largest, glm::length(expected.radiosity[v]));
            QVERIFY2(glm::length(frame->lit->radiosity[v] - expected.radiosity[v]) <=
                         1e-6f * glm::length(expected.radiosity[v]) + 1e-9f,
                     qPrintable(QStringLiteral("vertex %1").arg(v)));
        }
        QVERIFY(largest > 0.0f);
    }

    void pauseHoldsTheSolveAndResumeContinuesIt()
    {
        PreviewRunner runner;
        runner.start(longSample());
        QVERIFY(waitForState(runner, PreviewState::Running));
        QTRY_VERIFY_WITH_TIMEOUT(runner.frame() && runner.frame()->snapshot.stats.iterations > 2, 60000);
        runner.pause();
        QVERIFY(waitForState(runner, PreviewState::Paused, 5000));
        QTRY_VERIFY(!runner.frame()->running);
        const int paused = runner.frame()->snapshot.stats.iterations;
        QTest::qWait(300);
        QCOMPARE(runner.frame()->snapshot.stats.iterations, paused);
        runner.resume();
        QCOMPARE(runner.state(), PreviewState::Running);
        QTRY_VERIFY_WITH_TIMEOUT(runner.frame()->snapshot.stats.iterations > paused, 20000);
        runner.stop();
        QVERIFY(waitForState(runner, PreviewState::Finished, 5000));
    }

    void resetDropsTheSolutionAndEveryWorker()
    {
        PreviewRunner runner;
        for (int i = 0; i < 5; ++i) {
            runner.start(longSample());
            QTest::qWait(20 * i);
        }
        QVERIFY(waitForState(runner, PreviewState::Running));
        runner.reset();
        QCOMPARE(runner.state(), PreviewState::Idle);
        QVERIFY(!runner.frame());
        QTRY_COMPARE_WITH_TIMEOUT(runner.retiredSessions(), 0, 5000);
        QTRY_COMPARE_WITH_TIMEOUT(PreviewSession::liveSessions(), 0, 5000);
    }

    void aSceneThatCannotBePreparedFailsWithItsReason()
    {
        model::Scene scene = test::loadSample("cornell-box");
        scene.objects[0].parts[0].faces[0].material = "no-such-material";
        PreviewRunner runner;
        QSignalSpy failed(&runner, &PreviewRunner::failed);
        runner.start(scene);
        QVERIFY(waitForState(runner, PreviewState::Failed, 30000));
        QCOMPARE(failed.count(), 1);
        QVERIFY(!failed.first().first().toString().isEmpty());
    }

    // What escapes a solver on the worker thread (running out of memory, a
    // fault of the solver's own) ends the session with the reason; before,
    // it ended the editor. The frames shown so far stay.
    void whatEscapesTheSolverFailsTheSessionNotTheEditor_data()
    {
        QTest::addColumn<int>("kind");
        QTest::addColumn<QString>("expected");
        QTest::newRow("out of memory") << 0 << QStringLiteral("the solver ran out of memory");
        QTest::newRow("an exception") << 1 << QStringLiteral("the solver failed: an invariant broke");
        QTest::newRow("anything else") << 2 << QStringLiteral("the solver failed");
    }
    void whatEscapesTheSolverFailsTheSessionNotTheEditor()
    {
        QFETCH(int, kind);
        QFETCH(QString, expected);
        PreviewSession::Config config;
        config.scene = draftSample("cornell-box");
        config.publishIntervalMs = 0;
        config.afterShot = [kind](const solver::SolverStats& stats) {
            if (stats.iterations < 5)
                return;
            if (kind == 0)
                throw std::bad_alloc();
            if (kind == 1)
                throw std::logic_error("an invariant broke");
            throw 42;
        };
        std::atomic<int> failures{0};
        PreviewSession session(std::move(config), [&](SessionEvent event) {
            if (event == SessionEvent::Failed)
                ++failures;
        });
        QTRY_VERIFY_WITH_TIMEOUT(session.exited(), 30000);
        QCOMPARE(failures.load(), 1);
        const model::Diagnostics diagnostics = session.diagnostics();
        QVERIFY(!diagnostics.empty());
        QVERIFY(diagnostics.back().isError());
        QVERIFY2(QString::fromStdString(diagnostics.back().message).startsWith(expected),
                 diagnostics.back().message.c_str());
        QVERIFY2(session.latestFrame() != nullptr, "the frames before the failure stay");
    }

    // A run announces its end before its final frame is built, which takes
    // a while on a mesh the run refined. After Continue, until a frame of
    // the new run comes, the last one is of a running solve: it must not
    // pass for the new run's final frame.
    void afterContinueTheLastFrameIsOfARunningSolveUntilTheNextComes()
    {
        PreviewSession::Config config;
        config.scene = draftSample("cornell-box");
        config.scene.solver.maxIterations = 5;
        std::atomic<bool> hold{false}; // keeps the continued run at its first shot
        config.afterShot = [&hold](const solver::SolverStats&) {
            while (hold.load())
                std::this_thread::sleep_for(std::chrono::milliseconds(1));
        };
        PreviewSession session(std::move(config), [](SessionEvent) {});
        QTRY_VERIFY_WITH_TIMEOUT(session.finished() && session.latestFrame() && !session.latestFrame()->running, 60000);
        QCOMPARE(session.latestFrame()->snapshot.stats.iterations, 5);
        hold.store(true);
        QVERIFY(session.continueRun());
        QVERIFY(session.latestFrame()->running);
        QCOMPARE(session.latestFrame()->snapshot.stats.iterations, 5);
        hold.store(false);
        QTRY_VERIFY_WITH_TIMEOUT(session.finished() && !session.latestFrame()->running, 60000);
        QCOMPARE(session.latestFrame()->snapshot.stats.iterations, 10);
    }

    void aFailedSolveLeavesTheDocumentAsItWasAndTheWindowSolvingAgain()
    {
        auto window = makeWindow();
        window->document()->reset(draftSample("cornell-box"));
        const std::string before = model::serializeScene(window->document()->scene());
        model::Scene scene = window->document()->scene();
        scene.solver.patchSize = 0.0005; // refused: half a billion elements
        PreviewRunner* runner = window->preview()->runner();
        QSignalSpy failed(runner, &PreviewRunner::failed);
        runner->start(scene);
        QVERIFY(waitForState(*runner, PreviewState::Failed, 30000));
        QCOMPARE(failed.count(), 1);
        QVERIFY2(failed.first().first().toString().contains(QStringLiteral("20 million")),
                 qPrintable(failed.first().first().toString()));
        QVERIFY(model::serializeScene(window->document()->scene()) == before);
        QVERIFY(!window->document()->isModified());
        window->preview()->run();
        QVERIFY(waitForFinal(*runner, 60000));
    }

    // The status says why a solve stopped, with the light not yet shot, and
    // Continue goes on from there: N shots and then N more are the 2N shots
    // of one solve.
    void aSolveAtItsIterationLimitSaysSoAndContinueGoesOnFromThere()
    {
        auto window = makeWindow();
        model::Scene scene = draftSample("two-lights-room");
        scene.solver.maxIterations = 30;
        window->document()->reset(scene);
        PreviewController* preview = window->preview();
        auto* progress = window->findChild<QProgressBar*>(QStringLiteral("previewProgress"));
        QVERIFY(progress);
        preview->run();
        QVERIFY(waitForState(*preview->runner(), PreviewState::Running));
        QVERIFY(waitForFinal(*preview->runner()));
        QTRY_VERIFY(
            preview->statusText().startsWith(QStringLiteral("Stopped at the iteration limit, not converged: "
                                                            "iteration 30, unshot ")));
        QVERIFY(preview->statusText().contains(QStringLiteral("(Continue goes on)")));
        QCOMPARE(preview->solverDock()->status(), preview->statusText());
        QVERIFY(progress->isHidden());
        QVERIFY(preview->continueAction()->isEnabled());

        preview->continueAction()->trigger();
        QCOMPARE(preview->runner()->state(), PreviewState::Running);
        QVERIFY(!preview->continueAction()->isEnabled());
        QVERIFY(!progress->isHidden());
        QVERIFY(waitForFinal(*preview->runner()));
        const solver::SolverStats continued = preview->runner()->frame()->snapshot.stats;
        QCOMPARE(continued.iterations, 60);
        QCOMPARE(continued.stop, solver::StopReason::MaxIterations);

        PreviewRunner straight;
        straight.start(scene, 60);
        QVERIFY(waitForFinal(straight));
        const solver::SolverStats once = straight.frame()->snapshot.stats;
        QCOMPARE(continued.elements, once.elements);
        QCOMPARE(continued.unshotRatio, once.unshotRatio);
    }

    // An exact number of shots (what --preview-iterations asks for) runs
    // without the convergence test; ending below the scene's threshold, the
    // status says converged, not "not converged".
    void anExactShotCountThatEndsBelowTheThresholdSaysConverged()
    {
        auto window = makeWindow();
        model::Scene scene = draftSample("cornell-box");
        scene.solver.convergence = 0.5; // reached after the lamp's first shots
        window->document()->reset(scene);
        PreviewController* preview = window->preview();
        preview->runIterations(200);
        QVERIFY(waitForFinal(*preview->runner()));
        const solver::SolverStats stats = preview->runner()->frame()->snapshot.stats;
        QCOMPARE(stats.iterations, 200);
        QCOMPARE(stats.stop, solver::StopReason::MaxIterations);
        QVERIFY(stats.unshotRatio < 0.5);
        QTRY_VERIFY2(preview->statusText().startsWith(QStringLiteral("Converged: iteration 200, unshot ")),
                     qPrintable(preview->statusText()));
    }

    // A refinement round brings no frame for up to a few hundred ms: the
    // status says what the solver is doing and the bar turns busy.
    void aRefinementRoundShowsInTheStatus()
    {
        auto window = makeWindow();
        window->document()->reset(test::bigRoundsRoom());
        PreviewController* preview = window->preview();
        auto* progress = window->findChild<QProgressBar*>(QStringLiteral("previewProgress"));
        preview->run();
        QVERIFY(waitForState(*preview->runner(), PreviewState::Running));
        bool seen = false;
        QElapsedTimer clock;
        clock.start();
        while (!seen && clock.elapsed() < 60000) {
            QTest::qWait(5);
            seen = preview->statusText().contains(QStringLiteral("(refining the mesh…)")) && progress->maximum() == 0;
        }
        preview->runner()->stop();
        QVERIFY2(seen, "no refinement round showed in the status");
        QVERIFY(waitForState(*preview->runner(), PreviewState::Finished));
    }

    void aSolveStoppedByTheUserSaysSoAndAConvergedOneOffersNoContinue()
    {
        auto window = makeWindow();
        window->document()->reset(longSample());
        PreviewController* preview = window->preview();
        preview->run();
        QVERIFY(waitForState(*preview->runner(), PreviewState::Running));
        QTRY_VERIFY_WITH_TIMEOUT(
            preview->runner()->frame() && preview->runner()->frame()->snapshot.stats.iterations > 3, 30000);
        QTRY_VERIFY(preview->progressPercent() >= 0);
        preview->runner()->stop();
        QVERIFY(waitForFinal(*preview->runner()));
        QTRY_VERIFY(preview->statusText().startsWith(QStringLiteral("Stopped by you, not converged: ")));
        QVERIFY(preview->continueAction()->isEnabled());
        // An edit makes the solution stale: Continue would go on with a scene
        // that is gone, so only Run is offered.
        window->document()->push(new SetSolverSettings(window->document(), draftSample("cornell-box").solver));
        QTRY_VERIFY(preview->runner()->isStale());
        QTRY_VERIFY(!preview->continueAction()->isEnabled());

        model::Scene quick = draftSample("cornell-box");
        quick.solver.convergence = 0.05;
        quick.solver.maxIterations = 100000;
        window->document()->reset(quick);
        preview->run();
        QVERIFY(waitForFinal(*preview->runner()));
        QTRY_VERIFY(preview->statusText().startsWith(QStringLiteral("Converged: ")));
        QVERIFY(!preview->continueAction()->isEnabled());
        QCOMPARE(preview->progressPercent(), 100); // the unshot power below the target
    }

    void theViewportGetsTheSolutionAndMeshLayersWhileSolving()
    {
        auto window = makeWindow();
        window->resize(800, 600);
        window->document()->reset(longSample());
        PreviewController* preview = window->preview();
        PreviewDisplay display;
        display.showMesh = true; // the heaviest layers
        preview->setDisplay(display);
        preview->run();
        QVERIFY(waitForState(*preview->runner(), PreviewState::Running));
        QTest::qWait(3000);
        preview->runner()->stop();
        QVERIFY(waitForState(*preview->runner(), PreviewState::Finished, 5000));
        QTest::qWait(100);
        QVERIFY(window->viewport()->hasLayer(QString::fromLatin1(kSolutionLayer)));
        QVERIFY(window->viewport()->layer(QString::fromLatin1(kSolutionLayer))->replacesSurfaces);
        QVERIFY(window->viewport()->hasLayer(QString::fromLatin1(kMeshLayer)));
    }

    void theStatusBarShowsIterationUnshotElementsAndTime()
    {
        auto window = makeWindow();
        window->document()->reset(draftSample("cornell-box"));
        PreviewController* preview = window->preview();
        QCOMPARE(preview->statusText(), PreviewController::tr("Preview: not solved"));
        preview->runIterations(10);
        QVERIFY(waitForFinal(*preview->runner()));
        QTRY_VERIFY(preview->layersCurrent());
        const QString text = preview->statusText();
        QVERIFY2(text.contains(QStringLiteral("iteration 10")), qPrintable(text));
        QVERIFY2(text.contains(QString::number(preview->runner()->frame()->snapshot.stats.elements)), qPrintable(text));
        QVERIFY2(text.contains(QStringLiteral("unshot")), qPrintable(text));
    }

    void editingMarksThePreviewStaleAndLiveResolvesAfterAPause()
    {
        auto window = makeWindow();
        window->document()->reset(draftSample("cornell-box"));
        PreviewController* preview = window->preview();
        preview->runIterations(5);
        QVERIFY(waitForFinal(*preview->runner()));
        QVERIFY(!preview->runner()->isStale());
        model::SolverSettings s = window->document()->scene().solver;
        s.maxIterations = 20;
        s.convergence = 1e-6; // the iteration count decides
        QVERIFY(window->document()->push(new SetSolverSettings(window->document(), s)));
        QVERIFY(preview->runner()->isStale());
        QVERIFY(preview->statusText().contains(PreviewController::tr(" (stale: the scene changed)")));
        // Not live: nothing happens by itself.
        QTest::qWait(300);
        QCOMPARE(preview->runner()->state(), PreviewState::Finished);

        preview->setLiveDelay(150);
        preview->setLive(true);
        QTRY_VERIFY_WITH_TIMEOUT(preview->runner()->state() == PreviewState::Finished && !preview->runner()->isStale(),
                                 30000);
        // A burst of edits solves once, after the burst.
        QSignalSpy states(preview->runner(), &PreviewRunner::stateChanged);
        for (int i = 0; i < 5; ++i) {
            s.maxIterations = 30 + i;
            QVERIFY(window->document()->push(new SetSolverSettings(window->document(), s)));
            QTest::qWait(40);
        }
        QVERIFY(preview->runner()->isStale());
        QTRY_VERIFY_WITH_TIMEOUT(preview->runner()->state() == PreviewState::Finished &&
                                     !preview->runner()->isStale() && !preview->runner()->frame()->running,
                                 30000);
        int preparing = 0;
        for (const QList<QVariant>& args : states)
            preparing += args.first().value<PreviewState>() == PreviewState::Preparing ? 1 : 0;
        QCOMPARE(preparing, 1);
        QCOMPARE(preview->runner()->frame()->snapshot.stats.iterations, 34);
    }

    void theInspectorNamesTheElementUnderTheCursor()
    {
        PreviewRunner runner;
        runner.start(draftSample("cornell-box"), 10);
        QVERIFY(waitForFinal(runner));
        const PreviewFrame& frame = *runner.frame();
        // Straight down onto the middle of the floor (y = 0), from inside the box.
        const model::Scene scene = test::loadSample("cornell-box");
        Ray ray;
        ray.origin = {0.1, 0.5, 0.5};
        ray.direction = {0.0, -1.0, 0.0};
        const auto hit = inspectElement(frame, ray);
        QVERIFY(hit);
        QVERIFY(hit->element >= 0);
        QVERIFY2(QString::fromStdString(hit->faceId).contains(QStringLiteral("floor")), hit->faceId.c_str());
        QVERIFY(std::abs(hit->point.y) < 1e-6);
        QVERIFY(hit->patch >= 0);
        QVERIFY(!hit->regionId.empty());
        QVERIFY(hit->area > 0.0);
        QCOMPARE(hit->radiosity, frame.snapshot.radiosity[size_t(hit->element)]);
        QVERIFY(describeInspection(*hit).contains(QString::fromStdString(hit->faceId)));
        ray.direction = {0.0, 1.0, 0.0};
        ray.origin = {0.1, 100.0, 0.5};
        QVERIFY(!inspectElement(frame, ray));
    }

    void theHemicubeOfAPatchArrivesAsFiveFacesOfElementColours()
    {
        PreviewRunner runner;
        QSignalSpy ready(&runner, &PreviewRunner::hemicubeReady);
        runner.start(draftSample("cornell-box"), 3);
        QVERIFY(waitForFinal(runner));
        runner.requestHemicube(0, 64);
        QVERIFY(ready.wait(10000));
        const auto images = ready.first().first().value<HemicubeImages>();
        QCOMPARE(images.patch, 0);
        QCOMPARE(images.faces[0].width, 64);
        QCOMPARE(images.faces[0].height, 64);
        for (int f = 1; f < 5; ++f)
            QCOMPARE(images.faces[size_t(f)].height, 32);
        QVERIFY(images.elementsSeen > 10);
        int coloured = 0;
        for (size_t p = 0; p < images.faces[0].argb.size(); ++p) {
            const int e = images.faces[0].element[p];
            if (e >= 0) {
                QCOMPARE(images.faces[0].argb[p], elementColour(e));
                ++coloured;
            }
        }
        QVERIFY(coloured > 64 * 64 / 2); // the closed box fills the top face

        // A patch of the lamp (its elements are the brightest): as its shots
        // see it, at twice the resolution (solver/shooting/shooting.h).
        const auto& radiosity = runner.frame()->snapshot.radiosity;
        const auto brightest = std::max_element(radiosity.begin(), radiosity.end(),
                                                [](const auto& a, const auto& b) { return a.g < b.g; });
        const int lampPatch = runner.frame()->elementPatch[size_t(brightest - radiosity.begin())];
        ready.clear();
        runner.requestHemicube(lampPatch, 64);
        QVERIFY(ready.wait(10000));
        const auto lamp = ready.first().first().value<HemicubeImages>();
        QCOMPARE(lamp.patch, lampPatch);
        QCOMPARE(lamp.faces[0].width, 128);
        QCOMPARE(lamp.faces[1].height, 64);
    }

    void theConvergencePlotHasOnePointPerIteration()
    {
        PreviewRunner runner;
        runner.start(draftSample("cornell-box"), 30);
        QVERIFY(waitForFinal(runner));
        const std::vector<ConvergencePoint>& h = runner.frame()->history;
        QCOMPARE(int(h.size()), 30);
        for (size_t i = 0; i < h.size(); ++i) {
            QCOMPARE(h[i].iteration, int(i) + 1);
            QVERIFY(h[i].balanceError < 1e-9);
            QVERIFY(std::abs(h[i].unshot + h[i].absorbed + h[i].escaped - 1.0) < 1e-9);
        }
        // Absorbed power grows, though not at every shot: a shot that takes
        // back an overrelaxed patch's overshoot lowers it a little.
        QVERIFY(h.back().absorbed > h.front().absorbed);
        ConvergenceDock dock;
        dock.setHistory(h);
        QCOMPARE(dock.pointCount(), 30);
    }

    void falseColourGivesALegendAndExposureBrightens()
    {
        PreviewRunner runner;
        runner.start(draftSample("cornell-box"), 20);
        QVERIFY(waitForFinal(runner));
        PreviewDisplay display;
        const PreviewLayers normal = buildPreviewLayers(*runner.frame(), display);
        QVERIFY(!normal.legend);
        QCOMPARE(normal.solution.triangles.vertices().size() / 7, runner.frame()->lit->indices.size());
        auto redSum = [&](double exposure) {
            PreviewDisplay d = display;
            d.exposure = exposure;
            const PreviewLayers layers = buildPreviewLayers(*runner.frame(), d);
            const std::vector<float>& v = layers.solution.triangles.vertices();
            double sum = 0.0;
            for (size_t i = 3; i < v.size(); i += 7)
                sum += v[i];
            return sum;
        };
        const double darker = redSum(-1.0), normalSum = redSum(0.0), brighter = redSum(1.0);
        qInfo("sum of red: %.1f at exposure -1, %.1f at 0, %.1f at +1", darker, normalSum, brighter);
        // One stop down: 2^(-1/2.2) = 0.73 of every encoded value (none clips); up: brighter, some clip at white.
        QVERIFY(darker < 0.8 * normalSum && darker > 0.65 * normalSum);
        QVERIFY(brighter > normalSum);
        display.falseColour = true;
        const PreviewLayers falseColour = buildPreviewLayers(*runner.frame(), display);
        QVERIFY(falseColour.legend);
        QVERIFY(!falseColour.legend->ticks.empty());
        QVERIFY(!falseColour.mesh);
        display.showMesh = true;
        const PreviewLayers mesh = buildPreviewLayers(*runner.frame(), display);
        QVERIFY(mesh.mesh);
        // Every element edge once: at least 3/2 lines per element (closed meshes share edges).
        QVERIFY(mesh.mesh->lines.vertices().size() / 14 >= runner.frame()->snapshot.mesh->triangles.size() * 3 / 2);
    }

    void exportsWriteTheLitModelAndABatchSceneWhoseCommandRuns()
    {
        auto window = makeWindow();
        window->document()->reset(draftSample("cornell-box"));
        PreviewController* preview = window->preview();
        QTemporaryDir dir;
        QVERIFY(preview->exportLitModel(dir.filePath(QStringLiteral("none.ply"))).has_value()); // nothing solved
        preview->runIterations(10);
        QVERIFY(waitForFinal(*preview->runner()));
        QTRY_VERIFY(preview->layersCurrent());
        for (const char* name : {"lit.ply", "lit.obj", "lit.glb"}) {
            const QString path = dir.filePath(QString::fromLatin1(name));
            const auto error = preview->exportLitModel(path);
            QVERIFY2(!error, error ? qPrintable(*error) : "");
            QVERIFY(QFileInfo(path).size() > 1000);
        }
        QVERIFY(preview->exportLitModel(dir.filePath(QStringLiteral("lit.xyz"))).has_value());

        QString command;
        const QString batch = dir.filePath(QStringLiteral("batch.json"));
        QVERIFY(!preview->exportForBatch(batch, &command));
        QVERIFY(command.startsWith(QStringLiteral("regio-solve solve ")));
        QVERIFY(command.contains(batch));
        const model::Result<model::Scene> read = model::loadSceneFile(batch.toStdString());
        QVERIFY(read.ok());
        QCOMPARE(read->solver, applyPreset(window->document()->scene().solver, SolverPreset::Final));
        QVERIFY(read->objects == window->document()->scene().objects);
        // The command's arguments are regio-solve's (a short run instead of the final one).
        std::vector<std::string> args;
        for (const QString& a : batchArguments(batch, preview->display()))
            args.push_back(a.toStdString());
        args.insert(args.end(), {"--iterations", "3", "--hemicube", "32", "--quiet"});
        const test::CommandRun run = test::runRegioSolve(args);
        QVERIFY2(run.exited && run.exitCode == 0, run.err.c_str());
        for (const char* out : {"batch.report.json", "batch.glb", "batch.png"})
            QVERIFY2(QFileInfo::exists(dir.filePath(QString::fromLatin1(out))), out);
    }
};

REGIO_QTEST_MAIN(PreviewRunnerTest)
#include "preview_runner_test.moc"
