#pragma once
// Main windows and editor processes for the editor tests.
#include "editor/app/main_window.h"
#include "editor/document/scene_document.h"
#include "editor/viewport/viewport.h"
#include "model/scene.h"

#include <QProcess>
#include <QSize>
#include <QStringList>
#include <QTest>

#include <memory>

namespace regio::test {

// A window that reads and writes no settings, asks nothing and does not autosave.
inline std::unique_ptr<editor::MainWindow> quietWindow()
{
    editor::MainWindowOptions options;
    options.persistent = false;
    options.interactive = false;
    options.autosave = false;
    return std::make_unique<editor::MainWindow>(options);
}

// Shows the window and waits until it is exposed and its viewport has drawn
// (GL tests run on xcb under Xvfb; a failure here means no usable GL).
inline void showAndWaitForFrame(editor::MainWindow& window)
{
    window.show();
    if (!QTest::qWaitForWindowExposed(&window))
        qFatal("the window was never exposed");
    if (!QTest::qWaitFor([&] { return window.viewport()->hasRenderedFrame(); }, 20000))
        qFatal("the viewport never rendered a frame");
}

// A quiet window holding `scene` at `size`, shown, its viewport drawn.
inline std::unique_ptr<editor::MainWindow> showWindow(const model::Scene& scene, QSize size = {900, 650})
{
    auto window = quietWindow();
    window->resize(size);
    window->document()->reset(scene);
    showAndWaitForFrame(*window);
    return window;
}

struct EditorRun {
    int exitCode = -1; // -1: crashed or timed out
    QString stderrText;
};

// Runs the built `regio` on the xcb platform with `arguments`.
inline EditorRun runEditor(const QStringList& arguments, int timeoutMs = 180000)
{
    QProcess process;
    process.setProgram(QStringLiteral(REGIO_EDITOR_EXECUTABLE));
    process.setArguments(arguments);
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("xcb"));
    process.setProcessEnvironment(env);
    process.start();
    if (!process.waitForFinished(timeoutMs))
        return {};
    return {process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1,
            QString::fromLocal8Bit(process.readAllStandardError())};
}

} // namespace regio::test
