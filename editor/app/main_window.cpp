#include "editor/app/main_window.h"

#include "editor/app/autosave.h"
#include "editor/app/diagnostics_dialog.h"
#include "editor/app/import_dialog.h"
#include "editor/app/preferences_dialog.h"
#include "editor/app/recent_files.h"
#include "editor/bsp/bsp_authoring.h"
#include "editor/bsp/bsp_order_dock.h"
#include "editor/docks/diagnostics_dock.h"
#include "editor/docks/materials_dock.h"
#include "editor/docks/properties_dock.h"
#include "editor/docks/scene_tree_dock.h"
#include "editor/docks/scene_tree_model.h"
#include "editor/document/commands/import_command.h"
#include "editor/document/qt_conversions.h"
#include "editor/document/scene_document.h"
#include "editor/objects/authoring.h"
#include "editor/preview/preview_controller.h"
#include "editor/preview/solver_dock.h"
#include "editor/regions/region_authoring.h"
#include "editor/regions/regions_dock.h"
#include "editor/viewport/viewport.h"
#include "importer/import_model.h"

#include <QApplication>
#include <QCloseEvent>
#include <QDateTime>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QHeaderView>
#include <QLabel>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QStatusBar>
#include <QStyle>
#include <QTreeView>
#include <QUndoStack>
#include <QUndoView>

#include <algorithm>

