#include "editor/bsp/bsp_order_dock.h"

#include "editor/bsp/bsp_authoring.h"
#include "editor/bsp/painter_playback.h"
#include "editor/document/qt_conversions.h"
#include "editor/document/scene_document.h"

#include <QCheckBox>
#include <QComboBox>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QSlider>
#include <QTabWidget>
#include <QTableWidget>
#include <QTimer>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <algorithm>

namespace regio::editor {

namespace {

constexpr int kNodeRole = Qt::UserRole + 1;
// Deeper levels of a big tree open on demand; the first few show its shape.
constexpr int kExpandedLevels = 3;

} // namespace

BspOrderDock::BspOrderDock(BspAuthoring* authoring, SceneDocument* document, QWidget* parent)
    : QDockWidget(tr("BSP Order"), parent)
    , m_authoring(authoring)
    , m_document(document)
{
    setObjectName(QStringLiteral("BspOrderDock"));
    auto* body = new QWidget(this);
    auto* layout = new QVBoxLayout(body);
    layout->setContentsMargins(4, 4, 4, 4);

    auto* regionRow = new QHBoxLayout;
    regionRow->addWidget(new QLabel(tr("Region:"), body));
    m_regions = new QComboBox(body);
    m_regions->setToolTip(tr("The region whose BSP root order is edited (also chosen by selecting a region)"));
    regionRow->addWidget(m_regions, 1);
    layout->addLayout(regionRow);

    auto* tabs = new QTabWidget(body);
    layout->addWidget(tabs, 1);

    // --- Order tab ----------------------------------------------------------
    auto* orderPage = new QWidget(tabs);
    auto* orderLayout = new QVBoxLayout(orderPage);
    orderLayout->setContentsMargins(2, 2, 2, 2);
    m_list = new QListWidget(orderPage);
    m_list->setDragDropMode(QAbstractItemView::InternalMove);
    m_list->setDefaultDropAction(Qt::MoveAction);
    m_list->setSelectionMode(QAbstractItemView::SingleSelection);
    m_list->setToolTip(tr("Faces used as BSP roots, first = root of the region's tree; drag to reorder"));
    orderLayout->addWidget(m_list, 1);
    // Two rows of two: one row of four would make the whole right-hand
    // column of panels wide enough to crowd the viewport on a laptop.
    auto* buttons = new QGridLayout;
    m_top = new QPushButton(tr("Move to Top"), orderPage);
    m_remove = new QPushButton(tr("Remove"), orderPage);
    m_pick = new QPushButton(tr("Pick in Viewport"), orderPage);
    m_pick->setCheckable(true);
    m_pick->setToolTip(tr("Click faces in the viewport to add them at the end of the order; Esc ends"));
    m_insertSelected = new QPushButton(tr("Insert Selected"), orderPage);
    buttons->addWidget(m_top, 0, 0);
    buttons->addWidget(m_remove, 0, 1);
    buttons->addWidget(m_pick, 1, 0);
    buttons->addWidget(m_insertSelected, 1, 1);
    orderLayout->addLayout(buttons);

    m_figures = new QTableWidget(3, 5, orderPage);
    m_figures->setHorizontalHeaderLabels(
        {tr("Region"), tr("Scene"), tr("Single BSP"), tr("Suggested region"), tr("Suggested scene")});
    m_figures->setVerticalHeaderLabels({tr("Fragments"), tr("Splits"), tr("Depth")});
    m_figures->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_figures->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_figures->setSelectionMode(QAbstractItemView::NoSelection);
    m_figures->setToolTip(
        tr("Fragments after region clipping and BSP splits, polygons split, longest root-to-leaf path; "
           "Single BSP is the whole scene as one tree without regions"));
    m_figures->setMaximumHeight(m_figures->verticalHeader()->length() + m_figures->horizontalHeader()->height() + 6);
    orderLayout->addWidget(m_figures);
    m_figuresNote = new QLabel(orderPage);
    m_figuresNote->setWordWrap(true);
    orderLayout->addWidget(m_figuresNote);
    auto* suggestRow = new QHBoxLayout;
    m_suggest = new QPushButton(tr("Suggest Order"), orderPage);
    m_suggest->setToolTip(
        tr("Greedy low-split, balanced root order (Thibault and Naylor), shown before it is applied"));
    m_apply = new QPushButton(tr("Apply"), orderPage);
    m_discard = new QPushButton(tr("Discard"), orderPage);
    for (QPushButton* b : {m_suggest, m_apply, m_discard})
        suggestRow->addWidget(b);
    orderLayout->addLayout(suggestRow);
    tabs->addTab(orderPage, tr("Order"));

    // --- Tree tab -----------------------------------------------------------
    auto* treePage = new QWidget(tabs);
    auto* treeLayout = new QVBoxLayout(treePage);
    treeLayout->setContentsMargins(2, 2, 2, 2);
    m_showFragments = new QCheckBox(tr("Show fragments and split lines in the viewport"), treePage);
    treeLayout->addWidget(m_showFragments);
    m_tree = new QTreeWidget(treePage);
    m_tree->setColumnCount(2);
    m_tree->setHeaderLabels({tr("Root face"), tr("Fragments")});
    m_tree->header()->setSectionResizeMode(0, QHeaderView::Stretch);
    m_tree->header()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
    m_tree->header()->setStretchLastSection(false);
    m_tree->setToolTip(
        tr("The region's BSP tree: each node's plane is its root face's; select a node to see its plane"));
    treeLayout->addWidget(m_tree, 1);
    m_treeNote = new QLabel(treePage);
    m_treeNote->setWordWrap(true);
    treeLayout->addWidget(m_treeNote);
    tabs->addTab(treePage, tr("Tree"));

    // --- Playback tab ---------------------------------------------------------
    auto* playPage = new QWidget(tabs);
    auto* playLayout = new QVBoxLayout(playPage);
    playLayout->setContentsMargins(2, 2, 2, 2);
    auto* playExplain = new QLabel(tr("Pick a point or a patch: the elements are painted in the order the solver's "
                                      "hemicube paints them from there, back to front (blue first, red last; "
                                      "grey: seen from behind, painted as blockers)."),
                                   playPage);
    playExplain->setWordWrap(true);
    playLayout->addWidget(playExplain);
    auto* pickRow = new QHBoxLayout;
    m_fromPoint = new QPushButton(tr("From Point…"), playPage);
    m_fromPatch = new QPushButton(tr("From Patch…"), playPage);
    m_stop = new QPushButton(tr("Stop"), playPage);
    for (QPushButton* b : {m_fromPoint, m_fromPatch, m_stop})
        pickRow->addWidget(b);
    playLayout->addLayout(pickRow);
    auto* sliderRow = new QHBoxLayout;
    m_play = new QPushButton(tr("Play"), playPage);
    m_slider = new QSlider(Qt::Horizontal, playPage);
    m_slider->setToolTip(tr("Elements painted so far"));
    sliderRow->addWidget(m_play);
    sliderRow->addWidget(m_slider, 1);
    playLayout->addLayout(sliderRow);
    m_stepLabel = new QLabel(playPage);
    m_stepLabel->setWordWrap(true);
    playLayout->addWidget(m_stepLabel);
    playLayout->addStretch(1);
    tabs->addTab(playPage, tr("Painter Order"));

    setWidget(body);

    // --- wiring ----------------------------------------------------------------
    connect(m_regions, &QComboBox::currentIndexChanged, this, [this](int index) {
        if (!m_rebuilding && index >= 0)
            m_authoring->setCurrentRegion(toStd(m_regions->itemData(index).toString()));
    });
    connect(m_list->model(), &QAbstractItemModel::rowsMoved, this,
            [this](const QModelIndex&, int start, int, const QModelIndex&, int row) {
                if (m_rebuilding)
                    return;
                onRowsMoved(start, row > start ? row - 1 : row);
            });
    connect(m_list, &QListWidget::currentRowChanged, this, &BspOrderDock::updateButtons);
    connect(m_top, &QPushButton::clicked, this, [this] { m_authoring->moveToTop(m_list->currentRow()); });
    connect(m_remove, &QPushButton::clicked, this, [this] {
        const int row = m_list->currentRow();
        if (m_authoring->removeEntry(row))
            m_list->setCurrentRow(std::min(row, m_list->count() - 1));
    });
    connect(m_pick, &QPushButton::clicked, this, [this](bool on) {
        if (on)
            m_authoring->startInsertPick();
        else
            m_authoring->cancelTools();
    });
    connect(m_insertSelected, &QPushButton::clicked, m_authoring, &BspAuthoring::insertSelectedFaces);
    connect(m_suggest, &QPushButton::clicked, m_authoring, &BspAuthoring::suggestOrder);
    connect(m_apply, &QPushButton::clicked, m_authoring, &BspAuthoring::applySuggestion);
    connect(m_discard, &QPushButton::clicked, m_authoring, &BspAuthoring::discardSuggestion);
    connect(m_showFragments, &QCheckBox::toggled, m_authoring, &BspAuthoring::setShowFragments);
    connect(m_tree, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem* item) {
        if (!m_rebuilding)
            m_authoring->setHighlightedNode(item ? nodeOf(item) : -1);
    });
    PainterPlayback* playback = m_authoring->playback();
    connect(m_fromPoint, &QPushButton::clicked, this, [this] { m_authoring->startPlaybackPick(false); });
    connect(m_fromPatch, &QPushButton::clicked, this, [this] { m_authoring->startPlaybackPick(true); });
    connect(m_stop, &QPushButton::clicked, this, [this, playback] {
        m_authoring->cancelTools();
        playback->stop();
    });
    connect(m_play, &QPushButton::clicked, this, [playback] {
        if (playback->playing())
            playback->pause();
        else
            playback->play();
    });
    connect(m_slider, &QSlider::valueChanged, this, [this, playback](int value) {
        if (!m_rebuilding)
            playback->setStep(value);
    });
    connect(playback, &PainterPlayback::changed, this, &BspOrderDock::updatePlayback);

