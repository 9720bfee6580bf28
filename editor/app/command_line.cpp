#include "editor/app/command_line.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QRegularExpression>

namespace regio::editor {

QSize parseSize(const QString& text)
{
    static const QRegularExpression pattern(QStringLiteral("^\\s*(\\d{1,5})\\s*[xX×]\\s*(\\d{1,5})\\s*$"));
    const QRegularExpressionMatch match = pattern.match(text);
    if (!match.hasMatch())
        return {};
    const int w = match.captured(1).toInt(), h = match.captured(2).toInt();
    if (w < 64 || h < 64 || w > 16384 || h > 16384)
        return {};
    return {w, h};
}

CommandLineOptions parseCommandLine(const QStringList& arguments)
{
    CommandLineOptions options;
    QCommandLineParser parser;
    parser.setApplicationDescription(QCoreApplication::translate(
        "regio::editor::CommandLine", "Regio: an editor for radiosity scenes with regions and BSP orders."));
    const QCommandLineOption helpOption = parser.addHelpOption();
    const QCommandLineOption versionOption = parser.addVersionOption();
    const QCommandLineOption screenshot(
        QStringLiteral("screenshot"),
        QCoreApplication::translate("regio::editor::CommandLine",
                                    "Show the scene, save a picture of the window to <file> and exit."),
        QStringLiteral("file"));
    const QCommandLineOption size(
        QStringLiteral("size"),
        QCoreApplication::translate("regio::editor::CommandLine", "Window size, for example 1280x800."),
        QStringLiteral("WxH"));
    const QCommandLineOption language(
        QStringLiteral("lang"),
        QCoreApplication::translate("regio::editor::CommandLine", "User interface language for this run (en, cs, de)."),
        QStringLiteral("code"));
    const QCommandLineOption previewIterations(
        QStringLiteral("preview-iterations"),
        QCoreApplication::translate("regio::editor::CommandLine",
                                    "With --screenshot: solve the radiosity preview with exactly <n> shooting "
                                    "steps first and show it."),
        QStringLiteral("n"));
    const QCommandLineOption panel(
        QStringLiteral("panel"),
        QCoreApplication::translate("regio::editor::CommandLine",
                                    "With --screenshot: bring the panel <name> to the front first (Materials, "
                                    "Regions, BspOrder, Solver, Properties)."),
        QStringLiteral("name"));
    parser.addOption(panel);
    parser.addOption(previewIterations);
    parser.addOption(screenshot);
    parser.addOption(size);
    parser.addOption(language);
    parser.addPositionalArgument(
        QStringLiteral("scene"),
        QCoreApplication::translate("regio::editor::CommandLine", "The scene file to open (.json)."),
        QStringLiteral("[SCENE.json]"));

    if (!parser.parse(arguments)) {
        options.ok = false;
        options.error = parser.errorText();
        return options;
    }
    // First, so that --help and every error come out in the language asked.
    options.language = parser.value(language);
    if (parser.isSet(helpOption)) {
        options.exitNow = true;
        options.message = parser.helpText();
        return options;
    }
    if (parser.isSet(versionOption)) {
        options.exitNow = true;
        options.message = QCoreApplication::applicationName() + QLatin1Char(' ') +
                          QCoreApplication::applicationVersion() + QLatin1Char('\n');
        return options;
    }
    const QStringList positional = parser.positionalArguments();
    if (positional.size() > 1) {
        options.ok = false;
        options.error =
            QCoreApplication::translate("regio::editor::CommandLine", "only one scene file can be opened, got %1")
                .arg(positional.size());
        return options;
    }
    if (!positional.isEmpty())
        options.scenePath = positional.first();
    options.screenshotPath = parser.value(screenshot);
    if (parser.isSet(screenshot) && options.screenshotPath.isEmpty()) {
        options.ok = false;
        options.error = QCoreApplication::translate("regio::editor::CommandLine", "--screenshot needs a file name");
        return options;
    }
    options.panel = parser.value(panel);
    if (parser.isSet(size)) {
        options.size = parseSize(parser.value(size));
        if (!options.size.isValid()) {
            options.ok = false;
            options.error = QCoreApplication::translate("regio::editor::CommandLine",
                                                        "--size wants WIDTHxHEIGHT in pixels (64 to 16384), got \"%1\"")
                                .arg(parser.value(size));
            return options;
        }
    }
    if (parser.isSet(previewIterations)) {
        bool ok = false;
        const int n = parser.value(previewIterations).toInt(&ok);
        if (!ok || n < 0 || n > 10000000) {
            options.ok = false;
            options.error = QCoreApplication::translate("regio::editor::CommandLine",
                                                        "--preview-iterations wants a number of shooting steps "
                                                        "(0 or more), got \"%1\"")
                                .arg(parser.value(previewIterations));
            return options;
        }
        if (options.screenshotPath.isEmpty()) {
            options.ok = false;
            options.error =
                QCoreApplication::translate("regio::editor::CommandLine", "--preview-iterations needs --screenshot");
            return options;
        }
        options.previewIterations = n;
    }
    options.language = parser.value(language);
    return options;
}

} // namespace regio::editor
