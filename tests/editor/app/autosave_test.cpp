// Crash recovery: unsaved changes are autosaved; after a crash the next
// start finds them and restores them.
#include "editor/app/autosave.h"
#include "editor/document/commands/object_commands.h"
#include "support/editor_documents.h"
#include "support/qt_test_registry.h"

#include <QFile>
#include <QProcess>
#include <QSignalSpy>
#include <QSysInfo>
#include <QTemporaryDir>

#include <memory>

using namespace regio;
using namespace regio::editor;

namespace {

// The id of a process that has finished.
qint64 deadProcessId()
{
    QProcess process;
    process.start(QStringLiteral("/bin/true"));
    const qint64 pid = process.processId();
    process.waitForFinished();
    return pid;
}

} // namespace

class AutosaveTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { test::initTestEnvironment(); }

    void anUnmodifiedDocumentLeavesNoRecoveryFile()
    {
        QTemporaryDir dir;
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        Autosave autosave(&document, dir.path());
        QVERIFY(autosave.saveNow());
        QVERIFY(!QFile::exists(autosave.recoveryPath()));
    }

    void unsavedChangesAreWrittenToTheRecoveryFile()
    {
        QTemporaryDir dir;
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        Autosave autosave(&document, dir.path());
        document.push(new RemoveObject(&document, "crate"));
        QVERIFY(autosave.saveNow());
        QVERIFY(QFile::exists(autosave.recoveryPath()));
        const model::Result<model::Scene> read = model::loadSceneFile(autosave.recoveryPath().toStdString());
        QVERIFY(read.ok());
        QVERIFY(*read == document.scene());
    }

    void theTimerAutosavesOnlyWhenSomethingChanged()
    {
        QTemporaryDir dir;
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        Autosave autosave(&document, dir.path());
        autosave.setIntervalMs(20);
        QTest::qWait(80);
        QVERIFY(!QFile::exists(autosave.recoveryPath()));
        document.push(new SetObjectName(&document, "crate", "Crate"));
        QTRY_VERIFY_WITH_TIMEOUT(QFile::exists(autosave.recoveryPath()), 2000);
    }

    void savingTheDocumentRemovesTheRecoveryFile()
    {
        QTemporaryDir dir;
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        Autosave autosave(&document, dir.filePath(QStringLiteral("recovery")));
        document.push(new RemoveObject(&document, "crate"));
        QVERIFY(autosave.saveNow());
        QVERIFY(document.save(dir.filePath(QStringLiteral("scene.json"))));
        QVERIFY(!QFile::exists(autosave.recoveryPath()));
    }

    void aRunningEditorsRecoveryFileIsNotAnOrphan()
    {
        QTemporaryDir dir;
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        Autosave autosave(&document, dir.path());
        document.push(new RemoveObject(&document, "crate"));
        QVERIFY(autosave.saveNow());
        QVERIFY(Autosave::findOrphans(dir.path()).isEmpty());
    }

    void aClosedEditorLeavesNothingToRecover()
    {
        QTemporaryDir dir;
        {
            SceneDocument document;
            test::resetDocument(document, test::smallScene());
            Autosave autosave(&document, dir.path());
            document.push(new RemoveObject(&document, "crate"));
            QVERIFY(autosave.saveNow());
        } // a normal shutdown
        QVERIFY(Autosave::findOrphans(dir.path()).isEmpty());
    }

    void afterACrashTheNextStartRestoresTheChangesAsUnsaved()
    {
        QTemporaryDir dir;
        const QString original = dir.filePath(QStringLiteral("room.json"));
        model::Scene crashed;
        // Never deleted while the "editor" runs: a crash runs no destructor.
        SceneDocument* document = nullptr;
        Autosave* autosave = nullptr;
        {
            document = new SceneDocument;
            model::Diagnostics diagnostics;
            QVERIFY(document->open(test::sampleFile("two-lights-room"), diagnostics));
            QVERIFY(document->save(original));
            autosave = new Autosave(document, dir.filePath(QStringLiteral("recovery")));
            document->push(new RemoveObject(document, "boxes"));
            document->push(new SetObjectName(document, "table", "Kitchen table"));
            QVERIFY(autosave->saveNow());
            crashed = document->scene();
            // A crash: the editor never shuts down (nothing is deleted) and
            // its lock file is left naming a process that no longer runs.
            const QString lockPath = autosave->recoveryPath().chopped(5) + QStringLiteral(".lock");
            QFile::remove(lockPath);
            QFile lock(lockPath);
            QVERIFY(lock.open(QIODevice::WriteOnly));
            lock.write(QByteArray::number(deadProcessId()) + '\n' + QCoreApplication::applicationName().toUtf8() +
                       '\n' + QSysInfo::machineHostName().toUtf8() + '\n');
            lock.close();
        }

        const QList<RecoveryFile> orphans = Autosave::findOrphans(dir.filePath(QStringLiteral("recovery")));
        QCOMPARE(orphans.size(), 1);
        QCOMPARE(orphans.first().originalPath, QFileInfo(original).absoluteFilePath());

        SceneDocument restored;
        QString error;
        QVERIFY2(Autosave::restore(orphans.first(), &restored, &error), qPrintable(error));
        QVERIFY(restored.scene() == crashed);
        QCOMPARE(restored.filePath(), QFileInfo(original).absoluteFilePath());
        QVERIFY(restored.isModified());
        // Restored once: it is gone from the recovery folder.
        QVERIFY(Autosave::findOrphans(dir.filePath(QStringLiteral("recovery"))).isEmpty());
        // The crashed editor's memory, which a real crash gives back to the system.
        delete autosave;
        delete document;
    }

    void anUnreadableRecoveryFileIsReportedAndChangesNothing()
    {
        QTemporaryDir dir;
        QFile broken(dir.filePath(QStringLiteral("0000.json")));
        QVERIFY(broken.open(QIODevice::WriteOnly));
        broken.write("{ not json");
        broken.close();
        const QList<RecoveryFile> orphans = Autosave::findOrphans(dir.path());
        QCOMPARE(orphans.size(), 1);
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        QString error;
        QVERIFY(!Autosave::restore(orphans.first(), &document, &error));
        QVERIFY(!error.isEmpty());
        QVERIFY(document.scene() == test::smallScene());
    }
};

REGIO_QTEST_MAIN(AutosaveTest)
#include "autosave_test.moc"
