#include "editor/docks/scene_tree_model.h"

#include "editor/document/qt_conversions.h"

#include <QApplication>
#include <QIcon>
#include <QMimeData>
#include <QPainter>
#include <QPixmap>
#include <QStyle>

namespace regio::editor {

const QString SceneTreeModel::kPartsMimeType = QStringLiteral("application/x-regio-part-ids");

namespace {

std::string nodeKey(SelectionKind kind, const std::string& id) { return std::to_string(int(kind)) + ':' + id; }

QIcon swatch(const model::Material* material)
{
    QPixmap pixmap(14, 14);
    pixmap.fill(Qt::transparent);
    QPainter painter(&pixmap);
    painter.setPen(QColor(40, 40, 40));
    if (!material) {
        painter.setBrush(Qt::magenta);
    } else if (material->emission.r + material->emission.g + material->emission.b > 0.0) {
        painter.setBrush(emissionDisplayColor(material->emission));
        painter.drawRect(0, 0, 13, 13);
        painter.setPen(QColor(255, 220, 60));
        painter.drawLine(3, 7, 10, 7); // a light mark on emitters
        painter.drawLine(7, 3, 7, 10);
        return QIcon(pixmap);
    } else {
        painter.setBrush(linearToColor(material->reflectance));
    }
    painter.drawRect(0, 0, 13, 13);
    return QIcon(pixmap);
}

} // namespace

SceneTreeModel::SceneTreeModel(QObject* parent)
    : QAbstractItemModel(parent)
{
}

void SceneTreeModel::setScene(const model::Scene* scene)
{
    m_scene = scene;
    rebuild();
}

void SceneTreeModel::rebuild()
{
    beginResetModel();
    m_nodes.clear();
    m_roots.clear();
    m_nodeById.clear();
    if (m_scene) {
        for (int o = 0; o < int(m_scene->objects.size()); ++o) {
            const int objectNode = int(m_nodes.size());
            m_nodes.push_back({SelectionKind::Object, o, -1, -1, -1, int(m_roots.size()), {}});
            m_roots.push_back(objectNode);
            const auto& parts = m_scene->objects[size_t(o)].parts;
            for (int p = 0; p < int(parts.size()); ++p) {
                const int partNode = int(m_nodes.size());
                m_nodes.push_back(
                    {SelectionKind::Part, o, p, -1, objectNode, int(m_nodes[size_t(objectNode)].children.size()), {}});
                m_nodes[size_t(objectNode)].children.push_back(partNode);
                for (int f = 0; f < int(parts[size_t(p)].faces.size()); ++f) {
                    const int faceNode = int(m_nodes.size());
                    m_nodes.push_back({SelectionKind::Face, o, p, f, partNode, f, {}});
                    m_nodes[size_t(partNode)].children.push_back(faceNode);
                }
            }
        }
        for (int n = 0; n < int(m_nodes.size()); ++n)
            m_nodeById.emplace(
                nodeKey(m_nodes[size_t(n)].kind, idAt(createIndex(m_nodes[size_t(n)].row, 0, quintptr(n)))), n);
    }
    endResetModel();
}

const SceneTreeModel::Node* SceneTreeModel::nodeAt(const QModelIndex& index) const
{
    if (!index.isValid())
        return nullptr;
    const quintptr n = index.internalId();
    return n < m_nodes.size() ? &m_nodes[n] : nullptr;
}

QModelIndex SceneTreeModel::indexOfNode(int node, int column) const
{
    if (node < 0)
        return {};
    return createIndex(m_nodes[size_t(node)].row, column, quintptr(node));
}

QModelIndex SceneTreeModel::indexOf(SelectionKind kind, const std::string& id) const
{
    auto it = m_nodeById.find(nodeKey(kind, id));
    return it == m_nodeById.end() ? QModelIndex() : indexOfNode(it->second);
}

SelectionKind SceneTreeModel::kindAt(const QModelIndex& index) const
{
    const Node* node = nodeAt(index);
    return node ? node->kind : SelectionKind::None;
}

std::string SceneTreeModel::idAt(const QModelIndex& index) const
{
    const Node* node = nodeAt(index);
    if (!node || !m_scene)
        return {};
    const model::Object& object = m_scene->objects[size_t(node->object)];
    if (node->kind == SelectionKind::Object)
        return object.id;
    const model::Part& part = object.parts[size_t(node->part)];
    if (node->kind == SelectionKind::Part)
        return part.id;
    return part.faces[size_t(node->face)].id;
}

QModelIndex SceneTreeModel::index(int row, int column, const QModelIndex& parent) const
{
    if (column < 0 || column >= ColumnCount || row < 0)
        return {};
    const std::vector<int>* children = &m_roots;
    if (parent.isValid()) {
        const Node* node = nodeAt(parent);
        if (!node)
            return {};
        children = &node->children;
    }
    if (row >= int(children->size()))
        return {};
    return indexOfNode((*children)[size_t(row)], column);
}

QModelIndex SceneTreeModel::parent(const QModelIndex& child) const
{
    const Node* node = nodeAt(child);
    return node ? indexOfNode(node->parent) : QModelIndex();
}

int SceneTreeModel::rowCount(const QModelIndex& parent) const
{
    if (!parent.isValid())
        return int(m_roots.size());
    if (parent.column() != 0)
        return 0;
    const Node* node = nodeAt(parent);
    return node ? int(node->children.size()) : 0;
}

int SceneTreeModel::columnCount(const QModelIndex&) const { return ColumnCount; }

QVariant SceneTreeModel::data(const QModelIndex& index, int role) const
{
    const Node* node = nodeAt(index);
    if (!node || !m_scene)
        return {};
    const model::Object& object = m_scene->objects[size_t(node->object)];
    const model::Part* part = node->part >= 0 ? &object.parts[size_t(node->part)] : nullptr;
    const model::Face* face = node->face >= 0 ? &part->faces[size_t(node->face)] : nullptr;

    if (role == KindRole)
        return int(node->kind);
    if (role == ElementIdRole)
        return toQString(idAt(index));

    switch (index.column()) {
    case IdColumn:
        if (role == Qt::DisplayRole || role == Qt::ToolTipRole)
            return toQString(idAt(index));
        if (role == Qt::DecorationRole) {
            QStyle* style = QApplication::style();
            switch (node->kind) {
            case SelectionKind::Object: return style->standardIcon(QStyle::SP_DirIcon);
            case SelectionKind::Part: return style->standardIcon(QStyle::SP_FileIcon);
            default: return {};
            }
        }
        break;
    case NameColumn:
        if (role == Qt::DisplayRole) {
            if (node->kind == SelectionKind::Object)
                return toQString(object.name);
            if (node->kind == SelectionKind::Part)
                return toQString(part->name);
            return tr("%n vertices", nullptr, int(face->loop.size()));
        }
        break;
    case MaterialColumn: {
        std::string materialId;
        if (node->kind == SelectionKind::Part)
            materialId = part->material;
        else if (node->kind == SelectionKind::Face)
            materialId = face->material.empty() ? part->material : face->material;
        if (materialId.empty())
            return {};
        const model::Material* material = m_scene->findMaterial(materialId);
        if (role == Qt::DisplayRole) {
            if (node->kind == SelectionKind::Face && face->material.empty())
                return tr("%1 (part)").arg(toQString(materialId));
            return toQString(materialId);
        }
        if (role == Qt::DecorationRole)
            return swatch(material);
        if (role == Qt::ToolTipRole && !material)
            return tr("Unknown material \"%1\"").arg(toQString(materialId));
        break;
    }
    default: break;
    }
    return {};
}

QVariant SceneTreeModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case IdColumn: return tr("Id");
    case NameColumn: return tr("Name");
    case MaterialColumn: return tr("Material");
    }
    return {};
}

