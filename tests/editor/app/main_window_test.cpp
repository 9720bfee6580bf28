// The main window: title, file workflow, recent files, settings.
#include "editor/app/main_window.h"
#include "editor/app/recent_files.h"
#include "editor/app/sample_scenes.h"
#include "editor/document/commands/object_commands.h"
#include "support/editor_documents.h"
#include "support/qt_test_registry.h"

#include <QAction>
#include <QFile>
#include <QMenu>
#include <QMenuBar>
#include <QSettings>
#include <QTemporaryDir>

#include <memory>

using namespace regio;
using namespace regio::editor;

namespace {

std::unique_ptr<MainWindow> makeWindow(bool persistent = false)
{
    MainWindowOptions options;
    options.persistent = persistent;
    options.interactive = false;
    options.autosave = false;
    return std::make_unique<MainWindow>(options);
}

QAction* findAction(QWidget* window, const QString& text)
{
    for (QAction* action : window->findChildren<QAction*>())
        if (action->text().remove(QLatin1Char('&')) == text)
            return action;
    return nullptr;
}

} // namespace

class MainWindowTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        test::initTestEnvironment();
        QCoreApplication::setOrganizationName(QStringLiteral("RegioTest"));
        QCoreApplication::setApplicationName(QStringLiteral("RegioMainWindowTest"));
    }

    void init()
    {
        QSettings settings;
        settings.clear();
    }

    void theHelpMenuOffersTheGuideAndTheExamples()
    {
        auto window = makeWindow();
        QMenu* help = nullptr;
        for (QAction* action : window->menuBar()->actions())
            if (action->text() == MainWindow::tr("&Help"))
                help = action->menu();
        QVERIFY(help);
        QAction* guide = nullptr;
        QMenu* examples = nullptr;
        for (QAction* action : help->actions()) {
            if (action->text() == MainWindow::tr("User &Guide"))
                guide = action;
            if (action->menu() && action->text() == MainWindow::tr("E&xamples"))
                examples = action->menu();
        }
        QVERIFY(guide);
        QCOMPARE(guide->shortcut(), QKeySequence(QKeySequence::HelpContents));
        QVERIFY(QFile::exists(userGuideFile()));
        QVERIFY(examples);
        QStringList names;
        for (QAction* action : examples->actions())
            names << action->text();
        QCOMPARE(names, (QStringList{QStringLiteral("cornell-box.json"), QStringLiteral("two-lights-room.json")}));
        examples->actions().first()->trigger();
        QVERIFY(window->document()->filePath().endsWith(QStringLiteral("cornell-box.json")));
    }

    void theTitleNamesTheFileAndMarksUnsavedChanges()
    {
        auto window = makeWindow();
        QVERIFY(window->windowTitle().startsWith(QStringLiteral("Untitled[*]")));
        QVERIFY(window->openFile(test::sampleFile("cornell-box")));
        QVERIFY(window->windowTitle().startsWith(QStringLiteral("cornell-box.json[*]")));
        QVERIFY(!window->isWindowModified());
        window->document()->push(new RemoveObject(window->document(), "short"));
        QVERIFY(window->isWindowModified());
        window->document()->undoStack()->undo();
        QVERIFY(!window->isWindowModified());
    }

    void openingABrokenFileKeepsTheOpenSceneAndReportsWhy()
    {
        QTemporaryDir dir;
        const QString broken = dir.filePath(QStringLiteral("broken.json"));
        QFile file(broken);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("{\"format\": \"regio-scene\", \"version\": 99}");
        file.close();

        auto window = makeWindow();
        QVERIFY(window->openFile(test::sampleFile("cornell-box")));
        const model::Scene before = window->document()->scene();
        model::Diagnostics diagnostics;
        QVERIFY(!window->openFile(broken, &diagnostics));
        QVERIFY(model::hasErrors(diagnostics));
        QVERIFY(window->document()->scene() == before);
        QVERIFY(window->windowTitle().startsWith(QStringLiteral("cornell-box.json")));
    }

    void openedFilesGoToTheFrontOfTheRecentFiles()
    {
        auto window = makeWindow(true);
        QVERIFY(window->openFile(test::sampleFile("cornell-box")));
        QVERIFY(window->openFile(test::sampleFile("two-lights-room")));
        QVERIFY(window->openFile(test::sampleFile("cornell-box")));
        QSettings settings;
        const QStringList recent = RecentFiles(settings).files();
        QCOMPARE(recent.size(), 2);
        QVERIFY(recent.first().endsWith(QStringLiteral("cornell-box.json")));
    }

    void theRecentFilesListIsBounded()
    {
        QSettings settings;
        RecentFiles recent(settings);
        for (int i = 0; i < 30; ++i)
            recent.add(QStringLiteral("/tmp/scene%1.json").arg(i));
        QCOMPARE(recent.files().size(), RecentFiles::kMaximum);
        QCOMPARE(recent.files().first(), QStringLiteral("/tmp/scene29.json"));
    }

    void theWindowStateIsKeptBetweenRuns()
    {
        {
            auto window = makeWindow(true);
            window->resize(1000, 700);
            window->close(); // writes the settings
        }
        QSettings settings;
        QVERIFY(settings.contains(QStringLiteral("window/geometry")));
        QVERIFY(settings.contains(QStringLiteral("window/state")));
    }

    void standardActionsUseTheStandardShortcuts()
    {
        auto window = makeWindow();
        QCOMPARE(findAction(window.get(), QStringLiteral("Open…"))->shortcut(), QKeySequence(QKeySequence::Open));
        QCOMPARE(findAction(window.get(), QStringLiteral("Save"))->shortcut(), QKeySequence(QKeySequence::Save));
        QCOMPARE(findAction(window.get(), QStringLiteral("New"))->shortcut(), QKeySequence(QKeySequence::New));
        QVERIFY(
            findAction(window.get(), QStringLiteral("Undo"))->shortcuts().contains(QKeySequence(QKeySequence::Undo)));
    }

    void undoAndRedoActionsDriveTheDocumentsStack()
    {
        auto window = makeWindow();
        window->document()->reset(test::smallScene());
        window->document()->push(new RemoveObject(window->document(), "crate"));
        QAction* undo = findAction(window.get(), QStringLiteral("Undo Delete crate"));
        QVERIFY(undo);
        undo->trigger();
        QVERIFY(window->document()->scene() == test::smallScene());
    }

    void theMenusAreFileEditCreateModifyRegionsBspViewSolveHelp()
    {
        auto window = makeWindow();
        QStringList titles;
        for (QAction* action : window->menuBar()->actions())
            titles << action->text();
        QCOMPARE(titles, (QStringList{QStringLiteral("&File"), QStringLiteral("&Edit"), QStringLiteral("&Create"),
                                      QStringLiteral("&Modify"), QStringLiteral("&Regions"), QStringLiteral("&BSP"),
                                      QStringLiteral("&View"), QStringLiteral("&Solve"), QStringLiteral("&Help")}));
    }
};

REGIO_QTEST_MAIN(MainWindowTest)
#include "main_window_test.moc"
