// The radiosity preview in a shown window on a real OpenGL context (Xvfb +
// Mesa): editing while solving never crashes, leaks or loses the document;
// the --preview-iterations screenshot shows the lit scene; the mesh overlay
// draws anchoring edges on screen. That the UI thread keeps running while the
// viewport uploads the solution: preview_gl_timing_test.cpp.
#include "editor/app/main_window.h"
#include "editor/document/commands/material_commands.h"
#include "editor/document/commands/solver_settings_commands.h"
#include "editor/document/scene_document.h"
#include "editor/preview/preview_controller.h"
#include "editor/preview/preview_display.h"
#include "editor/preview/solver_presets.h"
#include "editor/viewport/viewport.h"
#include "model/edit/edit_materials.h"
#include "support/editor_documents.h"
#include "support/editor_windows.h"
#include "support/qt_test_registry.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QImage>
#include <QProcess>
#include <QSet>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QTimer>

#include <memory>
#include <random>

using namespace regio;
using namespace regio::editor;

namespace {

using test::showWindow;

int runEditor(const QStringList& arguments)
{
    const test::EditorRun run = test::runEditor(arguments);
    if (run.exitCode != 0)
        qWarning("%s", qPrintable(run.stderrText));
    return run.exitCode;
}

double meanDifference(const QImage& a, const QImage& b)
{
    double sum = 0.0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            const QRgb p = a.pixel(x, y), q = b.pixel(x, y);
            sum += std::abs(qRed(p) - qRed(q)) + std::abs(qGreen(p) - qGreen(q)) + std::abs(qBlue(p) - qBlue(q));
        }
    return sum / (3.0 * a.width() * a.height());
}

int distinctColours(const QImage& image, const QRect& area)
{
    QSet<QRgb> colours;
    for (int y = area.top(); y <= area.bottom(); y += 2)
        for (int x = area.left(); x <= area.right(); x += 2)
            colours.insert(image.pixel(x, y) & 0xf8f8f8);
    return int(colours.size());
}

} // namespace

class PreviewGlTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { test::initTestEnvironment(); }

    void editingStoppingAndResettingWhileSolvingNeverLosesTheDocument()
    {
        model::Scene scene = test::loadSample("two-lights-room");
        scene.solver = applyPreset(scene.solver, SolverPreset::Draft);
        auto window = showWindow(scene);
        SceneDocument* document = window->document();
        PreviewController* preview = window->preview();
        preview->setLiveDelay(20);
        preview->setLive(true);
        std::mt19937 random(7);
        const model::Scene original = document->scene();
        // What the document must hold at the end: the same edits applied to a copy.
        model::Scene expected = original;
        std::vector<std::string> materials;
        for (const model::Material& m : original.materials)
            materials.push_back(m.id);
        int edits = 0;
        for (int step = 0; step < 300; ++step) {
            switch (random() % 8) {
            case 0:
            case 1:
            case 2: {
                const std::string& id = materials[random() % materials.size()];
                const double r = 0.1 + 0.8 * double(random() % 100) / 100.0;
                const model::Rgb value{r, r * 0.9, r * 0.8};
                QVERIFY(document->push(new SetMaterialReflectance(document, id, value)));
                QVERIFY(model::setMaterialReflectance(expected, id, value));
                ++edits;
                break;
            }
            case 3: {
                model::SolverSettings s = document->scene().solver;
                s.maxIterations = 10 + int(random() % 200);
                QVERIFY(document->push(new SetSolverSettings(document, s)));
                expected.solver = s;
                ++edits;
                break;
            }
            case 4: preview->run(); break;
            case 5: preview->runner()->stop(); break;
            case 6:
                preview->runner()->state() == PreviewState::Paused ? preview->runner()->resume()
                                                                   : preview->runner()->pause();
                break;
            case 7: preview->runner()->reset(); break;
            }
            QTest::qWait(int(random() % 25));
        }
        QVERIFY(edits > 50);
        QVERIFY(document->scene() == expected);
        QVERIFY(document->isModified());
        // The history is intact: undo goes back to the file exactly.
        while (document->undoStack()->canUndo())
            document->undoStack()->undo();
        QVERIFY(document->scene() == original);
        while (document->undoStack()->canRedo())
            document->undoStack()->redo();
        // And the document still saves and reads back.
        QTemporaryDir dir;
        const QString saved = dir.filePath(QStringLiteral("stress.json"));
        QVERIFY(document->save(saved));
        const model::Result<model::Scene> read = model::loadSceneFile(saved.toStdString());
        QVERIFY(read.ok() && *read == document->scene());
        // A solve of the edited scene still works, then a reset leaves no worker behind.
        preview->run();
        QTRY_VERIFY_WITH_TIMEOUT(preview->runner()->state() == PreviewState::Finished, 60000);
        QVERIFY(!preview->runner()->isStale());
        QTRY_VERIFY_WITH_TIMEOUT(preview->layersCurrent(), 10000);
        QVERIFY(window->viewport()->hasLayer(QString::fromLatin1(kSolutionLayer)));
        preview->setLive(false);
        preview->runner()->reset();
        QTRY_COMPARE_WITH_TIMEOUT(PreviewSession::liveSessions(), 0, 5000);
        QVERIFY(!window->viewport()->hasLayer(QString::fromLatin1(kSolutionLayer)));
        window.reset();
        QCOMPARE(PreviewSession::liveSessions(), 0);
    }

    void closingTheWindowDuringASolveJoinsTheWorker()
    {
        model::Scene scene = test::loadSample("two-lights-room");
        scene.solver.maxIterations = 100000;
        scene.solver.convergence = 1e-9;
        auto window = showWindow(scene);
        window->preview()->run();
        QTRY_VERIFY_WITH_TIMEOUT(window->preview()->runner()->state() == PreviewState::Running, 60000);
        QElapsedTimer clock;
        clock.start();
        window.reset();
        qInfo("window closed during a solve in %lld ms", clock.elapsed());
        QCOMPARE(PreviewSession::liveSessions(), 0);
    }

    void theMeshOverlayShowsAnchoringEdgesOnScreenOnlyWithAnchoring()
    {
        // Pixels of the anchoring colour (orange, a hue the lit room does not take).
        auto anchoringPixels = [](bool anchoring) {
            model::Scene scene = test::loadSample("two-lights-room");
            scene.solver.hemicube = 64;
            scene.solver.adaptive.enabled = true;
            scene.solver.adaptive.threshold = 0.02;
            scene.solver.adaptive.anchoring = anchoring;
            auto window = showWindow(scene, {640, 480});
            PreviewController* preview = window->preview();
            PreviewDisplay display;
            display.showMesh = true;
            preview->setDisplay(display);
            preview->runIterations(6);
            if (!QTest::qWaitFor(
                    [&] {
                        return preview->runner()->state() == PreviewState::Finished &&
                               !preview->runner()->frame()->running && preview->layersCurrent();
                    },
                    60000))
                return -1;
            if (preview->runner()->frame()->snapshot.stats.adaptiveRounds == 0)
                return -2;
            window->viewport()->update();
            QTest::qWait(100);
            const QImage frame = window->viewport()->grabFramebuffer();
            int n = 0;
            for (int y = 0; y < frame.height(); ++y)
                for (int x = 0; x < frame.width(); ++x) {
                    const QRgb p = frame.pixel(x, y);
                    n += qRed(p) > 200 && qGreen(p) > 80 && qGreen(p) < 150 && qBlue(p) < 70 ? 1 : 0;
                }
            return n;
        };
        const int with = anchoringPixels(true), without = anchoringPixels(false);
        qInfo("anchoring-coloured pixels: %d with anchoring, %d without", with, without);
        QVERIFY2(with > 100, "anchoring edges are drawn");
        QVERIFY(without >= 0);
        QVERIFY(without * 10 < with);
    }

    void thePreviewIterationsScreenshotShowsTheLitScene()
    {
        QTemporaryDir dir;
        const QString scene = test::sampleFile("cornell-box");
        const QString unlit = dir.filePath(QStringLiteral("unlit.png"));
        const QString lit = dir.filePath(QStringLiteral("lit.png"));
        QCOMPARE(runEditor({scene, QStringLiteral("--screenshot"), unlit, QStringLiteral("--size"),
                            QStringLiteral("900x650")}),
                 0);
        QCOMPARE(runEditor({scene, QStringLiteral("--screenshot"), lit, QStringLiteral("--size"),
                            QStringLiteral("900x650"), QStringLiteral("--preview-iterations"), QStringLiteral("30")}),
                 0);
        const QImage a(unlit), b(lit);
        QVERIFY(!a.isNull() && !b.isNull());
        QCOMPARE(a.size(), b.size());
        const double difference = meanDifference(a, b);
        const QRect middle(b.width() / 3, b.height() / 3, b.width() / 3, b.height() / 3);
        const int colours = distinctColours(b, middle);
        qInfo("mean difference %.1f levels, %d distinct colours in the middle of the lit picture", difference, colours);
        QVERIFY(difference > 3.0);
        QVERIFY(colours > 30); // shading, not a blank or flat picture
    }
};

namespace {

// Its own main rather than the set-up of QTEST_MAIN: the default surface format
// has to be set before the application exists.
int runPreviewGlTest(int argc, char* argv[])
{
    QSurfaceFormat::setDefaultFormat(Viewport::requestedFormat());
    QApplication app(argc, argv);
    PreviewGlTest test;
    return QTest::qExec(&test, argc, argv);
}

} // namespace

REGIO_QTEST_OWN_MAIN(PreviewGlTest, runPreviewGlTest)

#include "preview_gl_test.moc"
