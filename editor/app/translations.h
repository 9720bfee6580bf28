#pragma once
// Loads the user interface translation: Regio's own strings (embedded .qm
// files under :/i18n) and, when installed, Qt's for standard dialogs.
#include <QString>
#include <QStringList>

class QCoreApplication;

namespace regio::editor {

// Languages the editor ships, as codes ("en" is the source language).
QStringList availableLanguages();
// The native name of a language code ("čeština" for "cs").
QString languageDisplayName(const QString& code);
// `preference` empty = the system locale. Returns the language installed
// ("en" when nothing needed loading or nothing matched).
QString installTranslators(QCoreApplication& app, const QString& preference);

} // namespace regio::editor
