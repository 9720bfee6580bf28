// Authoring: actions, menus and the interactive (dialog) entry points.
#include "editor/objects/authoring.h"
#include "editor/app/sample_scenes.h"

#include "editor/document/qt_conversions.h"
#include "editor/document/scene_document.h"
#include "editor/objects/primitive_dialog.h"
#include "editor/viewport/viewport.h"

#include <QAction>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDir>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMessageBox>
#include <QToolBar>

namespace regio::editor {

Authoring::Authoring(SceneDocument* document, Viewport* viewport, QWidget* dialogParent, bool interactive)
    : QObject(dialogParent)
    , m_document(document)
    , m_viewport(viewport)
    , m_dialogParent(dialogParent)
    , m_interactive(interactive)
{
    const std::pair<PrimitiveKind, QKeySequence> kinds[] = {
        {PrimitiveKind::Box, QKeySequence(Qt::SHIFT | Qt::Key_B)},
        {PrimitiveKind::Room, {}},
        {PrimitiveKind::Prism, {}},
        {PrimitiveKind::Wedge, {}},
        {PrimitiveKind::Stairs, {}},
    };
    for (const auto& [kind, key] : kinds) {
        auto* action = new QAction(PrimitiveDialog::kindName(kind) + QStringLiteral("…"), this);
        action->setShortcut(key);
        action->setStatusTip(tr("New object: %1").arg(PrimitiveDialog::kindName(kind)));
        const PrimitiveKind k = kind;
        connect(action, &QAction::triggered, this, [this, k] { createPrimitiveInteractively(k); });
        m_createActions << action;
    }
    m_newMaterial = new QAction(tr("&Material"), this);
    m_newMaterial->setStatusTip(tr("Add a new grey material"));
    connect(m_newMaterial, &QAction::triggered, this, &Authoring::createMaterial);

    m_group = new QAction(tr("&Group"), this);
    m_group->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_G));
    m_group->setStatusTip(tr("Put the selected parts (or objects) into one new object"));
    connect(m_group, &QAction::triggered, this, &Authoring::groupSelection);
    m_ungroup = new QAction(tr("&Ungroup"), this);
    m_ungroup->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_G));
    m_ungroup->setStatusTip(tr("Make every part of the selected objects an object of its own"));
    connect(m_ungroup, &QAction::triggered, this, &Authoring::ungroupSelection);

    m_splitX = new QAction(tr("Split Across &X"), this);
    m_splitY = new QAction(tr("Split Across &Y"), this);
    m_splitZ = new QAction(tr("Split Across &Z"), this);
    for (QAction* a : {m_splitX, m_splitY, m_splitZ})
        a->setStatusTip(tr("Cut the selected parts in two with a plane through the selection's centre"));
    connect(m_splitX, &QAction::triggered, this, [this] { splitSelectionAlong(0); });
    connect(m_splitY, &QAction::triggered, this, [this] { splitSelectionAlong(1); });
    connect(m_splitZ, &QAction::triggered, this, [this] { splitSelectionAlong(2); });
    m_clip = new QAction(tr("&Clip Tool (Three Points)"), this);
    m_clip->setShortcut(QKeySequence(Qt::Key_C));
    m_clip->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    viewport->addAction(m_clip);
    m_clip->setStatusTip(tr("Click three points; the plane through them cuts the selected parts"));
    connect(m_clip, &QAction::triggered, this, &Authoring::startClip);

    m_storeCamera = new QAction(tr("Store View as Scene &Camera"), this);
    m_storeCamera->setStatusTip(tr("Save the current view in the scene file"));
    connect(m_storeCamera, &QAction::triggered, this, &Authoring::storeViewAsSceneCamera);

    m_navigationHelp = new QAction(tr("&Navigation and Shortcuts"), this);
    m_navigationHelp->setShortcut(QKeySequence::HelpContents);
    connect(m_navigationHelp, &QAction::triggered, this, [this] {
        QMessageBox::information(m_dialogParent, tr("Navigation"),
                                 tr("<table>"
                                    "<tr><td><b>Middle drag</b> or <b>Alt+left drag</b></td><td>orbit</td></tr>"
                                    "<tr><td><b>Shift+middle</b> or <b>Alt+Shift+left</b></td><td>pan</td></tr>"
                                    "<tr><td><b>Wheel</b>, <b>Ctrl+middle</b>, pinch</td><td>zoom</td></tr>"
                                    "<tr><td><b>Two-finger scroll</b></td><td>orbit (Shift: pan)</td></tr>"
                                    "<tr><td><b>Right drag + W A S D Q E</b></td><td>fly (Shift: faster)</td></tr>"
                                    "<tr><td><b>F</b> / <b>Home</b></td><td>frame selection / everything</td></tr>"
                                    "<tr><td><b>Keypad 1 3 7</b> (Ctrl: opposite), <b>0</b>, <b>5</b></td>"
                                    "<td>front, right, top, isometric, orthographic</td></tr>"
                                    "<tr><td><b>1 2 3</b></td><td>select objects, parts, faces</td></tr>"
                                    "<tr><td><b>W E R</b></td><td>move, rotate, scale gizmo</td></tr>"
                                    "<tr><td><b>C</b></td><td>clip tool: click three points</td></tr>"
                                    "<tr><td><b>Click</b>, <b>Ctrl+click</b></td><td>select, add or remove</td></tr>"
                                    "</table>"));
    });

    connect(viewport, &Viewport::transformDragged, this, &Authoring::onTransformDragged);
    connect(viewport, &Viewport::transformDragFinished, this, [this] { m_dragStart.clear(); });
    connect(viewport, &Viewport::clipPlaneChosen, this, [this](const model::Plane& plane) { splitSelection(plane); });
    connect(document, &SceneDocument::materialsChanged, this, &Authoring::rebuildMaterialMenu);
}

