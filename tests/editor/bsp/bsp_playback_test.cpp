// Painter-order playback (paper §5.6, Appendix A): the sequence the editor
// replays is the solver's traversal from the same point, element for element,
// on the solver's own preparation of the scene; stepping and playing only
// change how much of it is shown.
#include "editor/app/main_window.h"
#include "editor/bsp/bsp_authoring.h"
#include "editor/bsp/bsp_layers.h"
#include "editor/bsp/painter_playback.h"
#include "editor/document/scene_document.h"
#include "editor/viewport/viewport.h"
#include "solver/authoring/region_proposal.h"
#include "solver/solver.h"
#include "solver/visibility/traversal.h"
#include "support/editor_documents.h"
#include "support/editor_windows.h"
#include "support/furnished_room.h"
#include "support/qt_test_registry.h"

#include <QElapsedTimer>
#include <QSignalSpy>

#include <memory>

using namespace regio;
using namespace regio::editor;

namespace {

std::unique_ptr<MainWindow> makeWindow(const QString& scene)
{
    auto window = test::quietWindow();
    if (!window->openFile(scene))
        qFatal("cannot open %s", qPrintable(scene));
    return window;
}

// The solver's order on the solver's own preparation of the scene (a
// Solver made from the same scene, as regio-solve makes it): the node walk of
// solver/visibility/traversal.h, and the painted elements of solver/visibility/painter_order.h,
// which the solver's tests hold equal to what Visibility paints.
void compareWithSolver(const solver::PainterOrder& order, const solver::PreparedScene& prepared, const model::Vec3& eye,
                       const model::Plane* cull)
{
    std::vector<int> nodes;
    solver::backToFrontNodes(prepared, eye, cull, nodes);
    QCOMPARE(order.nodes, nodes);
    const solver::PainterOrder expected =
        cull ? solver::painterOrder(prepared, eye, *cull) : solver::painterOrder(prepared, eye);
    QCOMPARE(order.culledRegions, expected.culledRegions);
    QCOMPARE(order.steps.size(), expected.steps.size());
    QVERIFY(!order.steps.empty());
    for (size_t i = 0; i < order.steps.size(); ++i) {
        QCOMPARE(order.steps[i].element, expected.steps[i].element);
        QCOMPARE(order.steps[i].node, expected.steps[i].node);
        QCOMPARE(order.steps[i].receives, expected.steps[i].receives);
    }
}

// A Solver made from the scene as regio-solve makes it, but with adaptive
// subdivision off: the playback paints the prepared mesh, before any split.
std::unique_ptr<solver::Solver> solverFor(const model::Scene& scene)
{
    solver::SolverOptions options;
    options.adaptive = false;
    model::Result<std::unique_ptr<solver::Solver>> created = solver::Solver::create(scene, options);
    if (!created.ok())
        qFatal("the solver refused the scene");
    return std::move(*created);
}

} // namespace

class BspPlaybackTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { test::initTestEnvironment(); }

    void thePlaybackFromAPointIsTheSolversTraversalFromThere_data()
    {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<double>("x");
        QTest::addColumn<double>("y");
        QTest::addColumn<double>("z");
        QTest::newRow("two lights, west region") << test::sampleFile("two-lights-room") << 1.0 << 1.2 << 2.0;
        QTest::newRow("two lights, above the table") << test::sampleFile("two-lights-room") << 3.1 << 1.5 << 1.7;
        QTest::newRow("two lights, east corner") << test::sampleFile("two-lights-room") << 5.9 << 2.9 << 3.9;
        QTest::newRow("cornell box") << test::sampleFile("cornell-box") << 0.28 << 0.27 << 0.25;
    }

    void thePlaybackFromAPointIsTheSolversTraversalFromThere()
    {
        QFETCH(QString, scene);
        QFETCH(double, x);
        QFETCH(double, y);
        QFETCH(double, z);
        auto window = makeWindow(scene);
        PainterPlayback* playback = window->bspAuthoring()->playback();
        const model::Vec3 eye(x, y, z);
        QVERIFY(playback->startFromPoint(eye));
        auto solver = solverFor(window->document()->scene());
        QCOMPARE(playback->prepared()->elements.size(), solver->prepared().elements.size());
        compareWithSolver(*playback->order(), solver->prepared(), eye, nullptr);
        QVERIFY(playback->order()->culledRegions.empty()); // nothing is culled from a free point
    }

    void thePlaybackFromAPatchIsTheSolversShotFromThatPatch()
    {
        auto window = makeWindow(test::sampleFile("two-lights-room"));
        PainterPlayback* playback = window->bspAuthoring()->playback();
        auto solver = solverFor(window->document()->scene());
        const solver::PreparedScene& prepared = solver->prepared();
        // A patch of the west lamp: regions behind its plane are culled.
        const int patch = playback->patchAt("lamp1.panel.ny", model::Vec3(1.0, 2.9, 2.0));
        QVERIFY(patch >= 0);
        QVERIFY(playback->startFromPatch(patch));
        const solver::Patch& p = prepared.patches[size_t(patch)];
        // The patch under the point: its triangle holds it.
        QCOMPARE(playback->patchAt("lamp1.panel.ny", p.centroid), patch);
        // The shooter sits at the patch centroid on its face's plane (ShooterFrame::make).
        const model::Plane plane =
            model::Plane::fromPointNormal(p.centroid, prepared.properties[size_t(p.properties)].plane.normal);
        compareWithSolver(*playback->order(), prepared, p.centroid, &plane);
    }

    void onAHundredObjectRoomInRegionsThePlaybackIsTheSolversTraversal()
    {
        const model::Scene room = test::furnishedRoom(1);
        const model::Scene scene = solver::withRegions(room, solver::proposeRegions(room)->regions);
        MainWindowOptions options;
        options.persistent = false;
        options.interactive = false;
        options.autosave = false;
        MainWindow window(options);
        test::resetDocument(*window.document(), scene);
        PainterPlayback* playback = window.bspAuthoring()->playback();
        const model::Vec3 eye(5.3, 1.4, 4.1);
        QElapsedTimer clock;
        clock.start();
        QVERIFY(playback->startFromPoint(eye));
        const qint64 first = clock.restart();
        QVERIFY(playback->startFromPoint(eye + model::Vec3(2.0, 0.0, 1.0)));
        const qint64 again = clock.elapsed();
        auto solver = solverFor(scene);
        compareWithSolver(*playback->order(), solver->prepared(), eye + model::Vec3(2.0, 0.0, 1.0), nullptr);
        qInfo("100-object room, %d regions, %d elements: first playback %lld ms (preparing the scene), next %lld ms",
              int(scene.regions.size()), playback->stepCount(), first, again);
    }

    void steppingShowsThePaintedElementsInOrder()
    {
        auto window = makeWindow(test::sampleFile("cornell-box"));
        PainterPlayback* playback = window->bspAuthoring()->playback();
        Viewport* viewport = window->viewport();
        QVERIFY(playback->startFromPoint(model::Vec3(0.28, 0.27, 0.25)));
        // Started: the whole sequence as a colour ramp.
        QCOMPARE(playback->step(), playback->stepCount());
        const ViewportLayer* layer = viewport->layer(PainterPlayback::layerName());
        QVERIFY(layer);
        QVERIFY(layer->replacesSurfaces);
        // Two triangles (front and back) of 3 vertices of 7 floats per piece
        // triangle painted; an element whose edges take the corners of a
        // touching face is painted as a fan of several.
        const auto floatsOf = [&](int steps) {
            size_t triangles = 0;
            for (int i = 0; i < steps; ++i)
                triangles += size_t(std::max(playback->order()->steps[size_t(i)].pieceCount, 1));
            return triangles * 2 * 3 * 7;
        };
        QCOMPARE(layer->triangles.vertices().size(), floatsOf(playback->stepCount()));
        QVERIFY(floatsOf(playback->stepCount()) > size_t(playback->stepCount()) * 2 * 3 * 7);
        playback->setStep(5);
        QCOMPARE(viewport->layer(PainterPlayback::layerName())->triangles.vertices().size(), floatsOf(5));
        // The first painted element gets the first ramp colour.
        const auto& v = viewport->layer(PainterPlayback::layerName())->triangles.vertices();
        const glm::vec4 first = paintStepColour(0, playback->stepCount(), playback->order()->steps[0].receives);
        QCOMPARE(v[3], first.r);
        QCOMPARE(v[4], first.g);
        QCOMPARE(v[5], first.b);
        // Playing runs the sequence to its end.
        playback->setSpeed(100000);
        playback->play();
        QVERIFY(playback->playing());
        QTRY_COMPARE_WITH_TIMEOUT(playback->step(), playback->stepCount(), 10000);
        QVERIFY(!playback->playing());
        playback->stop();
        QVERIFY(!viewport->hasLayer(PainterPlayback::layerName()));
        QVERIFY(!viewport->hasLayer(PainterPlayback::markerLayerName()));
    }

    void aSceneChangeEndsThePlayback()
    {
        auto window = makeWindow(test::sampleFile("two-lights-room"));
        BspAuthoring* bsp = window->bspAuthoring();
        PainterPlayback* playback = bsp->playback();
        QVERIFY(playback->startFromPoint(model::Vec3(3.0, 1.5, 2.0)));
        QVERIFY(playback->active());
        QVERIFY(bsp->moveToTop(2));
        QVERIFY(!playback->active());
        QVERIFY(!window->viewport()->hasLayer(PainterPlayback::layerName()));
    }

    void rampColoursRunFromBlueToRedAndBlockersAreGrey()
    {
        const glm::vec4 first = paintStepColour(0, 100, true);
        const glm::vec4 last = paintStepColour(99, 100, true);
        QVERIFY(first.b > first.r);
        QVERIFY(last.r > last.b);
        const glm::vec4 blocker = paintStepColour(50, 100, false);
        QCOMPARE(blocker.r, blocker.g);
        QCOMPARE(blocker.g, blocker.b);
    }
};

REGIO_QTEST_MAIN(BspPlaybackTest)
#include "bsp_playback_test.moc"
