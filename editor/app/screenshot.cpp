#include "editor/app/screenshot.h"

#include "editor/app/image_file.h"

#include "editor/app/main_window.h"
#include "editor/viewport/viewport.h"

#include <QDir>
#include <QFileInfo>
#include <QImage>
#include <QImageWriter>
#include <QPainter>
#include <QPixmap>

namespace regio::editor {

ScreenshotRunner::ScreenshotRunner(MainWindow* window, QString path, int timeoutMs, QObject* parent)
    : QObject(parent)
    , m_window(window)
    , m_path(std::move(path))
{
    m_timeout.setSingleShot(true);
    m_timeout.setInterval(timeoutMs);
    connect(&m_timeout, &QTimer::timeout, this,
            [this] { finish(2, tr("no frame was rendered within %1 s").arg(m_timeout.interval() / 1000)); });
}

void ScreenshotRunner::start()
{
    Viewport* viewport = m_window->viewport();
    connect(viewport, &Viewport::renderingFailed, this,
            [this](const QString& message) { finish(2, tr("the viewport cannot render: %1").arg(message)); });
    if (viewport->hasRenderedFrame()) {
        QTimer::singleShot(0, this, &ScreenshotRunner::grabNow);
    } else {
        connect(viewport, &Viewport::frameRendered, this, [this] {
            // Let the frame reach the window before grabbing it.
            QTimer::singleShot(50, this, &ScreenshotRunner::grabNow);
        });
    }
    m_timeout.start();
}

void ScreenshotRunner::grabNow()
{
    if (m_done)
        return;
    Viewport* viewport = m_window->viewport();
    if (!viewport->renderingError().isEmpty()) {
        finish(2, tr("the viewport cannot render: %1").arg(viewport->renderingError()));
        return;
    }
    QPixmap pixmap = m_window->grab();
    // QWidget::grab renders child widgets through their paint events; the GL
    // viewport's content comes from its framebuffer, so paint that in too
    // (at the device pixel ratio of the grab).
    const QImage frame = viewport->grabFramebuffer();
    if (frame.isNull()) {
        finish(2, tr("the viewport's framebuffer could not be read"));
        return;
    }
    {
        QPainter painter(&pixmap);
        const QPoint topLeft = viewport->mapTo(m_window, QPoint(0, 0));
        painter.drawImage(QRect(topLeft, viewport->size()), frame);
    }
    const QFileInfo info(m_path);
    QDir().mkpath(info.absolutePath());
    if (const std::optional<QString> error = writeImageFile(m_path, pixmap.toImage())) {
        finish(2, *error);
        return;
    }
    finish(0, {});
}

void ScreenshotRunner::finish(int code, const QString& message)
{
    if (m_done)
        return;
    m_done = true;
    m_timeout.stop();
    emit finished(code, message);
}

} // namespace regio::editor