void Authoring::populateCreateMenu(QMenu* menu)
{
    menu->addActions(m_createActions);
    menu->addSeparator();
    menu->addAction(m_newMaterial);
}

void Authoring::populateModifyMenu(QMenu* menu)
{
    menu->addAction(m_group);
    menu->addAction(m_ungroup);
    menu->addSeparator();
    menu->addAction(m_splitX);
    menu->addAction(m_splitY);
    menu->addAction(m_splitZ);
    menu->addAction(m_clip);
    menu->addSeparator();
    m_materialMenu = menu->addMenu(tr("Assign &Material"));
    rebuildMaterialMenu();
    menu->addSeparator();
    menu->addAction(m_storeCamera);
}

void Authoring::populateToolBar(QToolBar* toolBar)
{
    toolBar->addActions(m_createActions);
    toolBar->addSeparator();
    toolBar->addAction(m_clip);
}

void Authoring::populateContextMenu(QMenu* menu)
{
    menu->addAction(m_group);
    menu->addAction(m_ungroup);
    menu->addSeparator();
    menu->addAction(m_splitX);
    menu->addAction(m_splitY);
    menu->addAction(m_splitZ);
    if (m_materialMenu)
        menu->addMenu(m_materialMenu);
}

void Authoring::populateExamplesMenu(QMenu* menu, std::function<void(const QString&)> open)
{
    const QDir dir(sampleScenesFolder());
    const QStringList files = dir.entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name);
    for (const QString& file : files) {
        const QString path = dir.absoluteFilePath(file);
        menu->addAction(file, this, [open, path] { open(path); });
    }
    menu->setEnabled(!files.isEmpty());
}

void Authoring::rebuildMaterialMenu()
{
    if (!m_materialMenu)
        return;
    m_materialMenu->clear();
    for (const model::Material& material : m_document->scene().materials) {
        const std::string id = material.id;
        QPixmap swatch(12, 12);
        const bool emits = material.emission.r + material.emission.g + material.emission.b > 0.0;
        swatch.fill(emits ? emissionDisplayColor(material.emission) : linearToColor(material.reflectance));
        m_materialMenu->addAction(QIcon(swatch),
                                  toQString(material.name.empty() ? id : material.name + " (" + id + ")"), this,
                                  [this, id] { assignMaterial(id); });
    }
    if (m_document->scene().materials.empty())
        m_materialMenu->addAction(tr("No materials"))->setEnabled(false);
    updateActions();
}

