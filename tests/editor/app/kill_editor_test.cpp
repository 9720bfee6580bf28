// Nothing lost when the editor is killed: a copy of this process (fork)
// edits a scene, saves it and autosaves its recovery file without pause,
// the way the editor does, and is killed with SIGKILL at random moments.
// After every kill the scene file is whole and exactly one of the states
// the editor had saved, the recovery file is whole and exactly one of the
// states it had autosaved, and the next start of the editor's window offers
// the recovery and restores it as unsaved changes.
#include "editor/app/autosave.h"
#include "editor/app/main_window.h"
#include "editor/document/commands/object_commands.h"
#include "editor/document/scene_document.h"
#include "model/io/scene_json.h"
#include "support/editor_documents.h"
#include "support/qt_test_registry.h"

#include <QApplication>
#include <QDir>
#include <QMessageBox>
#include <QPushButton>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTimer>

#include <csignal>
#include <random>

#include <sys/wait.h>
#include <unistd.h>

using namespace regio;
using namespace regio::editor;

namespace {

// The scene after edit `i` of the child: the table renamed "name-i".
model::Scene afterEdit(const model::Scene& base, int i)
{
    model::Scene scene = base;
    if (i > 0)
        scene.findObject("table")->name = "name-" + std::to_string(i);
    return scene;
}

// The edit number a scene holds (0: the base), -1 when it is no state the
// child went through.
int editOf(const model::Scene& base, const model::Scene& scene)
{
    const model::Object* table = scene.findObject("table");
    if (table == nullptr)
        return -1;
    int i = 0;
    if (table->name.rfind("name-", 0) == 0)
        i = std::stoi(table->name.substr(5));
    return scene == afterEdit(base, i) ? i : -1;
}

// The child: edits, autosaves after every edit and saves the scene after
// every third, until it is killed; after each edit it writes a byte to
// `progress`. Never returns.
[[noreturn]] void editForever(const QString& scenePath, int progress)
{
    auto* document = new SceneDocument;
    model::Diagnostics diagnostics;
    if (!document->open(scenePath, diagnostics))
        ::_exit(3);
    auto* autosave = new Autosave(document); // the editor's own recovery folder
    for (int i = 1;; ++i) {
        document->push(new SetObjectName(document, "table", "name-" + std::to_string(i)));
        if (!autosave->saveNow())
            ::_exit(4);
        if (i % 3 == 0 && !document->save(scenePath))
            ::_exit(5);
        const char edit = 1;
        if (::write(progress, &edit, 1) != 1)
            ::_exit(6);
    }
}

// Answers the recovery question of the next start with "Restore".
void restoreWhenAsked()
{
    QTimer::singleShot(20, [] {
        auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
        if (box == nullptr) {
            restoreWhenAsked();
            return;
        }
        for (QAbstractButton* button : box->buttons())
            if (button->text() == MainWindow::tr("Restore"))
                button->click();
    });
}

} // namespace

class KillEditorTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { test::initTestEnvironment(); }

    void killedAtRandomWhileSavingAndAutosavingTheEditorLosesNothing()
    {
        // A home of its own: the recovery folder is the editor's default one.
        QTemporaryDir home;
        qputenv("HOME", home.path().toUtf8());
        const QString recovery = Autosave::defaultDirectory();
        const QString scenePath = home.filePath(QStringLiteral("room.json"));
        const model::Scene base = test::loadSample("two-lights-room");
        {
            SceneDocument document;
            test::resetDocument(document, base);
            QVERIFY(document.save(scenePath));
        }

        std::mt19937 random(17);
        int kills = 0, midWork = 0, recovered = 0;
        int lastSaved = 0;
        for (int round = 0; round < 30; ++round) {
            int progress[2];
            QVERIFY(::pipe(progress) == 0);
            const pid_t child = ::fork();
            QVERIFY(child >= 0);
            if (child == 0) {
                ::close(progress[0]);
                editForever(scenePath, progress[1]);
            }
            ::close(progress[1]);
            // The kill comes after a few edits, however slow a loaded machine
            // makes the child, and then at a random moment of its work.
            const int edits = std::uniform_int_distribution<int>(1, 6)(random);
            for (int i = 0; i < edits; ++i) {
                char edit = 0;
                QVERIFY2(::read(progress[0], &edit, 1) == 1, "the child stopped before it was killed");
            }
            ::usleep(std::uniform_int_distribution<useconds_t>(0, 20000)(random));
            ::kill(child, SIGKILL);
            ::close(progress[0]);
            int status = 0;
            ::waitpid(child, &status, 0);
            QVERIFY2(WIFSIGNALED(status), "the child stopped before it was killed");
            ++kills;

            // The scene file: whole, and a state the editor saved (the child
            // starts each round from what the last one saved).
            const model::Result<model::Scene> saved = model::loadSceneFile(scenePath.toStdString());
            QVERIFY2(saved.ok(), "the saved scene is not whole after a kill");
            const int savedEdit = editOf(base, *saved);
            QVERIFY2(savedEdit >= 0, "the saved scene is no state the editor saved");
            lastSaved = savedEdit;

            // The recovery file, if the kill came after the first autosave.
            const QList<RecoveryFile> orphans = Autosave::findOrphans(recovery);
            QVERIFY(orphans.size() <= 1);
            if (orphans.isEmpty())
                continue;
            ++midWork;
            const model::Result<model::Scene> autosaved = model::loadSceneFile(orphans.first().scenePath.toStdString());
            QVERIFY2(autosaved.ok(), "the recovery file is not whole after a kill");
            QVERIFY2(editOf(base, *autosaved) >= 0, "the recovery file is no state the editor had");

            if (midWork % 5 == 0) {
                // The next start: the window offers the recovery and restores it.
                MainWindowOptions options;
                options.persistent = false;
                MainWindow window(options);
                restoreWhenAsked();
                window.offerRecovery();
                QVERIFY(window.document()->scene() == *autosaved);
                QVERIFY(window.document()->isModified());
                QCOMPARE(window.document()->filePath(), QFileInfo(scenePath).absoluteFilePath());
                QVERIFY(Autosave::findOrphans(recovery).isEmpty());
                ++recovered;
            } else {
                Autosave::remove(orphans.first());
            }
        }
        qInfo("%d kills, %d with a recovery file, %d recovered through the window, the scene at edit %d", kills,
              midWork, recovered, lastSaved);
        QCOMPARE(kills, 30);
        QVERIFY(midWork >= 10);
        QVERIFY(recovered >= 2);
        QVERIFY(lastSaved > 0);
    }
};

REGIO_QTEST_MAIN(KillEditorTest)
#include "kill_editor_test.moc"
