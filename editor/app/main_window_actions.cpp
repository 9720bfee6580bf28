// MainWindow's actions, menus and toolbars.
#include "editor/app/main_window.h"
#include "editor/app/sample_scenes.h"
#include "editor/bsp/bsp_authoring.h"
#include "editor/docks/diagnostics_dock.h"
#include "editor/docks/materials_dock.h"
#include "editor/docks/properties_dock.h"
#include "editor/docks/scene_tree_dock.h"
#include "editor/document/scene_document.h"
#include "editor/objects/authoring.h"
#include "editor/preview/preview_controller.h"
#include "editor/regions/region_authoring.h"
#include "editor/viewport/viewport.h"

#include <QActionGroup>
#include <QApplication>
#include <QDesktopServices>
#include <QDir>
#include <QDockWidget>
#include <QMenuBar>
#include <QStatusBar>
#include <QStyle>
#include <QToolBar>
#include <QUndoStack>
#include <QUrl>

namespace regio::editor {

namespace {

QAction* makeAction(QObject* parent, const QString& text, const QKeySequence& shortcut = {}, const QString& tip = {})
{
    auto* action = new QAction(text, parent);
    if (!shortcut.isEmpty())
        action->setShortcut(shortcut);
    if (!tip.isEmpty())
        action->setStatusTip(tip);
    return action;
}

QAction* makeCheckable(QObject* parent, const QString& text, const QKeySequence& shortcut, bool checked)
{
    QAction* action = makeAction(parent, text, shortcut);
    action->setCheckable(true);
    action->setChecked(checked);
    return action;
}

} // namespace

void MainWindow::createActions()
{
    QStyle* style = QApplication::style();
    auto& a = m_actions;

    a.newScene = makeAction(this, tr("&New"), QKeySequence::New, tr("Start a new, empty scene"));
    a.newScene->setIcon(style->standardIcon(QStyle::SP_FileIcon));
    connect(a.newScene, &QAction::triggered, this, &MainWindow::newScene);
    a.open = makeAction(this, tr("&Open…"), QKeySequence::Open, tr("Open a scene file"));
    a.open->setIcon(style->standardIcon(QStyle::SP_DialogOpenButton));
    connect(a.open, &QAction::triggered, this, &MainWindow::open);
    a.importModel = makeAction(this, tr("&Import Model…"), QKeySequence(tr("Ctrl+I")),
                               tr("Import a model file (OBJ, glTF, FBX, Collada, PLY, STL, 3DS, ...)"));
    connect(a.importModel, &QAction::triggered, this, &MainWindow::importModelFile);
    a.save = makeAction(this, tr("&Save"), QKeySequence::Save, tr("Save the scene"));
    a.save->setIcon(style->standardIcon(QStyle::SP_DialogSaveButton));
    connect(a.save, &QAction::triggered, this, &MainWindow::save);
    a.saveAs = makeAction(this, tr("Save &As…"), QKeySequence::SaveAs, tr("Save the scene under a new name"));
    connect(a.saveAs, &QAction::triggered, this, &MainWindow::saveAs);
    a.revert = makeAction(this, tr("Re&vert"), {}, tr("Drop unsaved changes and reload the file"));
    connect(a.revert, &QAction::triggered, this, &MainWindow::revert);
    a.preferences = makeAction(this, tr("&Preferences…"), QKeySequence::Preferences);
    a.preferences->setMenuRole(QAction::PreferencesRole);
    connect(a.preferences, &QAction::triggered, this, &MainWindow::showPreferences);
    a.quit = makeAction(this, tr("&Quit"), QKeySequence::Quit);
    a.quit->setMenuRole(QAction::QuitRole);
    connect(a.quit, &QAction::triggered, this, &QWidget::close);

    QUndoStack* stack = m_document->undoStack();
    a.undo = stack->createUndoAction(this, tr("&Undo"));
    a.undo->setShortcuts(QKeySequence::Undo);
    a.undo->setIcon(style->standardIcon(QStyle::SP_ArrowBack));
    a.redo = stack->createRedoAction(this, tr("&Redo"));
    a.redo->setShortcuts(QKeySequence::Redo);
    a.redo->setIcon(style->standardIcon(QStyle::SP_ArrowForward));
    a.selectAll = makeAction(this, tr("Select &All"), QKeySequence::SelectAll);
    connect(a.selectAll, &QAction::triggered, m_authoring, &Authoring::selectAll);
    a.deselect = makeAction(this, tr("&Deselect"), QKeySequence::Deselect);
    if (a.deselect->shortcut().isEmpty())
        a.deselect->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_A));
    connect(a.deselect, &QAction::triggered, m_document, &SceneDocument::clearSelection);
    a.duplicate = makeAction(this, tr("D&uplicate"), QKeySequence(Qt::CTRL | Qt::Key_D),
                             tr("Copy the selected objects or parts"));
    connect(a.duplicate, &QAction::triggered, m_authoring, &Authoring::duplicateSelection);
    a.remove = makeAction(this, tr("De&lete"), QKeySequence::Delete, tr("Delete the selection"));
    a.remove->setIcon(style->standardIcon(QStyle::SP_TrashIcon));
    connect(a.remove, &QAction::triggered, m_authoring, &Authoring::deleteSelection);
    a.rename = makeAction(this, tr("Re&name…"), QKeySequence(Qt::Key_F2), tr("Rename the selected element"));
    connect(a.rename, &QAction::triggered, m_authoring, &Authoring::renameSelection);

    a.frameSelection = makeAction(this, tr("&Frame Selection"), QKeySequence(Qt::Key_F),
                                  tr("Fit the selection in the view (everything when nothing is selected)"));
    connect(a.frameSelection, &QAction::triggered, m_viewport, &Viewport::frameSelection);
    a.frameAll = makeAction(this, tr("Frame &All"), QKeySequence(Qt::Key_Home));
    connect(a.frameAll, &QAction::triggered, m_viewport, &Viewport::frameAll);
    a.orthographic = makeCheckable(this, tr("&Orthographic"), QKeySequence(Qt::KeypadModifier | Qt::Key_5), false);
    connect(a.orthographic, &QAction::toggled, m_viewport, &Viewport::setOrthographic);
    a.cullBackFaces = makeCheckable(this, tr("Hide &Back Faces"), {}, true);
    a.cullBackFaces->setStatusTip(tr("Faces seen from behind are not drawn: look into rooms from outside"));
    connect(a.cullBackFaces, &QAction::toggled, m_viewport, &Viewport::setCullBackFaces);
    a.showGrid = makeCheckable(this, tr("Show &Grid"), {}, true);
    connect(a.showGrid, &QAction::toggled, m_viewport, &Viewport::setShowGrid);
    a.showRegions = makeCheckable(this, tr("Show &Regions"), {}, true);
    connect(a.showRegions, &QAction::toggled, m_viewport, &Viewport::setShowRegions);

    auto* shading = new QActionGroup(this);
    a.solid = makeCheckable(shading, tr("&Solid"), QKeySequence(Qt::ALT | Qt::Key_1), true);
    a.wireframe = makeCheckable(shading, tr("&Wireframe"), QKeySequence(Qt::ALT | Qt::Key_2), false);
    a.normals = makeCheckable(shading, tr("Face &Normals"), QKeySequence(Qt::ALT | Qt::Key_3), false);
    a.normals->setStatusTip(tr("Colour faces by their normal and show which way they face"));
    connect(a.solid, &QAction::triggered, this, [this] { m_viewport->setShading(ShadingMode::Solid); });
    connect(a.wireframe, &QAction::triggered, this, [this] { m_viewport->setShading(ShadingMode::Wireframe); });
    connect(a.normals, &QAction::triggered, this, [this] { m_viewport->setShading(ShadingMode::Normals); });

    auto* pick = new QActionGroup(this);
    a.pickObjects = makeCheckable(pick, tr("Select &Objects"), QKeySequence(Qt::Key_1), true);
    a.pickParts = makeCheckable(pick, tr("Select &Parts"), QKeySequence(Qt::Key_2), false);
    a.pickFaces = makeCheckable(pick, tr("Select F&aces"), QKeySequence(Qt::Key_3), false);
    connect(a.pickObjects, &QAction::triggered, this, [this] { m_viewport->setPickMode(PickMode::Object); });
    connect(a.pickParts, &QAction::triggered, this, [this] { m_viewport->setPickMode(PickMode::Part); });
    connect(a.pickFaces, &QAction::triggered, this, [this] { m_viewport->setPickMode(PickMode::Face); });

    auto* gizmo = new QActionGroup(this);
    a.gizmoMove = makeCheckable(gizmo, tr("&Move"), QKeySequence(Qt::Key_W), true);
    a.gizmoRotate = makeCheckable(gizmo, tr("&Rotate"), QKeySequence(Qt::Key_E), false);
    a.gizmoScale = makeCheckable(gizmo, tr("&Scale"), QKeySequence(Qt::Key_R), false);
    connect(a.gizmoMove, &QAction::triggered, this, [this] { m_viewport->setGizmoMode(GizmoMode::Move); });
    connect(a.gizmoRotate, &QAction::triggered, this, [this] { m_viewport->setGizmoMode(GizmoMode::Rotate); });
    connect(a.gizmoScale, &QAction::triggered, this, [this] { m_viewport->setGizmoMode(GizmoMode::Scale); });
    a.snap = makeCheckable(this, tr("Snap to &Grid"), {}, true);
    connect(a.snap, &QAction::toggled, this, [this](bool on) {
        m_preferences.snapToGrid = on;
        m_viewport->setSnapEnabled(on);
    });

    struct ViewEntry {
        QString text;
        StandardView view;
        QKeySequence key;
    };
    const ViewEntry views[] = {
        {tr("&Front"), StandardView::Front, QKeySequence(Qt::KeypadModifier | Qt::Key_1)},
        {tr("&Back"), StandardView::Back,
         QKeySequence(QKeyCombination(Qt::ControlModifier | Qt::KeypadModifier, Qt::Key_1))},
        {tr("&Right"), StandardView::Right, QKeySequence(Qt::KeypadModifier | Qt::Key_3)},
        {tr("&Left"), StandardView::Left,
         QKeySequence(QKeyCombination(Qt::ControlModifier | Qt::KeypadModifier, Qt::Key_3))},
        {tr("&Top"), StandardView::Top, QKeySequence(Qt::KeypadModifier | Qt::Key_7)},
        {tr("Botto&m"), StandardView::Bottom,
         QKeySequence(QKeyCombination(Qt::ControlModifier | Qt::KeypadModifier, Qt::Key_7))},
        {tr("&Isometric"), StandardView::Iso, QKeySequence(Qt::KeypadModifier | Qt::Key_0)},
    };
    for (const ViewEntry& entry : views) {
        QAction* action = makeAction(this, entry.text, entry.key);
        const StandardView view = entry.view;
        connect(action, &QAction::triggered, this, [this, view] {
            m_viewport->setStandardView(view);
            m_viewport->frameSelection();
        });
        m_standardViewActions << action;
    }

    a.about = makeAction(this, tr("&About Regio"));
    a.about->setMenuRole(QAction::AboutRole);
    connect(a.about, &QAction::triggered, this, &MainWindow::showAbout);
    a.aboutQt = makeAction(this, tr("About &Qt"));
    a.userGuide = makeAction(this, tr("User &Guide"));
    a.userGuide->setShortcut(QKeySequence::HelpContents);
    a.userGuide->setStatusTip(tr("Open the user guide"));
    connect(a.userGuide, &QAction::triggered, this, [this] {
        const QString guide = userGuideFile();
        if (!QDesktopServices::openUrl(QUrl::fromLocalFile(guide)))
            statusBar()->showMessage(tr("No program opens %1 on this system").arg(QDir::toNativeSeparators(guide)),
                                     10000);
    });
    a.resetLayout = makeAction(this, tr("&Reset Layout"));
    a.resetLayout->setStatusTip(tr("Put every panel back where it was at first start, sized to the window"));
    connect(a.resetLayout, &QAction::triggered, this, &MainWindow::resetLayout);
    a.aboutQt->setMenuRole(QAction::AboutQtRole);
    connect(a.aboutQt, &QAction::triggered, qApp, &QApplication::aboutQt);

    // The viewport's keys (F, 1-3, W/E/R) must not fire while typing in a dock.
    for (QAction* action :
         {a.frameSelection, a.pickObjects, a.pickParts, a.pickFaces, a.gizmoMove, a.gizmoRotate, a.gizmoScale}) {
        action->setShortcutContext(Qt::WidgetWithChildrenShortcut);
        m_viewport->addAction(action);
    }
    for (QAction* action : m_standardViewActions) {
        action->setShortcutContext(Qt::WidgetWithChildrenShortcut);
        m_viewport->addAction(action);
    }
}

