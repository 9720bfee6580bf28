// Region authoring edits: resizing by handle drags (one undo step per drag),
// clipping a straddling part to the regions, accepting or discarding a
// proposal of automatic regions, and all of it surviving save and load.
#include "editor/document/commands/part_commands.h"
#include "editor/document/commands/region_clip_command.h"
#include "editor/document/commands/region_commands.h"
#include "editor/document/scene_document.h"
#include "editor/regions/region_authoring.h"
#include "editor/regions/region_box_tool.h"
#include "editor/regions/region_drag_command.h"
#include "editor/regions/region_layers.h"
#include "editor/regions/regions_dock.h"
#include "editor/viewport/viewport.h"
#include "model/geometry/region_clip.h"
#include "solver/authoring/region_proposal.h"
#include "support/editor_documents.h"
#include "support/qt_test_registry.h"

#include <QAction>
#include <QLabel>
#include <QMainWindow>
#include <QMenu>
#include <QTemporaryDir>
#include <QUndoStack>

using namespace regio;
using namespace regio::editor;

namespace {

// The small scene with the region "left" shrunk so the crate (x 2..2.5)
// crosses its boundary at x = 2.25, and a region "right" beyond it.
model::Scene straddlingScene()
{
    model::Scene scene = test::smallScene();
    scene.regions[0].max.x = 2.25;
    scene.regions.push_back({"right", "Right", {2.25, -1, -1}, {4, 3, 2}, {}});
    return scene;
}

// A window holding a viewport and the region authoring, as the editor has them.
struct RegionFixture {
    SceneDocument document; // outlives the window and everything in it
    QMainWindow window;
    Viewport* viewport;
    RegionAuthoring* regions;

    explicit RegionFixture(model::Scene scene)
    {
        test::resetDocument(document, std::move(scene));
        viewport = new Viewport(&document, &window);
        window.setCentralWidget(viewport);
        regions = new RegionAuthoring(&document, viewport, nullptr, nullptr, &window);
    }
};

} // namespace

class RegionsCommandsTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { test::initTestEnvironment(); }

    void theStepsOfOneHandleDragAreOneUndoStep()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        for (int i = 1; i <= 8; ++i)
            QVERIFY(document.push(new ResizeRegionByHandle(&document, "left", {-1, -1, -1}, {3 + 0.1 * i, 3, 2}, 1)));
        QCOMPARE(document.undoStack()->count(), 1);
        QCOMPARE(document.scene().findRegion("left")->max.x, 3.8);
        VERIFY_UNDO_REDO(document, test::smallScene());
    }

    void twoDragsOfTheSameHandleAreTwoUndoSteps()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        QVERIFY(document.push(new ResizeRegionByHandle(&document, "left", {-1, -1, -1}, {3.5, 3, 2}, 1)));
        QVERIFY(document.push(new ResizeRegionByHandle(&document, "left", {-1, -1, -1}, {4, 3, 2}, 1)));
        const model::Scene afterFirst = document.scene();
        QVERIFY(document.push(new ResizeRegionByHandle(&document, "left", {-1, -1, -1}, {4.5, 3, 2}, 2)));
        QVERIFY(document.push(new ResizeRegionByHandle(&document, "left", {-1, -1, -1}, {5, 3, 2}, 2)));
        QCOMPARE(document.undoStack()->count(), 2);
        document.undoStack()->undo();
        QVERIFY(document.scene() == afterFirst);
        document.undoStack()->undo();
        QVERIFY(document.scene() == test::smallScene());
    }

    void aHandleDragDoesNotMergeWithANumericEdit()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        QVERIFY(document.push(new SetRegionBox(&document, "left", {-1, -1, -1}, {3.5, 3, 2})));
        QVERIFY(document.push(new ResizeRegionByHandle(&document, "left", {-1, -1, -1}, {4, 3, 2}, 7)));
        QCOMPARE(document.undoStack()->count(), 2);
    }

    void aDragBackToWhereItStartedLeavesNoUndoStep()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        QVERIFY(document.push(new ResizeRegionByHandle(&document, "left", {-1, -1, -1}, {3.5, 3, 2}, 1)));
        QVERIFY(document.push(new ResizeRegionByHandle(&document, "left", {-1, -1, -1}, {3, 3, 2}, 1)));
        QCOMPARE(document.undoStack()->count(), 0);
        QVERIFY(document.scene() == test::smallScene());
    }

    void clippingAStraddlingPartMakesOnePiecePerRegionAndCanBeUndone()
    {
        SceneDocument document;
        test::resetDocument(document, straddlingScene());
        const model::Scene before = document.scene();
        QVERIFY(model::partStraddlesRegions(before, *before.findPart("crate.body")));
        auto* command = new ClipPartToRegions(&document, "crate.body");
        QVERIFY(document.push(command));
        QCOMPARE(command->pieces(), (std::vector<std::string>{"crate.body-left", "crate.body-right"}));
        QVERIFY(!document.scene().findPart("crate.body"));
        for (const std::string& piece : command->pieces())
            QVERIFY(!model::partStraddlesRegions(document.scene(), *document.scene().findPart(piece)));
        QCOMPARE(document.undoStack()->count(), 1);
        VERIFY_UNDO_REDO(document, before);
    }

    void clippingAPartInsideOneRegionIsRefusedAndChangesNothing()
    {
        SceneDocument document;
        test::resetDocument(document, straddlingScene());
        QVERIFY(!document.push(new ClipPartToRegions(&document, "table.desk")));
        QCOMPARE(document.undoStack()->count(), 0);
        QVERIFY(document.scene() == straddlingScene());
    }

    void clipSelectedPartsClipsOnlyTheStraddlingOnesInOneStep()
    {
        RegionFixture a(straddlingScene());
        a.document.setSelection(Selection::of(SelectionKind::Part, {"crate.body", "table.desk"}));
        a.regions->updateActions();
        QVERIFY(a.regions->clipSelectedAction()->isEnabled());
        QVERIFY(a.regions->clipSelectedParts());
        QCOMPARE(a.document.undoStack()->count(), 1);
        QVERIFY(a.document.scene().findPart("table.desk"));
        QVERIFY(a.document.scene().findPart("crate.body-right"));
        QVERIFY(a.document.selection() == Selection::of(SelectionKind::Part, {"crate.body-left", "crate.body-right"}));
        VERIFY_UNDO_REDO(a.document, straddlingScene());
    }

    void aRegionAroundTheSelectionCoversItOnTheGridInOneStep()
    {
        RegionFixture a(test::smallScene());
        a.viewport->setSnapEnabled(true);
        a.viewport->setGridStep(0.25);
        a.document.setSelection(Selection::single(SelectionKind::Part, "crate.body"));
        QVERIFY(a.regions->addRegionAroundSelection());
        QCOMPARE(a.document.undoStack()->count(), 1);
        const model::Region& added = a.document.scene().regions.back();
        QCOMPARE(added.min, model::Vec3(2, 0, 0));
        QCOMPARE(added.max, model::Vec3(2.5, 0.5, 0.5));
        QVERIFY(a.document.selection() == Selection::single(SelectionKind::Region, added.id));
        VERIFY_UNDO_REDO(a.document, test::smallScene());
    }

    void acceptingAProposalReplacesTheRegionsInOneUndoStep()
    {
        const model::Scene scene = test::loadSample("two-lights-room");
        RegionFixture a(scene);
        QVERIFY(a.regions->proposeRegions());
        QVERIFY(a.regions->proposal().has_value());
        const std::vector<model::Region> proposed = a.regions->proposal()->regions;
        QVERIFY(!proposed.empty());
        QVERIFY(a.viewport->hasLayer(QString::fromLatin1(kRegionProposalLayer)));
        QVERIFY(a.regions->dock()->proposalVisible());
        QVERIFY(a.document.scene() == scene); // a preview changes nothing

        QVERIFY(a.regions->acceptProposal());
        QCOMPARE(a.document.undoStack()->count(), 1);
        QVERIFY(a.document.scene().regions == proposed);
        QVERIFY(!a.viewport->hasLayer(QString::fromLatin1(kRegionProposalLayer)));
        QVERIFY(!a.regions->dock()->proposalVisible());
        VERIFY_UNDO_REDO(a.document, scene);
    }

    void theProposalsFiguresAreTheSolversForTheProposedRegions()
    {
        const model::Scene scene = test::loadSample("two-lights-room");
        RegionFixture a(scene);
        QVERIFY(a.regions->proposeRegions());
        const solver::RegionProposal& proposal = *a.regions->proposal();
        const model::Result<solver::SceneBspFigures> expected =
            solver::computeBspFigures(solver::withRegions(scene, proposal.regions));
        QVERIFY(expected.ok());
        QCOMPARE(proposal.figures.fragments, expected->fragments);
        QVERIFY(a.regions->dock()->proposalLabel()->text().contains(QString::number(expected->fragments)));
    }

    void discardingAProposalLeavesTheSceneAndHistoryAlone()
    {
        const model::Scene scene = test::loadSample("two-lights-room");
        RegionFixture a(scene);
        QVERIFY(a.regions->proposeRegions());
        a.regions->discardProposal();
        QVERIFY(!a.regions->proposal());
        QVERIFY(!a.viewport->hasLayer(QString::fromLatin1(kRegionProposalLayer)));
        QVERIFY(!a.regions->acceptAction()->isEnabled());
        QCOMPARE(a.document.undoStack()->count(), 0);
        QVERIFY(a.document.scene() == scene);
    }

    void aProposalIsDroppedWhenTheSceneChanges()
    {
        const model::Scene scene = test::loadSample("two-lights-room");
        RegionFixture a(scene);
        QVERIFY(a.regions->proposeRegions());
        a.document.setSelection(Selection::single(SelectionKind::Region, scene.regions.front().id));
        QVERIFY(a.regions->proposal()); // selecting is no change
        const std::string part = scene.objects.front().parts.front().id;
        QVERIFY(a.document.push(new RenamePart(&a.document, part, part + "-renamed")));
        QVERIFY(!a.regions->proposal());
        QVERIFY(!a.viewport->hasLayer(QString::fromLatin1(kRegionProposalLayer)));

        QVERIFY(a.regions->proposeRegions());
        a.document.reset(test::smallScene());
        QVERIFY(!a.regions->proposal());
    }

    void theRegionsMenuOffersTheToolTheFixesTheProposalAndTheViews()
    {
        RegionFixture a(straddlingScene());
        QMenu menu;
        a.regions->populateRegionsMenu(&menu);
        const QList<QAction*> actions = menu.actions();
        for (QAction* action :
             {a.regions->drawAction(), a.regions->proposeAction(), a.regions->acceptAction(),
              a.regions->discardAction(), a.regions->clipSelectedAction(), a.regions->showBoxesAction(),
              a.regions->colourByRegionAction(), a.regions->showPlanesAction()})
            QVERIFY2(actions.contains(action), qPrintable(action->text()));
        QVERIFY(a.regions->drawAction()->isCheckable());
        // Clipping is offered only for a selection that straddles.
        a.document.setSelection(Selection::single(SelectionKind::Part, "table.desk"));
        QVERIFY(!a.regions->clipSelectedAction()->isEnabled());
        a.document.setSelection(Selection::single(SelectionKind::Object, "crate"));
        QVERIFY(a.regions->clipSelectedAction()->isEnabled());
        // The menu's tool action and the viewport's tool stay in step.
        a.regions->drawAction()->trigger();
        QVERIFY(a.viewport->tool() == a.regions->tool());
        a.viewport->setTool(nullptr);
        QVERIFY(!a.regions->drawAction()->isChecked());
    }

    void regionEditsSurviveSaveAndLoad()
    {
        SceneDocument document;
        test::resetDocument(document, straddlingScene());
        QVERIFY(document.push(new AddRegion(&document, {"top", "Top", {-1, 3, -1}, {4, 4, 2}, {}})));
        QVERIFY(document.push(new ResizeRegionByHandle(&document, "top", {-1, 3, -1}, {4, 4.5, 2}, 1)));
        QVERIFY(document.push(new RenameRegion(&document, "right", "east")));
        QVERIFY(document.push(new SetRegionName(&document, "east", "East side")));
        QVERIFY(document.push(new ClipPartToRegions(&document, "crate.body")));

        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("regions.json"));
        QString error;
        QVERIFY2(document.save(path, &error), qPrintable(error));
        SceneDocument loaded;
        model::Diagnostics diagnostics;
        QVERIFY(loaded.open(path, diagnostics));
        QVERIFY(loaded.scene().regions == document.scene().regions);
        QVERIFY(loaded.scene() == document.scene());
        QCOMPARE(loaded.scene().findRegion("top")->max.y, 4.5);
        QVERIFY(loaded.scene().findPart("crate.body-east"));
    }
};

REGIO_QTEST_MAIN(RegionsCommandsTest)
#include "regions_commands_test.moc"
