// Where File > Open Example looks: an installed editor's share/regio/scenes,
// else the source tree's samples.
#include "editor/app/sample_scenes.h"

#include "support/qt_test_registry.h"

#include <QDir>
#include <QFile>
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
};

REGIO_QTEST_MAIN(SampleScenesTest)
#include "sample_scenes_test.moc"