namespace regio::editor {

MainWindow::MainWindow(MainWindowOptions options, QWidget* parent)
    : QMainWindow(parent)
    , m_options(options)
    , m_document(new SceneDocument(this))
{
    setObjectName(QStringLiteral("MainWindow"));
    if (m_options.persistent) {
        QSettings settings;
        m_preferences = Preferences::load(settings);
    }
    m_viewport = new Viewport(m_document, this);
    setCentralWidget(m_viewport);
    m_authoring = new Authoring(m_document, m_viewport, this, m_options.interactive);

    createActions();
    createDocks();
    createMenus();
    createToolBars();

    m_statistics = new QLabel(this);
    m_problems = new QLabel(this);
    statusBar()->addPermanentWidget(m_problems);
    statusBar()->addPermanentWidget(m_statistics);

    connect(m_document, &SceneDocument::modifiedChanged, this, &MainWindow::updateTitle);
    connect(m_document, &SceneDocument::filePathChanged, this, &MainWindow::updateTitle);
    connect(m_document, &SceneDocument::objectsChanged, this, &MainWindow::updateStatistics);
    connect(m_document, &SceneDocument::materialsChanged, this, &MainWindow::updateStatistics);
    connect(m_document, &SceneDocument::regionsChanged, this, &MainWindow::updateStatistics);
    connect(m_document, &SceneDocument::selectionChanged, this, &MainWindow::updateActions);
    connect(m_document, &SceneDocument::sceneReset, m_viewport, &Viewport::resetView);
    connect(m_document, &SceneDocument::editFailed, this,
            [this](const QString& message) { statusBar()->showMessage(tr("Refused: %1").arg(message), 8000); });
    connect(m_viewport, &Viewport::statusMessage, this,
            [this](const QString& message) { statusBar()->showMessage(message, 5000); });
    connect(m_viewport, &Viewport::renderingFailed, this, [this](const QString& message) {
        statusBar()->showMessage(message);
        if (m_options.interactive)
            QMessageBox::warning(this, tr("Viewport"), message);
    });
    connect(m_diagnostics, &DiagnosticsDock::problemCountChanged, this, [this](int errors, int warnings) {
        m_problems->setText(errors + warnings == 0 ? tr("No problems")
                                                   : tr("%n error(s)", nullptr, errors) + QStringLiteral(", ") +
                                                         tr("%n warning(s)", nullptr, warnings));
    });
    connect(m_diagnostics, &DiagnosticsDock::elementActivated, this, [this](const Selection& selection) {
        if (selection.kind == SelectionKind::Material)
            m_materials->raise();
        m_viewport->frameSelection();
    });

    if (m_options.autosave) {
        m_autosave = new Autosave(m_document, {}, this);
        connect(m_autosave, &Autosave::saveFailed, this,
                [this](const QString& message) { statusBar()->showMessage(message, 10000); });
    }
    m_defaultState = saveState();
    readSettings();
    applyPreferences();
    m_document->reset(model::Scene{});
    updateTitle();
    updateActions();
    updateStatistics();
}

MainWindow::~MainWindow() = default;

// --- docks ------------------------------------------------------------------

void MainWindow::createDocks()
{
    setCorner(Qt::BottomRightCorner, Qt::RightDockWidgetArea);
    setCorner(Qt::BottomLeftCorner, Qt::LeftDockWidgetArea);

    m_sceneTree = new SceneTreeDock(m_document, m_authoring, this);
    addDockWidget(Qt::LeftDockWidgetArea, m_sceneTree);

    m_properties = new PropertiesDock(m_document, m_authoring, this);
    addDockWidget(Qt::RightDockWidgetArea, m_properties);
    m_materials = new MaterialsDock(m_document, m_authoring, this);
    addDockWidget(Qt::RightDockWidgetArea, m_materials);

    m_diagnostics = new DiagnosticsDock(m_document, this);
    addDockWidget(Qt::BottomDockWidgetArea, m_diagnostics);

    m_regions = new RegionAuthoring(m_document, m_viewport, m_authoring, m_diagnostics, this);
    addDockWidget(Qt::RightDockWidgetArea, m_regions->dock());
    tabifyDockWidget(m_materials, m_regions->dock());
    m_materials->raise();
    connect(m_regions, &RegionAuthoring::statusMessage, this,
            [this](const QString& message) { statusBar()->showMessage(message, 5000); });

    m_bsp = new BspAuthoring(m_document, m_viewport, this);
    addDockWidget(Qt::RightDockWidgetArea, m_bsp->dock());
    tabifyDockWidget(m_materials, m_bsp->dock());
    m_materials->raise();
    connect(m_bsp, &BspAuthoring::statusMessage, this,
            [this](const QString& message) { statusBar()->showMessage(message, 5000); });

    m_historyDock = new QDockWidget(tr("History"), this);
    m_historyDock->setObjectName(QStringLiteral("HistoryDock"));
    m_history = new QUndoView(m_document->undoStack(), m_historyDock);
    m_history->setEmptyLabel(tr("<opened scene>"));
    m_historyDock->setWidget(m_history);
    addDockWidget(Qt::LeftDockWidgetArea, m_historyDock);
    splitDockWidget(m_sceneTree, m_historyDock, Qt::Vertical);

    m_preview = new PreviewController(m_document, m_viewport, this, m_options.interactive);
    tabifyDockWidget(m_properties, m_preview->solverDock());
    connect(m_properties, &PropertiesDock::solverPanelRequested, this, [this] {
        m_preview->solverDock()->show();
        m_preview->solverDock()->raise();
    });
    m_properties->raise();
}

// --- layout ------------------------------------------------------------------

void MainWindow::showEvent(QShowEvent* event)
{
    QMainWindow::showEvent(event);
    if (m_layoutPending) {
        m_layoutPending = false;
        sizeDocksToContent();
    }
}

void MainWindow::resetLayout()
{
    restoreState(m_defaultState);
    for (QDockWidget* dock : findChildren<QDockWidget*>())
        dock->setFloating(false);
    m_properties->raise();
    m_materials->raise();
    sizeDocksToContent();
}

void MainWindow::sizeDocksToContent()
{
    const int width = this->width();
    const int height = this->height();
    // The scene tree: its id column as wide as the longest top-level id (a
    // collapsed tree shows only those), the dock as wide as that column and
    // the tree's frame, but not past a fifth of the window.
    QTreeView* tree = m_sceneTree->view();
    tree->resizeColumnToContents(SceneTreeModel::IdColumn);
    const int idColumn = std::max(tree->header()->sectionSize(SceneTreeModel::IdColumn), 60);
    const int frame = tree->frameWidth() * 2 + m_sceneTree->style()->pixelMetric(QStyle::PM_ScrollBarExtent) + 16;
    int left = std::clamp(idColumn + frame, 160, std::max(160, width / 5));
    // The right column: the properties, materials and solver panels.
    int right = std::clamp(width * 22 / 100, 280, 440);
    // The viewport keeps at least 60 % of the width.
    const int most = width * 40 / 100 - 8;
    if (left + right > most) {
        right = std::max(220, most - left);
        left = std::max(120, most - right);
    }
    resizeDocks({m_sceneTree}, {left}, Qt::Horizontal);
    resizeDocks({m_properties}, {right}, Qt::Horizontal);
    resizeDocks({m_sceneTree, m_historyDock}, {3, 1}, Qt::Vertical);
    // The properties and the solver above the materials, regions and BSP
    // orders: the Solver panel's settings want the height.
    resizeDocks({m_properties, m_materials}, {11, 9}, Qt::Vertical);
    resizeDocks({m_diagnostics}, {std::clamp(height / 7, 100, 200)}, Qt::Vertical);
}

// --- settings ------------------------------------------------------------------

void MainWindow::readSettings()
{
    if (!m_options.persistent) {
        resize(1280, 800);
        return;
    }
    QSettings settings;
    if (!restoreGeometry(settings.value(QStringLiteral("window/geometry")).toByteArray()))
        resize(1280, 800);
    // A layout the user left is kept; the first start sizes the panels.
    m_layoutPending = !restoreState(settings.value(QStringLiteral("window/state")).toByteArray());
    settings.beginGroup(QStringLiteral("view"));
    m_actions.cullBackFaces->setChecked(settings.value(QStringLiteral("cullBackFaces"), true).toBool());
    m_actions.showGrid->setChecked(settings.value(QStringLiteral("showGrid"), true).toBool());
    m_actions.showRegions->setChecked(settings.value(QStringLiteral("showRegions"), true).toBool());
    settings.endGroup();
    updateRecentMenu();
}

void MainWindow::writeSettings()
{
    if (!m_options.persistent)
        return;
    QSettings settings;
    settings.setValue(QStringLiteral("window/geometry"), saveGeometry());
    settings.setValue(QStringLiteral("window/state"), saveState());
    settings.beginGroup(QStringLiteral("view"));
    settings.setValue(QStringLiteral("cullBackFaces"), m_actions.cullBackFaces->isChecked());
    settings.setValue(QStringLiteral("showGrid"), m_actions.showGrid->isChecked());
    settings.setValue(QStringLiteral("showRegions"), m_actions.showRegions->isChecked());
    settings.endGroup();
}

void MainWindow::applyPreferences()
{
    m_viewport->setGridStep(m_preferences.gridStep);
    m_viewport->setSnapEnabled(m_preferences.snapToGrid);
    m_viewport->setAngleStep(m_preferences.angleSnapDegrees);
    m_actions.snap->setChecked(m_preferences.snapToGrid);
    if (m_autosave)
        m_autosave->setIntervalMinutes(m_preferences.autosaveMinutes);
}

void MainWindow::showPreferences()
{
    PreferencesDialog dialog(m_preferences, this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    const Preferences chosen = dialog.preferences();
    const bool languageChanged = chosen.language != m_preferences.language;
    m_preferences = chosen;
    if (m_options.persistent) {
        QSettings settings;
        m_preferences.save(settings);
    }
    applyPreferences();
    if (languageChanged)
        QMessageBox::information(this, tr("Preferences"),
                                 tr("The new language takes effect when Regio is started again."));
}

// --- title and status ---------------------------------------------------------------

void MainWindow::updateTitle()
{
    setWindowFilePath(m_document->filePath());
    setWindowTitle(tr("%1[*] — Regio").arg(m_document->displayName()));
    setWindowModified(m_document->isModified());
    m_actions.revert->setEnabled(!m_document->filePath().isEmpty() && m_document->isModified());
}

void MainWindow::updateStatistics()
{
    const model::Scene& scene = m_document->scene();
    int parts = 0, faces = 0;
    for (const model::Object& object : scene.objects) {
        parts += int(object.parts.size());
        for (const model::Part& part : object.parts)
            faces += int(part.faces.size());
    }
    m_statistics->setText(tr("%1 objects, %2 parts, %3 faces, %4 materials, %5 regions")
                              .arg(scene.objects.size())
                              .arg(parts)
                              .arg(faces)
                              .arg(scene.materials.size())
                              .arg(scene.regions.size()));
}

void MainWindow::updateActions()
{
    const Selection& s = m_document->selection();
    m_actions.deselect->setEnabled(!s.empty());
    m_actions.duplicate->setEnabled(!s.empty() && (s.kind == SelectionKind::Object || s.kind == SelectionKind::Part));
    m_actions.remove->setEnabled(!s.empty() && s.kind != SelectionKind::Face);
    m_actions.rename->setEnabled(s.ids.size() == 1);
    m_authoring->updateActions();
}

// --- files --------------------------------------------------------------------------

bool MainWindow::maybeSave()
{
    if (!m_document->isModified())
        return true;
    if (!m_options.interactive)
        return false;
    const auto answer =
        QMessageBox::warning(this, tr("Unsaved changes"),
                             tr("The scene \"%1\" has unsaved changes. Save them?").arg(m_document->displayName()),
                             QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    if (answer == QMessageBox::Save)
        return save();
    return answer == QMessageBox::Discard;
}

void MainWindow::newScene()
{
    if (!maybeSave())
        return;
    m_document->reset(model::Scene{});
    statusBar()->showMessage(tr("New scene"), 3000);
}

void MainWindow::open()
{
    if (!maybeSave())
        return;
    const QString dir = m_document->filePath().isEmpty() ? QString() : QFileInfo(m_document->filePath()).path();
    const QString path =
        QFileDialog::getOpenFileName(this, tr("Open Scene"), dir, tr("Regio scenes (*.json);;All files (*)"));
    if (!path.isEmpty())
        openFile(path);
}

void MainWindow::importModelFile()
{
    const QString dir = m_document->filePath().isEmpty() ? QString() : QFileInfo(m_document->filePath()).path();
    const QString path = QFileDialog::getOpenFileName(this, tr("Import Model"), dir,
                                                      tr("Models (*.obj *.gltf *.glb *.fbx *.dae *.ply *.stl *.3ds "
                                                         "*.blend *.off *.x *.lwo *.ase *.ac);;All files (*)"));
    if (path.isEmpty())
        return;
    ImportDialog dialog(path, !m_document->scene().objects.empty(), this);
    if (dialog.exec() != QDialog::Accepted || !dialog.imported())
        return;
    addImported(*dialog.imported(), dialog.target() == ImportDialog::Target::OpenScene, path);
}

bool MainWindow::addImported(const importer::Imported& imported, bool intoOpenScene, const QString& path)
{
    const QString name = QFileInfo(path).fileName();
    if (!intoOpenScene) {
        if (!maybeSave())
            return false;
        // A new, unsaved scene: closing asks where to save it.
        m_document->reset(imported.scene, QString(), true);
        statusBar()->showMessage(tr("Imported %1 as a new scene").arg(name), 5000);
        return true;
    }
    model::MergeItems items = model::itemsToMerge(m_document->scene(), imported.scene);
    const std::size_t objects = items.objects.size();
    m_document->undoStack()->push(new AddSceneItems(m_document, tr("Import %1").arg(name), std::move(items)));
    statusBar()->showMessage(tr("Imported %1 (objects: %2)").arg(name).arg(objects), 5000);
    return true;
}

bool MainWindow::openFile(const QString& path, model::Diagnostics* diagnosticsOut)
{
    model::Diagnostics diagnostics;
    const bool ok = m_document->open(path, diagnostics);
    if (diagnosticsOut)
        *diagnosticsOut = diagnostics;
    if (!ok) {
        showOpenFailure(path, diagnostics);
        return false;
    }
    if (m_options.persistent) {
        QSettings settings;
        RecentFiles(settings).add(path);
        updateRecentMenu();
    }
    statusBar()->showMessage(tr("Opened %1").arg(QDir::toNativeSeparators(path)), 5000);
    return true;
}

void MainWindow::showOpenFailure(const QString& path, const model::Diagnostics& diagnostics)
{
    statusBar()->showMessage(tr("Could not open %1").arg(QDir::toNativeSeparators(path)), 8000);
    if (!m_options.interactive)
        return;
    DiagnosticsDialog dialog(tr("Cannot open scene"),
                             tr("<b>%1</b> could not be opened. The scene you are editing is unchanged.")
                                 .arg(QDir::toNativeSeparators(path).toHtmlEscaped()),
                             diagnostics, this);
    dialog.exec();
}

bool MainWindow::saveTo(const QString& path)
{
    QString error;
    if (!m_document->save(path, &error)) {
        statusBar()->showMessage(tr("Save failed"), 5000);
        if (m_options.interactive)
            QMessageBox::critical(this, tr("Save failed"),
                                  tr("The scene could not be saved to %1:\n%2\nThe file on disk is unchanged.")
                                      .arg(QDir::toNativeSeparators(path), error));
        return false;
    }
    if (m_options.persistent) {
        QSettings settings;
        RecentFiles(settings).add(path);
        updateRecentMenu();
    }
    statusBar()->showMessage(tr("Saved %1").arg(QDir::toNativeSeparators(path)), 5000);
    return true;
}

bool MainWindow::save()
{
    if (m_document->filePath().isEmpty())
        return saveAs();
    return saveTo(m_document->filePath());
}

bool MainWindow::saveAs()
{
    QString path = QFileDialog::getSaveFileName(
        this, tr("Save Scene As"), m_document->filePath().isEmpty() ? tr("untitled.json") : m_document->filePath(),
        tr("Regio scenes (*.json)"));
    if (path.isEmpty())
        return false;
    if (QFileInfo(path).suffix().isEmpty())
        path += QStringLiteral(".json");
    return saveTo(path);
}

void MainWindow::revert()
{
    if (m_document->filePath().isEmpty() || !m_document->isModified())
        return;
    if (m_options.interactive &&
        QMessageBox::question(this, tr("Revert"),
                              tr("Drop every change since \"%1\" was last saved?").arg(m_document->displayName()),
                              QMessageBox::Yes | QMessageBox::No, QMessageBox::No) != QMessageBox::Yes)
        return;
    model::Diagnostics diagnostics;
    if (!m_document->revert(diagnostics))
        showOpenFailure(m_document->filePath(), diagnostics);
}

void MainWindow::openRecent(const QString& path)
{
    if (!maybeSave())
        return;
    if (!QFileInfo::exists(path)) {
        QSettings settings;
        RecentFiles(settings).remove(path);
        updateRecentMenu();
        if (m_options.interactive)
            QMessageBox::warning(this, tr("Open Recent"),
                                 tr("%1 no longer exists.").arg(QDir::toNativeSeparators(path)));
        return;
    }
    openFile(path);
}

void MainWindow::updateRecentMenu()
{
    m_recentMenu->clear();
    QStringList files;
    if (m_options.persistent) {
        QSettings settings;
        files = RecentFiles(settings).files();
    }
    int n = 0;
    for (const QString& file : files) {
        const QString label = tr("&%1 %2").arg(++n % 10).arg(QFileInfo(file).fileName());
        QAction* action = m_recentMenu->addAction(label, this, [this, file] { openRecent(file); });
        action->setToolTip(QDir::toNativeSeparators(file));
        action->setStatusTip(QDir::toNativeSeparators(file));
    }
    if (files.isEmpty()) {
        m_recentMenu->addAction(tr("No recent files"))->setEnabled(false);
        return;
    }
    m_recentMenu->addSeparator();
    m_recentMenu->addAction(tr("Clear List"), this, [this] {
        QSettings settings;
        RecentFiles(settings).clear();
        updateRecentMenu();
    });
}

void MainWindow::offerRecovery()
{
    if (!m_options.interactive || !m_autosave)
        return;
    const QList<RecoveryFile> orphans = Autosave::findOrphans();
    for (const RecoveryFile& file : orphans) {
        const QString original =
            file.originalPath.isEmpty() ? tr("an unsaved scene") : QDir::toNativeSeparators(file.originalPath);
        QMessageBox box(QMessageBox::Question, tr("Recover Scene"),
                        tr("Regio did not shut down cleanly. Changes to %1 were autosaved on %2.")
                            .arg(original, QLocale().toString(QDateTime::fromMSecsSinceEpoch(file.savedAtMs),
                                                              QLocale::ShortFormat)),
                        QMessageBox::NoButton, this);
        box.setInformativeText(tr("Restore them? Discarding deletes the autosaved copy."));
        QPushButton* restore = box.addButton(tr("Restore"), QMessageBox::AcceptRole);
        box.addButton(QMessageBox::Discard);
        QPushButton* later = box.addButton(tr("Later"), QMessageBox::RejectRole);
        box.setDefaultButton(restore);
        box.exec();
        if (box.clickedButton() == later)
            continue;
        if (box.clickedButton() != restore) {
            Autosave::remove(file);
            continue;
        }
        if (m_document->isModified() && !maybeSave())
            return;
        QString error;
        if (!Autosave::restore(file, m_document, &error))
            QMessageBox::warning(this, tr("Recover Scene"), tr("The autosaved scene cannot be read: %1").arg(error));
        else
            statusBar()->showMessage(tr("Recovered autosaved changes; save to keep them."), 10000);
        return; // one document per window
    }
}

void MainWindow::closeEvent(QCloseEvent* event)
{
    if (m_options.interactive && !maybeSave()) {
        event->ignore();
        return;
    }
    writeSettings();
    event->accept();
}

void MainWindow::showAbout()
{
    QMessageBox::about(this, tr("About Regio"),
                       tr("<h3>Regio %1</h3><p>An editor for radiosity scenes: whole-part B-rep objects, "
                          "axis-aligned regions and their BSP root-patch orders.</p>")
                           .arg(QStringLiteral(REGIO_VERSION)));
}

} // namespace regio::editor