    connect(m_document, &SceneDocument::regionsChanged, this, [this] {
        rebuildRegions();
        rebuildList();
    });
    connect(m_document, &SceneDocument::sceneReset, this, [this] {
        rebuildRegions();
        rebuildList();
    });
    connect(m_document, &SceneDocument::objectsChanged, this, &BspOrderDock::rebuildList);
    connect(m_document, &SceneDocument::selectionChanged, this, &BspOrderDock::updateButtons);
    connect(m_authoring, &BspAuthoring::currentRegionChanged, this, [this] {
        rebuildRegions();
        rebuildList();
        rebuildFigures();
        rebuildTree();
    });
    connect(m_authoring, &BspAuthoring::suggestionChanged, this, [this] {
        rebuildFigures();
        updateButtons();
    });
    connect(m_authoring, &BspAuthoring::viewsChanged, this, &BspOrderDock::updateButtons);
    connect(m_authoring->analyser(), &BspAnalyser::analysed, this, [this] {
        rebuildFigures();
        rebuildTree();
    });
    connect(m_authoring->analyser(), &BspAnalyser::becameStale, this, &BspOrderDock::rebuildFigures);

    rebuildRegions();
    rebuildList();
    rebuildFigures();
    rebuildTree();
    updatePlayback();
}

int BspOrderDock::nodeOf(const QTreeWidgetItem* item) { return item ? item->data(0, kNodeRole).toInt() : -1; }

