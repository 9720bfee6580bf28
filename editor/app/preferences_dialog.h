#pragma once
#include "editor/app/preferences.h"

#include <QDialog>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QSpinBox;

namespace regio::editor {

class PreferencesDialog : public QDialog {
    Q_OBJECT
public:
    explicit PreferencesDialog(const Preferences& preferences, QWidget* parent = nullptr);
    Preferences preferences() const;

private:
    QComboBox* m_language;
    QSpinBox* m_autosave;
    QDoubleSpinBox* m_grid;
    QCheckBox* m_snap;
    QDoubleSpinBox* m_angle;
};

} // namespace regio::editor
