#pragma once
// Whole-part authoring: the Create and Modify menus and everything that
// turns a user's intent into undo commands on the document - primitives,
// duplicate, delete, rename, group and ungroup, the plane cut (along an axis
// through the selection's centre, or through three clicked points), material
// assignment and gizmo or numeric transforms. Every public edit here works
// without dialogs too, so tests drive the same code paths the menus do.
#include "editor/document/selection.h"
#include "editor/objects/primitives.h"
#include "model/edit/edit_parts.h"
#include "model/geometry/geometry.h"

#include <QObject>

#include <functional>
#include <glm/mat4x4.hpp>

class QAction;
class QMenu;
class QToolBar;
class QWidget;

namespace regio::editor {

class SceneDocument;
class Viewport;

class Authoring : public QObject {
    Q_OBJECT
public:
    Authoring(SceneDocument* document, Viewport* viewport, QWidget* dialogParent, bool interactive);

    void populateCreateMenu(QMenu* menu);
    void populateModifyMenu(QMenu* menu);
    void populateToolBar(QToolBar* toolBar);
    void populateContextMenu(QMenu* menu);
    void populateExamplesMenu(QMenu* menu, std::function<void(const QString&)> open);
    QAction* navigationHelpAction() const { return m_navigationHelp; }
    void updateActions();

    // --- edits (each one undo step; false if nothing was done) -----------
    // Creates a primitive and selects it.
    bool createPrimitive(const PrimitiveParams& params);
    // Default parameters for a new primitive: a fresh id, the first
    // material, standing on the ground below the view's centre.
    PrimitiveParams defaultPrimitive(PrimitiveKind kind) const;
    bool createMaterial();
    bool duplicateSelection();
    bool deleteSelection();
    // Changes the selected element's id and (objects, parts, materials,
    // regions) display name.
    bool renameElement(SelectionKind kind, const std::string& id, const std::string& newId, const std::string& newName);
    bool groupSelection();
    bool ungroupSelection();
    // Splits the selected parts (or every part of the selected objects) that
    // the plane crosses.
    bool splitSelection(const model::Plane& plane);
    bool splitSelectionAlong(int axis); // 0 x, 1 y, 2 z through the selection's centre
    bool assignMaterial(const std::string& materialId);
    bool transformSelection(const glm::dmat4& transform, const QString& text = {});
    bool moveParts(const std::vector<std::string>& partIds, const std::string& targetObjectId);
    bool storeViewAsSceneCamera();

public slots:
    void selectAll();
    void renameSelection(); // with a dialog
    void createPrimitiveInteractively(PrimitiveKind kind);
    void startClip();

private:
    void onTransformDragged(const std::vector<std::string>& partIds, const glm::dmat4& transform, int serial);
    void rebuildMaterialMenu();
    bool pushMacro(const QString& text, const std::function<bool()>& body);
    model::Box3 selectionBounds() const;

    SceneDocument* m_document;
    Viewport* m_viewport;
    QWidget* m_dialogParent;
    bool m_interactive;

    QList<QAction*> m_createActions;
    QAction* m_newMaterial = nullptr;
    QAction* m_group = nullptr;
    QAction* m_ungroup = nullptr;
    QAction* m_splitX = nullptr;
    QAction* m_splitY = nullptr;
    QAction* m_splitZ = nullptr;
    QAction* m_clip = nullptr;
    QAction* m_storeCamera = nullptr;
    QAction* m_navigationHelp = nullptr;
    QMenu* m_materialMenu = nullptr;

    int m_dragSerial = 0;
    std::vector<model::PartGeometry> m_dragStart;
};

} // namespace regio::editor
