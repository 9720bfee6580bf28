#include "editor/docks/materials_dock.h"

#include "editor/docks/colour_button.h"
#include "editor/docks/vector_editor.h"
#include "editor/document/commands/material_commands.h"
#include "editor/document/qt_conversions.h"
#include "editor/document/scene_document.h"
#include "editor/objects/authoring.h"

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

#include <algorithm>

namespace regio::editor {

namespace {

QIcon swatchIcon(const model::Material& m)
{
    QPixmap pixmap(16, 16);
    const bool emits = m.emission.r + m.emission.g + m.emission.b > 0.0;
    pixmap.fill(emits ? emissionDisplayColor(m.emission) : linearToColor(m.reflectance));
    return QIcon(pixmap);
}

} // namespace

MaterialsDock::MaterialsDock(SceneDocument* document, Authoring* authoring, QWidget* parent)
    : QDockWidget(tr("Materials"), parent)
    , m_document(document)
    , m_authoring(authoring)
{
    setObjectName(QStringLiteral("MaterialsDock"));
    auto* body = new QWidget(this);
    auto* layout = new QVBoxLayout(body);
    layout->setContentsMargins(2, 2, 2, 2);
    m_list = new QListWidget(body);
    m_list->setIconSize(QSize(16, 16));
    layout->addWidget(m_list, 1);

    auto* buttons = new QHBoxLayout;
    auto* add = new QPushButton(tr("Add"), body);
    connect(add, &QPushButton::clicked, this, [this] { m_authoring->createMaterial(); });
    m_remove = new QPushButton(tr("Delete"), body);
    m_remove->setToolTip(tr("Only a material nothing uses can be deleted"));
    connect(m_remove, &QPushButton::clicked, this, [this] {
        const std::string id = currentMaterial();
        if (!id.empty())
            m_document->push(new RemoveMaterial(m_document, id));
    });
    m_assign = new QPushButton(tr("Assign to Selection"), body);
    connect(m_assign, &QPushButton::clicked, this, [this] {
        const std::string id = currentMaterial();
        if (!id.empty())
            m_authoring->assignMaterial(id);
    });
    buttons->addWidget(add);
    buttons->addWidget(m_remove);
    buttons->addWidget(m_assign);
    layout->addLayout(buttons);

    m_editors = new QWidget(body);
    auto* form = new QFormLayout(m_editors);
    form->setContentsMargins(0, 0, 0, 0);
    m_id = new QLabel(m_editors);
    m_id->setTextInteractionFlags(Qt::TextSelectableByMouse);
    form->addRow(tr("Id:"), m_id);
    m_name = new QLineEdit(m_editors);
    m_name->setPlaceholderText(tr("(no name)"));
    connect(m_name, &QLineEdit::editingFinished, this, [this] {
        const std::string id = currentMaterial();
        const model::Material* m = m_document->scene().findMaterial(id);
        if (!m_refreshing && m && m->name != toStd(m_name->text()))
            m_document->push(new SetMaterialName(m_document, id, toStd(m_name->text())));
    });
    form->addRow(tr("Name:"), m_name);

    m_reflectanceColour = new ColourButton(m_editors);
    m_reflectance = new VectorEditor(m_editors, 0.0, 0.999, 3, 0.01);
    m_reflectance->setToolTip(tr("Diffuse reflectance per channel (red, green, blue), below 1"));
    auto* reflectanceRow = new QHBoxLayout;
    reflectanceRow->addWidget(m_reflectanceColour);
    reflectanceRow->addWidget(m_reflectance, 1);
    form->addRow(tr("Reflectance:"), reflectanceRow);
    connect(m_reflectance, &VectorEditor::valueEdited, this, &MaterialsDock::setReflectance);
    connect(m_reflectanceColour, &ColourButton::colourPicked, this, [this](const QColor& colour) {
        model::Rgb rho = colorToLinear(colour);
        rho = glm::min(rho, model::Rgb(0.999)); // a reflectance of 1 never converges
        setReflectance(rho);
    });

    m_emissionColour = new ColourButton(m_editors);
    m_emission = new VectorEditor(m_editors, 0.0, 1e7, 3, 1.0);
    m_emission->setToolTip(tr("Emitted power per unit area per channel (W/m²)"));
    auto* emissionRow = new QHBoxLayout;
    emissionRow->addWidget(m_emissionColour);
    emissionRow->addWidget(m_emission, 1);
    form->addRow(tr("Emission:"), emissionRow);
    connect(m_emission, &VectorEditor::valueEdited, this, &MaterialsDock::setEmission);
    connect(m_emissionColour, &ColourButton::colourPicked, this, [this](const QColor& colour) {
        // The picker chooses the hue; the strength stays.
        const model::Material* m = m_document->scene().findMaterial(currentMaterial());
        if (!m)
            return;
        const double peak = std::max({m->emission.r, m->emission.g, m->emission.b});
        model::Rgb hue = colorToLinear(colour);
        const double huePeak = std::max({hue.r, hue.g, hue.b});
        if (huePeak > 0.0)
            hue /= huePeak;
        setEmission(hue * (peak > 0.0 ? peak : 1.0));
    });
    m_emissionStrength = new QDoubleSpinBox(m_editors);
    m_emissionStrength->setRange(0.0, 1e7);
    m_emissionStrength->setDecimals(3);
    m_emissionStrength->setKeyboardTracking(false);
    m_emissionStrength->setToolTip(tr("The strongest channel of the emission; the others keep their ratio"));
    connect(m_emissionStrength, &QDoubleSpinBox::valueChanged, this, [this](double strength) {
        const model::Material* m = m_document->scene().findMaterial(currentMaterial());
        if (m_refreshing || !m)
            return;
        const double peak = std::max({m->emission.r, m->emission.g, m->emission.b});
        setEmission(peak > 0.0 ? m->emission * (strength / peak) : model::Rgb(strength));
    });
    form->addRow(tr("Strength:"), m_emissionStrength);
    layout->addWidget(m_editors);
    setWidget(body);

    connect(document, &SceneDocument::materialsChanged, this, &MaterialsDock::rebuildList);
    connect(document, &SceneDocument::objectsChanged, this, &MaterialsDock::refreshEditors);
    connect(m_list, &QListWidget::currentRowChanged, this, &MaterialsDock::refreshEditors);
    connect(document, &SceneDocument::selectionChanged, this, [this] {
        const Selection& s = m_document->selection();
        if (s.kind == SelectionKind::Material && !s.empty())
            for (int row = 0; row < m_list->count(); ++row)
                if (m_list->item(row)->data(Qt::UserRole).toString() == toQString(s.ids.front()))
                    m_list->setCurrentRow(row);
        refreshEditors();
    });
    connect(m_list, &QListWidget::itemDoubleClicked, this, [this](QListWidgetItem* item) {
        m_document->setSelection(
            Selection::single(SelectionKind::Material, toStd(item->data(Qt::UserRole).toString())));
    });
    rebuildList();
}

std::string MaterialsDock::currentMaterial() const
{
    const QListWidgetItem* item = m_list->currentItem();
    return item ? toStd(item->data(Qt::UserRole).toString()) : std::string();
}

void MaterialsDock::rebuildList()
{
    const std::string current = currentMaterial();
    m_refreshing = true;
    m_list->clear();
    int currentRow = -1;
    for (const model::Material& m : m_document->scene().materials) {
        auto* item = new QListWidgetItem(swatchIcon(m), toQString(m.name.empty() ? m.id : m.name + " (" + m.id + ")"));
        item->setData(Qt::UserRole, toQString(m.id));
        if (m.id == current)
            currentRow = m_list->count();
        m_list->addItem(item);
    }
    m_list->setCurrentRow(currentRow >= 0 ? currentRow : (m_list->count() > 0 ? 0 : -1));
    m_refreshing = false;
    refreshEditors();
}

void MaterialsDock::refreshEditors()
{
    const model::Material* m = m_document->scene().findMaterial(currentMaterial());
    m_editors->setEnabled(m != nullptr);
    m_remove->setEnabled(m != nullptr);
    const Selection& s = m_document->selection();
    m_assign->setEnabled(
        m != nullptr && !s.empty() &&
        (s.kind == SelectionKind::Object || s.kind == SelectionKind::Part || s.kind == SelectionKind::Face));
    if (!m)
        return;
    m_refreshing = true;
    m_id->setText(toQString(m->id));
    m_name->setText(toQString(m->name));
    m_reflectance->setValue(m->reflectance);
    m_reflectanceColour->setColour(linearToColor(m->reflectance));
    m_emission->setValue(m->emission);
    m_emissionColour->setColour(emissionDisplayColor(m->emission));
    m_emissionStrength->setValue(std::max({m->emission.r, m->emission.g, m->emission.b}));
    m_refreshing = false;
}

void MaterialsDock::setReflectance(const model::Rgb& value)
{
    const std::string id = currentMaterial();
    const model::Material* m = m_document->scene().findMaterial(id);
    if (m_refreshing || !m || m->reflectance == value)
        return;
    if (!m_document->push(new SetMaterialReflectance(m_document, id, value)))
        refreshEditors();
}

void MaterialsDock::setEmission(const model::Rgb& value)
{
    const std::string id = currentMaterial();
    const model::Material* m = m_document->scene().findMaterial(id);
    if (m_refreshing || !m || m->emission == value)
        return;
    if (!m_document->push(new SetMaterialEmission(m_document, id, value)))
        refreshEditors();
}

} // namespace regio::editor
