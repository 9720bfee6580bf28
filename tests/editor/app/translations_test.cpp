// The Czech translation is embedded, complete, and used when chosen.
#include "editor/app/main_window.h"
#include "editor/app/translations.h"
#include "support/editor_documents.h"
#include "support/qt_test_registry.h"

#include <QDir>
#include <QFile>
#include <QMenuBar>
#include <QProcess>
#include <QTemporaryDir>
#include <QTranslator>
#include <QXmlStreamReader>

#include <memory>

using namespace regio;
using namespace regio::editor;

namespace {

const QString kTsFile = QStringLiteral(REGIO_SOURCE_DIR "/translations/regio_cs.ts");

// Messages of a .ts file whose translation is missing, empty or unfinished.
QStringList untranslated(const QString& path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {QStringLiteral("cannot read ") + path};
    QXmlStreamReader xml(&file);
    QStringList out;
    QString source;
    while (!xml.atEnd()) {
        xml.readNext();
        if (!xml.isStartElement())
            continue;
        if (xml.name() == QLatin1String("source")) {
            source = xml.readElementText();
        } else if (xml.name() == QLatin1String("translation")) {
            const bool unfinished = xml.attributes().value(QLatin1String("type")) == QLatin1String("unfinished");
            const QString text = xml.readElementText(QXmlStreamReader::IncludeChildElements);
            if (unfinished || text.trimmed().isEmpty())
                out << source;
        }
    }
    return out;
}

} // namespace

class TranslationsTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { test::initTestEnvironment(); }

    void czechIsShippedInsideTheProgram()
    {
        QVERIFY(QFile::exists(QStringLiteral(":/i18n/regio_cs.qm")));
        QVERIFY(availableLanguages().contains(QStringLiteral("cs")));
        QVERIFY(availableLanguages().contains(QStringLiteral("en")));
        QCOMPARE(languageDisplayName(QStringLiteral("cs")), QStringLiteral("čeština"));
    }

    void everyMessageOfTheCzechFileIsTranslated()
    {
        const QStringList missing = untranslated(kTsFile);
        QVERIFY2(missing.isEmpty(), qPrintable(missing.join(QStringLiteral(" | "))));
    }

    void theCzechFileCoversEveryStringInTheSources()
    {
        // lupdate on a copy: nothing may come out new (untranslated).
        QTemporaryDir dir;
        const QString copy = dir.filePath(QStringLiteral("regio_cs.ts"));
        QVERIFY(QFile::copy(kTsFile, copy));
        QFile::setPermissions(copy, QFile::ReadOwner | QFile::WriteOwner);
        QProcess lupdate;
        lupdate.start(QStringLiteral(REGIO_LUPDATE),
                      {QStringLiteral("-no-obsolete"), QStringLiteral("-locations"), QStringLiteral("none"),
                       QStringLiteral("-extensions"), QStringLiteral("cpp,h"), QStringLiteral("-I"),
                       QStringLiteral(REGIO_SOURCE_DIR), QStringLiteral(REGIO_SOURCE_DIR "/editor"),
                       QStringLiteral("-ts"), copy});
        QVERIFY(lupdate.waitForFinished(120000));
        QCOMPARE(lupdate.exitCode(), 0);
        const QStringList missing = untranslated(copy);
        QVERIFY2(missing.isEmpty(),
                 qPrintable(QStringLiteral("not in regio_cs.ts: ") + missing.join(QStringLiteral(" | "))));
    }

    void choosingCzechTranslatesTheWindow()
    {
        const QString installed = installTranslators(*QCoreApplication::instance(), QStringLiteral("cs"));
        QCOMPARE(installed, QStringLiteral("cs"));
        MainWindowOptions options;
        options.persistent = false;
        options.interactive = false;
        options.autosave = false;
        auto window = std::make_unique<MainWindow>(options);
        QStringList titles;
        for (QAction* action : window->menuBar()->actions())
            titles << action->text();
        QCOMPARE(titles.first(), QStringLiteral("&Soubor"));
        QVERIFY(window->windowTitle().startsWith(QStringLiteral("Bez názvu")));
    }

    void englishNeedsNoTranslator()
    {
        QCOMPARE(installTranslators(*QCoreApplication::instance(), QStringLiteral("en")), QStringLiteral("en"));
    }
};

REGIO_QTEST_MAIN(TranslationsTest)
#include "translations_test.moc"