Qt::ItemFlags SceneTreeModel::flags(const QModelIndex& index) const
{
    if (!index.isValid())
        return Qt::ItemIsDropEnabled; // dropping on empty space ungroups
    Qt::ItemFlags f = Qt::ItemIsEnabled | Qt::ItemIsSelectable;
    switch (kindAt(index)) {
    case SelectionKind::Object: f |= Qt::ItemIsDropEnabled; break;
    case SelectionKind::Part: f |= Qt::ItemIsDragEnabled; break;
    default: break;
    }
    return f;
}

QStringList SceneTreeModel::mimeTypes() const { return {kPartsMimeType}; }

QMimeData* SceneTreeModel::mimeData(const QModelIndexList& indexes) const
{
    QStringList ids;
    for (const QModelIndex& index : indexes)
        if (index.column() == 0 && kindAt(index) == SelectionKind::Part)
            ids << toQString(idAt(index));
    if (ids.isEmpty())
        return nullptr;
    auto* data = new QMimeData;
    data->setData(kPartsMimeType, ids.join(QLatin1Char('\n')).toUtf8());
    return data;
}

bool SceneTreeModel::canDropMimeData(const QMimeData* data, Qt::DropAction, int, int, const QModelIndex& parent) const
{
    if (!data || !data->hasFormat(kPartsMimeType))
        return false;
    // Onto an object (or between rows of the root: a new object); not into parts.
    return !parent.isValid() || kindAt(parent) == SelectionKind::Object;
}

bool SceneTreeModel::dropMimeData(const QMimeData* data, Qt::DropAction action, int row, int column,
                                  const QModelIndex& parent)
{
    if (!canDropMimeData(data, action, row, column, parent) || !m_moveParts)
        return false;
    const QStringList ids = QString::fromUtf8(data->data(kPartsMimeType)).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    const std::string target = parent.isValid() ? idAt(parent) : std::string();
    // The edit rebuilds this model; run it after the view has finished
    // handling the drop, and report "not handled" so the view does not remove
    // the dragged rows itself.
    QMetaObject::invokeMethod(
        this, [this, parts = toStdVector(ids), target] { m_moveParts(parts, target); }, Qt::QueuedConnection);
    return false;
}

} // namespace regio::editor
