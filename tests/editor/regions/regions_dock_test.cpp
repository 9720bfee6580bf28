// The Regions dock and the region views: contents and the solver's BSP
// fragment counts per region, selection kept in step with the document, the
// regional tree as the solver builds it, the viewport layers, and the live
// straddle diagnostic with its one-click fix.
#include "editor/docks/diagnostics_dock.h"
#include "editor/docks/diagnostics_model.h"
#include "editor/document/commands/region_commands.h"
#include "editor/document/qt_conversions.h"
#include "editor/document/scene_document.h"
#include "editor/regions/region_authoring.h"
#include "editor/regions/region_figures.h"
#include "editor/regions/region_layers.h"
#include "editor/regions/regions_dock.h"
#include "editor/viewport/viewport.h"
#include "region_fixture.h"
#include "solver/authoring/bsp_figures.h"
#include "solver/authoring/region_proposal.h"
#include "solver/prepare/prepare.h"
#include "support/command_run.h"
#include "support/editor_documents.h"
#include "support/furnished_room.h"
#include "support/qt_test_registry.h"

#include <QAction>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QMainWindow>
#include <QTemporaryDir>
#include <QTreeView>
#include <QTreeWidget>
#include <QUndoStack>

using namespace regio;
using namespace regio::editor;

namespace {

using test::RegionFixture;

// The regional tree's nodes as the dock lists them, depth first.
void collect(const QTreeWidgetItem* item, QStringList& out)
{
    out << item->text(0);
    for (int i = 0; i < item->childCount(); ++i)
        collect(item->child(i), out);
}

// The solver's regional tree in the same order: back subtree before front.
void collect(const solver::PreparedScene& prepared, const model::Scene& scene, int node, QStringList& out)
{
    const solver::RegionalNode& n = prepared.regionalNodes[size_t(node)];
    if (n.isLeaf()) { // the region, named when it has a name
        const model::Region& region = scene.regions[size_t(n.region)];
        out << (region.name.empty() ? QString::fromStdString(region.id)
                                    : QStringLiteral("%1 (%2)").arg(QString::fromStdString(region.id),
                                                                    QString::fromStdString(region.name)));
        return;
    }
    out << QStringLiteral("%1 = %2").arg(QStringLiteral("xyz").mid(n.axis, 1), formatNumber(n.position, 4));
    if (n.back >= 0)
        collect(prepared, scene, n.back, out);
    if (n.front >= 0)
        collect(prepared, scene, n.front, out);
}

// The `bsp` block of `regio-solve solve FILE --report` (one shot: the figures
// come from preparation).
QJsonObject solveReportBsp(const QString& scenePath)
{
    test::ScratchDir scratch;
    const std::string report = (scratch / "report.json").string();
    const test::CommandRun run = test::runRegioSolve(
        {"solve", scenePath.toStdString(), "--iterations", "1", "--hemicube", "8", "--quiet", "--report", report});
    if (!run.exited || run.exitCode != 0)
        qFatal("regio-solve failed: %s", run.err.c_str());
    return QJsonDocument::fromJson(QByteArray::fromStdString(test::readText(report))).object()["bsp"].toObject();
}

int findDiagnostic(const DiagnosticsModel* model, const QString& needle)
{
    for (int row = 0; row < model->rowCount(); ++row)
        if (QString::fromStdString(model->diagnostics()[size_t(row)].message).contains(needle))
            return row;
    return -1;
}

} // namespace

class RegionsDockTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { test::initTestEnvironment(); }

    void everyRegionIsListedWithItsPartAndFaceCounts()
    {
        RegionFixture f(test::smallScene());
        // The region "left" holds the table's desk and legs, the crate and the lamp: 4 boxes of 6 faces.
        QCOMPARE(f.dock()->regionList()->topLevelItemCount(), 1);
        QCOMPARE(f.dock()->cellText("left", RegionsDock::PartsColumn), QStringLiteral("4"));
        QCOMPARE(f.dock()->cellText("left", RegionsDock::FacesColumn), QStringLiteral("24"));
        QVERIFY(f.document.push(new SetRegionBox(&f.document, "left", {-1, -1, -1}, {1.5, 3, 2})));
        QCOMPARE(f.dock()->cellText("left", RegionsDock::PartsColumn), QStringLiteral("3"));
        QCOMPARE(f.dock()->cellText("left", RegionsDock::FacesColumn), QStringLiteral("18"));
    }

    void theFragmentCountsAreTheSolversBspFigures()
    {
        const model::Scene scene = test::loadSample("two-lights-room");
        RegionFixture f(scene);
        QVERIFY(f.regions->figures()->waitUntilCurrent());
        const model::Result<solver::SceneBspFigures> expected = solver::computeBspFigures(scene);
        QVERIFY(expected.ok());
        QCOMPARE(expected->regions.size(), scene.regions.size());
        for (const solver::RegionBspFigures& region : expected->regions)
            QCOMPARE(f.dock()->cellText(region.id, RegionsDock::FragmentsColumn),
                     QString::number(region.figures.fragments));
        QVERIFY(f.dock()->summary()->text().contains(QString::number(expected->fragments)));
        const model::Result<solver::SceneBspFigures> single =
            solver::computeBspFigures(scene, {model::RegionsMode::None, 256});
        QVERIFY(f.dock()->summary()->text().contains(QString::number(single->fragments)));
    }

    void theFragmentCountsFollowAnEditAfterAPause()
    {
        const model::Scene scene = test::loadSample("two-lights-room");
        RegionFixture f(scene);
        QVERIFY(f.regions->figures()->waitUntilCurrent());
        const model::Region& first = scene.regions.front();
        QVERIFY(f.document.push(new RemoveRegion(&f.document, first.id)));
        QVERIFY(f.regions->figures()->stale());
        QVERIFY(f.regions->figures()->waitUntilCurrent());
        const model::Result<solver::SceneBspFigures> expected = solver::computeBspFigures(f.document.scene());
        QVERIFY(expected.ok());
        for (const solver::RegionBspFigures& region : expected->regions)
            QCOMPARE(f.dock()->cellText(region.id, RegionsDock::FragmentsColumn),
                     QString::number(region.figures.fragments));
    }

    void theFragmentCountsOfEditedRegionsAreWhatRegioSolveReportsForTheSavedFile()
    {
        const model::Scene scene = test::loadSample("two-lights-room");
        RegionFixture f(scene);
        // Accepted automatic regions, then one of them resized.
        QVERIFY(f.regions->proposeRegions());
        QVERIFY(f.regions->acceptProposal());
        const model::Region first = f.document.scene().regions.front();
        QVERIFY(f.document.push(
            new SetRegionBox(&f.document, first.id, first.min, first.max + model::Vec3(0.0, 0.25, 0.0))));
        QVERIFY(f.regions->figures()->waitUntilCurrent());

        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("edited.json"));
        QVERIFY(f.document.save(path));
        const QJsonObject bsp = solveReportBsp(path);
        const QJsonArray perRegion = bsp["perRegion"].toArray();
        QCOMPARE(perRegion.size(), qsizetype(f.document.scene().regions.size()));
        for (const QJsonValue& value : perRegion) {
            const QJsonObject region = value.toObject();
            QCOMPARE(f.dock()->cellText(region["id"].toString().toStdString(), RegionsDock::FragmentsColumn),
                     QString::number(region["fragments"].toInt()));
        }
        QVERIFY(f.dock()->summary()->text().contains(QString::number(bsp["fragments"].toInt())));
    }

    void editsOnAHundredObjectRoomLeaveTheFiguresToTheWorkerThread()
    {
        model::Scene room = test::furnishedRoom(1);
        room.regions = solver::proposeRegions(room)->regions;
        QVERIFY(room.regions.size() > 10);
        RegionFixture f(room);
        QVERIFY(f.regions->figures()->waitUntilCurrent());
        // What the UI thread does for one step of a drag: the command, the
        // dock's lists and every layer. The BSP builds are not part of it:
        // the figures are stale when the edit returns (how long it takes:
        // regions_dock_timing_test.cpp).
        const model::Region& r = f.document.scene().regions.front();
        // Shrunk, so it cannot come to overlap a neighbour.
        QVERIFY(f.document.push(new SetRegionBox(&f.document, r.id, r.min, r.max - model::Vec3(0.0, 0.1, 0.0))));
        QVERIFY(f.regions->figures()->stale());
        QVERIFY(f.regions->figures()->waitUntilCurrent());
        const model::Result<solver::SceneBspFigures> expected = solver::computeBspFigures(f.document.scene());
        QVERIFY(expected.ok());
        QVERIFY2(f.dock()->summary()->text().contains(QString::number(expected->fragments)),
                 qPrintable(f.dock()->summary()->text()));
    }

    void selectionFollowsTheDocumentBothWays()
    {
        RegionFixture f(test::loadSample("two-lights-room"));
        const std::string second = f.document.scene().regions[1].id;
        f.document.setSelection(Selection::single(SelectionKind::Region, second));
        const QList<QTreeWidgetItem*> selected = f.dock()->regionList()->selectedItems();
        QCOMPARE(selected.size(), 1);
        QCOMPARE(selected.front()->text(RegionsDock::IdColumn), QString::fromStdString(second));

        f.dock()->regionList()->clearSelection();
        f.dock()->regionList()->topLevelItem(0)->setSelected(true);
        QVERIFY(f.document.selection() == Selection::single(SelectionKind::Region, f.document.scene().regions[0].id));
    }

    void editingTheIdAndNameInTheListRenamesThroughCommands()
    {
        RegionFixture f(test::smallScene());
        QTreeWidgetItem* row = f.dock()->regionList()->topLevelItem(0);
        row->setText(RegionsDock::NameColumn, QStringLiteral("West wing"));
        QTRY_COMPARE(f.document.scene().findRegion("left")->name, std::string("West wing"));
        row = f.dock()->regionList()->topLevelItem(0);
        row->setText(RegionsDock::IdColumn, QStringLiteral("west"));
        QTRY_VERIFY(f.document.scene().findRegion("west"));
        QVERIFY(f.document.selection() == Selection::single(SelectionKind::Region, "west"));
        QCOMPARE(f.document.undoStack()->count(), 2);
        f.document.undoStack()->undo();
        f.document.undoStack()->undo();
        QVERIFY(f.document.scene() == test::smallScene());
    }

    void theRegionalTreeViewListsTheSolversSeparatingPlanes()
    {
        const model::Scene scene = test::loadSample("two-lights-room");
        QVERIFY(scene.regions.size() >= 2);
        RegionFixture f(scene);
        const model::Result<solver::PreparedScene> prepared = solver::prepareScene(scene);
        QVERIFY(prepared.ok());
        QStringList expected;
        collect(*prepared, scene, prepared->regionalRoot, expected);
        QStringList shown;
        QCOMPARE(f.dock()->treeView()->topLevelItemCount(), 1);
        collect(f.dock()->treeView()->topLevelItem(0), shown);
        QCOMPARE(shown, expected);
        QCOMPARE(int(regionalTreeOf(scene).planes.size()), int(scene.regions.size()) - 1);
    }

    void theSeparatingPlanesLayerHasOneQuadPerPlane()
    {
        const model::Scene scene = test::loadSample("two-lights-room");
        RegionFixture f(scene);
        const QString name = QString::fromLatin1(kSeparatingPlanesLayer);
        QVERIFY(!f.viewport->hasLayer(name));
        f.regions->showPlanesAction()->setChecked(true);
        QVERIFY(f.viewport->hasLayer(name));
        const RegionalTreeView tree = regionalTreeOf(scene);
        constexpr size_t floatsPerVertex = 7, quadVertices = 2 * 3; // two triangles
        QCOMPARE(f.viewport->layer(name)->triangles.vertices().size(),
                 tree.planes.size() * quadVertices * floatsPerVertex);
        // Each quad lies in its plane and inside the scene's extent.
        const model::Box3 extent = sceneExtent(scene);
        for (const SeparatingPlane& plane : tree.planes) {
            QVERIFY(plane.position >= extent.min[plane.axis] && plane.position <= extent.max[plane.axis]);
            QVERIFY(plane.cell.min[(plane.axis + 1) % 3] >= extent.min[(plane.axis + 1) % 3]);
        }
        f.regions->showPlanesAction()->setChecked(false);
        QVERIFY(!f.viewport->hasLayer(name));
    }

    void colourByRegionReplacesTheSurfacesWithOneColourPerRegion()
    {
        model::Scene scene = test::smallScene();
        scene.regions[0].max.x = 1.5; // the crate (x 2..2.5) is now outside every region
        RegionFixture f(scene);
        f.viewport->setCullBackFaces(false);
        f.regions->colourByRegionAction()->setChecked(true);
        const ViewportLayer* layer = f.viewport->layer(QString::fromLatin1(kRegionColoursLayer));
        QVERIFY(layer);
        QVERIFY(layer->replacesSurfaces);
        const model::Part& crate = *scene.findPart("crate.body");
        const model::Part& desk = *scene.findPart("table.desk");
        auto loopOf = [](const model::Part& part) {
            std::vector<model::Vec3> loop;
            for (int v : part.faces.front().loop)
                loop.push_back(part.vertices[size_t(v)]);
            return loop;
        };
        QCOMPARE(regionHoldingPolygon(scene, loopOf(desk)), 0);
        QCOMPARE(regionHoldingPolygon(scene, loopOf(crate)), -1);
        // Every face is drawn: two triangles per quad face of the four boxes.
        QCOMPARE(layer->triangles.vertices().size(), size_t(4 * 6 * 2 * 3 * 7));
        f.regions->colourByRegionAction()->setChecked(false);
        QVERIFY(!f.viewport->hasLayer(QString::fromLatin1(kRegionColoursLayer)));

        // As the viewport's own surfaces: faces seen from behind are left out
        // when it hides back faces (of a closed box, at most three show).
        f.viewport->setCullBackFaces(true);
        f.regions->colourByRegionAction()->setChecked(true);
        layer = f.viewport->layer(QString::fromLatin1(kRegionColoursLayer));
        const size_t shown = layer->triangles.vertices().size() / (2 * 3 * 7);
        QVERIFY2(shown >= 4 && shown <= 4 * 3, qPrintable(QString::number(shown)));
        f.regions->colourByRegionAction()->setChecked(false);
        QVERIFY(!f.viewport->hasLayer(QString::fromLatin1(kRegionColoursLayer)));
    }

    void theBoxesLayerFollowsTheRegions()
    {
        RegionFixture f(test::smallScene());
        const QString name = QString::fromLatin1(kRegionBoxesLayer);
        QVERIFY(f.viewport->hasLayer(name));
        const size_t one = f.viewport->layer(name)->lines.vertices().size();
        QVERIFY(f.document.push(new AddRegion(&f.document, {"right", "", {3, -1, -1}, {5, 3, 2}, {}})));
        QCOMPARE(f.viewport->layer(name)->lines.vertices().size(), 2 * one);
        f.regions->showBoxesAction()->setChecked(false);
        QVERIFY(!f.viewport->hasLayer(name));
    }

    void aStraddlingPartIsFlaggedLiveAndTheFixRemovesTheFlag()
    {
        RegionFixture f(test::smallScene());
        f.diagnostics->validateNow();
        QCOMPARE(findDiagnostic(f.diagnostics->model(), QStringLiteral("straddles")), -1);

        // Shrink the region so its boundary runs through the crate.
        QVERIFY(f.document.push(new SetRegionBox(&f.document, "left", {-1, -1, -1}, {2.25, 3, 2})));
        QVERIFY(f.document.push(new AddRegion(&f.document, {"right", "", {2.25, -1, -1}, {4, 3, 2}, {}})));
        QTRY_VERIFY(findDiagnostic(f.diagnostics->model(), QStringLiteral("crate.body")) >= 0);
        const int row = findDiagnostic(f.diagnostics->model(), QStringLiteral("crate.body"));
        QVERIFY(QString::fromStdString(f.diagnostics->model()->diagnostics()[size_t(row)].message)
                    .contains(QStringLiteral("straddles")));
        // "Where" names the part by its id before its pointer.
        const QString where =
            f.diagnostics->model()
                ->data(f.diagnostics->model()->index(row, DiagnosticsModel::LocationColumn), Qt::DisplayRole)
                .toString();
        QVERIFY2(where.startsWith(QStringLiteral("part crate.body  /objects/")), qPrintable(where));

        QTreeView* view = f.diagnostics->view();
        auto* fix = view->findChild<QAction*>(QStringLiteral("ClipPartToRegionsFix"));
        QVERIFY(fix);
        QVERIFY(view->actions().contains(fix));
        view->setCurrentIndex(f.diagnostics->model()->index(row, 0));
        QVERIFY(fix->isEnabled());
        const int steps = f.document.undoStack()->count();
        fix->trigger();
        QCOMPARE(f.document.undoStack()->count(), steps + 1);
        QVERIFY(!f.document.scene().findPart("crate.body"));
        QTRY_COMPARE(findDiagnostic(f.diagnostics->model(), QStringLiteral("straddles")), -1);

        // Undo brings the part and the flag back.
        f.document.undoStack()->undo();
        QTRY_VERIFY(findDiagnostic(f.diagnostics->model(), QStringLiteral("straddles")) >= 0);
    }

    void overlappingRegionsAreFlaggedLiveInTheDiagnosticsAndTheList()
    {
        RegionFixture f(test::smallScene());
        QVERIFY(f.document.push(new AddRegion(&f.document, {"inner", "", {0, 0, 0}, {1, 1, 1}, {}})));
        QTRY_VERIFY(findDiagnostic(f.diagnostics->model(), QStringLiteral("overlaps")) >= 0);
        QVERIFY(
            f.dock()->regionList()->topLevelItem(1)->toolTip(RegionsDock::IdColumn).contains(QStringLiteral("left")));
        // The fix is offered only where it exists: not on an overlap.
        QTreeView* view = f.diagnostics->view();
        view->setCurrentIndex(
            f.diagnostics->model()->index(findDiagnostic(f.diagnostics->model(), QStringLiteral("overlaps")), 0));
        QVERIFY(!view->findChild<QAction*>(QStringLiteral("ClipPartToRegionsFix"))->isEnabled());
        // No regional tree while they overlap.
        QCOMPARE(f.dock()->treeView()->topLevelItemCount(), 1);
        QCOMPARE(f.dock()->treeView()->topLevelItem(0)->childCount(), 0);
    }
};

REGIO_QTEST_MAIN(RegionsDockTest)
#include "regions_dock_test.moc"
