// The BSP order editor (paper §5.3): every edit of the dock is one undo step,
// orders survive save and load, the figures the dock shows are the ones
// regio-solve reports for the same file, the suggested order is shown before
// it is applied, and the tree and fragment views follow the solver's trees.
#include "editor/app/main_window.h"
#include "editor/bsp/bsp_analysis.h"
#include "editor/bsp/bsp_authoring.h"
#include "editor/bsp/bsp_layers.h"
#include "editor/bsp/bsp_order_dock.h"
#include "editor/document/qt_conversions.h"
#include "editor/document/scene_document.h"
#include "editor/viewport/viewport.h"
#include "model/io/scene_json.h"
#include "solver/authoring/region_proposal.h"
#include "support/command_run.h"
#include "support/editor_documents.h"
#include "support/editor_windows.h"
#include "support/furnished_room.h"
#include "support/qt_test_registry.h"

#include <QAbstractItemModel>
#include <QComboBox>
#include <QElapsedTimer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QListWidget>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTreeWidget>

#include <memory>

using namespace regio;
using namespace regio::editor;

namespace {

std::unique_ptr<MainWindow> makeWindow() { return test::quietWindow(); }

std::vector<std::string> orderOf(const SceneDocument& document, const std::string& region)
{
    const model::Region* r = document.scene().findRegion(region);
    return r ? r->bspOrder : std::vector<std::string>{};
}

// The `bsp` block of `regio-solve solve FILE --report` (one shot: the figures
// come from preparation, shooting does not change them).
QJsonObject solveReportBsp(const QString& scenePath, const char* regionsMode)
{
    test::ScratchDir scratch;
    const std::string report = (scratch / "report.json").string();
    const test::CommandRun run = test::runRegioSolve({"solve", toStd(scenePath), "--iterations", "1", "--hemicube", "8",
                                                      "--regions", regionsMode, "--quiet", "--report", report});
    if (!run.exited || run.exitCode != 0)
        qFatal("regio-solve failed: %s", run.err.c_str());
    return QJsonDocument::fromJson(QByteArray::fromStdString(test::readText(report))).object()["bsp"].toObject();
}

QJsonObject perRegion(const QJsonObject& bsp, const QString& id)
{
    for (const QJsonValue& region : bsp["perRegion"].toArray())
        if (region.toObject()["id"].toString() == id)
            return region.toObject();
    return {};
}

} // namespace

class BspOrderTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { test::initTestEnvironment(); }

    void movingAnEntryDoesUndoesAndRedoes()
    {
        auto window = makeWindow();
        QVERIFY(window->openFile(test::sampleFile("two-lights-room")));
        BspAuthoring* bsp = window->bspAuthoring();
        SceneDocument& document = *window->document();
        bsp->setCurrentRegion("middle");
        const model::Scene before = document.scene();
        const std::vector<std::string> order = orderOf(document, "middle");
        QVERIFY(bsp->moveEntry(0, 2));
        QCOMPARE(orderOf(document, "middle")[2], order[0]);
        QCOMPARE(orderOf(document, "middle")[0], order[1]);
        QCOMPARE(document.undoStack()->count(), 1);
        VERIFY_UNDO_REDO(document, before);
    }

    void moveToTopMakesTheEntryTheRootAndUndoes()
    {
        auto window = makeWindow();
        QVERIFY(window->openFile(test::sampleFile("two-lights-room")));
        BspAuthoring* bsp = window->bspAuthoring();
        SceneDocument& document = *window->document();
        bsp->setCurrentRegion("east");
        const model::Scene before = document.scene();
        const std::string last = orderOf(document, "east").back();
        QVERIFY(bsp->moveToTop(int(orderOf(document, "east").size()) - 1));
        QCOMPARE(orderOf(document, "east").front(), last);
        QVERIFY(!bsp->moveToTop(0)); // already the root: nothing to do, nothing on the stack
        QCOMPARE(document.undoStack()->count(), 1);
        VERIFY_UNDO_REDO(document, before);
    }

    void removingAnEntryDoesUndoesAndRedoes()
    {
        auto window = makeWindow();
        QVERIFY(window->openFile(test::sampleFile("two-lights-room")));
        BspAuthoring* bsp = window->bspAuthoring();
        SceneDocument& document = *window->document();
        bsp->setCurrentRegion("west");
        const model::Scene before = document.scene();
        const std::string second = orderOf(document, "west")[1];
        QVERIFY(bsp->removeEntry(1));
        const std::vector<std::string> after = orderOf(document, "west");
        QCOMPARE(after.size(), before.findRegion("west")->bspOrder.size() - 1);
        QVERIFY(std::find(after.begin(), after.end(), second) == after.end());
        VERIFY_UNDO_REDO(document, before);
    }

    void insertingAFaceAppendsItAndRefusesFacesOutsideTheRegionOrAlreadyListed()
    {
        auto window = makeWindow();
        QVERIFY(window->openFile(test::sampleFile("two-lights-room")));
        BspAuthoring* bsp = window->bspAuthoring();
        SceneDocument& document = *window->document();
        bsp->setCurrentRegion("middle");
        const model::Scene before = document.scene();
        QVERIFY(bsp->insertFace("table.leg1.px"));
        QCOMPARE(orderOf(document, "middle").back(), std::string("table.leg1.px"));
        VERIFY_UNDO_REDO(document, before);
        const model::Scene after = document.scene();
        QVERIFY(!bsp->insertFace("shelf.left.px")); // a face of the west region
        QVERIFY(!bsp->insertFace("table.desk.py")); // already listed
        QVERIFY(!bsp->insertFace("no.such.face"));
        QVERIFY(document.scene() == after);
        QCOMPARE(document.undoStack()->count(), 1);
    }

    void insertingTheSelectedFacesIsOneUndoStep()
    {
        auto window = makeWindow();
        QVERIFY(window->openFile(test::sampleFile("two-lights-room")));
        BspAuthoring* bsp = window->bspAuthoring();
        SceneDocument& document = *window->document();
        bsp->setCurrentRegion("middle");
        const model::Scene before = document.scene();
        // A whole part: its six faces, all inside the middle region.
        document.setSelection(Selection::single(SelectionKind::Part, "table.leg2"));
        const int added = bsp->insertSelectedFaces();
        QCOMPARE(added, 6);
        QCOMPARE(orderOf(document, "middle").size(), before.findRegion("middle")->bspOrder.size() + 6);
        QCOMPARE(document.undoStack()->count(), 1);
        VERIFY_UNDO_REDO(document, before);
    }

    void draggingARowInTheListMovesTheEntry()
    {
        auto window = makeWindow();
        QVERIFY(window->openFile(test::sampleFile("two-lights-room")));
        BspAuthoring* bsp = window->bspAuthoring();
        SceneDocument& document = *window->document();
        bsp->setCurrentRegion("middle");
        QListWidget* list = bsp->dock()->orderList();
        const std::vector<std::string> order = orderOf(document, "middle");
        QCOMPARE(list->count(), int(order.size()));
        QCOMPARE(list->item(0)->text(), toQString(order[0]));
        // What an internal drag and drop does to the list's model: row 3 dropped above row 0.
        QVERIFY(list->model()->moveRow(QModelIndex(), 3, QModelIndex(), 0));
        QTRY_COMPARE(orderOf(document, "middle")[0], order[3]);
        QCOMPARE(document.undoStack()->count(), 1);
        QCOMPARE(list->item(0)->text(), toQString(order[3]));
        document.undoStack()->undo();
        QCOMPARE(orderOf(document, "middle"), order);
        QCOMPARE(list->item(0)->text(), toQString(order[0]));
    }

    void selectingARegionMakesItTheEditedOne()
    {
        auto window = makeWindow();
        QVERIFY(window->openFile(test::sampleFile("two-lights-room")));
        BspAuthoring* bsp = window->bspAuthoring();
        QCOMPARE(bsp->currentRegion(), std::string("west"));
        window->document()->setSelection(Selection::single(SelectionKind::Region, "east"));
        QCOMPARE(bsp->currentRegion(), std::string("east"));
        QCOMPARE(bsp->dock()->regionCombo()->currentData().toString(), QStringLiteral("east"));
        QCOMPARE(bsp->dock()->orderList()->count(), int(orderOf(*window->document(), "east").size()));
    }

    void orderEditsSurviveSaveAndLoad()
    {
        auto window = makeWindow();
        QVERIFY(window->openFile(test::sampleFile("two-lights-room")));
        BspAuthoring* bsp = window->bspAuthoring();
        SceneDocument& document = *window->document();
        bsp->setCurrentRegion("middle");
        QVERIFY(bsp->moveToTop(3));
        QVERIFY(bsp->insertFace("table.leg3.nx", 1));
        QVERIFY(bsp->removeEntry(4));
        bsp->setCurrentRegion("east");
        QVERIFY(bsp->suggestOrder());
        QVERIFY(bsp->applySuggestion());
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("orders.json"));
        QVERIFY(document.save(path));
        SceneDocument reloaded;
        model::Diagnostics diagnostics;
        QVERIFY(reloaded.open(path, diagnostics));
        for (const char* region : {"west", "middle", "east"})
            QCOMPARE(orderOf(reloaded, region), orderOf(document, region));
        QVERIFY(reloaded.scene() == document.scene());
    }

    void applyingTheSuggestionIsOneUndoStepAndGivesTheFiguresItShowed()
    {
        auto window = makeWindow();
        QVERIFY(window->openFile(test::sampleFile("two-lights-room")));
        BspAuthoring* bsp = window->bspAuthoring();
        BspOrderDock* dock = bsp->dock();
        SceneDocument& document = *window->document();
        bsp->setCurrentRegion("west");
        // Scene order in the west region: the suggestion has something to improve.
        bsp->analyser()->refreshNow();
        QVERIFY(bsp->suggestOrder());
        QVERIFY(bsp->suggestion().has_value());
        const solver::BspOrderSuggestion suggestion = *bsp->suggestion();
        QCOMPARE(document.undoStack()->count(), 0); // shown, not applied
        QCOMPARE(dock->figure(BspOrderDock::FragmentsRow, BspOrderDock::SuggestedRegionColumn),
                 suggestion.suggested.fragments);
        QCOMPARE(dock->figure(BspOrderDock::FragmentsRow, BspOrderDock::RegionColumn), suggestion.current.fragments);
        QVERIFY(suggestion.suggested.fragments <= suggestion.current.fragments);
        const int predictedScene = dock->figure(BspOrderDock::FragmentsRow, BspOrderDock::SuggestedSceneColumn);
        const int predictedDepth = dock->figure(BspOrderDock::DepthRow, BspOrderDock::SuggestedSceneColumn);

        const model::Scene before = document.scene();
        QVERIFY(bsp->applySuggestion());
        QVERIFY(!bsp->suggestion().has_value());
        QCOMPARE(document.undoStack()->count(), 1);
        QCOMPARE(orderOf(document, "west"), suggestion.order);
        bsp->analyser()->refreshNow();
        QCOMPARE(dock->figure(BspOrderDock::FragmentsRow, BspOrderDock::RegionColumn), suggestion.suggested.fragments);
        QCOMPARE(dock->figure(BspOrderDock::SplitsRow, BspOrderDock::RegionColumn), suggestion.suggested.splits);
        QCOMPARE(dock->figure(BspOrderDock::DepthRow, BspOrderDock::RegionColumn), suggestion.suggested.depth);
        QCOMPARE(dock->figure(BspOrderDock::FragmentsRow, BspOrderDock::SceneColumn), predictedScene);
        QCOMPARE(dock->figure(BspOrderDock::DepthRow, BspOrderDock::SceneColumn), predictedDepth);
        VERIFY_UNDO_REDO(document, before);
    }

    void discardingTheSuggestionLeavesTheScene()
    {
        auto window = makeWindow();
        QVERIFY(window->openFile(test::sampleFile("two-lights-room")));
        BspAuthoring* bsp = window->bspAuthoring();
        const model::Scene before = window->document()->scene();
        QVERIFY(bsp->suggestOrder());
        bsp->discardSuggestion();
        QVERIFY(!bsp->suggestion().has_value());
        QVERIFY(!bsp->applySuggestion());
        QVERIFY(window->document()->scene() == before);
        QCOMPARE(window->document()->undoStack()->count(), 0);
    }

    void theDockShowsTheFiguresOfTheSolveReport_data()
    {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<bool>("edited");
        QTest::newRow("two-lights-room") << test::sampleFile("two-lights-room") << false;
        QTest::newRow("two-lights-room, orders edited") << test::sampleFile("two-lights-room") << true;
        QTest::newRow("cornell-box") << test::sampleFile("cornell-box") << false;
    }

    void theDockShowsTheFiguresOfTheSolveReport()
    {
        QFETCH(QString, scene);
        QFETCH(bool, edited);
        auto window = makeWindow();
        QVERIFY(window->openFile(scene));
        BspAuthoring* bsp = window->bspAuthoring();
        if (edited) {
            bsp->setCurrentRegion("west");
            QVERIFY(bsp->removeEntry(0));
            QVERIFY(bsp->moveToTop(5));
            bsp->setCurrentRegion("middle");
            QVERIFY(bsp->insertFace("table.leg4.pz", 0));
        }
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("scene.json"));
        QVERIFY(window->document()->save(path));
        bsp->analyser()->refreshNow();
        const BspOrderDock* dock = bsp->dock();

        const QJsonObject authored = solveReportBsp(path, "authored");
        QCOMPARE(dock->figure(BspOrderDock::FragmentsRow, BspOrderDock::SceneColumn), authored["fragments"].toInt());
        QCOMPARE(dock->figure(BspOrderDock::SplitsRow, BspOrderDock::SceneColumn), authored["splits"].toInt());
        QCOMPARE(dock->figure(BspOrderDock::DepthRow, BspOrderDock::SceneColumn), authored["maxDepth"].toInt());
        const QJsonObject baseline = solveReportBsp(path, "none");
        QCOMPARE(dock->figure(BspOrderDock::FragmentsRow, BspOrderDock::BaselineColumn), baseline["fragments"].toInt());
        QCOMPARE(dock->figure(BspOrderDock::SplitsRow, BspOrderDock::BaselineColumn), baseline["splits"].toInt());
        QCOMPARE(dock->figure(BspOrderDock::DepthRow, BspOrderDock::BaselineColumn), baseline["maxDepth"].toInt());

        // Every region, as the dock shows it when the region is chosen.
        for (const model::Region& region : window->document()->scene().regions) {
            bsp->setCurrentRegion(region.id);
            const QJsonObject figures = perRegion(authored, toQString(region.id));
            QVERIFY(!figures.isEmpty());
            QCOMPARE(dock->figure(BspOrderDock::FragmentsRow, BspOrderDock::RegionColumn),
                     figures["fragments"].toInt());
            QCOMPARE(dock->figure(BspOrderDock::SplitsRow, BspOrderDock::RegionColumn), figures["splits"].toInt());
            QCOMPARE(dock->figure(BspOrderDock::DepthRow, BspOrderDock::RegionColumn), figures["depth"].toInt());
        }
    }

    void figuresAreComputedOffTheUiThreadAfterEdits()
    {
        auto window = makeWindow();
        QVERIFY(window->openFile(test::sampleFile("two-lights-room")));
        BspAuthoring* bsp = window->bspAuthoring();
        BspAnalyser* analyser = bsp->analyser();
        QTRY_VERIFY_WITH_TIMEOUT(!analyser->stale(), 20000);
        bsp->setCurrentRegion("middle");
        const int before = bsp->dock()->figure(BspOrderDock::FragmentsRow, BspOrderDock::RegionColumn);
        QSignalSpy analysed(analyser, &BspAnalyser::analysed);
        // A burst of edits (as a drag would make): each returns at once, the
        // figures follow once when the edits stop.
        QElapsedTimer clock;
        clock.start();
        for (int i = 0; i < 10; ++i)
            QVERIFY(bsp->moveEntry(0, 5));
        const qint64 editing = clock.elapsed();
        QVERIFY(analyser->stale());
        QCOMPARE(analysed.count(), 0);
        QTRY_VERIFY_WITH_TIMEOUT(!analyser->stale(), 20000);
        QVERIFY2(analysed.count() <= 2, qPrintable(QString::number(analysed.count())));
        qInfo("10 edits took %lld ms on the UI thread; one analysis of the scene takes %.1f ms", editing,
              analyser->current().milliseconds);
        QVERIFY(bsp->dock()->figure(BspOrderDock::FragmentsRow, BspOrderDock::RegionColumn) >= 0);
        Q_UNUSED(before);
    }

    void theAnalysisOfAHundredObjectRoomIsTheSolversAndStaysOffTheUiThread()
    {
        // The generated room of 100 objects in the regions the solver proposes,
        // scene order (the README's "proposed regions, scene order" row).
        const model::Scene room = test::furnishedRoom(1);
        solver::RegionProposalOptions options;
        options.suggestOrders = false;
        const model::Scene scene = solver::withRegions(room, solver::proposeRegions(room, options)->regions);
        QVERIFY(scene.regions.size() > 1);
        QElapsedTimer clock;
        clock.start();
        const BspAnalysis analysis = analyseBsp(scene);
        const qint64 analysing = clock.elapsed();
        const model::Result<solver::SceneBspFigures> authored =
            solver::computeBspFigures(scene, {solver::RegionsMode::Authored});
        const model::Result<solver::SceneBspFigures> single =
            solver::computeBspFigures(scene, {solver::RegionsMode::None});
        QVERIFY(analysis.authored && authored.ok() && analysis.baseline && single.ok());
        QCOMPARE(analysis.authored->fragments, authored->fragments);
        QCOMPARE(analysis.authored->splits, authored->splits);
        QCOMPARE(analysis.authored->maxDepth, authored->maxDepth);
        QCOMPARE(analysis.baseline->fragments, single->fragments);
        QVERIFY(analysis.authored->fragments < analysis.baseline->fragments);

        // In the editor: an edit returns before the figures are recomputed.
        auto window = makeWindow();
        test::resetDocument(*window->document(), scene);
        BspAuthoring* bsp = window->bspAuthoring();
        QTRY_VERIFY_WITH_TIMEOUT(!bsp->analyser()->stale(), 60000);
        bsp->setCurrentRegion(scene.regions.front().id);
        clock.restart();
        QVERIFY(bsp->suggestOrder());
        const qint64 suggesting = clock.elapsed();
        clock.restart();
        QVERIFY(bsp->applySuggestion());
        const qint64 applying = clock.elapsed();
        QVERIFY(bsp->analyser()->stale());
        QTRY_VERIFY_WITH_TIMEOUT(!bsp->analyser()->stale(), 60000);
        qInfo(
            "100-object room, %d regions: analysis %lld ms (worker), suggestion for one region %lld ms, "
            "applying it %lld ms on the UI thread; %d fragments against %d for a single BSP",
            int(scene.regions.size()), analysing, suggesting, applying, analysis.authored->fragments,
            analysis.baseline->fragments);
    }

    void suggestedOrdersInEveryRegionGiveNoMoreFragmentsThanSceneOrder_data()
    {
        QTest::addColumn<QString>("name");
        QTest::newRow("two-lights-room") << QStringLiteral("two-lights-room");
        QTest::newRow("furnished room of 100 objects, proposed regions") << QStringLiteral("furnished");
    }

    void suggestedOrdersInEveryRegionGiveNoMoreFragmentsThanSceneOrder()
    {
        QFETCH(QString, name);
        model::Scene scene;
        if (name == QStringLiteral("furnished")) {
            const model::Scene room = test::furnishedRoom(1);
            solver::RegionProposalOptions options;
            options.suggestOrders = false;
            scene = solver::withRegions(room, solver::proposeRegions(room, options)->regions);
        } else {
            scene = test::loadSample("two-lights-room");
        }
        for (model::Region& region : scene.regions)
            region.bspOrder.clear(); // scene order
        auto window = makeWindow();
        test::resetDocument(*window->document(), scene);
        BspAuthoring* bsp = window->bspAuthoring();
        bsp->analyser()->refreshNow();
        const solver::SceneBspFigures sceneOrder = *bsp->analyser()->current().authored;
        for (const model::Region& region : scene.regions) {
            bsp->setCurrentRegion(region.id);
            QVERIFY(bsp->suggestOrder());
            QVERIFY(bsp->suggestion()->suggested.fragments <= bsp->suggestion()->current.fragments);
            QVERIFY(bsp->applySuggestion());
        }
        QCOMPARE(window->document()->undoStack()->count(), int(scene.regions.size()));
        bsp->analyser()->refreshNow();
        const BspAnalysis& suggested = bsp->analyser()->current();
        QVERIFY(suggested.authored->fragments <= sceneOrder.fragments);
        QVERIFY(suggested.authored->fragments < suggested.baseline->fragments ||
                suggested.authored->fragments == sceneOrder.fragments);
        qInfo(
            "%s, %d regions: scene order %d fragments (%d splits, depth %d); suggested orders %d (%d splits, "
            "depth %d); single BSP with those orders concatenated %d",
            qPrintable(name), int(scene.regions.size()), sceneOrder.fragments, sceneOrder.splits, sceneOrder.maxDepth,
            suggested.authored->fragments, suggested.authored->splits, suggested.authored->maxDepth,
            suggested.baseline->fragments);
    }

    void theTreeViewShowsTheRegionsBspAndHighlightsTheSelectedNodesPlane()
    {
        auto window = makeWindow();
        QVERIFY(window->openFile(test::sampleFile("two-lights-room")));
        BspAuthoring* bsp = window->bspAuthoring();
        bsp->setCurrentRegion("middle");
        bsp->analyser()->refreshNow();
        const BspAnalysis& analysis = bsp->analyser()->current();
        const int region = analysis.preparedRegion("middle");
        QVERIFY(region >= 0);
        const solver::PreparedScene& prepared = *analysis.prepared;
        QTreeWidget* tree = bsp->dock()->treeWidget();
        QCOMPARE(tree->topLevelItemCount(), 1);
        QTreeWidgetItem* root = tree->topLevelItem(0);
        QCOMPARE(BspOrderDock::nodeOf(root), prepared.regions[size_t(region)].bspRoot);
        // The root's face is the first of the order: the author's root.
        QCOMPARE(root->text(0), toQString(orderOf(*window->document(), "middle").front()));
        // Every node of the region appears once.
        int items = 0;
        std::vector<QTreeWidgetItem*> pending{root};
        while (!pending.empty()) {
            QTreeWidgetItem* item = pending.back();
            pending.pop_back();
            ++items;
            const solver::BspNode& node = prepared.nodes[size_t(BspOrderDock::nodeOf(item))];
            QCOMPARE(item->text(1).toInt(), node.fragmentCount);
            QCOMPARE(node.region, region);
            for (int c = 0; c < item->childCount(); ++c)
                pending.push_back(item->child(c));
        }
        QCOMPARE(items, prepared.regions[size_t(region)].stats.nodes);

        QTreeWidgetItem* child = root->child(0);
        tree->setCurrentItem(child);
        QCOMPARE(bsp->highlightedNode(), BspOrderDock::nodeOf(child));
        const ViewportLayer* layer = window->viewport()->layer(BspAuthoring::nodeLayerName());
        QVERIFY(layer);
        QVERIFY(!layer->triangles.empty());
        // The plane polygon lies on the node's plane and inside the region box.
        const solver::BspNode& node = prepared.nodes[size_t(bsp->highlightedNode())];
        const std::vector<model::Vec3> polygon = planeInBox(node.plane, prepared.regions[size_t(region)].box);
        QVERIFY(polygon.size() >= 3);
        for (const model::Vec3& p : polygon) {
            QVERIFY(std::abs(node.plane.signedDistance(p)) < 1e-9);
            QVERIFY(prepared.regions[size_t(region)].box.contains(p, 1e-9));
        }
        tree->setCurrentItem(nullptr);
        QVERIFY(!window->viewport()->hasLayer(BspAuthoring::nodeLayerName()));
    }

    void theFragmentLayerMarksBspSplitsOnlyWhereTheTreeSplits()
    {
        auto window = makeWindow();
        QVERIFY(window->openFile(test::sampleFile("two-lights-room")));
        BspAuthoring* bsp = window->bspAuthoring();
        SceneDocument& document = *window->document();
        bsp->setCurrentRegion("west");
        bsp->analyser()->refreshNow();
        const BspAnalysis& clean = bsp->analyser()->current();
        QCOMPARE(clean.region("west")->figures.splits, 0);
        FragmentEdgeCounts counts;
        buildFragmentLayer(*clean.scene, *clean.prepared, clean.preparedRegion("west"), &counts);
        QCOMPARE(counts.bspSplits, 0);
        QVERIFY(counts.boundary > 0);

        // The shelf's side as the root: its plane cuts the room's walls.
        QVERIFY(bsp->moveToTop(int(orderOf(document, "west").size()) - 4));
        bsp->analyser()->refreshNow();
        const BspAnalysis& split = bsp->analyser()->current();
        QVERIFY(split.region("west")->figures.splits > 0);
        buildFragmentLayer(*split.scene, *split.prepared, split.preparedRegion("west"), &counts);
        QVERIFY(counts.bspSplits > 0);

        bsp->setShowFragments(true);
        QVERIFY(window->viewport()->hasLayer(BspAuthoring::fragmentLayerName()));
        QVERIFY(!window->viewport()->layer(BspAuthoring::fragmentLayerName())->lines.empty());
        bsp->setShowFragments(false);
        QVERIFY(!window->viewport()->hasLayer(BspAuthoring::fragmentLayerName()));
    }
};

REGIO_QTEST_MAIN(BspOrderTest)
#include "bsp_order_test.moc"