int BspOrderDock::figure(FigureRow row, FigureColumn column) const
{
    const QTableWidgetItem* item = m_figures->item(row, column);
    if (!item || item->text().isEmpty())
        return -1;
    bool ok = false;
    const int value = item->data(Qt::UserRole).toInt(&ok);
    return ok ? value : -1;
}

void BspOrderDock::rebuildRegions()
{
    m_rebuilding = true;
    m_regions->clear();
    for (const model::Region& region : m_document->scene().regions) {
        const QString label = region.name.empty() ? toQString(region.id)
                                                  : tr("%1 (%2)").arg(toQString(region.name), toQString(region.id));
        m_regions->addItem(label, toQString(region.id));
    }
    m_regions->setCurrentIndex(m_regions->findData(toQString(m_authoring->currentRegion())));
    m_regions->setEnabled(m_regions->count() > 0);
    m_rebuilding = false;
}

void BspOrderDock::rebuildList()
{
    m_rebuilding = true;
    const int row = m_list->currentRow();
    m_list->clear();
    const model::Scene& scene = m_document->scene();
    for (const std::string& face : m_authoring->currentOrder()) {
        auto* item = new QListWidgetItem(toQString(face), m_list);
        item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsDragEnabled);
        if (!scene.locateFace(face).valid())
            item->setForeground(Qt::red);
    }
    m_list->setCurrentRow(std::min(row, m_list->count() - 1));
    m_rebuilding = false;
    updateButtons();
}

void BspOrderDock::onRowsMoved(int from, int to)
{
    // The edit rebuilds the list; the drop that moved the row is still on
    // the stack, so the command runs when the event loop is back.
    QTimer::singleShot(0, this, [this, from, to] {
        if (!m_authoring->moveEntry(from, to))
            rebuildList();
        else
            m_list->setCurrentRow(to);
    });
}

