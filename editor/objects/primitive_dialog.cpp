#include "editor/objects/primitive_dialog.h"

#include "editor/document/qt_conversions.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QRegularExpressionValidator>
#include <QSpinBox>

namespace regio::editor {

QString PrimitiveDialog::kindName(PrimitiveKind kind)
{
    switch (kind) {
    case PrimitiveKind::Box: return tr("Box");
    case PrimitiveKind::Room: return tr("Room");
    case PrimitiveKind::Prism: return tr("Prism / Cylinder");
    case PrimitiveKind::Wedge: return tr("Wedge");
    case PrimitiveKind::Stairs: return tr("Stairs");
    }
    return {};
}

PrimitiveDialog::PrimitiveDialog(const PrimitiveParams& initial, const model::Scene& scene, QWidget* parent)
    : QDialog(parent)
    , m_params(initial)
{
    setWindowTitle(tr("New object: %1").arg(kindName(initial.kind)));
    auto* form = new QFormLayout(this);

    m_id = new QLineEdit(toQString(initial.id), this);
    m_id->setValidator(new QRegularExpressionValidator(QRegularExpression(QStringLiteral("[^\\s]+")), m_id));
    form->addRow(tr("&Id:"), m_id);

    m_material = new QComboBox(this);
    m_material->addItem(tr("(none)"), QString());
    for (const model::Material& material : scene.materials)
        m_material->addItem(toQString(material.name.empty() ? material.id : material.name + " (" + material.id + ")"),
                            toQString(material.id));
    m_material->setCurrentIndex(std::max(0, m_material->findData(toQString(initial.material))));
    form->addRow(tr("&Material:"), m_material);

    auto vectorRow = [&](QDoubleSpinBox** boxes, const model::Vec3& value, double min) {
        auto* row = new QWidget(this);
        auto* layout = new QHBoxLayout(row);
        layout->setContentsMargins(0, 0, 0, 0);
        for (int i = 0; i < 3; ++i) {
            boxes[i] = new QDoubleSpinBox(row);
            boxes[i]->setRange(min, 1e5);
            boxes[i]->setDecimals(3);
            boxes[i]->setSingleStep(0.1);
            boxes[i]->setValue(value[i]);
            boxes[i]->setPrefix(QStringLiteral("xyz").mid(i, 1) + QStringLiteral(": "));
            layout->addWidget(boxes[i]);
        }
        return row;
    };
    form->addRow(tr("&Base centre (m):"), vectorRow(m_base, initial.base, -1e5));
    form->addRow(tr("&Size (m):"), vectorRow(m_size, initial.size, 0.001));
    if (initial.kind == PrimitiveKind::Prism || initial.kind == PrimitiveKind::Stairs) {
        m_count = new QSpinBox(this);
        m_count->setRange(initial.kind == PrimitiveKind::Prism ? 3 : 1,
                          initial.kind == PrimitiveKind::Prism ? 1024 : 1000);
        m_count->setValue(initial.kind == PrimitiveKind::Prism ? initial.sides : initial.steps);
        form->addRow(initial.kind == PrimitiveKind::Prism ? tr("Si&des:") : tr("S&teps:"), m_count);
    }

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    form->addRow(buttons);
}

PrimitiveParams PrimitiveDialog::params() const
{
    PrimitiveParams p = m_params;
    p.id = toStd(m_id->text().trimmed());
    p.material = toStd(m_material->currentData().toString());
    for (int i = 0; i < 3; ++i) {
        p.base[i] = m_base[i]->value();
        p.size[i] = m_size[i]->value();
    }
    if (m_count) {
        if (p.kind == PrimitiveKind::Prism)
            p.sides = m_count->value();
        else
            p.steps = m_count->value();
    }
    return p;
}

} // namespace regio::editor
