#pragma once
// The BSP order dock (paper §5.3): per region, the ordered list of faces used
// as BSP roots, edited by drag and drop, move to top, remove, pick in the
// viewport and insert selected faces; the live figures (fragments, splits,
// depth) of the region and the scene beside the single-BSP baseline and, when
// one is pending, the suggested order's; the region's BSP tree; and the
// painter-order playback controls. It reads the document and the
// BspAuthoring feature and edits only through BspAuthoring (undo commands).
#include <QDockWidget>

class QComboBox;
class QLabel;
class QListWidget;
class QPushButton;
class QSlider;
class QTableWidget;
class QTreeWidget;
class QTreeWidgetItem;
class QCheckBox;

namespace regio::editor {

class BspAuthoring;
class SceneDocument;

class BspOrderDock : public QDockWidget {
    Q_OBJECT
public:
    BspOrderDock(BspAuthoring* authoring, SceneDocument* document, QWidget* parent = nullptr);

    // Rows and columns of the figures table.
    enum FigureRow { FragmentsRow, SplitsRow, DepthRow };
    enum FigureColumn { RegionColumn, SceneColumn, BaselineColumn, SuggestedRegionColumn, SuggestedSceneColumn };
    // The number shown in a cell (-1 when the cell is empty).
    int figure(FigureRow row, FigureColumn column) const;

    QComboBox* regionCombo() const { return m_regions; }
    QListWidget* orderList() const { return m_list; }
    QTreeWidget* treeWidget() const { return m_tree; }
    QSlider* playbackSlider() const { return m_slider; }
    // Node index (in the analysis' prepared scene) of a tree item.
    static int nodeOf(const QTreeWidgetItem* item);

private:
    void rebuildRegions();
    void rebuildList();
    void rebuildFigures();
    void rebuildTree();
    void updateButtons();
    void updatePlayback();
    void onRowsMoved(int from, int to);
    void setCell(int row, int column, int value, bool better = false);

    BspAuthoring* m_authoring;
    SceneDocument* m_document;
    QComboBox* m_regions = nullptr;
    QListWidget* m_list = nullptr;
    QPushButton* m_top = nullptr;
    QPushButton* m_remove = nullptr;
    QPushButton* m_pick = nullptr;
    QPushButton* m_insertSelected = nullptr;
    QTableWidget* m_figures = nullptr;
    QLabel* m_figuresNote = nullptr;
    QPushButton* m_suggest = nullptr;
    QPushButton* m_apply = nullptr;
    QPushButton* m_discard = nullptr;
    QTreeWidget* m_tree = nullptr;
    QCheckBox* m_showFragments = nullptr;
    QLabel* m_treeNote = nullptr;
    QPushButton* m_fromPoint = nullptr;
    QPushButton* m_fromPatch = nullptr;
    QPushButton* m_play = nullptr;
    QPushButton* m_stop = nullptr;
    QSlider* m_slider = nullptr;
    QLabel* m_stepLabel = nullptr;
    bool m_rebuilding = false;
};

} // namespace regio::editor
