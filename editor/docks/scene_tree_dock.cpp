#include "editor/docks/scene_tree_dock.h"

#include "editor/docks/scene_tree_model.h"
#include "editor/document/qt_conversions.h"
#include "editor/document/scene_document.h"
#include "editor/objects/authoring.h"

#include <QHeaderView>
#include <QItemSelectionModel>
#include <QLineEdit>
#include <QMenu>
#include <QSet>
#include <QSortFilterProxyModel>
#include <QTreeView>
#include <QVBoxLayout>

namespace regio::editor {

SceneTreeDock::SceneTreeDock(SceneDocument* document, Authoring* authoring, QWidget* parent)
    : QDockWidget(tr("Scene"), parent)
    , m_document(document)
    , m_authoring(authoring)
    , m_model(new SceneTreeModel(this))
    , m_proxy(new QSortFilterProxyModel(this))
{
    setObjectName(QStringLiteral("SceneTreeDock"));
    auto* body = new QWidget(this);
    auto* layout = new QVBoxLayout(body);
    layout->setContentsMargins(2, 2, 2, 2);
    m_filter = new QLineEdit(body);
    m_filter->setPlaceholderText(tr("Filter by id or name"));
    m_filter->setClearButtonEnabled(true);
    layout->addWidget(m_filter);

    m_proxy->setSourceModel(m_model);
    m_proxy->setRecursiveFilteringEnabled(true);
    m_proxy->setFilterCaseSensitivity(Qt::CaseInsensitive);
    m_proxy->setFilterKeyColumn(-1);
    connect(m_filter, &QLineEdit::textChanged, m_proxy, &QSortFilterProxyModel::setFilterFixedString);

    m_view = new QTreeView(body);
    m_view->setModel(m_proxy);
    m_view->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_view->setDragEnabled(true);
    m_view->setAcceptDrops(true);
    m_view->setDropIndicatorShown(true);
    m_view->setDragDropMode(QAbstractItemView::DragDrop);
    m_view->setDefaultDropAction(Qt::MoveAction);
    m_view->setUniformRowHeights(true);
    m_view->setContextMenuPolicy(Qt::CustomContextMenu);
    m_view->header()->setSectionResizeMode(QHeaderView::Interactive);
    m_view->header()->resizeSection(SceneTreeModel::IdColumn, 150);
    m_view->header()->resizeSection(SceneTreeModel::NameColumn, 90);
    layout->addWidget(m_view);
    setWidget(body);

    m_model->setMovePartsHandler([this](const std::vector<std::string>& parts, const std::string& target) {
        m_authoring->moveParts(parts, target);
    });
    m_model->setScene(&document->scene());

    connect(document, &SceneDocument::objectsChanged, this, &SceneTreeDock::rebuild);
    connect(document, &SceneDocument::materialsChanged, this, [this] {
        // Swatches only: repaint, no rebuild (keeps expansion and scroll).
        m_view->viewport()->update();
    });
    connect(document, &SceneDocument::selectionChanged, this, &SceneTreeDock::documentSelectionChanged);
    connect(m_view->selectionModel(), &QItemSelectionModel::selectionChanged, this,
            &SceneTreeDock::viewSelectionChanged);
    connect(m_view, &QTreeView::doubleClicked, this, &SceneTreeDock::frameRequested);
    connect(m_view, &QTreeView::customContextMenuRequested, this, &SceneTreeDock::showContextMenu);
}

void SceneTreeDock::rebuild()
{
    // Keep what the user had open across the rebuild, by id.
    QSet<QString> expanded;
    for (int r = 0; r < m_proxy->rowCount(); ++r) {
        const QModelIndex object = m_proxy->index(r, 0);
        if (m_view->isExpanded(object))
            expanded << object.data(SceneTreeModel::ElementIdRole).toString();
        for (int p = 0; p < m_proxy->rowCount(object); ++p) {
            const QModelIndex part = m_proxy->index(p, 0, object);
            if (m_view->isExpanded(part))
                expanded << part.data(SceneTreeModel::ElementIdRole).toString();
        }
    }
    m_syncing = true;
    m_model->rebuild();
    for (int r = 0; r < m_proxy->rowCount(); ++r) {
        const QModelIndex object = m_proxy->index(r, 0);
        if (expanded.contains(object.data(SceneTreeModel::ElementIdRole).toString()))
            m_view->expand(object);
        for (int p = 0; p < m_proxy->rowCount(object); ++p) {
            const QModelIndex part = m_proxy->index(p, 0, object);
            if (expanded.contains(part.data(SceneTreeModel::ElementIdRole).toString()))
                m_view->expand(part);
        }
    }
    m_syncing = false;
    documentSelectionChanged();
}

void SceneTreeDock::documentSelectionChanged()
{
    if (m_syncing)
        return;
    m_syncing = true;
    const Selection& selection = m_document->selection();
    QItemSelection items;
    QModelIndex first;
    for (const std::string& id : selection.ids) {
        const QModelIndex source = m_model->indexOf(selection.kind, id);
        const QModelIndex index = m_proxy->mapFromSource(source);
        if (!index.isValid())
            continue;
        if (!first.isValid())
            first = index;
        items.select(index, index.siblingAtColumn(SceneTreeModel::ColumnCount - 1));
        for (QModelIndex p = index.parent(); p.isValid(); p = p.parent())
            m_view->expand(p);
    }
    m_view->selectionModel()->select(items, QItemSelectionModel::ClearAndSelect);
    if (first.isValid()) {
        m_view->selectionModel()->setCurrentIndex(first, QItemSelectionModel::NoUpdate);
        m_view->scrollTo(first);
    }
    m_syncing = false;
}

void SceneTreeDock::viewSelectionChanged()
{
    if (m_syncing)
        return;
    // One kind at a time: the kind of the current row wins.
    const QModelIndex current = m_proxy->mapToSource(m_view->selectionModel()->currentIndex());
    SelectionKind kind = m_model->kindAt(current);
    std::vector<std::string> ids;
    const QModelIndexList rows = m_view->selectionModel()->selectedRows();
    for (const QModelIndex& row : rows) {
        const QModelIndex source = m_proxy->mapToSource(row);
        if (kind == SelectionKind::None)
            kind = m_model->kindAt(source);
        if (m_model->kindAt(source) == kind)
            ids.push_back(m_model->idAt(source));
    }
    m_syncing = true;
    m_document->setSelection(Selection::of(kind, std::move(ids)));
    m_syncing = false;
}

void SceneTreeDock::showContextMenu(const QPoint& pos)
{
    QMenu menu(this);
    m_authoring->populateContextMenu(&menu);
    if (!menu.isEmpty())
        menu.exec(m_view->viewport()->mapToGlobal(pos));
}

} // namespace regio::editor