void BspOrderDock::setCell(int row, int column, int value, bool better)
{
    auto* item = new QTableWidgetItem(value < 0 ? QString() : QString::number(value));
    item->setData(Qt::UserRole, value);
    item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
    if (better) {
        QFont font = item->font();
        font.setBold(true);
        item->setFont(font);
    }
    m_figures->setItem(row, column, item);
}

void BspOrderDock::rebuildFigures()
{
    const BspAnalysis& analysis = m_authoring->analyser()->current();
    const solver::RegionBspFigures* region = analysis.region(m_authoring->currentRegion());
    const auto& suggestion = m_authoring->suggestion();
    for (int row = 0; row < 3; ++row)
        for (int column = 0; column < 5; ++column)
            setCell(row, column, -1);
    if (region) {
        setCell(FragmentsRow, RegionColumn, region->figures.fragments);
        setCell(SplitsRow, RegionColumn, region->figures.splits);
        setCell(DepthRow, RegionColumn, region->figures.depth);
    }
    if (analysis.authored) {
        setCell(FragmentsRow, SceneColumn, analysis.authored->fragments);
        setCell(SplitsRow, SceneColumn, analysis.authored->splits);
        setCell(DepthRow, SceneColumn, analysis.authored->maxDepth);
    }
    if (analysis.baseline) {
        setCell(FragmentsRow, BaselineColumn, analysis.baseline->fragments);
        setCell(SplitsRow, BaselineColumn, analysis.baseline->splits);
        setCell(DepthRow, BaselineColumn, analysis.baseline->maxDepth);
    }
    if (suggestion && suggestion->regionId == m_authoring->currentRegion()) {
        const solver::BspFigures& s = suggestion->suggested;
        const solver::BspFigures& c = suggestion->current;
        setCell(FragmentsRow, SuggestedRegionColumn, s.fragments, s.fragments < c.fragments);
        setCell(SplitsRow, SuggestedRegionColumn, s.splits, s.splits < c.splits);
        setCell(DepthRow, SuggestedRegionColumn, s.depth, s.depth < c.depth);
        if (analysis.authored && !m_authoring->analyser()->stale()) {
            // Scene totals are sums over regions (depth the deepest), so
            // swapping this region's tree gives them exactly.
            int depth = s.depth;
            for (const solver::RegionBspFigures& r : analysis.authored->regions)
                if (r.id != suggestion->regionId)
                    depth = std::max(depth, r.figures.depth);
            setCell(FragmentsRow, SuggestedSceneColumn, analysis.authored->fragments - c.fragments + s.fragments,
                    s.fragments < c.fragments);
            setCell(SplitsRow, SuggestedSceneColumn, analysis.authored->splits - c.splits + s.splits,
                    s.splits < c.splits);
            setCell(DepthRow, SuggestedSceneColumn, depth, depth < analysis.authored->maxDepth);
        }
    }
    const bool hasSuggestion = suggestion.has_value();
    m_figures->setColumnHidden(SuggestedRegionColumn, !hasSuggestion);
    m_figures->setColumnHidden(SuggestedSceneColumn, !hasSuggestion);

    QString note;
    if (m_authoring->analyser()->stale())
        note = tr("Updating…");
    else if (!analysis.authored) {
        for (const model::Diagnostic& d : analysis.diagnostics)
            if (d.severity == model::Severity::Error) {
                note = tr("The scene cannot be prepared: %1").arg(toQString(d.message));
                break;
            }
    } else {
        note = tr("Computed by the solver's preparation in %1 ms").arg(QString::number(analysis.milliseconds, 'f', 0));
    }
    if (hasSuggestion)
        note += QLatin1Char('\n') +
                tr("Suggested order: %n root face(s). Apply replaces the region's order (one undo step).", nullptr,
                   int(suggestion->order.size()));
    m_figuresNote->setText(note);
}

