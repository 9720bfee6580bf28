// The docks are views of the document: they show it, follow its selection,
// and edit it only through undo commands.
#include "editor/app/main_window.h"
#include "editor/docks/diagnostics_dock.h"
#include "editor/docks/diagnostics_model.h"
#include "editor/docks/materials_dock.h"
#include "editor/docks/properties_dock.h"
#include "editor/docks/scene_tree_dock.h"
#include "editor/docks/scene_tree_model.h"
#include "editor/docks/vector_editor.h"
#include "editor/document/commands/part_commands.h"
#include "editor/document/commands/region_commands.h"
#include "editor/preview/solver_dock.h"
#include "support/editor_documents.h"
#include "support/qt_test_registry.h"

#include <QDoubleSpinBox>
#include <QItemSelectionModel>
#include <QLineEdit>
#include <QListWidget>
#include <QMimeData>
#include <QPushButton>
#include <QScrollArea>
#include <QSignalSpy>
#include <QSortFilterProxyModel>
#include <QSpinBox>
#include <QTreeView>

#include <glm/gtc/matrix_transform.hpp>

#include <memory>

using namespace regio;
using namespace regio::editor;

namespace {

std::unique_ptr<MainWindow> makeWindow(model::Scene scene)
{
    MainWindowOptions options;
    options.persistent = false;
    options.interactive = false;
    options.autosave = false;
    auto window = std::make_unique<MainWindow>(options);
    window->document()->reset(std::move(scene));
    return window;
}

template <typename T>
T* dock(MainWindow* window)
{
    T* found = window->findChild<T*>();
    if (!found)
        qFatal("dock missing");
    return found;
}

} // namespace

class DocksTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { test::initTestEnvironment(); }

    void theSceneTreeListsObjectsPartsAndFaces()
    {
        auto window = makeWindow(test::smallScene());
        SceneTreeModel* model = dock<SceneTreeDock>(window.get())->model();
        QCOMPARE(model->rowCount(), 3);
        const QModelIndex table = model->index(0, 0);
        QCOMPARE(model->idAt(table), std::string("table"));
        QCOMPARE(model->rowCount(table), 2);
        const QModelIndex desk = model->index(0, 0, table);
        QCOMPARE(model->kindAt(desk), SelectionKind::Part);
        QCOMPARE(model->rowCount(desk), 6);
        QCOMPARE(model->kindAt(model->index(0, 0, desk)), SelectionKind::Face);
        // The material column names the part's material, with a swatch.
        const QModelIndex material = model->index(0, SceneTreeModel::MaterialColumn, table);
        QCOMPARE(material.data().toString(), QStringLiteral("white"));
        QVERIFY(material.data(Qt::DecorationRole).isValid());
    }

    void theSceneTreeFollowsEdits()
    {
        auto window = makeWindow(test::smallScene());
        SceneTreeModel* model = dock<SceneTreeDock>(window.get())->model();
        window->document()->push(new RemovePart(window->document(), "table.legs"));
        QCOMPARE(model->rowCount(model->index(0, 0)), 1);
        window->document()->undoStack()->undo();
        QCOMPARE(model->rowCount(model->index(0, 0)), 2);
    }

    void movingAPartDoesNotRebuildTheTree()
    {
        auto window = makeWindow(test::smallScene());
        SceneTreeModel* model = dock<SceneTreeDock>(window.get())->model();
        QSignalSpy resets(model, &QAbstractItemModel::modelReset);
        window->document()->push(
            new TransformParts(window->document(), {"crate.body"}, glm::translate(glm::dmat4(1.0), {0.0, 1.0, 0.0})));
        QCOMPARE(resets.count(), 0);
    }

    void selectingInTheTreeSelectsInTheDocumentAndBack()
    {
        auto window = makeWindow(test::smallScene());
        SceneTreeDock* tree = dock<SceneTreeDock>(window.get());
        SceneDocument* document = window->document();
        auto* proxy = qobject_cast<QSortFilterProxyModel*>(tree->view()->model());
        const QModelIndex crate = proxy->mapFromSource(tree->model()->indexOf(SelectionKind::Object, "crate"));
        tree->view()->selectionModel()->setCurrentIndex(crate, QItemSelectionModel::ClearAndSelect |
                                                                   QItemSelectionModel::Rows);
        QCOMPARE(document->selection(), Selection::single(SelectionKind::Object, "crate"));

        document->setSelection(Selection::single(SelectionKind::Face, "table.legs.py"));
        const QModelIndexList rows = tree->view()->selectionModel()->selectedRows();
        QCOMPARE(rows.size(), 1);
        QCOMPARE(rows.first().data(SceneTreeModel::ElementIdRole).toString(), QStringLiteral("table.legs.py"));
    }

    void droppingPartsOnAnObjectRegroupsThem()
    {
        auto window = makeWindow(test::smallScene());
        SceneTreeModel* model = dock<SceneTreeDock>(window.get())->model();
        const QModelIndex crateBody = model->indexOf(SelectionKind::Part, "crate.body");
        std::unique_ptr<QMimeData> data(model->mimeData({crateBody}));
        QVERIFY(data);
        const QModelIndex table = model->indexOf(SelectionKind::Object, "table");
        QVERIFY(model->canDropMimeData(data.get(), Qt::MoveAction, -1, -1, table));
        model->dropMimeData(data.get(), Qt::MoveAction, -1, -1, table);
        QTRY_VERIFY(window->document()->scene().ownerOfPart("crate.body") &&
                    window->document()->scene().ownerOfPart("crate.body")->id == "table");
        QVERIFY(!window->document()->scene().findObject("crate"));
        QCOMPARE(window->document()->undoStack()->count(), 1);
    }

    void partsCannotBeDroppedIntoAPart()
    {
        auto window = makeWindow(test::smallScene());
        SceneTreeModel* model = dock<SceneTreeDock>(window.get())->model();
        std::unique_ptr<QMimeData> data(model->mimeData({model->indexOf(SelectionKind::Part, "crate.body")}));
        QVERIFY(!model->canDropMimeData(data.get(), Qt::MoveAction, -1, -1,
                                        model->indexOf(SelectionKind::Part, "table.desk")));
    }

    void diagnosticsAreRecomputedAfterAnEdit()
    {
        auto window = makeWindow(test::smallScene());
        DiagnosticsDock* diagnostics = dock<DiagnosticsDock>(window.get());
        QCOMPARE(diagnostics->model()->rowCount(), 0);
        QSignalSpy counts(diagnostics, &DiagnosticsDock::problemCountChanged);
        // A second region overlapping the first is an error.
        QVERIFY(window->document()->push(new AddRegion(window->document(), {"overlap", "", {0, 0, 0}, {1, 1, 1}, {}})));
        QCOMPARE(diagnostics->model()->rowCount(), 0); // debounced: not yet
        QTRY_VERIFY(diagnostics->model()->errorCount() > 0);
        QVERIFY(!counts.isEmpty());
        QCOMPARE(counts.last().at(0).toInt(), diagnostics->model()->errorCount());
    }

    void activatingADiagnosticSelectsTheElementItNames()
    {
        model::Scene broken = test::smallScene();
        broken.findPart("crate.body")->vertices[0].y += 0.1;
        auto window = makeWindow(broken);
        DiagnosticsDock* diagnostics = dock<DiagnosticsDock>(window.get());
        diagnostics->validateNow();
        QVERIFY(diagnostics->model()->rowCount() > 0);
        QSignalSpy activated(diagnostics, &DiagnosticsDock::elementActivated);
        const QModelIndex first = diagnostics->model()->index(0, 0);
        const model::Diagnostic* d = diagnostics->model()->at(first);
        QVERIFY(d && !d->idPath.empty());
        emit diagnostics->view()->activated(first);
        QCOMPARE(activated.count(), 1);
        const Selection& s = window->document()->selection();
        QVERIFY(!s.empty());
        QVERIFY(s.ids.front().rfind("crate", 0) == 0);
    }

    void theSelectionForADiagnosticIsItsInnermostExistingElement()
    {
        const model::Scene scene = test::smallScene();
        QCOMPARE(DiagnosticsDock::selectionFor(scene, {"crate", "crate.body", "crate.body.px"}),
                 Selection::single(SelectionKind::Face, "crate.body.px"));
        QCOMPARE(DiagnosticsDock::selectionFor(scene, {"crate", "crate.body", "gone"}),
                 Selection::single(SelectionKind::Part, "crate.body"));
        QCOMPARE(DiagnosticsDock::selectionFor(scene, {"white"}), Selection::single(SelectionKind::Material, "white"));
        QVERIFY(DiagnosticsDock::selectionFor(scene, {}).empty());
    }

    // The solver's settings have one place, the Solver panel: the
    // Properties panel with nothing selected points there. (A second set of
    // controls once stored every setting rounded to its own decimals.)
    void thePropertiesPointToTheSolverPanelWhenNothingIsSelected()
    {
        auto window = makeWindow(test::smallScene());
        PropertiesDock* properties = dock<PropertiesDock>(window.get());
        QCOMPARE(properties->currentPage(), 0);
        QVERIFY(properties->findChildren<QSpinBox*>().size() < 3); // no hemicube, no iterations
        auto* solver = dock<SolverDock>(window.get());
        solver->hide();
        QVERIFY(solver->isHidden());
        auto* show = properties->findChild<QPushButton*>(QStringLiteral("showSolverPanel"));
        QVERIFY(show);
        show->click();
        QVERIFY(!solver->isHidden());
        QCOMPARE(window->document()->undoStack()->count(), 0);
    }

    // The Solver panel shares the right-hand column (about 22 % of the
    // window, 320 px at 1440) with other panels: its content fits that
    // without a horizontal scrollbar.
    void theSolverPanelFitsANarrowColumn()
    {
        auto window = makeWindow(test::smallScene());
        auto* solver = dock<SolverDock>(window.get());
        auto* scroll = qobject_cast<QScrollArea*>(solver->widget());
        QVERIFY(scroll && scroll->widget());
        // Room for the dock's frame and the vertical scrollbar in 320 px.
        const int needed = scroll->widget()->minimumSizeHint().width();
        QVERIFY2(needed <= 290, qPrintable(QStringLiteral("%1 px").arg(needed)));
    }

    void editingTheCentreMovesTheSelection()
    {
        auto window = makeWindow(test::smallScene());
        SceneDocument* document = window->document();
        document->setSelection(Selection::single(SelectionKind::Object, "crate"));
        PropertiesDock* properties = dock<PropertiesDock>(window.get());
        VectorEditor* centre = properties->positionEditor();
        QCOMPARE(centre->value(), model::Vec3(2.25, 0.25, 0.25));
        centre->spinBox(1)->setValue(1.25);
        const model::Part* body = document->scene().findPart("crate.body");
        model::Box3 box;
        for (const model::Vec3& v : body->vertices)
            box.extend(v);
        QCOMPARE(box.center().y, 1.25);
        QCOMPARE(document->undoStack()->count(), 1);
    }

    void namingAPartInThePropertiesIsUndoable()
    {
        auto window = makeWindow(test::smallScene());
        SceneDocument* document = window->document();
        document->setSelection(Selection::single(SelectionKind::Part, "crate.body"));
        QLineEdit* name = dock<PropertiesDock>(window.get())->nameEdit();
        name->setText(QStringLiteral("Body"));
        emit name->editingFinished();
        QCOMPARE(document->scene().findPart("crate.body")->name, std::string("Body"));
        document->undoStack()->undo();
        QVERIFY(document->scene() == test::smallScene());
    }

    void theMaterialsDockListsMaterialsAndEditsReflectance()
    {
        auto window = makeWindow(test::smallScene());
        MaterialsDock* materials = dock<MaterialsDock>(window.get());
        QCOMPARE(materials->list()->count(), 3);
        materials->list()->setCurrentRow(1);
        QCOMPARE(materials->currentMaterial(), std::string("red"));
        QCOMPARE(materials->reflectanceEditor()->value(), model::Rgb(0.6, 0.1, 0.1));
        materials->reflectanceEditor()->spinBox(1)->setValue(0.3);
        materials->reflectanceEditor()->spinBox(1)->setValue(0.35);
        QCOMPARE(window->document()->scene().findMaterial("red")->reflectance, model::Rgb(0.6, 0.35, 0.1));
        QCOMPARE(window->document()->undoStack()->count(), 1); // scrubbing merges
        window->document()->undoStack()->undo();
        QCOMPARE(materials->reflectanceEditor()->value(), model::Rgb(0.6, 0.1, 0.1));
    }

    void editingOneChannelLeavesTheOthersExactlyAsTheSceneHasThem()
    {
        // Channels with more decimals than the editor shows (three).
        model::Scene scene = test::smallScene();
        scene.findMaterial("red")->reflectance = model::Rgb(0.61234, 0.11111, 0.09876);
        auto window = makeWindow(scene);
        MaterialsDock* materials = dock<MaterialsDock>(window.get());
        materials->list()->setCurrentRow(1);
        materials->reflectanceEditor()->spinBox(1)->setValue(0.35);
        QCOMPARE(window->document()->scene().findMaterial("red")->reflectance, model::Rgb(0.61234, 0.35, 0.09876));
        window->document()->undoStack()->undo();
        QVERIFY(window->document()->scene() == scene);
    }

    void theMaterialsDockKeepsItsCurrentMaterialAcrossEdits()
    {
        auto window = makeWindow(test::smallScene());
        MaterialsDock* materials = dock<MaterialsDock>(window.get());
        materials->list()->setCurrentRow(2);
        materials->emissionEditor()->spinBox(0)->setValue(30.0);
        QCOMPARE(materials->currentMaterial(), std::string("light"));
        QCOMPARE(window->document()->scene().findMaterial("light")->emission.r, 30.0);
    }
};

REGIO_QTEST_MAIN(DocksTest)
#include "docks_test.moc"