void MainWindow::createMenus()
{
    auto& a = m_actions;
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->addAction(a.newScene);
    file->addAction(a.open);
    m_recentMenu = file->addMenu(tr("Open &Recent"));
    m_authoring->populateExamplesMenu(file->addMenu(tr("Open E&xample")), [this](const QString& path) {
        if (maybeSave())
            openFile(path);
    });
    file->addAction(a.importModel);
    file->addSeparator();
    file->addAction(a.save);
    file->addAction(a.saveAs);
    file->addAction(a.revert);
    file->addSeparator();
    file->addAction(a.preferences);
    file->addSeparator();
    file->addAction(a.quit);

    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    edit->addAction(a.undo);
    edit->addAction(a.redo);
    edit->addSeparator();
    edit->addAction(a.duplicate);
    edit->addAction(a.remove);
    edit->addAction(a.rename);
    edit->addSeparator();
    edit->addAction(a.selectAll);
    edit->addAction(a.deselect);
    edit->addSeparator();
    edit->addAction(a.pickObjects);
    edit->addAction(a.pickParts);
    edit->addAction(a.pickFaces);

    m_authoring->populateCreateMenu(menuBar()->addMenu(tr("&Create")));
    QMenu* modify = menuBar()->addMenu(tr("&Modify"));
    modify->addAction(a.gizmoMove);
    modify->addAction(a.gizmoRotate);
    modify->addAction(a.gizmoScale);
    modify->addAction(a.snap);
    modify->addSeparator();
    m_authoring->populateModifyMenu(modify);
    m_regions->populateRegionsMenu(menuBar()->addMenu(tr("&Regions")));
    m_bsp->populateBspMenu(menuBar()->addMenu(tr("&BSP")));

    m_viewMenu = menuBar()->addMenu(tr("&View"));
    m_viewMenu->addAction(a.solid);
    m_viewMenu->addAction(a.wireframe);
    m_viewMenu->addAction(a.normals);
    m_viewMenu->addSeparator();
    m_viewMenu->addAction(a.cullBackFaces);
    m_viewMenu->addAction(a.showGrid);
    m_viewMenu->addAction(a.showRegions);
    m_viewMenu->addSeparator();
    m_viewMenu->addAction(a.frameSelection);
    m_viewMenu->addAction(a.frameAll);
    QMenu* standard = m_viewMenu->addMenu(tr("Standard &Views"));
    standard->addActions(m_standardViewActions);
    m_viewMenu->addAction(a.orthographic);
    m_viewMenu->addSeparator();
    QMenu* docks = m_viewMenu->addMenu(tr("&Panels"));
    for (QDockWidget* dock : findChildren<QDockWidget*>())
        docks->addAction(dock->toggleViewAction());
    m_viewMenu->addAction(a.resetLayout);

    m_preview->populateMenu(menuBar()->addMenu(tr("&Solve")));

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->addAction(a.userGuide);
    m_authoring->populateExamplesMenu(help->addMenu(tr("E&xamples")), [this](const QString& path) {
        if (maybeSave())
            openFile(path);
    });
    help->addAction(m_authoring->navigationHelpAction());
    help->addSeparator();
    help->addAction(a.about);
    help->addAction(a.aboutQt);
}

