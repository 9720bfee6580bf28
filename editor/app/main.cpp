// regio [SCENE.json] [--screenshot FILE.png] [--size WxH] [--preview-iterations N]
#include "editor/app/command_line.h"
#include "editor/app/main_window.h"
#include "editor/app/preferences.h"
#include "editor/app/screenshot.h"
#include "editor/app/translations.h"
#include "editor/preview/preview_screenshot.h"
#include "editor/viewport/viewport.h"

#include <QApplication>
#include <QDir>
#include <QSettings>
#include <QSurfaceFormat>
#include <QTimer>

#include <cstdio>

using namespace regio::editor;

namespace {

void printError(const QString& message) { std::fprintf(stderr, "regio: %s\n", qPrintable(message)); }

int runScreenshot(const CommandLineOptions& options)
{
    MainWindowOptions windowOptions;
    windowOptions.persistent = false;
    windowOptions.interactive = false;
    windowOptions.autosave = false;
    MainWindow window(windowOptions);
    window.resize(options.size.isValid() ? options.size : QSize(1280, 800));
    if (!options.scenePath.isEmpty()) {
        regio::model::Diagnostics diagnostics;
        if (!window.openFile(options.scenePath, &diagnostics)) {
            printError(QCoreApplication::translate("main", "cannot open %1:").arg(options.scenePath));
            for (const auto& d : diagnostics)
                std::fprintf(stderr, "  %s: %s\n", d.pointer.empty() ? "/" : d.pointer.c_str(), d.message.c_str());
            return 2;
        }
    }
    window.show();
    if (options.previewIterations >= 0) {
        QString error;
        if (!solvePreviewForScreenshot(window, options.previewIterations, &error)) {
            printError(error);
            return 2;
        }
    }
    int exitCode = 2;
    ScreenshotRunner runner(&window, options.screenshotPath);
    QObject::connect(&runner, &ScreenshotRunner::finished, qApp, [&](int code, const QString& message) {
        exitCode = code;
        if (code != 0)
            printError(message);
        QCoreApplication::exit(code);
    });
    runner.start();
    QCoreApplication::exec();
    return exitCode;
}

} // namespace

int main(int argc, char* argv[])
{
    // The viewport needs a 3.3 core context; ask for it before any widget exists.
    QSurfaceFormat::setDefaultFormat(Viewport::requestedFormat());
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("Regio"));
    QApplication::setApplicationName(QStringLiteral("Regio"));
    QApplication::setApplicationVersion(QStringLiteral(REGIO_VERSION));

    QSettings settings;
    const Preferences preferences = Preferences::load(settings);
    const QString language = parseCommandLine(QApplication::arguments()).language;
    installTranslators(app, language.isEmpty() ? preferences.language : language);
    // Parsed again so that its messages come out in the chosen language.
    const CommandLineOptions options = parseCommandLine(QApplication::arguments());
    if (!options.ok) {
        printError(options.error);
        return 2;
    }
    if (options.exitNow) {
        std::fputs(qPrintable(options.message), stdout);
        return 0;
    }
    if (!options.screenshotPath.isEmpty())
        return runScreenshot(options);

    MainWindow window;
    if (options.size.isValid())
        window.resize(options.size);
    window.show();
    if (!options.scenePath.isEmpty())
        window.openFile(options.scenePath);
    // After the window is up: the recovery question needs a parent on screen.
    QTimer::singleShot(0, &window, &MainWindow::offerRecovery);
    return app.exec();
}
