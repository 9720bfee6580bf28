// Undo commands on objects: every one does, undoes and redoes exactly.
#include "editor/document/commands/object_commands.h"
#include "support/editor_documents.h"
#include "support/qt_test_registry.h"

#include <QSignalSpy>

using namespace regio;
using namespace regio::editor;

class ObjectCommandsTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { test::initTestEnvironment(); }

    void addingAnObjectPutsItInTheSceneAndUndoTakesItOut()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        const model::Scene before = document.scene();
        model::Object box{"box", "Box", {*model::makeBox("box.body", {3, 0, 3}, {4, 1, 4}, "white")}};
        QVERIFY(document.push(new AddObject(&document, box)));
        QVERIFY(document.scene().findObject("box"));
        QCOMPARE(document.scene().objects.back().id, std::string("box"));
        VERIFY_UNDO_REDO(document, before);
    }

    void addingAnObjectAtAnIndexInsertsItThere()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        model::Object box{"box", "", {*model::makeBox("box.body", {3, 0, 3}, {4, 1, 4}, "white")}};
        QVERIFY(document.push(new AddObject(&document, box, 0)));
        QCOMPARE(document.scene().objects.front().id, std::string("box"));
    }

    void addingAnObjectWithATakenIdIsRefused()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        model::Object clash{"crate", "", {*model::makeBox("other.body", {3, 0, 3}, {4, 1, 4}, "white")}};
        QVERIFY(!document.push(new AddObject(&document, clash)));
        QVERIFY(document.scene() == test::smallScene());
    }

    void removingAnObjectTakesItsFacesOutOfBspOrdersAndUndoPutsThemBack()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        const model::Scene before = document.scene();
        QVERIFY(document.push(new RemoveObject(&document, "table")));
        QVERIFY(!document.scene().findObject("table"));
        QVERIFY(document.scene().regions.front().bspOrder.empty());
        VERIFY_UNDO_REDO(document, before);
    }

    void duplicatingAnObjectAddsACopyWithFreshIdsRightAfterIt()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        const model::Scene before = document.scene();
        auto* command = new DuplicateObject(&document, "table");
        QVERIFY(document.push(command));
        QCOMPARE(command->copyId(), std::string("table-2"));
        QCOMPARE(document.scene().objects[1].id, std::string("table-2"));
        QVERIFY(document.scene().findPart("table-2.desk"));
        VERIFY_UNDO_REDO(document, before);
        // Redo brings back the same copy, with the same ids.
        QVERIFY(document.scene().findPart("table-2.legs"));
    }

    void renamingAnObjectChangesOnlyItsId()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        const model::Scene before = document.scene();
        QVERIFY(document.push(new RenameObject(&document, "crate", "box")));
        QVERIFY(document.scene().findObject("box"));
        QVERIFY(document.scene().findPart("crate.body"));
        VERIFY_UNDO_REDO(document, before);
    }

    void settingAnObjectsNameCanBeUndone()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        const model::Scene before = document.scene();
        QVERIFY(document.push(new SetObjectName(&document, "crate", "Wooden crate")));
        QCOMPARE(document.scene().findObject("crate")->name, std::string("Wooden crate"));
        VERIFY_UNDO_REDO(document, before);
    }

    void typingANameMergesIntoOneUndoStep()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        document.push(new SetObjectName(&document, "crate", "W"));
        document.push(new SetObjectName(&document, "crate", "Wo"));
        document.push(new SetObjectName(&document, "crate", "Wood"));
        QCOMPARE(document.undoStack()->count(), 1);
        document.undoStack()->undo();
        QVERIFY(document.scene() == test::smallScene());
    }

    void namesOfDifferentObjectsDoNotMerge()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        document.push(new SetObjectName(&document, "crate", "A"));
        document.push(new SetObjectName(&document, "lamp", "B"));
        QCOMPARE(document.undoStack()->count(), 2);
    }

    void aNameChangedBackToTheOriginalLeavesNothingToUndo()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        document.push(new SetObjectName(&document, "table", "Desk"));
        document.push(new SetObjectName(&document, "table", "Table"));
        QCOMPARE(document.undoStack()->count(), 0);
        QVERIFY(!document.isModified());
    }

    void groupingPartsMakesOneObjectOfThem()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        const model::Scene before = document.scene();
        QVERIFY(document.push(ChangeObjectLayout::groupParts(&document, {"crate.body", "lamp.panel"}, "group")));
        const model::Object* group = document.scene().findObject("group");
        QVERIFY(group);
        QCOMPARE(group->parts.size(), size_t(2));
        QVERIFY(!document.scene().findObject("crate")); // left empty, so removed
        VERIFY_UNDO_REDO(document, before);
    }

    void groupingObjectsMergesAllTheirParts()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        const model::Scene before = document.scene();
        QVERIFY(document.push(ChangeObjectLayout::groupObjects(&document, {"table", "crate"}, "furniture")));
        QCOMPARE(document.scene().findObject("furniture")->parts.size(), size_t(3));
        VERIFY_UNDO_REDO(document, before);
    }

    void ungroupingGivesEveryPartAnObject()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        const model::Scene before = document.scene();
        QVERIFY(document.push(ChangeObjectLayout::ungroup(&document, "table")));
        QCOMPARE(document.scene().findObject("table")->parts.size(), size_t(1));
        QVERIFY(document.scene().findObject("table-legs"));
        VERIFY_UNDO_REDO(document, before);
    }

    void ungroupingASinglePartObjectIsRefused()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        QVERIFY(!document.push(ChangeObjectLayout::ungroup(&document, "crate")));
        QCOMPARE(document.undoStack()->count(), 0);
    }

    void movingPartsToAnotherObjectRemovesObjectsLeftEmpty()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        const model::Scene before = document.scene();
        QVERIFY(document.push(ChangeObjectLayout::moveParts(&document, {"crate.body"}, "table")));
        QCOMPARE(document.scene().findObject("table")->parts.back().id, std::string("crate.body"));
        QVERIFY(!document.scene().findObject("crate"));
        VERIFY_UNDO_REDO(document, before);
    }

    void movingPartsToNoObjectGivesEachItsOwn()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        const model::Scene before = document.scene();
        QVERIFY(document.push(ChangeObjectLayout::moveParts(&document, {"table.legs"}, {})));
        QVERIFY(document.scene().findObject("table-legs"));
        QCOMPARE(document.scene().ownerOfPart("table.legs")->id, std::string("table-legs"));
        QCOMPARE(document.scene().findObject("table")->parts.size(), size_t(1));
        VERIFY_UNDO_REDO(document, before);
    }

    void movingAnUnknownPartIsRefused()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        QVERIFY(!document.push(ChangeObjectLayout::moveParts(&document, {"nope"}, "table")));
        QVERIFY(document.scene() == test::smallScene());
    }
};

REGIO_QTEST_MAIN(ObjectCommandsTest)
#include "object_commands_test.moc"
