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
#include <QDockWidget>
#include <QElapsedTimer>
#include <QSettings>
#include <QSurfaceFormat>
#include <QThread>
#include <QTimer>

#include <cstdio>
#include <variant>

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
    if (!options.panel.isEmpty()) {
        auto* dock = window.findChild<QDockWidget*>(options.panel + QStringLiteral("Dock"));
        if (dock == nullptr) {
            printError(QCoreApplication::translate("main", "there is no panel %1").arg(options.panel));
            return 2;
        }
        dock->show();
        dock->raise();
        // The Regions and BSP Order panels' figures come from the solver's
        // preparation on a worker thread a moment after the scene opens.
        QElapsedTimer waited;
        waited.start();
        while (waited.elapsed() < 1500) {
            QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
            QThread::msleep(10);
        }
    }
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

// Whether Qt's GUI platform will find what it needs: an X or Wayland
// display for the default platforms, nothing for offscreen and the like.
bool displayAvailable(const QStringList& arguments)
{
    QString platform = qEnvironmentVariable("QT_QPA_PLATFORM");
    if (const qsizetype at = arguments.indexOf(QStringLiteral("-platform")); at >= 0 && at + 1 < arguments.size())
        platform = arguments.at(at + 1);
    platform = platform.section(QLatin1Char(':'), 0, 0);
    const bool x = !qEnvironmentVariableIsEmpty("DISPLAY");
    const bool wayland = !qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY");
    if (platform.isEmpty())
        return x || wayland;
    if (platform == QLatin1String("xcb"))
        return x;
    if (platform.startsWith(QLatin1String("wayland")))
        return wayland;
    return true; // offscreen, minimal, vnc, eglfs, linuxfb: no display server
}

// What the command line asks, answered without a GUI platform where it can
// be: --help, --version and every error need no display, so they work over
// ssh and in scripts. Returns the options, or the exit code when done.
std::variant<CommandLineOptions, int> readCommandLine(int argc, char* argv[])
{
    QCoreApplication core(argc, argv);
    QSettings settings;
    const Preferences preferences = Preferences::load(settings);
    const QString language = parseCommandLine(QCoreApplication::arguments()).language;
    installTranslators(core, language.isEmpty() ? preferences.language : language);
    // Parsed again so that its messages come out in the chosen language.
    const CommandLineOptions options = parseCommandLine(QCoreApplication::arguments());
    if (!options.ok) {
        printError(options.error);
        return 2;
    }
    if (options.exitNow) {
        std::fputs(qPrintable(options.message), stdout);
        return 0;
    }
    if (!displayAvailable(QCoreApplication::arguments())) {
        printError(options.screenshotPath.isEmpty()
                       ? QCoreApplication::translate("main",
                                                     "there is no display to open the editor's window on (DISPLAY "
                                                     "is not set). Run it on a desktop, or with ssh -X.")
                       : QCoreApplication::translate(
                             "main",
                             "--screenshot draws the editor's window and needs a display, real or virtual: "
                             "run it on a desktop or under Xvfb (xvfb-run -a regio --screenshot ...)."));
        return 2;
    }
    return options;
}

} // namespace

int main(int argc, char* argv[])
{
    QCoreApplication::setOrganizationName(QStringLiteral("Regio"));
    QCoreApplication::setApplicationName(QStringLiteral("Regio"));
    QCoreApplication::setApplicationVersion(QStringLiteral(REGIO_VERSION));
    const std::variant<CommandLineOptions, int> read = readCommandLine(argc, argv);
    if (const int* exitCode = std::get_if<int>(&read))
        return *exitCode;
    const CommandLineOptions& options = std::get<CommandLineOptions>(read);

    // The viewport needs a 3.3 core context; ask for it before any widget exists.
    QSurfaceFormat::setDefaultFormat(Viewport::requestedFormat());
    QApplication app(argc, argv);
    QSettings settings;
    installTranslators(app, options.language.isEmpty() ? Preferences::load(settings).language : options.language);
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
