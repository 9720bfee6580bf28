// regio [SCENE.json] [--screenshot FILE.png] [--size WxH]
#include "editor/app/command_line.h"

#include "support/qt_test_registry.h"

#include <QCoreApplication>
#include <QTest>

using namespace regio::editor;

class CommandLineTest : public QObject {
    Q_OBJECT
private slots:
    void noArgumentsStartsWithANewScene()
    {
        const CommandLineOptions o = parseCommandLine({QStringLiteral("regio")});
        QVERIFY(o.ok);
        QVERIFY(o.scenePath.isEmpty());
        QVERIFY(o.screenshotPath.isEmpty());
        QVERIFY(!o.size.isValid());
    }

    void aSceneAScreenshotAndASizeAreAllRead()
    {
        const CommandLineOptions o =
            parseCommandLine({QStringLiteral("regio"), QStringLiteral("room.json"), QStringLiteral("--screenshot"),
                              QStringLiteral("out.png"), QStringLiteral("--size"), QStringLiteral("1600x1000")});
        QVERIFY(o.ok);
        QCOMPARE(o.scenePath, QStringLiteral("room.json"));
        QCOMPARE(o.screenshotPath, QStringLiteral("out.png"));
        QCOMPARE(o.size, QSize(1600, 1000));
    }

    void aMalformedSizeIsAnError()
    {
        for (const char* bad : {"1600", "wide", "10x10", "0x600", "99999x600"}) {
            const CommandLineOptions o =
                parseCommandLine({QStringLiteral("regio"), QStringLiteral("--size"), QString::fromLatin1(bad)});
            QVERIFY2(!o.ok, bad);
            QVERIFY(!o.error.isEmpty());
        }
    }

    void twoScenesAreAnError()
    {
        const CommandLineOptions o =
            parseCommandLine({QStringLiteral("regio"), QStringLiteral("a.json"), QStringLiteral("b.json")});
        QVERIFY(!o.ok);
    }

    void anUnknownOptionIsAnError()
    {
        const CommandLineOptions o = parseCommandLine({QStringLiteral("regio"), QStringLiteral("--frobnicate")});
        QVERIFY(!o.ok);
        QVERIFY(o.error.contains(QStringLiteral("frobnicate")));
    }

    void helpIsAnsweredWithoutStarting()
    {
        const CommandLineOptions o = parseCommandLine({QStringLiteral("regio"), QStringLiteral("--help")});
        QVERIFY(o.ok);
        QVERIFY(o.exitNow);
        QVERIFY(o.message.contains(QStringLiteral("--screenshot")));
    }
};

REGIO_QTEST_GUILESS_MAIN(CommandLineTest)
#include "command_line_test.moc"
