// Undo commands on materials.
#include "editor/document/commands/material_commands.h"
#include "support/editor_documents.h"
#include "support/qt_test_registry.h"

#include <QSignalSpy>

using namespace regio;
using namespace regio::editor;

class MaterialCommandsTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { test::initTestEnvironment(); }

    void addingAMaterialAppendsItAndUndoRemovesIt()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        const model::Scene before = document.scene();
        QSignalSpy materials(&document, &SceneDocument::materialsChanged);
        QVERIFY(document.push(new AddMaterial(&document, {"blue", "Blue", {0.1, 0.2, 0.6}, {0, 0, 0}})));
        QCOMPARE(document.scene().materials.back().id, std::string("blue"));
        QCOMPARE(materials.count(), 1);
        VERIFY_UNDO_REDO(document, before);
    }

    void valueChangesNameTheirMaterialInTheHistory()
    {
        SceneDocument document;
        const std::string id = test::smallScene().materials.front().id;
        SetMaterialReflectance reflectance(&document, id, {0.2, 0.2, 0.2});
        SetMaterialEmission emission(&document, id, {1.0, 1.0, 1.0});
        SetMaterialName name(&document, id, "Plaster");
        for (const QUndoCommand* command : std::initializer_list<const QUndoCommand*>{&reflectance, &emission, &name})
            QVERIFY2(command->text().contains(QString::fromStdString(id)), qPrintable(command->text()));
        QVERIFY(name.text().contains(QStringLiteral("Plaster")));
    }

    void aMaterialWithReflectanceOfOneIsRefused()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        QVERIFY(!document.push(new AddMaterial(&document, {"mirror", "", {1.0, 1.0, 1.0}, {0, 0, 0}})));
        QVERIFY(document.scene() == test::smallScene());
    }

    void anUnusedMaterialCanBeRemovedAndRestoredInPlace()
    {
        SceneDocument document;
        model::Scene scene = test::smallScene();
        scene.materials.insert(scene.materials.begin() + 1, {"spare", "", {0.3, 0.3, 0.3}, {0, 0, 0}});
        test::resetDocument(document, scene);
        QVERIFY(document.push(new RemoveMaterial(&document, "spare")));
        QVERIFY(!document.scene().findMaterial("spare"));
        VERIFY_UNDO_REDO(document, scene);
        document.undoStack()->undo();
        QCOMPARE(document.scene().materials[1].id, std::string("spare"));
    }

    void aMaterialInUseCannotBeRemoved()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        QSignalSpy failures(&document, &SceneDocument::editFailed);
        QVERIFY(!document.push(new RemoveMaterial(&document, "red")));
        QCOMPARE(failures.count(), 1);
        QVERIFY(document.scene() == test::smallScene());
    }

    void renamingAMaterialUpdatesEveryReference()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        const model::Scene before = document.scene();
        QSignalSpy objects(&document, &SceneDocument::objectsChanged);
        QVERIFY(document.push(new RenameMaterial(&document, "red", "crimson")));
        QCOMPARE(document.scene().findPart("crate.body")->material, std::string("crimson"));
        QVERIFY(objects.count() >= 1);
        VERIFY_UNDO_REDO(document, before);
    }

    void reflectanceEmissionAndNameCanEachBeUndone()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        model::Scene expected = document.scene();
        QVERIFY(document.push(new SetMaterialReflectance(&document, "white", {0.5, 0.6, 0.7})));
        QCOMPARE(document.scene().findMaterial("white")->reflectance, model::Rgb(0.5, 0.6, 0.7));
        VERIFY_UNDO_REDO(document, expected);
        expected = document.scene();
        QVERIFY(document.push(new SetMaterialEmission(&document, "white", {1, 2, 3})));
        QCOMPARE(document.scene().findMaterial("white")->emission, model::Rgb(1, 2, 3));
        VERIFY_UNDO_REDO(document, expected);
        expected = document.scene();
        QVERIFY(document.push(new SetMaterialName(&document, "white", "Chalk")));
        VERIFY_UNDO_REDO(document, expected);
    }

    void negativeEmissionIsRefused()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        QVERIFY(!document.push(new SetMaterialEmission(&document, "white", {-1, 0, 0})));
        QCOMPARE(document.undoStack()->count(), 0);
    }

    void draggingAColourMergesIntoOneStep()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        for (int i = 1; i <= 20; ++i)
            QVERIFY(document.push(new SetMaterialReflectance(&document, "red", {0.02 * i, 0.1, 0.1})));
        QCOMPARE(document.undoStack()->count(), 1);
        document.undoStack()->undo();
        QVERIFY(document.scene() == test::smallScene());
    }

    void reflectanceAndEmissionEditsDoNotMergeWithEachOther()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        document.push(new SetMaterialReflectance(&document, "red", {0.2, 0.1, 0.1}));
        document.push(new SetMaterialEmission(&document, "red", {1, 0, 0}));
        document.push(new SetMaterialReflectance(&document, "white", {0.2, 0.1, 0.1}));
        QCOMPARE(document.undoStack()->count(), 3);
    }
};

REGIO_QTEST_MAIN(MaterialCommandsTest)
#include "material_commands_test.moc"
