#pragma once
// `regio SCENE --screenshot FILE.png --preview-iterations N`: solve the
// preview with exactly N shooting steps (as `regio-solve solve --iterations
// N`) and wait until the viewport holds its layers, so that the screenshot
// shows the solution.
#include <QString>

namespace regio::editor {

class MainWindow;

// Blocks in a local event loop (the UI keeps running). False with `error`
// when the scene cannot be solved or nothing arrived within `timeoutMs`.
bool solvePreviewForScreenshot(MainWindow& window, int iterations, QString* error, int timeoutMs = 120000);

} // namespace regio::editor