void MainWindow::createToolBars()
{
    auto& a = m_actions;
    QToolBar* file = addToolBar(tr("File"));
    file->setObjectName(QStringLiteral("FileToolBar"));
    file->addAction(a.newScene);
    file->addAction(a.open);
    file->addAction(a.save);
    file->addSeparator();
    file->addAction(a.undo);
    file->addAction(a.redo);

    QToolBar* tools = addToolBar(tr("Tools"));
    tools->setObjectName(QStringLiteral("ToolsToolBar"));
    tools->setToolButtonStyle(Qt::ToolButtonTextOnly);
    tools->addAction(a.pickObjects);
    tools->addAction(a.pickParts);
    tools->addAction(a.pickFaces);
    tools->addSeparator();
    tools->addAction(a.gizmoMove);
    tools->addAction(a.gizmoRotate);
    tools->addAction(a.gizmoScale);
    tools->addAction(a.snap);
    tools->addSeparator();
    tools->addAction(a.solid);
    tools->addAction(a.wireframe);
    tools->addAction(a.normals);

    QToolBar* solve = addToolBar(tr("Solve"));
    solve->setObjectName(QStringLiteral("SolveToolBar"));
    m_preview->populateToolBar(solve);

    QToolBar* create = addToolBar(tr("Create"));
    create->setObjectName(QStringLiteral("CreateToolBar"));
    create->setToolButtonStyle(Qt::ToolButtonTextOnly);
    m_authoring->populateToolBar(create);
}

} // namespace regio::editor
