// Whole-part authoring as the menus drive it: each action is one undo step
// that leaves a valid scene.
#include "editor/app/main_window.h"
#include "editor/app/preferences_dialog.h"
#include "editor/objects/authoring.h"
#include "editor/objects/primitive_dialog.h"
#include "editor/viewport/viewport.h"
#include "model/validation/validation.h"
#include "support/editor_documents.h"
#include "support/qt_test_registry.h"

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

bool valid(const model::Scene& scene) { return !model::hasErrors(model::validateScene(scene)); }

} // namespace

class AuthoringTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { test::initTestEnvironment(); }

    void everyPrimitiveIsCreatedValidSelectedAndUndoneInOneStep_data()
    {
        QTest::addColumn<int>("kind");
        QTest::newRow("box") << int(PrimitiveKind::Box);
        QTest::newRow("room") << int(PrimitiveKind::Room);
        QTest::newRow("prism") << int(PrimitiveKind::Prism);
        QTest::newRow("wedge") << int(PrimitiveKind::Wedge);
        QTest::newRow("stairs") << int(PrimitiveKind::Stairs);
    }

    void everyPrimitiveIsCreatedValidSelectedAndUndoneInOneStep()
    {
        QFETCH(int, kind);
        auto window = makeWindow(test::smallScene());
        SceneDocument* document = window->document();
        Authoring* authoring = window->authoring();
        const PrimitiveParams params = authoring->defaultPrimitive(PrimitiveKind(kind));
        QVERIFY(!document->scene().idInUse(params.id));
        QVERIFY(authoring->createPrimitive(params));
        const model::Object* object = document->scene().findObject(params.id);
        QVERIFY(object);
        QVERIFY(!object->parts.empty());
        QVERIFY(valid(document->scene()));
        QCOMPARE(document->selection(), Selection::single(SelectionKind::Object, params.id));
        QCOMPARE(document->undoStack()->count(), 1);
        document->undoStack()->undo();
        QVERIFY(document->scene() == test::smallScene());
    }

    void thePrimitiveDialogOffersTheDefaultsAndGivesThemBack()
    {
        auto window = makeWindow(test::smallScene());
        for (PrimitiveKind kind : {PrimitiveKind::Box, PrimitiveKind::Prism, PrimitiveKind::Stairs}) {
            const PrimitiveParams defaults = window->authoring()->defaultPrimitive(kind);
            PrimitiveDialog dialog(defaults, window->document()->scene());
            const PrimitiveParams shown = dialog.params();
            QCOMPARE(shown.id, defaults.id);
            QCOMPARE(shown.material, defaults.material);
            QCOMPARE(shown.size, defaults.size);
            QCOMPARE(shown.base, defaults.base);
            QCOMPARE(shown.sides, defaults.sides);
            QCOMPARE(shown.steps, defaults.steps);
        }
    }

    void thePreferencesDialogGivesBackWhatItWasGiven()
    {
        Preferences p;
        p.language = QStringLiteral("cs");
        p.autosaveMinutes = 7;
        p.gridStep = 0.25;
        p.snapToGrid = false;
        p.angleSnapDegrees = 5.0;
        PreferencesDialog dialog(p);
        QVERIFY(dialog.preferences() == p);
    }

    void aSecondPrimitiveOfAKindGetsAFreshId()
    {
        auto window = makeWindow(test::smallScene());
        Authoring* authoring = window->authoring();
        QVERIFY(authoring->createPrimitive(authoring->defaultPrimitive(PrimitiveKind::Box)));
        const PrimitiveParams second = authoring->defaultPrimitive(PrimitiveKind::Box);
        QCOMPARE(second.id, std::string("box-2"));
        QVERIFY(authoring->createPrimitive(second));
        QVERIFY(valid(window->document()->scene()));
    }

    void aPrimitiveWithANonPositiveSizeIsRefused()
    {
        auto window = makeWindow(test::smallScene());
        PrimitiveParams params = window->authoring()->defaultPrimitive(PrimitiveKind::Box);
        params.size.y = 0.0;
        QVERIFY(!window->authoring()->createPrimitive(params));
        QCOMPARE(window->document()->undoStack()->count(), 0);
    }

    void duplicatingSelectsTheCopies()
    {
        auto window = makeWindow(test::smallScene());
        SceneDocument* document = window->document();
        document->setSelection(Selection::of(SelectionKind::Object, {"crate", "lamp"}));
        QVERIFY(window->authoring()->duplicateSelection());
        QCOMPARE(document->selection(), Selection::of(SelectionKind::Object, {"crate-2", "lamp-2"}));
        QCOMPARE(document->undoStack()->count(), 1);
        QVERIFY(valid(document->scene()));
    }

    void deletingEveryPartOfAnObjectDeletesTheObjectInTheSameStep()
    {
        auto window = makeWindow(test::smallScene());
        SceneDocument* document = window->document();
        document->setSelection(Selection::of(SelectionKind::Part, {"table.desk", "table.legs", "crate.body"}));
        QVERIFY(window->authoring()->deleteSelection());
        QVERIFY(!document->scene().findObject("table"));
        QVERIFY(!document->scene().findObject("crate"));
        QCOMPARE(document->undoStack()->count(), 1);
        document->undoStack()->undo();
        QVERIFY(document->scene() == test::smallScene());
    }

    void facesCannotBeDeletedOnTheirOwn()
    {
        auto window = makeWindow(test::smallScene());
        window->document()->setSelection(Selection::single(SelectionKind::Face, "crate.body.px"));
        QVERIFY(!window->authoring()->deleteSelection());
        QVERIFY(window->document()->scene() == test::smallScene());
    }

    void renamingChangesIdAndNameInOneStepAndKeepsTheSelection()
    {
        auto window = makeWindow(test::smallScene());
        SceneDocument* document = window->document();
        document->setSelection(Selection::single(SelectionKind::Object, "crate"));
        QVERIFY(window->authoring()->renameElement(SelectionKind::Object, "crate", "chest", "Old chest"));
        QCOMPARE(document->scene().findObject("chest")->name, std::string("Old chest"));
        QCOMPARE(document->selection(), Selection::single(SelectionKind::Object, "chest"));
        QCOMPARE(document->undoStack()->count(), 1);
    }

    void groupingAndUngroupingRoundTrip()
    {
        auto window = makeWindow(test::smallScene());
        SceneDocument* document = window->document();
        document->setSelection(Selection::of(SelectionKind::Object, {"crate", "lamp"}));
        QVERIFY(window->authoring()->groupSelection());
        QCOMPARE(document->selection().ids, std::vector<std::string>{"group"});
        QCOMPARE(document->scene().findObject("group")->parts.size(), size_t(2));
        QVERIFY(window->authoring()->ungroupSelection());
        QCOMPARE(document->scene().objects.size(), size_t(3));
        document->undoStack()->undo();
        document->undoStack()->undo();
        QVERIFY(document->scene() == test::smallScene());
    }

    void splittingAcrossAnAxisCutsEverySelectedPartThePlaneCrosses()
    {
        auto window = makeWindow(test::smallScene());
        SceneDocument* document = window->document();
        document->setSelection(Selection::single(SelectionKind::Object, "table"));
        QVERIFY(window->authoring()->splitSelectionAlong(0)); // x through the table's centre
        QCOMPARE(document->scene().findObject("table")->parts.size(), size_t(4));
        QCOMPARE(document->selection().kind, SelectionKind::Part);
        QCOMPARE(document->selection().ids.size(), size_t(4));
        QVERIFY(valid(document->scene()));
        QCOMPARE(document->undoStack()->count(), 1);
        document->undoStack()->undo();
        QVERIFY(document->scene() == test::smallScene());
    }

    void aCutPlaneThatMissesTheSelectionChangesNothing()
    {
        auto window = makeWindow(test::smallScene());
        window->document()->setSelection(Selection::single(SelectionKind::Part, "crate.body"));
        const model::Plane far = model::Plane::fromPointNormal({9, 9, 9}, {0, 1, 0});
        QVERIFY(!window->authoring()->splitSelection(far));
        QCOMPARE(window->document()->undoStack()->count(), 0);
    }

    void threeClickedPointsCutTheSelection()
    {
        auto window = makeWindow(test::smallScene());
        SceneDocument* document = window->document();
        document->setSelection(Selection::single(SelectionKind::Part, "crate.body"));
        // The clip tool reports the plane through its three points.
        emit window->viewport()->clipPlaneChosen(model::Plane::fromPointNormal({2.25, 0.25, 0.25}, {0, 0, 1}));
        QCOMPARE(document->scene().findObject("crate")->parts.size(), size_t(2));
        QVERIFY(valid(document->scene()));
    }

    void assigningAMaterialToAPartClearsItsFacesOwnMaterials()
    {
        model::Scene scene = test::smallScene();
        scene.findPart("crate.body")->faces[0].material = "white";
        auto window = makeWindow(scene);
        SceneDocument* document = window->document();
        document->setSelection(Selection::single(SelectionKind::Object, "crate"));
        QVERIFY(window->authoring()->assignMaterial("light"));
        const model::Part* part = document->scene().findPart("crate.body");
        QCOMPARE(part->material, std::string("light"));
        for (const model::Face& face : part->faces)
            QVERIFY(face.material.empty());
        QCOMPARE(document->undoStack()->count(), 1);
        document->undoStack()->undo();
        QVERIFY(document->scene() == scene);
    }

    void assigningAMaterialToFacesSetsOnlyThem()
    {
        auto window = makeWindow(test::smallScene());
        SceneDocument* document = window->document();
        document->setSelection(Selection::of(SelectionKind::Face, {"crate.body.px", "crate.body.nx"}));
        QVERIFY(window->authoring()->assignMaterial("white"));
        const model::Part* part = document->scene().findPart("crate.body");
        int own = 0;
        for (const model::Face& face : part->faces)
            own += face.material == "white";
        QCOMPARE(own, 2);
        QCOMPARE(part->material, std::string("red"));
    }

    void aGizmoDragIsOneUndoStep()
    {
        auto window = makeWindow(test::smallScene());
        SceneDocument* document = window->document();
        document->setSelection(Selection::single(SelectionKind::Object, "crate"));
        Viewport* viewport = window->viewport();
        for (int i = 1; i <= 10; ++i)
            emit viewport->transformDragged({"crate.body"}, glm::translate(glm::dmat4(1.0), {0.1 * i, 0.0, 0.0}), 42);
        emit viewport->transformDragFinished();
        QCOMPARE(document->undoStack()->count(), 1);
        QCOMPARE(document->scene().findPart("crate.body")->vertices[0].x,
                 test::smallScene().findPart("crate.body")->vertices[0].x + 1.0);
        document->undoStack()->undo();
        QVERIFY(document->scene() == test::smallScene());
    }

    void aNumericTransformMovesTheSelectedObjectsParts()
    {
        auto window = makeWindow(test::smallScene());
        SceneDocument* document = window->document();
        document->setSelection(Selection::single(SelectionKind::Object, "table"));
        QVERIFY(window->authoring()->transformSelection(glm::translate(glm::dmat4(1.0), {0.0, 1.0, 0.0})));
        QCOMPARE(document->scene().findPart("table.legs")->vertices[0].y,
                 test::smallScene().findPart("table.legs")->vertices[0].y + 1.0);
    }

    void theViewCanBeStoredAsTheSceneCamera()
    {
        auto window = makeWindow(test::smallScene());
        QVERIFY(window->authoring()->storeViewAsSceneCamera());
        QVERIFY(window->document()->scene().camera.has_value());
    }

    void selectAllSelectsEveryElementOfTheCurrentKind()
    {
        auto window = makeWindow(test::smallScene());
        SceneDocument* document = window->document();
        document->setSelection(Selection::single(SelectionKind::Part, "crate.body"));
        window->authoring()->selectAll();
        QCOMPARE(document->selection().ids.size(), size_t(4));
        document->clearSelection();
        window->authoring()->selectAll();
        QCOMPARE(document->selection().kind, SelectionKind::Object);
        QCOMPARE(document->selection().ids.size(), size_t(3));
    }
};

REGIO_QTEST_MAIN(AuthoringTest)
#include "authoring_test.moc"
