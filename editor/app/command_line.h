#pragma once
// `regio [SCENE.json] [--screenshot FILE.png] [--size WxH] [--preview-iterations N] [--panel NAME]`
#include <QSize>
#include <QString>
#include <QStringList>

namespace regio::editor {

struct CommandLineOptions {
    QString scenePath;          // empty: start with a new scene
    QString screenshotPath;     // non-empty: grab the window to this file and exit
    QSize size;                 // window size; invalid = the saved or default size
    QString language;           // --lang: overrides the preference for this run
    int previewIterations = -1; // --preview-iterations: shoot N times before the screenshot (-1 = no preview)
    QString panel;              // --panel: the panel to bring to the front for the screenshot (its object name)
    bool ok = true;             // false: `error` says why, exit 2
    QString error;
    bool exitNow = false; // --help or --version was answered
    QString message;      // what to print for --help / --version
};

CommandLineOptions parseCommandLine(const QStringList& arguments);

// "1280x800" -> QSize; invalid for anything else (or a side below 64 or above 16384).
QSize parseSize(const QString& text);

} // namespace regio::editor
