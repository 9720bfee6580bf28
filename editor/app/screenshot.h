#pragma once
// `regio SCENE --screenshot FILE.png`: waits for the viewport's first frame,
// grabs the whole window (GL content included) and writes it out.
#include <QObject>
#include <QString>
#include <QTimer>

namespace regio::editor {

class MainWindow;

class ScreenshotRunner : public QObject {
    Q_OBJECT
public:
    ScreenshotRunner(MainWindow* window, QString path, int timeoutMs = 30000, QObject* parent = nullptr);
    // Starts waiting; finished() follows exactly once.
    void start();

signals:
    // 0 on success; 2 with `message` saying why it failed.
    void finished(int exitCode, const QString& message);

private:
    void grabNow();
    void finish(int code, const QString& message);

    MainWindow* m_window;
    QString m_path;
    QTimer m_timeout;
    bool m_done = false;
};

} // namespace regio::editor
