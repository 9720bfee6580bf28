// The translations (Czech, German) are embedded, complete, consistent with
// their sources, and used when chosen or when the system's locale asks for
// them. translations/README.md says how to refresh them.
#include "editor/app/main_window.h"
#include "editor/app/translations.h"
#include "support/editor_documents.h"
#include "support/qt_test_registry.h"

#include <QDir>
#include <QFile>
#include <QMenuBar>
#include <QProcess>
#include <QProcessEnvironment>
#include <QTemporaryDir>
#include <QTranslator>
#include <QXmlStreamReader>

#include <memory>

using namespace regio;
using namespace regio::editor;

namespace {

QString tsFile(const QString& code) { return QStringLiteral(REGIO_SOURCE_DIR "/translations/regio_%1.ts").arg(code); }

// The placeholders (%1 .. %9, %n) of a message, sorted, and its number of
// mnemonic markers (an & before a letter).
QString signature(const QString& text)
{
    QStringList marks;
    for (qsizetype i = 0; i + 1 < text.size(); ++i) {
        if (text[i] == QLatin1Char('%') && (text[i + 1].isDigit() || text[i + 1] == QLatin1Char('n')))
            marks << text.mid(i, 2);
        if (text[i] == QLatin1Char('&') && text[i + 1].isLetter())
            marks << QStringLiteral("&");
    }
    marks.sort();
    return marks.join(QLatin1Char(' '));
}

// Messages of a .ts file that are not fit to ship: translation missing,
// empty or unfinished, obsolete or vanished, or with other placeholders or
// mnemonics than the source.
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
            const QStringView type = xml.attributes().value(QLatin1String("type"));
            if (!type.isEmpty()) {
                out << type.toString() + QStringLiteral(": ") + source;
                xml.skipCurrentElement();
                continue;
            }
            const QString text = xml.readElementText(QXmlStreamReader::IncludeChildElements);
            if (text.trimmed().isEmpty())
                out << QStringLiteral("empty: ") + source;
            else if (!source.contains(QStringLiteral("%n")) && signature(text) != signature(source))
                out << QStringLiteral("placeholders or mnemonic differ: ") + source + QStringLiteral(" -> ") + text;
        }
    }
    return out;
}

} // namespace

class TranslationsTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { test::initTestEnvironment(); }

    void eachLanguageIsShippedInsideTheProgram_data()
    {
        QTest::addColumn<QString>("code");
        QTest::addColumn<QString>("name");
        QTest::newRow("Czech") << QStringLiteral("cs") << QStringLiteral("čeština");
        QTest::newRow("German") << QStringLiteral("de") << QStringLiteral("Deutsch");
    }
    void eachLanguageIsShippedInsideTheProgram()
    {
        QFETCH(QString, code);
        QFETCH(QString, name);
        QVERIFY(QFile::exists(QStringLiteral(":/i18n/regio_%1.qm").arg(code)));
        QVERIFY(availableLanguages().contains(code));
        QVERIFY(availableLanguages().contains(QStringLiteral("en")));
        QCOMPARE(languageDisplayName(code), name);
    }

    void everyMessageOfEachFileIsTranslatedWithItsPlaceholders_data() { eachLanguageIsShippedInsideTheProgram_data(); }
    void everyMessageOfEachFileIsTranslatedWithItsPlaceholders()
    {
        QFETCH(QString, code);
        const QStringList problems = untranslated(tsFile(code));
        QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QStringLiteral(" | "))));
    }

    void eachFileHoldsExactlyTheStringsOfTheSources_data() { eachLanguageIsShippedInsideTheProgram_data(); }
    void eachFileHoldsExactlyTheStringsOfTheSources()
    {
        // lupdate on a copy, keeping what the sources no longer have: nothing
        // may come out new (untranslated) nor vanished (obsolete).
        QFETCH(QString, code);
        QTemporaryDir dir;
        const QString copy = dir.filePath(QStringLiteral("regio_%1.ts").arg(code));
        QVERIFY(QFile::copy(tsFile(code), copy));
        QFile::setPermissions(copy, QFile::ReadOwner | QFile::WriteOwner);
        QProcess lupdate;
        lupdate.start(QStringLiteral(REGIO_LUPDATE),
                      {QStringLiteral("-locations"), QStringLiteral("none"), QStringLiteral("-extensions"),
                       QStringLiteral("cpp,h"), QStringLiteral("-I"), QStringLiteral(REGIO_SOURCE_DIR),
                       QStringLiteral(REGIO_SOURCE_DIR "/editor"), QStringLiteral("-ts"), copy});
        QVERIFY(lupdate.waitForFinished(120000));
        QCOMPARE(lupdate.exitCode(), 0);
        const QStringList problems = untranslated(copy);
        QVERIFY2(problems.isEmpty(), qPrintable(QStringLiteral("regio_%1.ts against the sources: ").arg(code) +
                                                problems.join(QStringLiteral(" | "))));
    }

    // With no preference the system's locale chooses (LANG, as a desktop
    // sets it); --lang overrides both.
    void theSystemLocaleChoosesTheLanguageAndLangOverridesIt()
    {
        QTemporaryDir home;
        const auto help = [&](const QString& lang, const QStringList& arguments) {
            QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
            for (const char* name : {"LANGUAGE", "LC_ALL", "LC_MESSAGES", "DISPLAY", "QT_QPA_PLATFORM"})
                environment.remove(QString::fromLatin1(name));
            environment.insert(QStringLiteral("LANG"), lang);
            environment.insert(QStringLiteral("HOME"), home.path()); // no preference saved
            environment.insert(QStringLiteral("XDG_CONFIG_HOME"), home.filePath(QStringLiteral("config")));
            QProcess regio;
            regio.setProcessEnvironment(environment);
            regio.start(QStringLiteral(REGIO_EDITOR_EXECUTABLE), QStringList{QStringLiteral("--help")} + arguments);
            regio.waitForFinished(30000);
            return QString::fromUtf8(regio.readAllStandardOutput());
        };
        const QString english = QStringLiteral("Window size, for example 1280x800.");
        QVERIFY(help(QStringLiteral("en_GB.UTF-8"), {}).contains(english));
        const QString german = help(QStringLiteral("de_DE.UTF-8"), {});
        QVERIFY2(!german.contains(english) && !german.isEmpty(), qPrintable(german));
        QVERIFY2(!help(QStringLiteral("cs_CZ.UTF-8"), {}).contains(english), "Czech from the system locale");
        QVERIFY(
            help(QStringLiteral("de_DE.UTF-8"), {QStringLiteral("--lang"), QStringLiteral("en")}).contains(english));
    }

    void choosingALanguageTranslatesTheWindow_data()
    {
        QTest::addColumn<QString>("code");
        QTest::addColumn<QString>("file");
        QTest::addColumn<QString>("untitled");
        QTest::newRow("Czech") << QStringLiteral("cs") << QStringLiteral("&Soubor") << QStringLiteral("Bez názvu");
        QTest::newRow("German") << QStringLiteral("de") << QStringLiteral("&Datei") << QStringLiteral("Unbenannt");
    }
    void choosingALanguageTranslatesTheWindow()
    {
        QFETCH(QString, code);
        QFETCH(QString, file);
        QFETCH(QString, untitled);
        // One language at a time: the translators of an earlier row go.
        for (QTranslator* t : QCoreApplication::instance()->findChildren<QTranslator*>()) {
            QCoreApplication::removeTranslator(t);
            delete t;
        }
        const QString installed = installTranslators(*QCoreApplication::instance(), code);
        QCOMPARE(installed, code);
        MainWindowOptions options;
        options.persistent = false;
        options.interactive = false;
        options.autosave = false;
        auto window = std::make_unique<MainWindow>(options);
        QStringList titles;
        for (QAction* action : window->menuBar()->actions())
            titles << action->text();
        QCOMPARE(titles.first(), file);
        QVERIFY2(window->windowTitle().startsWith(untitled), qPrintable(window->windowTitle()));
    }

    void englishNeedsNoTranslator()
    {
        QCOMPARE(installTranslators(*QCoreApplication::instance(), QStringLiteral("en")), QStringLiteral("en"));
    }
};

REGIO_QTEST_MAIN(TranslationsTest)
#include "translations_test.moc"