void BspOrderDock::rebuildTree()
{
    m_rebuilding = true;
    m_tree->clear();
    const BspAnalysis& analysis = m_authoring->analyser()->current();
    int region = analysis.preparedRegion(m_authoring->currentRegion());
    if (region < 0 && analysis.prepared && m_document->scene().regions.empty() && !analysis.prepared->regions.empty())
        region = 0; // no regions: the scene's single tree
    if (region < 0 || !analysis.prepared) {
        m_treeNote->setText(analysis.prepared ? tr("No tree for this region") : QString());
        m_rebuilding = false;
        return;
    }
    const solver::PreparedScene& prepared = *analysis.prepared;
    const auto label = [&](int node) {
        const solver::BspNode& n = prepared.nodes[size_t(node)];
        const solver::Fragment& first = prepared.fragments[size_t(n.firstFragment)];
        return toQString(prepared.faces[size_t(prepared.properties[size_t(first.properties)].face)].id);
    };
    // Iterative, so a degenerate deep tree cannot overflow the stack.
    struct Pending {
        int node;
        QTreeWidgetItem* parent;
        QString side;
        int level;
    };
    std::vector<Pending> stack{{prepared.regions[size_t(region)].bspRoot, nullptr, QString(), 0}};
    while (!stack.empty()) {
        const Pending p = stack.back();
        stack.pop_back();
        if (p.node < 0)
            continue;
        const solver::BspNode& n = prepared.nodes[size_t(p.node)];
        auto* item = p.parent ? new QTreeWidgetItem(p.parent) : new QTreeWidgetItem(m_tree);
        item->setText(0, p.side.isEmpty() ? label(p.node) : tr("%1: %2").arg(p.side, label(p.node)));
        item->setText(1, QString::number(n.fragmentCount));
        item->setData(0, kNodeRole, p.node);
        item->setExpanded(p.level < kExpandedLevels);
        // Pushed back first, so front comes out first: front above back.
        stack.push_back({n.back, item, tr("back"), p.level + 1});
        stack.push_back({n.front, item, tr("front"), p.level + 1});
    }
    const solver::RegionStats& stats = prepared.regions[size_t(region)].stats;
    m_treeNote->setText(tr("%1 nodes, depth %2, %3 fragments from %4 polygons")
                            .arg(stats.nodes)
                            .arg(stats.depth)
                            .arg(stats.fragments)
                            .arg(stats.inputFaces));
    m_rebuilding = false;
}

void BspOrderDock::updateButtons()
{
    const bool region = !m_authoring->currentRegion().empty();
    const int row = m_list->currentRow();
    m_top->setEnabled(region && row > 0);
    m_remove->setEnabled(region && row >= 0);
    m_pick->setEnabled(region);
    m_pick->setChecked(m_authoring->insertPickActive());
    m_insertSelected->setEnabled(region && !m_document->selection().empty());
    m_suggest->setEnabled(region);
    m_apply->setEnabled(m_authoring->suggestion().has_value());
    m_discard->setEnabled(m_authoring->suggestion().has_value());
    m_showFragments->setChecked(m_authoring->fragmentsShown());
}

void BspOrderDock::updatePlayback()
{
    PainterPlayback* playback = m_authoring->playback();
    m_rebuilding = true;
    m_slider->setRange(0, playback->stepCount());
    m_slider->setValue(playback->step());
    m_rebuilding = false;
    m_slider->setEnabled(playback->active());
    m_play->setEnabled(playback->active());
    m_play->setText(playback->playing() ? tr("Pause") : tr("Play"));
    m_stop->setEnabled(playback->active());
    const solver::PainterOrder* order = playback->order();
    if (!order) {
        m_stepLabel->setText(tr("No playback"));
        return;
    }
    QString text = playback->patch() >= 0 ? tr("From patch %1").arg(playback->patch())
                                          : tr("From point (%1, %2, %3)")
                                                .arg(playback->eye().x, 0, 'f', 3)
                                                .arg(playback->eye().y, 0, 'f', 3)
                                                .arg(playback->eye().z, 0, 'f', 3);
    text += QLatin1Char('\n') + tr("%1 regions walked, %2 culled, %3 nodes, %4 elements")
                                    .arg(order->regions.size())
                                    .arg(order->culledRegions.size())
                                    .arg(order->nodes.size())
                                    .arg(order->steps.size());
    const int step = playback->step();
    if (step > 0) {
        const solver::PaintStep& last = order->steps[size_t(step - 1)];
        text += QLatin1Char('\n') + (last.receives ? tr("Step %1: element %2 of node %3, receiving")
                                                   : tr("Step %1: element %2 of node %3, blocking (seen from behind)"))
                                        .arg(step)
                                        .arg(last.element)
                                        .arg(last.node);
    }
    m_stepLabel->setText(text);
}

} // namespace regio::editor
