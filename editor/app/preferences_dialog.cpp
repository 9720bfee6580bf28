#include "editor/app/preferences_dialog.h"

#include "editor/app/translations.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QSpinBox>

namespace regio::editor {

PreferencesDialog::PreferencesDialog(const Preferences& p, QWidget* parent)
    : QDialog(parent)
{
    setWindowTitle(tr("Preferences"));
    auto* form = new QFormLayout(this);

    m_language = new QComboBox(this);
    m_language->addItem(tr("System default"), QString());
    for (const QString& code : availableLanguages())
        m_language->addItem(languageDisplayName(code), code);
    m_language->setCurrentIndex(std::max(0, m_language->findData(p.language)));
    form->addRow(tr("&Language:"), m_language);

    m_autosave = new QSpinBox(this);
    m_autosave->setRange(0, 120);
    m_autosave->setSuffix(tr(" min"));
    m_autosave->setSpecialValueText(tr("Off"));
    m_autosave->setValue(p.autosaveMinutes);
    m_autosave->setToolTip(tr("How often unsaved changes are written to a recovery file"));
    form->addRow(tr("&Autosave every:"), m_autosave);

    m_grid = new QDoubleSpinBox(this);
    m_grid->setRange(0.001, 100.0);
    m_grid->setDecimals(3);
    m_grid->setSingleStep(0.05);
    m_grid->setSuffix(tr(" m"));
    m_grid->setValue(p.gridStep);
    form->addRow(tr("&Grid step:"), m_grid);

    m_snap = new QCheckBox(tr("Snap moves, rotations and scaling"), this);
    m_snap->setChecked(p.snapToGrid);
    form->addRow(tr("&Snapping:"), m_snap);

    m_angle = new QDoubleSpinBox(this);
    m_angle->setRange(0.5, 90.0);
    m_angle->setDecimals(1);
    m_angle->setSuffix(QStringLiteral("°"));
    m_angle->setValue(p.angleSnapDegrees);
    form->addRow(tr("A&ngle step:"), m_angle);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    form->addRow(buttons);
}

Preferences PreferencesDialog::preferences() const
{
    Preferences p;
    p.language = m_language->currentData().toString();
    p.autosaveMinutes = m_autosave->value();
    p.gridStep = m_grid->value();
    p.snapToGrid = m_snap->isChecked();
    p.angleSnapDegrees = m_angle->value();
    return p;
}

} // namespace regio::editor
