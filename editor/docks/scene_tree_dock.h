#pragma once
// The scene tree dock: objects -> parts -> faces with a filter field. Its
// selection and the document's are kept equal in both directions.
#include <QDockWidget>

class QLineEdit;
class QSortFilterProxyModel;
class QTreeView;

namespace regio::editor {

class Authoring;
class SceneDocument;
class SceneTreeModel;

class SceneTreeDock : public QDockWidget {
    Q_OBJECT
public:
    SceneTreeDock(SceneDocument* document, Authoring* authoring, QWidget* parent = nullptr);

    QTreeView* view() const { return m_view; }
    SceneTreeModel* model() const { return m_model; }

signals:
    // Double click: the user wants to see the element.
    void frameRequested();

private:
    void rebuild();
    void documentSelectionChanged();
    void viewSelectionChanged();
    void showContextMenu(const QPoint& pos);

    SceneDocument* m_document;
    Authoring* m_authoring;
    SceneTreeModel* m_model;
    QSortFilterProxyModel* m_proxy;
    QTreeView* m_view;
    QLineEdit* m_filter;
    bool m_syncing = false;
};

} // namespace regio::editor
