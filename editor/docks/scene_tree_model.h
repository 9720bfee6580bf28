#pragma once
// The scene as a tree: objects -> parts -> faces, with ids, names and
// material swatches. Rebuilt when objects or materials change. Parts can be
// dragged onto another object (regroup) or onto empty space (a new object of
// their own); the drop is handed to a callback that pushes the undo command.
#include "editor/document/selection.h"
#include "model/scene.h"

#include <QAbstractItemModel>

#include <functional>
#include <string>
#include <unordered_map>
#include <vector>

namespace regio::editor {

class SceneTreeModel : public QAbstractItemModel {
    Q_OBJECT
public:
    enum Column { IdColumn, NameColumn, MaterialColumn, ColumnCount };
    enum Role { KindRole = Qt::UserRole + 1, ElementIdRole };

    // targetObjectId empty = give every part an object of its own.
    using MovePartsHandler =
        std::function<void(const std::vector<std::string>& partIds, const std::string& targetObjectId)>;

    explicit SceneTreeModel(QObject* parent = nullptr);

    void setScene(const model::Scene* scene); // rebuilds; the scene must outlive the model
    void rebuild();
    void setMovePartsHandler(MovePartsHandler handler) { m_moveParts = std::move(handler); }

    QModelIndex indexOf(SelectionKind kind, const std::string& id) const;
    SelectionKind kindAt(const QModelIndex& index) const;
    std::string idAt(const QModelIndex& index) const;

    QModelIndex index(int row, int column, const QModelIndex& parent = {}) const override;
    QModelIndex parent(const QModelIndex& child) const override;
    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;

    QStringList mimeTypes() const override;
    QMimeData* mimeData(const QModelIndexList& indexes) const override;
    bool canDropMimeData(const QMimeData* data, Qt::DropAction action, int row, int column,
                         const QModelIndex& parent) const override;
    bool dropMimeData(const QMimeData* data, Qt::DropAction action, int row, int column,
                      const QModelIndex& parent) override;
    Qt::DropActions supportedDropActions() const override { return Qt::MoveAction; }
    Qt::DropActions supportedDragActions() const override { return Qt::MoveAction; }

    static const QString kPartsMimeType;

private:
    struct Node {
        SelectionKind kind = SelectionKind::None;
        int object = -1, part = -1, face = -1; // indices into the scene
        int parent = -1;                       // node index, -1 = root
        int row = 0;
        std::vector<int> children;
    };
    const Node* nodeAt(const QModelIndex& index) const;
    QModelIndex indexOfNode(int node, int column = 0) const;

    const model::Scene* m_scene = nullptr;
    std::vector<Node> m_nodes;
    std::vector<int> m_roots;
    // (kind, id) -> node, so syncing a large selection stays linear.
    std::unordered_map<std::string, int> m_nodeById;
    MovePartsHandler m_moveParts;
};

} // namespace regio::editor