void Authoring::updateActions()
{
    const Selection& s = m_document->selection();
    const bool objects = s.kind == SelectionKind::Object && !s.empty();
    const bool parts = s.kind == SelectionKind::Part && !s.empty();
    m_group->setEnabled((parts) || (objects && s.ids.size() >= 2));
    bool ungroupable = false;
    if (objects)
        for (const std::string& id : s.ids)
            if (const model::Object* o = m_document->scene().findObject(id); o && o->parts.size() >= 2)
                ungroupable = true;
    m_ungroup->setEnabled(ungroupable);
    for (QAction* a : {m_splitX, m_splitY, m_splitZ, m_clip})
        a->setEnabled(objects || parts);
    if (m_materialMenu)
        m_materialMenu->setEnabled((objects || parts || s.kind == SelectionKind::Face) && !s.empty() &&
                                   !m_document->scene().materials.empty());
}

void Authoring::createPrimitiveInteractively(PrimitiveKind kind)
{
    PrimitiveParams params = defaultPrimitive(kind);
    if (m_interactive) {
        PrimitiveDialog dialog(params, m_document->scene(), m_dialogParent);
        if (dialog.exec() != QDialog::Accepted)
            return;
        params = dialog.params();
    }
    createPrimitive(params);
}

void Authoring::startClip()
{
    const Selection& s = m_document->selection();
    if (s.empty() || (s.kind != SelectionKind::Object && s.kind != SelectionKind::Part)) {
        emit m_viewport->statusMessage(tr("Select the parts or objects to cut first"));
        return;
    }
    m_viewport->setFocus();
    m_viewport->startClipByPoints();
}

void Authoring::renameSelection()
{
    const Selection& s = m_document->selection();
    if (s.ids.size() != 1)
        return;
    const model::Scene& scene = m_document->scene();
    const std::string id = s.ids.front();
    std::string name;
    bool hasName = true;
    switch (s.kind) {
    case SelectionKind::Object: name = scene.findObject(id)->name; break;
    case SelectionKind::Part: name = scene.findPart(id)->name; break;
    case SelectionKind::Material: name = scene.findMaterial(id)->name; break;
    case SelectionKind::Region: name = scene.findRegion(id)->name; break;
    default: hasName = false; break;
    }
    QDialog dialog(m_dialogParent);
    dialog.setWindowTitle(tr("Rename"));
    auto* form = new QFormLayout(&dialog);
    auto* idEdit = new QLineEdit(toQString(id), &dialog);
    form->addRow(tr("&Id:"), idEdit);
    auto* nameEdit = new QLineEdit(toQString(name), &dialog);
    if (hasName)
        form->addRow(tr("&Name:"), nameEdit);
    auto* note = new QLabel(tr("Ids are what files and BSP orders refer to; names are for people."), &dialog);
    note->setWordWrap(true);
    form->addRow(note);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, &dialog);
    connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
    form->addRow(buttons);
    if (dialog.exec() != QDialog::Accepted)
        return;
    renameElement(s.kind, id, toStd(idEdit->text().trimmed()), hasName ? toStd(nameEdit->text()) : name);
}

void Authoring::selectAll()
{
    const model::Scene& scene = m_document->scene();
    std::vector<std::string> ids;
    SelectionKind kind = m_document->selection().kind;
    if (kind != SelectionKind::Part && kind != SelectionKind::Face)
        kind = SelectionKind::Object;
    for (const model::Object& object : scene.objects) {
        if (kind == SelectionKind::Object)
            ids.push_back(object.id);
        for (const model::Part& part : object.parts) {
            if (kind == SelectionKind::Part)
                ids.push_back(part.id);
            if (kind == SelectionKind::Face)
                for (const model::Face& face : part.faces)
                    ids.push_back(face.id);
        }
    }
    m_document->setSelection(Selection::of(kind, std::move(ids)));
}

} // namespace regio::editor
