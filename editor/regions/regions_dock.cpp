#include "editor/regions/regions_dock.h"

#include "editor/document/commands/region_commands.h"
#include "editor/document/qt_conversions.h"
#include "editor/document/scene_document.h"
#include "editor/regions/region_figures.h"
#include "editor/regions/region_layers.h"

#include <QAction>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTabWidget>
#include <QToolBar>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace regio::editor {

namespace {

constexpr int kIdRole = Qt::UserRole;       // region id (list rows, tree leaves)
constexpr int kNodeRole = Qt::UserRole + 1; // regional tree node index

QColor swatch(int index)
{
    const glm::vec4 c = regionColour(index);
    return QColor::fromRgbF(c.r, c.g, c.b);
}

QString axisName(int axis) { return QStringLiteral("xyz").mid(axis, 1); }

} // namespace

RegionsDock::RegionsDock(SceneDocument* document, RegionFiguresWatcher* figures, const QList<QAction*>& actions,
                         QWidget* parent)
    : QDockWidget(tr("Regions"), parent)
    , m_document(document)
    , m_figures(figures)
{
    setObjectName(QStringLiteral("RegionsDock"));
    auto* body = new QWidget(this);
    auto* layout = new QVBoxLayout(body);
    layout->setContentsMargins(2, 2, 2, 2);

    auto* toolBar = new QToolBar(body);
    toolBar->setToolButtonStyle(Qt::ToolButtonTextOnly);
    toolBar->addActions(actions);
    layout->addWidget(toolBar);

    m_tabs = new QTabWidget(body);
    m_list = new QTreeWidget(m_tabs);
    m_list->setColumnCount(ColumnCount);
    m_list->setHeaderLabels({tr("Region"), tr("Name"), tr("Parts"), tr("Faces"), tr("Fragments")});
    m_list->setRootIsDecorated(false);
    m_list->setUniformRowHeights(true);
    m_list->setAlternatingRowColors(true);
    m_list->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_list->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed);
    m_list->header()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_list->setContextMenuPolicy(Qt::ActionsContextMenu);
    m_list->addActions(actions);
    m_list->headerItem()->setToolTip(FragmentsColumn,
                                     tr("Polygons in the region's BSP tree after clipping and splitting, "
                                        "as the solver builds it (fewer is better)"));
    m_tabs->addTab(m_list, tr("Regions"));

    m_tree = new QTreeWidget(m_tabs);
    m_tree->setColumnCount(2);
    m_tree->setHeaderLabels({tr("Node"), tr("Side")});
    m_tree->header()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_tabs->addTab(m_tree, tr("Regional Tree"));
    layout->addWidget(m_tabs);

    m_summary = new QLabel(body);
    m_summary->setWordWrap(true);
    layout->addWidget(m_summary);

    m_proposalPanel = new QWidget(body);
    auto* proposalLayout = new QVBoxLayout(m_proposalPanel);
    proposalLayout->setContentsMargins(0, 4, 0, 0);
    m_proposalText = new QLabel(m_proposalPanel);
    m_proposalText->setWordWrap(true);
    proposalLayout->addWidget(m_proposalText);
    auto* buttons = new QHBoxLayout;
    m_accept = new QPushButton(tr("Accept"), m_proposalPanel);
    m_discard = new QPushButton(tr("Discard"), m_proposalPanel);
    buttons->addStretch();
    buttons->addWidget(m_accept);
    buttons->addWidget(m_discard);
    proposalLayout->addLayout(buttons);
    m_proposalPanel->hide();
    layout->addWidget(m_proposalPanel);
    setWidget(body);

    m_refresh.setSingleShot(true);
    m_refresh.setInterval(60);
    connect(&m_refresh, &QTimer::timeout, this, &RegionsDock::refreshNow);
    auto later = [this] { m_refresh.start(); };
    connect(document, &SceneDocument::regionsChanged, this, &RegionsDock::refreshNow);
    connect(document, &SceneDocument::sceneReset, this, &RegionsDock::refreshNow);
    connect(document, &SceneDocument::objectsChanged, this, later);
    connect(document, &SceneDocument::geometryChanged, this, later);
    connect(document, &SceneDocument::selectionChanged, this, &RegionsDock::syncSelectionFromDocument);
    connect(figures, &RegionFiguresWatcher::figuresChanged, this, &RegionsDock::updateFigures);
    connect(figures, &RegionFiguresWatcher::staleChanged, this, &RegionsDock::updateFigures);
    connect(m_list, &QTreeWidget::itemSelectionChanged, this, &RegionsDock::onListSelectionChanged);
    connect(m_list, &QTreeWidget::itemChanged, this, &RegionsDock::onItemChanged);
    connect(m_tree, &QTreeWidget::itemSelectionChanged, this, &RegionsDock::onTreeSelectionChanged);
    refreshNow();
}

void RegionsDock::refreshNow()
{
    m_refresh.stop();
    rebuildList();
    rebuildTree();
}

