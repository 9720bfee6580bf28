// Random edits, merging bursts, undos and redos in the editor's window, with
// its panels (materials, solver settings, regions, BSP order, scene tree) and
// the live preview following every change: undone to the start the scene
// saves to exactly its loaded bytes, redone to the top exactly the edited
// ones, and no panel pushes an edit of its own while it shows what an undo
// or redo did (that would cut the redo history short). A real GL context
// (xcb): the window's viewport is a QOpenGLWidget.
#include "random_editor.h"

#include "editor/app/main_window.h"
#include "support/editor_documents.h"
#include "support/qt_test_registry.h"

#include <QAction>
#include <QCoreApplication>
#include <QTest>

using namespace regio;
using namespace regio::editor;

class RandomEditsWindowGlTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { test::initTestEnvironment(); }

    void shortSequencesInTheWindowWithThePanelsAndTheLivePreviewSaveByteForByte()
    {
        MainWindowOptions options;
        options.persistent = false;
        options.interactive = false;
        options.autosave = false;
        MainWindow window(options);
        window.show();
        QVERIFY(window.openFile(test::sampleFile("cornell-box")));
        const model::Scene loaded = window.document()->scene();
        QAction* live = nullptr;
        QAction* run = nullptr;
        for (QAction* action : window.findChildren<QAction*>()) {
            const QString text = action->text().remove(QLatin1Char('&'));
            if (text == QStringLiteral("Live"))
                live = action;
            else if (text == QStringLiteral("Run") && action->shortcut() == QKeySequence(Qt::Key_F5))
                run = action;
        }
        QVERIFY(live && live->isCheckable() && run);
        live->setChecked(true);
        run->trigger();
        for (unsigned seed = 1; seed <= 12; ++seed) {
            test::resetDocument(*window.document(), loaded);
            if (const QString failure =
                    test::runShortSequence(*window.document(), seed, [] { QCoreApplication::processEvents(); });
                !failure.isEmpty())
                QFAIL(qPrintable(QStringLiteral("seed %1: %2").arg(seed).arg(failure)));
        }
    }
};

REGIO_QTEST_MAIN(RandomEditsWindowGlTest)
#include "random_edits_window_gl_test.moc"
