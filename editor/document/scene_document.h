#pragma once
// One open scene: the model, its undo stack, the selection, the file path and
// the modified flag (the undo stack's clean state). Views read it and connect
// to its typed change signals; only undo commands (SceneCommand) write to it.
#include "editor/document/selection.h"
#include "model/diagnostic.h"
#include "model/scene.h"

#include <QObject>
#include <QString>

class QUndoStack;

namespace regio::editor {

class SceneCommand;

// What a change touched. Views rebuild only what a flag names.
enum class Change : unsigned {
    None = 0,
    Objects = 1u << 0,   // objects, parts, faces: geometry, ids, names, face materials
    Materials = 1u << 1, // the material list or a material's values
    Regions = 1u << 2,   // region boxes, names and BSP orders
    Settings = 1u << 3,  // solver settings
    Camera = 1u << 4,    // the scene's stored camera
    Geometry = 1u << 5,  // vertex positions only: ids, names and structure unchanged
    All = 0x3f,
};
inline Change operator|(Change a, Change b) { return Change(unsigned(a) | unsigned(b)); }
inline bool operator&(Change a, Change b) { return (unsigned(a) & unsigned(b)) != 0; }

class SceneDocument : public QObject {
    Q_OBJECT
public:
    explicit SceneDocument(QObject* parent = nullptr);
    ~SceneDocument() override;

    const model::Scene& scene() const { return m_scene; }
    QUndoStack* undoStack() const { return m_undoStack; }

    // Absolute path of the file, empty for a scene never saved.
    QString filePath() const { return m_filePath; }
    // The file name, or "Untitled" for a new scene.
    QString displayName() const;
    bool isModified() const;

    const Selection& selection() const { return m_selection; }
    void setSelection(Selection selection);
    void clearSelection() { setSelection({}); }

    // Replaces the whole scene (New, Open, Revert, recovery): clears the undo
    // stack and the selection. `modified` marks a scene that differs from its
    // file (a recovered autosave).
    void reset(model::Scene scene, const QString& filePath = {}, bool modified = false);
    // Reads a scene file. On any error the document is left exactly as it was
    // and `diagnostics` says why; warnings alone do not refuse the file.
    bool open(const QString& path, model::Diagnostics& diagnostics);
    // Re-reads the current file, dropping every change (and the undo history).
    bool revert(model::Diagnostics& diagnostics);
    // Writes atomically; on success the path becomes the document's and the
    // current state counts as unmodified. `error` says why it failed.
    bool save(const QString& path, QString* error = nullptr);

    // Pushes a command onto the undo stack. False (and editFailed emitted) if
    // its edit was refused by the model; the scene is then unchanged.
    bool push(SceneCommand* command);
    // Compound edits: every push between begin and end is one undo step. If
    // one of them fails, endMacro undoes the others and drops the macro.
    void beginMacro(const QString& text);
    bool endMacro();

signals:
    void objectsChanged();
    // Parts moved, turned or scaled; nothing else about them changed.
    void geometryChanged();
    void materialsChanged();
    void regionsChanged();
    void settingsChanged();
    void cameraChanged();
    // The whole scene was replaced (views rebuild everything).
    void sceneReset();
    void selectionChanged();
    void filePathChanged(const QString& path);
    void modifiedChanged(bool modified);
    // A model edit was refused; the message says why (for the status bar).
    void editFailed(const QString& message);

private:
    friend class SceneCommand;
    model::Scene& mutableScene() { return m_scene; }
    void notify(Change changes);
    void reportFailure(const model::Diagnostic& diagnostic);
    void setFilePath(const QString& path);

    model::Scene m_scene;
    QUndoStack* m_undoStack = nullptr;
    Selection m_selection;
    QString m_filePath;
    bool m_lastPushFailed = false;
    int m_macroDepth = 0;
    bool m_macroFailed = false;
};

} // namespace regio::editor
