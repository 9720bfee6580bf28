// SceneDocument: the one owner of a scene, its undo stack, selection, file
// path and modified flag.
#include "editor/document/commands/object_commands.h"
#include "editor/document/commands/part_commands.h"
#include "editor/document/scene_document.h"
#include "support/editor_documents.h"
#include "support/qt_test_registry.h"

#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>

using namespace regio;
using namespace regio::editor;

class SceneDocumentTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { test::initTestEnvironment(); }

    void aNewDocumentIsAnEmptyUntitledUnmodifiedScene()
    {
        SceneDocument document;
        QVERIFY(document.scene() == model::Scene{});
        QVERIFY(document.filePath().isEmpty());
        QCOMPARE(document.displayName(), QStringLiteral("Untitled"));
        QVERIFY(!document.isModified());
        QVERIFY(document.selection().empty());
    }

    void openingASceneFileLoadsItAndRemembersItsPath()
    {
        SceneDocument document;
        model::Diagnostics diagnostics;
        QVERIFY(document.open(test::sampleFile("cornell-box"), diagnostics));
        QVERIFY(document.scene() == test::loadSample("cornell-box"));
        QCOMPARE(document.displayName(), QStringLiteral("cornell-box.json"));
        QVERIFY(!document.isModified());
    }

    void openingABrokenFileLeavesTheOpenDocumentUnchanged()
    {
        QTemporaryDir dir;
        const QString broken = dir.filePath(QStringLiteral("broken.json"));
        QFile file(broken);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("{ \"format\": \"regio-scene\", \"version\": 1, \"materials\": [ { \"id\": ");
        file.close();

        SceneDocument document;
        model::Diagnostics diagnostics;
        QVERIFY(document.open(test::sampleFile("cornell-box"), diagnostics));
        document.push(new RemoveObject(&document, "short")); // unsaved work
        const model::Scene before = document.scene();
        const QString pathBefore = document.filePath();
        const int undoCountBefore = document.undoStack()->count();
        QSignalSpy resets(&document, &SceneDocument::sceneReset);

        QVERIFY(!document.open(broken, diagnostics));
        QVERIFY(!diagnostics.empty());
        QVERIFY(model::hasErrors(diagnostics));
        QVERIFY(document.scene() == before);
        QCOMPARE(document.filePath(), pathBefore);
        QCOMPARE(document.undoStack()->count(), undoCountBefore);
        QVERIFY(document.isModified());
        QCOMPARE(resets.count(), 0);
    }

    void openingAMissingFileReportsItAndChangesNothing()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        model::Diagnostics diagnostics;
        QVERIFY(!document.open(QStringLiteral("/nonexistent/scene.json"), diagnostics));
        QVERIFY(model::hasErrors(diagnostics));
        QVERIFY(document.scene() == test::smallScene());
    }

    void savingAndOpeningAgainGivesTheSameScene()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("round-trip.json"));
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        document.push(new SetPartMaterial(&document, "crate.body", "white"));
        QString error;
        QVERIFY2(document.save(path, &error), qPrintable(error));
        QCOMPARE(document.filePath(), QFileInfo(path).absoluteFilePath());
        QVERIFY(!document.isModified());

        SceneDocument reopened;
        model::Diagnostics diagnostics;
        QVERIFY(reopened.open(path, diagnostics));
        QVERIFY(reopened.scene() == document.scene());
    }

    void saveThenOpenThenSaveIsByteIdentical()
    {
        QTemporaryDir dir;
        SceneDocument document;
        model::Diagnostics diagnostics;
        QVERIFY(document.open(test::sampleFile("two-lights-room"), diagnostics));
        const QString first = dir.filePath(QStringLiteral("first.json"));
        const QString second = dir.filePath(QStringLiteral("second.json"));
        QVERIFY(document.save(first));
        SceneDocument again;
        QVERIFY(again.open(first, diagnostics));
        QVERIFY(again.save(second));
        QFile a(first), b(second);
        QVERIFY(a.open(QIODevice::ReadOnly) && b.open(QIODevice::ReadOnly));
        QCOMPARE(a.readAll(), b.readAll());
    }

    void aFailedSaveKeepsThePathAndTheModifiedFlag()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        document.push(new RemoveObject(&document, "crate"));
        QString error;
        QVERIFY(!document.save(QStringLiteral("/nonexistent-dir/x/scene.json"), &error));
        QVERIFY(!error.isEmpty());
        QVERIFY(document.filePath().isEmpty());
        QVERIFY(document.isModified());
    }

    void theModifiedFlagFollowsTheUndoStacksCleanState()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        QSignalSpy modified(&document, &SceneDocument::modifiedChanged);
        document.push(new SetObjectName(&document, "crate", "Crate"));
        QVERIFY(document.isModified());
        document.undoStack()->undo();
        QVERIFY(!document.isModified());
        document.undoStack()->redo();
        QVERIFY(document.isModified());
        QCOMPARE(modified.count(), 3);
    }

    void revertDropsEveryChangeAndTheHistory()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("scene.json"));
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        QVERIFY(document.save(path));
        document.push(new RemoveObject(&document, "table"));
        document.push(new RemoveObject(&document, "crate"));
        model::Diagnostics diagnostics;
        QVERIFY(document.revert(diagnostics));
        QVERIFY(document.scene() == test::smallScene());
        QCOMPARE(document.undoStack()->count(), 0);
        QVERIFY(!document.isModified());
    }

    void aRecoveredSceneCountsAsModifiedEvenWithAnEmptyHistory()
    {
        SceneDocument document;
        document.reset(test::smallScene(), QStringLiteral("/tmp/original.json"), true);
        QVERIFY(document.isModified());
        QCOMPARE(document.displayName(), QStringLiteral("original.json"));
    }

    void eachEditEmitsTheSignalsOfWhatItChanged()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        QSignalSpy objects(&document, &SceneDocument::objectsChanged);
        QSignalSpy materials(&document, &SceneDocument::materialsChanged);
        QSignalSpy regions(&document, &SceneDocument::regionsChanged);
        QSignalSpy settings(&document, &SceneDocument::settingsChanged);
        document.push(new SetPartName(&document, "crate.body", "Body"));
        QCOMPARE(objects.count(), 1);
        QCOMPARE(materials.count(), 0);
        QCOMPARE(regions.count(), 0);
        QCOMPARE(settings.count(), 0);
        // Removing the table takes its faces out of the region's BSP order.
        document.push(new RemoveObject(&document, "table"));
        QCOMPARE(objects.count(), 2);
        QCOMPARE(regions.count(), 1);
    }

    void movingPartsIsAGeometryChangeOnly()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        QSignalSpy objects(&document, &SceneDocument::objectsChanged);
        QSignalSpy geometry(&document, &SceneDocument::geometryChanged);
        document.push(new TransformParts(&document, {"crate.body"},
                                         glm::dmat4(2.0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1)));
        QCOMPARE(geometry.count(), 1);
        QCOMPARE(objects.count(), 0);
        document.undoStack()->undo();
        QCOMPARE(geometry.count(), 2);
        QCOMPARE(objects.count(), 0);
    }

    void aRefusedEditIsNotOnTheStackAndSaysWhy()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        QSignalSpy failures(&document, &SceneDocument::editFailed);
        QVERIFY(!document.push(new RenameObject(&document, "crate", "table"))); // id taken
        QCOMPARE(document.undoStack()->count(), 0);
        QCOMPARE(failures.count(), 1);
        QVERIFY(!failures.first().first().toString().isEmpty());
        QVERIFY(document.scene() == test::smallScene());
        QVERIFY(!document.isModified());
    }

    void aMacroIsOneUndoStep()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        document.beginMacro(QStringLiteral("two names"));
        QVERIFY(document.push(new SetObjectName(&document, "crate", "A")));
        QVERIFY(document.push(new SetObjectName(&document, "lamp", "B")));
        QVERIFY(document.endMacro());
        QCOMPARE(document.undoStack()->count(), 1);
        document.undoStack()->undo();
        QVERIFY(document.scene() == test::smallScene());
    }

    void aMacroWithARefusedStepIsRolledBackAndDropped()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        document.push(new SetObjectName(&document, "crate", "Kept"));
        const model::Scene before = document.scene();
        document.beginMacro(QStringLiteral("partly refused"));
        QVERIFY(document.push(new SetObjectName(&document, "lamp", "B")));
        QVERIFY(!document.push(new RemoveObject(&document, "no-such-object")));
        QVERIFY(!document.endMacro());
        QVERIFY(document.scene() == before);
        QCOMPARE(document.undoStack()->count(), 1);
        QCOMPARE(document.undoStack()->index(), 1);
        QVERIFY(!document.undoStack()->canRedo());
    }

    void theSelectionForgetsElementsThatAreDeleted()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        document.setSelection(Selection::of(SelectionKind::Object, {"crate", "lamp"}));
        QSignalSpy selection(&document, &SceneDocument::selectionChanged);
        document.push(new RemoveObject(&document, "crate"));
        QCOMPARE(document.selection().ids, std::vector<std::string>{"lamp"});
        QCOMPARE(selection.count(), 1);
    }

    void viewsNeverSeeASelectionNamingDeletedElements()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        document.setSelection(Selection::of(SelectionKind::Object, {"crate", "lamp"}));
        bool consistent = true;
        connect(&document, &SceneDocument::objectsChanged, this, [&] {
            for (const std::string& id : document.selection().ids)
                consistent = consistent && document.scene().findObject(id) != nullptr;
        });
        document.push(new RemoveObject(&document, "crate"));
        document.undoStack()->undo();
        document.setSelection(Selection::single(SelectionKind::Object, "crate"));
        document.undoStack()->redo();
        QVERIFY(consistent);
    }

    void selectingAnUnknownIdSelectsNothing()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        document.setSelection(Selection::single(SelectionKind::Part, "no-such-part"));
        QVERIFY(document.selection().empty());
        document.setSelection(Selection::single(SelectionKind::Face, "crate.body.px"));
        QCOMPARE(document.selection().kind, SelectionKind::Face);
    }
};

REGIO_QTEST_MAIN(SceneDocumentTest)
#include "scene_document_test.moc"
