// The radiosity preview with adaptive subdivision (paper §5.7): the element
// mesh overlay shows the subdivision and, in a colour of its own, the
// anchoring edges; Stop ends the solve also while a refinement round runs
// (how soon: preview_adaptive_timing_test.cpp); the solver dock's adaptive
// controls change what the preview solves; the status bar counts the elements
// of the growing mesh.
#include "editor/app/main_window.h"
#include "editor/document/scene_document.h"
#include "editor/preview/preview_controller.h"
#include "editor/preview/preview_display.h"
#include "editor/preview/preview_runner.h"
#include "editor/preview/solver_dock.h"
#include "editor/viewport/viewport.h"
#include "stop_during_round.h"
#include "support/editor_documents.h"
#include "support/editor_windows.h"
#include "support/preview_waits.h"
#include "support/qt_test_registry.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QStatusBar>
#include <QStringList>
#include <QTimer>

#include <algorithm>
#include <set>
#include <vector>

using namespace regio;
using namespace regio::editor;

namespace {

using test::waitForFinal;
using test::waitForState;

// The two-light room refining in earnest: the light's shadow borders split
// at every round. A coarse hemicube keeps the shots short; the rounds are
// what these tests are about.
model::Scene refiningRoom(bool anchoring = true)
{
    model::Scene scene = test::loadSample("two-lights-room");
    scene.solver.hemicube = 64;
    scene.solver.adaptive.enabled = true;
    scene.solver.adaptive.threshold = 0.02;
    scene.solver.adaptive.anchoring = anchoring;
    return scene;
}

// The Cornell box: fewer candidates than the round budgets allow, so the
// threshold decides how far it refines (in the room above the budget does).
model::Scene refiningBox()
{
    model::Scene scene = test::loadSample("cornell-box");
    scene.solver.hemicube = 64;
    scene.solver.elementsPerPatch = 4; // elements of 5 cm: 2 cm below lets them split
    scene.solver.adaptive.enabled = true;
    scene.solver.adaptive.threshold = 0.02;
    scene.solver.adaptive.minEdge = 0.02;
    scene.solver.adaptive.anchoring = true;
    return scene;
}

std::shared_ptr<const PreviewFrame> solve(const model::Scene& scene, int iterations)
{
    PreviewRunner runner;
    runner.start(scene, iterations);
    if (!waitForFinal(runner))
        return nullptr;
    return runner.frame();
}

// Line segments of a layer drawn in `colour` (LineList: 7 floats a vertex, 2 vertices a segment).
int segmentsOfColour(const ViewportLayer& layer, const glm::vec4& colour)
{
    const std::vector<float>& v = layer.lines.vertices();
    int n = 0;
    for (size_t i = 0; i + 13 < v.size(); i += 14)
        if (glm::vec4(v[i + 3], v[i + 4], v[i + 5], v[i + 6]) == colour)
            ++n;
    return n;
}

int segments(const ViewportLayer& layer) { return int(layer.lines.vertices().size() / 14); }

} // namespace

class PreviewAdaptiveTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { test::initTestEnvironment(); }

    void theMeshOverlayGrowsWithSubdivisionAndShowsAnchoringEdgesInTheirOwnColour()
    {
        // One shot: no round yet (a round runs before the shot after a light's
        // shot), only the splits along the furniture's feet before the first
        // shot (contact lines), anchored like any other.
        const auto before = solve(refiningRoom(), 1);
        const auto after = solve(refiningRoom(), 6);
        QVERIFY(before && after);
        QCOMPARE(before->snapshot.stats.adaptiveRounds, 0);
        QVERIFY(after->snapshot.stats.adaptiveRounds > 0);
        QVERIFY(after->snapshot.stats.elements > before->snapshot.stats.elements);
        QVERIFY(!after->snapshot.mesh->anchoredTriangles.empty());

        PreviewDisplay display;
        display.showMesh = true;
        const MeshOverlayColours colours = meshOverlayColours(display);
        QVERIFY(colours.element != colours.anchoring);
        const PreviewLayers coarse = buildPreviewLayers(*before, display);
        const PreviewLayers fine = buildPreviewLayers(*after, display);
        QVERIFY(coarse.mesh && fine.mesh);
        qInfo("mesh overlay: %d segments before refinement; after %d rounds %d element edges and %d anchoring edges",
              segments(*coarse.mesh), after->snapshot.stats.adaptiveRounds, fine.elementEdges, fine.anchoringEdges);
        QVERIFY(coarse.anchoringEdges > 0);
        QCOMPARE(segments(*coarse.mesh), coarse.elementEdges + coarse.anchoringEdges);
        QVERIFY(segments(*fine.mesh) > segments(*coarse.mesh));
        QVERIFY(fine.anchoringEdges > coarse.anchoringEdges);
        QCOMPARE(segments(*fine.mesh), fine.elementEdges + fine.anchoringEdges);
        QCOMPARE(segmentsOfColour(*fine.mesh, colours.anchoring), fine.anchoringEdges);
        QCOMPARE(segmentsOfColour(*fine.mesh, colours.element), fine.elementEdges);

        // The element edges are exactly the distinct edges of the elements.
        const solver::SolutionMesh& m = *after->snapshot.mesh;
        std::set<std::pair<int, int>> elementEdges;
        for (const auto& t : m.triangles)
            for (size_t k = 0; k < 3; ++k)
                elementEdges.insert(std::minmax(t[k], t[(k + 1) % 3]));
        QCOMPARE(int(elementEdges.size()), fine.elementEdges);

        // False colour: both kinds in the colours for it.
        display.falseColour = true;
        const PreviewLayers falseColour = buildPreviewLayers(*after, display);
        QCOMPARE(segmentsOfColour(*falseColour.mesh, meshOverlayColours(display).anchoring), fine.anchoringEdges);
    }

    void withAnchoringOffTheOverlayHasNoAnchoringEdges()
    {
        const auto after = solve(refiningRoom(false), 6);
        QVERIFY(after);
        QVERIFY(after->snapshot.stats.adaptiveRounds > 0);
        QVERIFY(after->snapshot.mesh->anchoredTriangles.empty());
        PreviewDisplay display;
        display.showMesh = true;
        const PreviewLayers layers = buildPreviewLayers(*after, display);
        QVERIFY(layers.mesh);
        QCOMPARE(layers.anchoringEdges, 0);
        QCOMPARE(segmentsOfColour(*layers.mesh, meshOverlayColours(display).anchoring), 0);
        QVERIFY(layers.elementEdges >= int(after->snapshot.mesh->triangles.size()) * 3 / 2);
    }

    void stopEndsTheSolveAlsoWhileARefinementRoundRuns()
    {
        // Each trial solves again and stops at another moment, twice in every
        // round of the solve (the mesh grows from 21k to 83k elements): a
        // round judges and splits in slices of a few ms, looks at the cancel
        // flag between them and leaves the hand-over of the grown mesh to the
        // next run when the flag came during the splits (solver/solver.cpp).
        constexpr int kLastRound = 8;
        int trials = 0, insideRounds = 0;
        for (int round = 0; round < kLastRound; ++round) {
            for (int delay : {0, 25}) {
                const test::StopTrial trial = test::stopDuringRound(round, delay);
                QVERIFY2(trial.failure.isEmpty(), qPrintable(trial.failure));
                ++trials;
                insideRounds += trial.insideRound ? 1 : 0;
            }
        }
        QVERIFY2(insideRounds * 2 >= trials, "the stops are meant to land inside refinement rounds");
    }

    void theSolverDocksAdaptiveControlsChangeWhatThePreviewSolves()
    {
        auto window = test::quietWindow();
        window->document()->reset(refiningBox());
        PreviewController* preview = window->preview();
        SolverDock* dock = preview->solverDock();
        auto elementsAfter = [&](int iterations) {
            preview->runIterations(iterations);
            if (!waitForFinal(*preview->runner()))
                return -1;
            return preview->runner()->frame()->snapshot.stats.elements;
        };
        auto* threshold = dock->findChild<QDoubleSpinBox*>(QStringLiteral("threshold"));
        auto* minEdge = dock->findChild<QDoubleSpinBox*>(QStringLiteral("minEdge"));
        auto* anchoring = dock->findChild<QCheckBox*>(QStringLiteral("anchoring"));
        QVERIFY(threshold && minEdge && anchoring);
        const int commands = window->document()->undoStack()->count();

        threshold->setValue(0.5);
        QCOMPARE(window->document()->scene().solver.adaptive.threshold, 0.5);
        const int loose = elementsAfter(6);
        threshold->setValue(0.02);
        const int strict = elementsAfter(6);
        const size_t anchoredStrict = preview->runner()->frame()->snapshot.mesh->anchoredTriangles.size();
        qInfo("threshold 0.5: %d elements, 0.02: %d elements after 6 shots", loose, strict);
        QVERIFY(loose > 0);
        QVERIFY(strict > loose);

        const double before = minEdge->value();
        minEdge->setValue(0.2);
        const int coarseLimit = elementsAfter(6);
        qInfo("minimum edge 0.2: %d elements", coarseLimit);
        QVERIFY(coarseLimit < strict);
        minEdge->setValue(before);

        QVERIFY(anchoring->isChecked());
        anchoring->setChecked(false);
        QCOMPARE(window->document()->scene().solver.adaptive.anchoring, false);
        const int unanchored = elementsAfter(6);
        QVERIFY(preview->runner()->frame()->snapshot.mesh->anchoredTriangles.empty());
        qInfo("anchoring off: %d elements, on: %d", unanchored, strict);
        QVERIFY(anchoredStrict > 0); // the solve with anchoring on was anchored; this one is not
        QVERIFY(window->document()->undoStack()->count() > commands);

        // Undo through the dock's commands brings the anchored solve back.
        window->document()->undoStack()->undo();
        QCOMPARE(window->document()->scene().solver.adaptive.anchoring, true);
        QCOMPARE(elementsAfter(6), strict);
    }

    void theStatusBarCountsTheElementsOfEveryFrameAsTheMeshGrows()
    {
        auto window = test::quietWindow();
        window->document()->reset(refiningRoom());
        PreviewController* preview = window->preview();
        PreviewDisplay display;
        display.showMesh = true;
        preview->setDisplay(display);
        std::vector<int> counts;
        int mismatches = 0;
        // Connected after the controller: its status is updated when this runs.
        connect(preview->runner(), &PreviewRunner::frameReady, this, [&] {
            const auto f = preview->runner()->frame();
            if (!f)
                return;
            const int elements = f->snapshot.stats.elements;
            if (counts.empty() || counts.back() != elements)
                counts.push_back(elements);
            const QString expected = QStringLiteral(", %1 elements,").arg(elements);
            QLabel* shown = nullptr;
            for (QLabel* label : window->statusBar()->findChildren<QLabel*>())
                if (label->text() == preview->statusText())
                    shown = label;
            if (!shown || !shown->text().contains(expected))
                ++mismatches;
        });
        preview->runIterations(12);
        QVERIFY(waitForFinal(*preview->runner()));
        QTRY_VERIFY(preview->layersCurrent());
        qInfo("element counts shown: %s", qPrintable([&] {
                  QStringList l;
                  for (int c : counts)
                      l << QString::number(c);
                  return l.join(QStringLiteral(" -> "));
              }()));
        QCOMPARE(mismatches, 0);
        QVERIFY(preview->runner()->frame()->snapshot.stats.adaptiveRounds > 0);
        QVERIFY2(counts.size() >= 2, "the mesh grows while the preview solves");
        QVERIFY(std::is_sorted(counts.begin(), counts.end()));
        QVERIFY(preview->statusText().contains(
            QStringLiteral(", %1 elements,").arg(preview->runner()->frame()->snapshot.stats.elements)));
        // The viewport's mesh layer is the grown, anchored mesh.
        const ViewportLayer* mesh = window->viewport()->layer(QString::fromLatin1(kMeshLayer));
        QVERIFY(mesh);
        QVERIFY(segmentsOfColour(*mesh, meshOverlayColours(display).anchoring) > 0);
    }
};

REGIO_QTEST_MAIN(PreviewAdaptiveTest)
#include "preview_adaptive_test.moc"
