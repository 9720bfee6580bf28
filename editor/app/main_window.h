#pragma once
// The editor window: one SceneDocument, the viewport in the middle, the docks
// around it, menus and toolbars with standard shortcuts, the file workflow
// (new, open, save, revert, recent files, autosave and recovery) and the
// window state kept in QSettings.
#include "editor/app/preferences.h"
#include "model/diagnostic.h"

#include <QMainWindow>
#include <QPointer>

class QAction;
class QActionGroup;
class QDockWidget;
class QLabel;
class QMenu;
class QUndoView;

namespace regio::importer {
struct Imported;
}

namespace regio::editor {

class Authoring;
class BspAuthoring;
class Autosave;
class DiagnosticsDock;
class MaterialsDock;
class PreviewController;
class PropertiesDock;
class RegionAuthoring;
class SceneDocument;
class SceneTreeDock;
class Viewport;

struct MainWindowOptions {
    // Read and write QSettings (window state, recent files, preferences).
    bool persistent = true;
    // Ask questions in dialogs. Screenshot runs and tests answer nothing.
    bool interactive = true;
    // Autosave to a recovery file.
    bool autosave = true;
};

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(MainWindowOptions options = {}, QWidget* parent = nullptr);
    ~MainWindow() override;

    SceneDocument* document() const { return m_document; }
    Viewport* viewport() const { return m_viewport; }
    Authoring* authoring() const { return m_authoring; }
    RegionAuthoring* regionAuthoring() const { return m_regions; }
    PreviewController* preview() const { return m_preview; }
    BspAuthoring* bspAuthoring() const { return m_bsp; }

    // Adds an imported model (File ▸ Import…): as a new scene (after asking
    // to save the open one; false when the user cancels), or into the open
    // scene as one undo step, its materials and objects with fresh ids
    // (model::itemsToMerge).
    bool addImported(const importer::Imported& imported, bool intoOpenScene, const QString& path);

    // Opens a scene. If it cannot be read the current document stays as it
    // is and (when interactive) a dialog lists the diagnostics.
    bool openFile(const QString& path, model::Diagnostics* diagnostics = nullptr);
    // Looks for recovery files of crashed sessions and offers to restore one.
    void offerRecovery();

    // View > Reset Layout: every panel where it is at first start, sized to
    // its content within the window (sizeDocksToContent has the rule).
    void resetLayout();

protected:
    void closeEvent(QCloseEvent* event) override;
    void showEvent(QShowEvent* event) override;

private:
    void createActions();
    void createMenus();
    void createToolBars();
    void createDocks();
    void readSettings();
    void writeSettings();
    void applyPreferences();
    // The panels' widths and heights for the window's size: the scene tree as
    // wide as its top-level ids, the right column about a fifth of the width,
    // the viewport at least 60 % of it.
    void sizeDocksToContent();

    void newScene();
    void open();
    void importModelFile();
    bool save();
    bool saveAs();
    void revert();
    void openRecent(const QString& path);
    void updateRecentMenu();
    void showPreferences();
    void showAbout();
    void updateTitle();
    void updateStatistics();
    void updateActions();
    // Save / Discard / Cancel when there are unsaved changes. True = go on.
    bool maybeSave();
    bool saveTo(const QString& path);
    void showOpenFailure(const QString& path, const model::Diagnostics& diagnostics);

    MainWindowOptions m_options;
    Preferences m_preferences;
    SceneDocument* m_document = nullptr;
    Viewport* m_viewport = nullptr;
    Authoring* m_authoring = nullptr;
    RegionAuthoring* m_regions = nullptr;
    BspAuthoring* m_bsp = nullptr;
    Autosave* m_autosave = nullptr;
    PreviewController* m_preview = nullptr;

    SceneTreeDock* m_sceneTree = nullptr;
    PropertiesDock* m_properties = nullptr;
    MaterialsDock* m_materials = nullptr;
    DiagnosticsDock* m_diagnostics = nullptr;
    QDockWidget* m_historyDock = nullptr;
    QUndoView* m_history = nullptr;

    QByteArray m_defaultState;   // the panels as createDocks() placed them
    bool m_layoutPending = true; // no saved layout: size the panels when first shown

    QMenu* m_recentMenu = nullptr;
    QMenu* m_viewMenu = nullptr;
    QLabel* m_statistics = nullptr;
    QLabel* m_problems = nullptr;

    struct {
        QAction *newScene, *open, *importModel, *save, *saveAs, *revert, *preferences, *quit;
        QAction *undo, *redo, *selectAll, *deselect, *duplicate, *remove, *rename;
        QAction *frameSelection, *frameAll, *orthographic, *cullBackFaces, *showGrid, *showRegions;
        QAction *solid, *wireframe, *normals;
        QAction *pickObjects, *pickParts, *pickFaces;
        QAction *gizmoMove, *gizmoRotate, *gizmoScale, *snap;
        QAction *about, *aboutQt, *resetLayout, *userGuide;
    } m_actions{};
    QList<QAction*> m_standardViewActions;
};

} // namespace regio::editor
