// Where File > Open Example looks: an installed editor's share/regio/scenes,
// else the source tree's samples.
#include "editor/app/sample_scenes.h"

#include "support/qt_test_registry.h"

#include <QDir>
#include <QFile>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

using namespace regio::editor;

class SampleScenesTest : public QObject {
    Q_OBJECT
private slots:
    void anInstalledEditorFindsTheScenesInstalledBesideIt()
    {
        QTemporaryDir prefix;
        QVERIFY(QDir(prefix.path()).mkpath(QStringLiteral("bin")));
        QVERIFY(QDir(prefix.path()).mkpath(QStringLiteral("share/regio/scenes")));
        QCOMPARE(sampleScenesFolder(prefix.filePath(QStringLiteral("bin"))),
                 QDir::cleanPath(prefix.filePath(QStringLiteral("share/regio/scenes"))));
    }

    void anEditorInItsBuildTreeFindsTheSourceTreesSamples()
    {
        QTemporaryDir build;
        const QString folder = sampleScenesFolder(build.path());
        QCOMPARE(folder, QStringLiteral(REGIO_SAMPLE_SCENES));
        QVERIFY(QFile::exists(folder + QStringLiteral("/cornell-box.json")));
    }

    void theUserGuideIsFoundInstalledOrInTheSourceTree()
    {
        QTemporaryDir prefix;
        QVERIFY(QDir(prefix.path()).mkpath(QStringLiteral("bin")));
        QCOMPARE(userGuideFile(prefix.filePath(QStringLiteral("bin"))), QStringLiteral(REGIO_DOCS "/guide.md"));
        QVERIFY(QFile::exists(userGuideFile(prefix.filePath(QStringLiteral("bin")))));
        QVERIFY(QDir(prefix.path()).mkpath(QStringLiteral("share/doc/regio-solve")));
        QFile guide(prefix.filePath(QStringLiteral("share/doc/regio-solve/guide.md")));
        QVERIFY(guide.open(QIODevice::WriteOnly));
        guide.close();
        QCOMPARE(userGuideFile(prefix.filePath(QStringLiteral("bin"))),
                 QDir::cleanPath(prefix.filePath(QStringLiteral("share/doc/regio-solve/guide.md"))));
    }

    // Every picture of the guide exists and is one the screenshot script
    // makes (scripts/guide-screenshots.sh): none is drawn by hand.
    void theGuidesPicturesAreAllMadeByItsScript()
    {
        QFile guide(QStringLiteral(REGIO_DOCS "/guide.md"));
        QVERIFY(guide.open(QIODevice::ReadOnly));
        const QString text = QString::fromUtf8(guide.readAll());
        QFile script(QStringLiteral(REGIO_DOCS "/../scripts/guide-screenshots.sh"));
        QVERIFY(script.open(QIODevice::ReadOnly));
        const QString made = QString::fromUtf8(script.readAll());
        const QRegularExpression picture(QStringLiteral("\\(images/guide/([a-z0-9-]+\\.png)\\)"));
        int pictures = 0;
        for (auto it = picture.globalMatch(text); it.hasNext();) {
            const QString name = it.next().captured(1);
            ++pictures;
            QVERIFY2(made.contains(name), qPrintable(name + QStringLiteral(" is not made by the script")));
            QVERIFY2(QFile::exists(QStringLiteral(REGIO_DOCS "/images/guide/") + name), qPrintable(name));
        }
        QVERIFY(pictures >= 5);
    }
};

REGIO_QTEST_MAIN(SampleScenesTest)
#include "sample_scenes_test.moc"
