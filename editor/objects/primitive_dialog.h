#pragma once
// Parameters of a new primitive: id, material, where and how big.
#include "editor/objects/primitives.h"

#include <QDialog>

class QComboBox;
class QDoubleSpinBox;
class QLineEdit;
class QSpinBox;

namespace regio::editor {

class PrimitiveDialog : public QDialog {
    Q_OBJECT
public:
    PrimitiveDialog(const PrimitiveParams& initial, const model::Scene& scene, QWidget* parent = nullptr);
    PrimitiveParams params() const;

    static QString kindName(PrimitiveKind kind);

private:
    PrimitiveParams m_params;
    QLineEdit* m_id;
    QComboBox* m_material;
    QDoubleSpinBox* m_base[3];
    QDoubleSpinBox* m_size[3];
    QSpinBox* m_count = nullptr;
};

} // namespace regio::editor
