#include "editor/preview/preview_screenshot.h"

#include "editor/app/main_window.h"
#include "editor/preview/preview_controller.h"

#include <QCoreApplication>
#include <QEventLoop>
#include <QTimer>

namespace regio::editor {

bool solvePreviewForScreenshot(MainWindow& window, int iterations, QString* error, int timeoutMs)
{
    PreviewController* preview = window.preview();
    PreviewRunner* runner = preview->runner();
    QEventLoop loop;
    bool ok = false;
    QString message;
    QTimer timeout;
    timeout.setSingleShot(true);
    QObject::connect(&timeout, &QTimer::timeout, &loop, [&] {
        message =
            QCoreApplication::translate("regio::editor::PreviewScreenshot", "the preview did not finish within %1 s")
                .arg(timeoutMs / 1000);
        loop.quit();
    });
    QObject::connect(runner, &PreviewRunner::failed, &loop, [&](const QString& why) {
        message = QCoreApplication::translate("regio::editor::PreviewScreenshot", "the preview failed: %1").arg(why);
        loop.quit();
    });
    // Done when the layers of the final frame are in the viewport.
    QObject::connect(preview, &PreviewController::layersApplied, &loop, [&] {
        if (runner->state() == PreviewState::Finished && preview->layersCurrent() && runner->frame() &&
            !runner->frame()->running) {
            ok = true;
            loop.quit();
        }
    });
    timeout.start(timeoutMs);
    preview->runIterations(iterations);
    loop.exec();
    if (!ok && error)
        *error = message;
    return ok;
}

} // namespace regio::editor