QTreeWidgetItem* RegionsDock::rowOf(const std::string& regionId) const
{
    const QString id = toQString(regionId);
    for (int i = 0; i < m_list->topLevelItemCount(); ++i)
        if (m_list->topLevelItem(i)->data(IdColumn, kIdRole).toString() == id)
            return m_list->topLevelItem(i);
    return nullptr;
}

QString RegionsDock::cellText(const std::string& regionId, Column column) const
{
    const QTreeWidgetItem* item = rowOf(regionId);
    return item ? item->text(column) : QString();
}

void RegionsDock::rebuildList()
{
    const model::Scene& scene = m_document->scene();
    const std::vector<RegionContents> contents = regionContents(scene);
    m_updating = true;
    m_list->clear();
    for (size_t r = 0; r < scene.regions.size(); ++r) {
        const model::Region& region = scene.regions[r];
        auto* item = new QTreeWidgetItem(m_list);
        item->setFlags(item->flags() | Qt::ItemIsEditable);
        item->setData(IdColumn, kIdRole, toQString(region.id));
        item->setText(IdColumn, toQString(region.id));
        item->setData(IdColumn, Qt::DecorationRole, swatch(int(r)));
        item->setText(NameColumn, toQString(region.name));
        item->setText(PartsColumn, QString::number(contents[r].parts));
        item->setText(FacesColumn, QString::number(contents[r].faces));
        for (int c : {PartsColumn, FacesColumn, FragmentsColumn})
            item->setTextAlignment(c, Qt::AlignRight | Qt::AlignVCenter);
        item->setToolTip(IdColumn, tr("min %1, max %2").arg(formatVector(region.min), formatVector(region.max)));
        // Overlaps are errors the solver refuses; flag them where the boxes are listed too.
        const model::Box3 box = boxOf(region);
        QStringList overlapping;
        for (size_t other = 0; other < scene.regions.size(); ++other)
            if (other != r && box.overlapsInterior(boxOf(scene.regions[other])))
                overlapping << toQString(scene.regions[other].id);
        if (!overlapping.isEmpty()) {
            for (int c = 0; c < ColumnCount; ++c) {
                item->setForeground(c, QColor(200, 40, 40));
                item->setToolTip(c, tr("Overlaps %1: regions must not share volume").arg(overlapping.join(", ")));
            }
        }
    }
    m_updating = false;
    updateFigures();
    syncSelectionFromDocument();
}

void RegionsDock::updateFigures()
{
    const std::optional<solver::BspComparison>& comparison = m_figures->comparison();
    const bool stale = m_figures->stale();
    m_updating = true;
    for (int i = 0; i < m_list->topLevelItemCount(); ++i) {
        QTreeWidgetItem* item = m_list->topLevelItem(i);
        QString text;
        if (comparison && comparison->authored) {
            const int index = comparison->authored->regionIndex(toStd(item->data(IdColumn, kIdRole).toString()));
            if (index >= 0)
                text = QString::number(comparison->authored->regions[size_t(index)].figures.fragments);
        }
        item->setText(FragmentsColumn, text);
        item->setForeground(FragmentsColumn, stale ? palette().color(QPalette::Disabled, QPalette::Text)
                                                   : palette().color(QPalette::Text));
    }
    m_updating = false;

    QString summary;
    if (!comparison) {
        summary = tr("Computing BSP figures…");
    } else if (!comparison->authored) {
        summary = tr("No BSP figures: the solver cannot prepare this scene (see Diagnostics).");
    } else {
        const solver::SceneBspFigures& a = *comparison->authored;
        summary = m_document->scene().regions.empty()
                      ? tr("No regions: one BSP tree, %1 fragments, %2 splits, depth %3.")
                            .arg(a.fragments)
                            .arg(a.splits)
                            .arg(a.maxDepth)
                      : tr("%1 regions: %2 fragments, %3 splits, depth %4.")
                            .arg(a.regions.size())
                            .arg(a.fragments)
                            .arg(a.splits)
                            .arg(a.maxDepth);
        if (comparison->baseline && !m_document->scene().regions.empty())
            summary += QLatin1Char(' ') + tr("Single BSP: %1 fragments, %2 splits, depth %3.")
                                              .arg(comparison->baseline->fragments)
                                              .arg(comparison->baseline->splits)
                                              .arg(comparison->baseline->maxDepth);
    }
    if (stale && comparison)
        summary += QLatin1Char(' ') + tr("(updating…)");
    m_summary->setText(summary);
}

