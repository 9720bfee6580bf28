#pragma once
// An interactive tool that borrows the viewport's mouse and keys (drawing a
// region box, picking a face for a list, inspecting the solution). While a
// tool is set, each event goes to it first; an event it uses (returns true)
// is not seen by the viewport's own navigation and selection, anything else
// (orbiting with the middle button, zooming) keeps working.
class QKeyEvent;
class QMouseEvent;

namespace regio::editor {

class Viewport;

class ViewportTool {
public:
    virtual ~ViewportTool() = default;
    virtual bool mousePress(Viewport&, QMouseEvent*) { return false; }
    virtual bool mouseMove(Viewport&, QMouseEvent*) { return false; }
    virtual bool mouseRelease(Viewport&, QMouseEvent*) { return false; }
    virtual bool keyPress(Viewport&, QKeyEvent*) { return false; }
    // The viewport dropped the tool (another tool was set, or Escape).
    virtual void deactivated() { }
};

} // namespace regio::editor
