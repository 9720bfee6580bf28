#include "editor/docks/vector_editor.h"

#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QSignalBlocker>

namespace regio::editor {

VectorEditor::VectorEditor(QWidget* parent, double min, double max, int decimals, double step, const QString& suffix)
    : QWidget(parent)
{
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    const char* axes[] = {"x", "y", "z"};
    for (int i = 0; i < 3; ++i) {
        auto* box = new QDoubleSpinBox(this);
        box->setRange(min, max);
        box->setDecimals(decimals);
        box->setSingleStep(step);
        box->setSuffix(suffix);
        box->setKeyboardTracking(false); // typed values commit on Enter
        box->setToolTip(QString::fromLatin1(axes[i]));
        box->setAccessibleName(QString::fromLatin1(axes[i]));
        box->setMinimumWidth(60);
        connect(box, &QDoubleSpinBox::valueChanged, this, [this] {
            if (!m_setting)
                emit valueEdited(value());
        });
        layout->addWidget(box);
        m_boxes[i] = box;
    }
}

model::Vec3 VectorEditor::value() const { return {m_boxes[0]->value(), m_boxes[1]->value(), m_boxes[2]->value()}; }

void VectorEditor::setValue(const model::Vec3& value)
{
    m_setting = true;
    for (int i = 0; i < 3; ++i)
        m_boxes[i]->setValue(value[i]);
    m_setting = false;
}

} // namespace regio::editor
