// Undo commands on the solver settings and the stored camera.
#include "editor/document/commands/solver_settings_commands.h"
#include "support/editor_documents.h"
#include "support/qt_test_registry.h"

#include <QSignalSpy>

using namespace regio;
using namespace regio::editor;

class SolverSettingsCommandsTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { test::initTestEnvironment(); }

    void changingTheSettingsCanBeUndone()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        const model::Scene before = document.scene();
        QSignalSpy settings(&document, &SceneDocument::settingsChanged);
        model::SolverSettings s = before.solver;
        s.hemicube = 300;
        s.adaptive.enabled = false;
        QVERIFY(document.push(new SetSolverSettings(&document, s)));
        QCOMPARE(document.scene().solver.hemicube, 300);
        QCOMPARE(settings.count(), 1);
        VERIFY_UNDO_REDO(document, before);
    }

    void anOddHemicubeResolutionIsRefused()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        model::SolverSettings s = document.scene().solver;
        s.hemicube = 151;
        QVERIFY(!document.push(new SetSolverSettings(&document, s)));
        QVERIFY(document.scene() == test::smallScene());
    }

    void scrubbingASettingMergesIntoOneStep()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        model::SolverSettings s = document.scene().solver;
        for (int n = 152; n <= 200; n += 2) {
            s.hemicube = n;
            QVERIFY(document.push(new SetSolverSettings(&document, s)));
        }
        QCOMPARE(document.undoStack()->count(), 1);
        document.undoStack()->undo();
        QVERIFY(document.scene() == test::smallScene());
    }

    void storingAndClearingTheSceneCameraCanBeUndone()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        const model::Scene before = document.scene();
        QSignalSpy camera(&document, &SceneDocument::cameraChanged);
        model::Camera view;
        view.position = {1, 2, 3};
        view.target = {0, 0, 0};
        QVERIFY(document.push(new SetSceneCamera(&document, view)));
        QVERIFY(document.scene().camera == view);
        QCOMPARE(camera.count(), 1);
        VERIFY_UNDO_REDO(document, before);
        const model::Scene stored = document.scene();
        QVERIFY(document.push(new SetSceneCamera(&document, std::nullopt)));
        QVERIFY(!document.scene().camera);
        VERIFY_UNDO_REDO(document, stored);
    }
};

REGIO_QTEST_MAIN(SolverSettingsCommandsTest)
#include "solver_settings_commands_test.moc"
