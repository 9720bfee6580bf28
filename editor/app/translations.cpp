#include "editor/app/translations.h"

#include <QCoreApplication>
#include <QDir>
#include <QLibraryInfo>
#include <QLocale>
#include <QTranslator>

namespace regio::editor {

QStringList availableLanguages()
{
    QStringList codes{QStringLiteral("en")};
    const QStringList files = QDir(QStringLiteral(":/i18n")).entryList({QStringLiteral("regio_*.qm")});
    for (const QString& file : files)
        codes << file.mid(6, file.size() - 9); // regio_XX.qm
    return codes;
}

QString languageDisplayName(const QString& code)
{
    const QLocale locale(code);
    QString name = locale.nativeLanguageName();
    return name.isEmpty() ? code : name;
}

QString installTranslators(QCoreApplication& app, const QString& preference)
{
    const QLocale locale = preference.isEmpty() ? QLocale::system() : QLocale(preference);
    if (locale.language() == QLocale::English || locale.language() == QLocale::C)
        return QStringLiteral("en");
    auto* own = new QTranslator(&app);
    if (!own->load(locale, QStringLiteral("regio"), QStringLiteral("_"), QStringLiteral(":/i18n"))) {
        delete own;
        return QStringLiteral("en");
    }
    app.installTranslator(own);
    // Qt's own strings (dialog buttons, colour picker): optional, from the
    // system's Qt translations when the package is installed.
    auto* qt = new QTranslator(&app);
    if (qt->load(locale, QStringLiteral("qtbase"), QStringLiteral("_"),
                 QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        app.installTranslator(qt);
    else
        delete qt;
    return QLocale::languageToCode(locale.language());
}

} // namespace regio::editor
