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
        // The range's widest number (an emission up to 10^7) would make the
        // row, and the whole right-hand panel column, wide: the boxes share
        // what the panel has instead, down to 60 px each.
        box->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
        // Only the component the user changed: the boxes show the others
        // rounded to their decimals (a reflectance of 0.7312 reads 0.731),
        // and the edit must not change values nobody touched.
        connect(box, &QDoubleSpinBox::valueChanged, this, [this, i](double component) {
            if (m_setting)
                return;
            m_value[i] = component;
            emit valueEdited(m_value);
        });
        layout->addWidget(box);
        m_boxes[i] = box;
    }
}

model::Vec3 VectorEditor::value() const { return m_value; }

void VectorEditor::setValue(const model::Vec3& value)
{
    m_value = value;
    m_setting = true;
    for (int i = 0; i < 3; ++i)
        m_boxes[i]->setValue(value[i]);
    m_setting = false;
}

} // namespace regio::editor
