#pragma once
// The Regions dock: the regions of the scene with what they hold and what
// they cost (parts, faces, BSP fragments from the solver's own preparation,
// beside the single-BSP baseline), and the regional tree the solver builds
// from their boxes (paper §5.2: inner nodes are separating planes, leaves are
// regions). Selection follows the document's; ids and names are edited in
// place through the region commands. A proposal of automatic regions shows
// its figures here until it is accepted or discarded.
#include <QDockWidget>
#include <QTimer>

#include <string>

class QAction;
class QLabel;
class QPushButton;
class QTabWidget;
class QTreeWidget;
class QTreeWidgetItem;

namespace regio::editor {

class RegionFiguresWatcher;
class SceneDocument;

class RegionsDock : public QDockWidget {
    Q_OBJECT
public:
    enum Column { IdColumn, NameColumn, PartsColumn, FacesColumn, FragmentsColumn, ColumnCount };

    RegionsDock(SceneDocument* document, RegionFiguresWatcher* figures, const QList<QAction*>& actions,
                QWidget* parent = nullptr);

    QTreeWidget* regionList() const { return m_list; }
    QTreeWidget* treeView() const { return m_tree; }
    QTabWidget* tabs() const { return m_tabs; }
    QLabel* summary() const { return m_summary; }
    // The text of a region's row in a column, empty when there is no such row.
    QString cellText(const std::string& regionId, Column column) const;

    // The proposal panel: its text, and Accept / Discard wired to the actions.
    void showProposal(const QString& text, QAction* accept, QAction* discard);
    void hideProposal();
    bool proposalVisible() const;
    QLabel* proposalLabel() const { return m_proposalText; }

    // Rebuilds the lists now instead of after the short pause.
    void refreshNow();

signals:
    // An inner node of the regional tree was selected (-1: none).
    void separatingPlaneSelected(int node);

private:
    void rebuildList();
    void rebuildTree();
    void updateFigures();
    void syncSelectionFromDocument();
    void onListSelectionChanged();
    void onItemChanged(QTreeWidgetItem* item, int column);
    void onTreeSelectionChanged();
    QTreeWidgetItem* rowOf(const std::string& regionId) const;

    SceneDocument* m_document;
    RegionFiguresWatcher* m_figures;
    QTabWidget* m_tabs;
    QTreeWidget* m_list;
    QTreeWidget* m_tree;
    QLabel* m_summary;
    QWidget* m_proposalPanel;
    QLabel* m_proposalText;
    QPushButton* m_accept;
    QPushButton* m_discard;
    QTimer m_refresh;
    bool m_updating = false;
};

} // namespace regio::editor