void RegionsDock::rebuildTree()
{
    const model::Scene& scene = m_document->scene();
    const RegionalTreeView view = regionalTreeOf(scene);
    m_updating = true;
    m_tree->clear();
    if (!view.ok) {
        auto* item = new QTreeWidgetItem(m_tree);
        item->setText(0, scene.regions.empty()
                             ? tr("No regions: the whole scene is one BSP tree")
                             : tr("No regional tree: the region boxes overlap or cannot be separated"));
        item->setFlags(Qt::ItemIsEnabled);
        m_updating = false;
        return;
    }
    // Depth first from the root; back before front, as the planes order space.
    struct Pending {
        int node;
        QTreeWidgetItem* parent;
        QString side;
    };
    std::vector<Pending> stack{{view.tree.root, nullptr, QString()}};
    while (!stack.empty()) {
        const Pending p = stack.back();
        stack.pop_back();
        const solver::RegionalNode& node = view.tree.nodes[size_t(p.node)];
        auto* item = p.parent ? new QTreeWidgetItem(p.parent) : new QTreeWidgetItem(m_tree);
        item->setText(1, p.side);
        item->setData(0, kNodeRole, p.node);
        if (node.isLeaf()) {
            const model::Region& region = scene.regions[size_t(node.region)];
            item->setText(0, region.name.empty() ? toQString(region.id)
                                                 : tr("%1 (%2)").arg(toQString(region.id), toQString(region.name)));
            item->setData(0, kIdRole, toQString(region.id));
            item->setData(0, Qt::DecorationRole, swatch(node.region));
            continue;
        }
        const QString axis = axisName(node.axis), at = formatNumber(node.position, 4);
        item->setText(0, tr("%1 = %2").arg(axis, at));
        item->setExpanded(true);
        if (node.front >= 0)
            stack.push_back({node.front, item, tr("front (%1 ≥ %2)").arg(axis, at)});
        if (node.back >= 0)
            stack.push_back({node.back, item, tr("back (%1 ≤ %2)").arg(axis, at)});
    }
    m_tree->expandAll();
    m_updating = false;
}

void RegionsDock::syncSelectionFromDocument()
{
    const Selection& s = m_document->selection();
    m_updating = true;
    for (int i = 0; i < m_list->topLevelItemCount(); ++i) {
        QTreeWidgetItem* item = m_list->topLevelItem(i);
        item->setSelected(s.kind == SelectionKind::Region &&
                          s.contains(toStd(item->data(IdColumn, kIdRole).toString())));
    }
    m_updating = false;
}

void RegionsDock::onListSelectionChanged()
{
    if (m_updating)
        return;
    std::vector<std::string> ids;
    for (QTreeWidgetItem* item : m_list->selectedItems())
        ids.push_back(toStd(item->data(IdColumn, kIdRole).toString()));
    if (ids.empty()) {
        if (m_document->selection().kind == SelectionKind::Region)
            m_document->clearSelection();
        return;
    }
    m_document->setSelection(Selection::of(SelectionKind::Region, std::move(ids)));
}

void RegionsDock::onItemChanged(QTreeWidgetItem* item, int column)
{
    if (m_updating)
        return;
    const std::string id = toStd(item->data(IdColumn, kIdRole).toString());
    const std::string text = toStd(item->text(column).trimmed());
    // Pushed from the event loop: the command rebuilds this list, which must
    // not happen while the view is still inside the edit of one of its items.
    QTimer::singleShot(0, this, [this, id, text, column] {
        const model::Region* region = m_document->scene().findRegion(id);
        bool changed = false;
        if (region && column == IdColumn && text != id && !text.empty()) {
            changed = m_document->push(new RenameRegion(m_document, id, text));
            if (changed)
                m_document->setSelection(Selection::single(SelectionKind::Region, text));
        } else if (region && column == NameColumn && text != region->name) {
            changed = m_document->push(new SetRegionName(m_document, id, text));
        }
        if (!changed) // refused or nothing to do: show the scene's values again
            refreshNow();
    });
}

void RegionsDock::onTreeSelectionChanged()
{
    if (m_updating)
        return;
    const QList<QTreeWidgetItem*> items = m_tree->selectedItems();
    if (items.isEmpty()) {
        emit separatingPlaneSelected(-1);
        return;
    }
    QTreeWidgetItem* item = items.front();
    const QString regionId = item->data(0, kIdRole).toString();
    if (!regionId.isEmpty()) {
        emit separatingPlaneSelected(-1);
        m_document->setSelection(Selection::single(SelectionKind::Region, toStd(regionId)));
        return;
    }
    emit separatingPlaneSelected(item->data(0, kNodeRole).toInt());
}

void RegionsDock::showProposal(const QString& text, QAction* accept, QAction* discard)
{
    m_proposalText->setText(text);
    disconnect(m_accept, &QPushButton::clicked, nullptr, nullptr);
    disconnect(m_discard, &QPushButton::clicked, nullptr, nullptr);
    connect(m_accept, &QPushButton::clicked, accept, &QAction::trigger);
    connect(m_discard, &QPushButton::clicked, discard, &QAction::trigger);
    m_proposalPanel->show();
}

void RegionsDock::hideProposal() { m_proposalPanel->hide(); }

bool RegionsDock::proposalVisible() const { return !m_proposalPanel->isHidden(); }

} // namespace regio::editor
