// The regio executable on a machine without a display (over ssh, in a
// script, in CI): --help, --version and command-line errors are answered
// without a GUI platform, and what needs one says what it needs instead of
// Qt's platform-plugin error.
#include "support/qt_test_registry.h"

#include <QProcess>
#include <QProcessEnvironment>

namespace {

struct Run {
    int exitCode = -1;
    QString out;
    QString err;
};

// Runs regio with no display and no platform chosen.
Run runHeadless(const QStringList& arguments)
{
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    for (const char* name : {"DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM"})
        environment.remove(QString::fromLatin1(name));
    environment.insert(QStringLiteral("LANGUAGE"), QStringLiteral("en"));
    QProcess process;
    process.setProcessEnvironment(environment);
    process.start(QStringLiteral(REGIO_EDITOR_EXECUTABLE), arguments);
    Run run;
    if (!process.waitForFinished(30000))
        return run;
    run.exitCode = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1;
    run.out = QString::fromUtf8(process.readAllStandardOutput());
    run.err = QString::fromUtf8(process.readAllStandardError());
    return run;
}

} // namespace

class EditorExecutableTest : public QObject {
    Q_OBJECT
private slots:
    void helpAndVersionNeedNoDisplay()
    {
        const Run help = runHeadless({QStringLiteral("--help")});
        QCOMPARE(help.exitCode, 0);
        QVERIFY2(help.out.contains(QStringLiteral("--screenshot")), qPrintable(help.out));
        QVERIFY2(help.err.isEmpty(), qPrintable(help.err));
        const Run version = runHeadless({QStringLiteral("--version")});
        QCOMPARE(version.exitCode, 0);
        QCOMPARE(version.out, QStringLiteral("Regio " REGIO_VERSION "\n"));
    }

    void aMistakeOnTheCommandLineIsReportedWithoutADisplay()
    {
        const Run run = runHeadless({QStringLiteral("--size"), QStringLiteral("wide")});
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.startsWith(QStringLiteral("regio: ")), qPrintable(run.err));
        QVERIFY2(!run.err.contains(QStringLiteral("display")), qPrintable(run.err));
    }

    void aScreenshotWithoutADisplaySaysWhatItNeeds()
    {
        const Run run = runHeadless({QStringLiteral("--screenshot"), QStringLiteral("/tmp/never-written.png")});
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains(QStringLiteral("needs a display")), qPrintable(run.err));
        QVERIFY2(run.err.contains(QStringLiteral("xvfb-run")), qPrintable(run.err));
        QVERIFY2(!run.err.contains(QStringLiteral("qt.qpa")), qPrintable(run.err));
    }

    void theWindowWithoutADisplaySaysSo()
    {
        const Run run = runHeadless({});
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains(QStringLiteral("no display")), qPrintable(run.err));
        QVERIFY2(!run.err.contains(QStringLiteral("qt.qpa")), qPrintable(run.err));
    }
};

REGIO_QTEST_MAIN(EditorExecutableTest)
#include "editor_executable_test.moc"
