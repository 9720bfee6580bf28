#pragma once
// Three spin boxes for x, y, z. valueEdited fires when the user commits a
// change (Enter, focus out, arrows or wheel), never for setValue.
#include "model/types.h"

#include <QWidget>

class QDoubleSpinBox;

namespace regio::editor {

class VectorEditor : public QWidget {
    Q_OBJECT
public:
    explicit VectorEditor(QWidget* parent = nullptr, double min = -1e5, double max = 1e5, int decimals = 3,
                          double step = 0.1, const QString& suffix = {});
    model::Vec3 value() const;
    void setValue(const model::Vec3& value);
    QDoubleSpinBox* spinBox(int axis) const { return m_boxes[axis]; }

signals:
    void valueEdited(const model::Vec3& value);

private:
    QDoubleSpinBox* m_boxes[3];
    model::Vec3 m_value{0.0}; // exact, as last set or edited; the boxes show it rounded
    bool m_setting = false;
};

} // namespace regio::editor
