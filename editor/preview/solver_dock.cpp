#include "editor/preview/solver_dock.h"

#include "editor/document/commands/solver_settings_commands.h"
#include "editor/document/scene_document.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>
#include <QPlainTextEdit>
#include <QScrollArea>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QToolButton>
#include <QVBoxLayout>

namespace regio::editor {

namespace {

QToolButton* buttonFor(QAction* action, QWidget* parent)
{
    auto* button = new QToolButton(parent);
    button->setDefaultAction(action);
    button->setToolButtonStyle(Qt::ToolButtonTextOnly);
    button->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    return button;
}

QDoubleSpinBox* doubleSpin(double min, double max, double step, int decimals, const QString& suffix)
{
    auto* spin = new QDoubleSpinBox;
    spin->setRange(min, max);
    spin->setSingleStep(step);
    spin->setDecimals(decimals);
    spin->setSuffix(suffix);
    spin->setKeyboardTracking(false);
    return spin;
}

QSpinBox* intSpin(int min, int max, int step)
{
    auto* spin = new QSpinBox;
    spin->setRange(min, max);
    spin->setSingleStep(step);
    spin->setKeyboardTracking(false);
    return spin;
}

} // namespace

SolverDock::SolverDock(SceneDocument* document, const Actions& actions, QWidget* parent)
    : QDockWidget(tr("Solver"), parent)
    , m_document(document)
{
    setObjectName(QStringLiteral("SolverDock"));
    auto* content = new QWidget;
    auto* layout = new QVBoxLayout(content);

    // Three buttons a row: the panel shares a narrow column with others.
    auto* controls = new QGridLayout;
    int slot = 0;
    for (QAction* a : {actions.run, actions.continueSolve, actions.pause, actions.stop, actions.reset}) {
        controls->addWidget(buttonFor(a, content), slot / 3, slot % 3);
        ++slot;
    }
    layout->addLayout(controls);
    m_status = new QLabel(content);
    m_status->setObjectName(QStringLiteral("solveStatus"));
    m_status->setWordWrap(true);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_status);
    auto* options = new QHBoxLayout;
    for (QAction* a : {actions.live, actions.inspect, actions.hemicube})
        options->addWidget(buttonFor(a, content));
    layout->addLayout(options);

    auto* settingsBox = new QGroupBox(tr("Settings"));
    auto* form = new QFormLayout(settingsBox);
    // In a narrow column a field goes under its label instead of widening
    // the panel past the column (a horizontal scrollbar).
    form->setRowWrapPolicy(QFormLayout::WrapLongRows);
    auto* presetRow = new QHBoxLayout;
    m_preset = new QComboBox;
    m_preset->addItem(tr("Custom"));
    for (SolverPreset p : {SolverPreset::Draft, SolverPreset::Normal, SolverPreset::Final})
        m_preset->addItem(presetName(p), int(p));
    presetRow->addWidget(m_preset, 1);
    presetRow->addWidget(buttonFor(actions.dryRun, settingsBox));
    form->addRow(tr("Preset:"), presetRow);

    m_hemicube = intSpin(8, 4096, 2);
    m_hemicube->setToolTip(tr("Resolution of the hemicube's top face (the sides are half as high)"));
    form->addRow(tr("Hemicube:"), m_hemicube);
    m_patchSize = doubleSpin(0.001, 1000.0, 0.05, 3, tr(" m"));
    form->addRow(tr("Patch size:"), m_patchSize);
    m_elementsPerPatch = intSpin(1, 4096, 1);
    form->addRow(tr("Elements per patch:"), m_elementsPerPatch);
    m_adaptive = new QGroupBox(tr("Adaptive subdivision"));
    m_adaptive->setCheckable(true);
    auto* adaptiveForm = new QFormLayout(m_adaptive);
    adaptiveForm->setRowWrapPolicy(QFormLayout::WrapLongRows);
    m_threshold = doubleSpin(0.001, 1.0, 0.01, 3, QString());
    m_threshold->setToolTip(tr("Relative radiosity difference to a neighbour that splits an element"));
    adaptiveForm->addRow(tr("Threshold:"), m_threshold);
    m_minEdge = doubleSpin(0.0001, 100.0, 0.01, 4, tr(" m"));
    adaptiveForm->addRow(tr("Minimum edge:"), m_minEdge);
    m_anchoring = new QCheckBox(tr("Anchor T-vertices"));
    adaptiveForm->addRow(m_anchoring);
    form->addRow(m_adaptive);
    m_maxIterations = intSpin(1, 10000000, 50);
    form->addRow(tr("Maximum iterations:"), m_maxIterations);
    m_convergence = doubleSpin(0.000001, 0.999999, 0.0005, 6, QString());
    m_convergence->setToolTip(tr("Stop when the unshot power falls below this fraction of the emitted power"));
    form->addRow(tr("Convergence:"), m_convergence);
    m_visibility = new QComboBox;
    m_visibility->addItem(tr("Painter (no z-buffer)"), int(model::Visibility::Painter));
    m_visibility->addItem(tr("Z-buffer"), int(model::Visibility::ZBuffer));
    form->addRow(tr("Visibility:"), m_visibility);
    m_regions = new QComboBox;
    m_regions->addItem(tr("Authored"), int(model::RegionsMode::Authored));
    m_regions->addItem(tr("None (one BSP tree)"), int(model::RegionsMode::None));
    m_regions->addItem(tr("Automatic"), int(model::RegionsMode::Auto));
    form->addRow(tr("Regions:"), m_regions);
    layout->addWidget(settingsBox);

    auto* displayBox = new QGroupBox(tr("Display"));
    auto* displayForm = new QFormLayout(displayBox);
    displayForm->setRowWrapPolicy(QFormLayout::WrapLongRows);
    m_exposure = doubleSpin(-20.0, 20.0, 0.25, 2, tr(" EV"));
    displayForm->addRow(tr("Exposure:"), m_exposure);
    m_gamma = doubleSpin(0.5, 4.0, 0.1, 2, QString());
    displayForm->addRow(tr("Gamma:"), m_gamma);
    m_ambient = new QCheckBox(tr("Ambient term"));
    m_ambient->setToolTip(tr("Show the not yet shot energy as a uniform ambient light (Cohen et al. 1988)"));
    displayForm->addRow(m_ambient);
    m_falseColour = new QCheckBox(tr("False colour"));
    m_falseScale = new QComboBox;
    m_falseScale->addItem(tr("Logarithmic"), int(output::FalseColourScale::Logarithmic));
    m_falseScale->addItem(tr("Linear"), int(output::FalseColourScale::Linear));
    auto* falseRow = new QHBoxLayout;
    falseRow->addWidget(m_falseColour);
    falseRow->addWidget(m_falseScale, 1);
    displayForm->addRow(falseRow);
    m_mesh = new QCheckBox(tr("Element mesh"));
    m_mesh->setToolTip(
        tr("Draw the element edges (where adaptive subdivision split elements) and, in orange "
           "(magenta on false colour), the edges anchoring adds to close T-vertices"));
    displayForm->addRow(m_mesh);
    m_legend = new LegendWidget;
    displayForm->addRow(m_legend);
    m_white = new QLabel;
    displayForm->addRow(m_white);
    layout->addWidget(displayBox);

    auto* inspectorBox = new QGroupBox(tr("Inspector"));
    auto* inspectorLayout = new QVBoxLayout(inspectorBox);
    m_inspection = new QPlainTextEdit;
    m_inspection->setReadOnly(true);
    m_inspection->setPlaceholderText(tr("Turn on Inspect and click a surface of the solution."));
    m_inspection->setMaximumHeight(150);
    inspectorLayout->addWidget(m_inspection);
    layout->addWidget(inspectorBox);
    layout->addStretch(1);

    auto* scroll = new QScrollArea;
    scroll->setWidgetResizable(true);
    scroll->setWidget(content);
    setWidget(scroll);

    // Names for tests and style sheets.
    m_preset->setObjectName(QStringLiteral("preset"));
    m_hemicube->setObjectName(QStringLiteral("hemicube"));
    m_patchSize->setObjectName(QStringLiteral("patchSize"));
    m_elementsPerPatch->setObjectName(QStringLiteral("elementsPerPatch"));
    m_adaptive->setObjectName(QStringLiteral("adaptive"));
    m_threshold->setObjectName(QStringLiteral("threshold"));
    m_minEdge->setObjectName(QStringLiteral("minEdge"));
    m_anchoring->setObjectName(QStringLiteral("anchoring"));
    m_maxIterations->setObjectName(QStringLiteral("maxIterations"));
    m_convergence->setObjectName(QStringLiteral("convergence"));
    m_visibility->setObjectName(QStringLiteral("visibility"));
    m_regions->setObjectName(QStringLiteral("regions"));
    m_exposure->setObjectName(QStringLiteral("exposure"));
    m_gamma->setObjectName(QStringLiteral("gamma"));
    m_falseColour->setObjectName(QStringLiteral("falseColour"));
    m_mesh->setObjectName(QStringLiteral("mesh"));

    connect(m_preset, &QComboBox::activated, this, [this](int index) {
        if (m_preset->itemData(index).isValid())
            applyPreset(SolverPreset(m_preset->itemData(index).toInt()));
    });
    for (QSpinBox* s : {m_hemicube, m_elementsPerPatch, m_maxIterations})
        connect(s, &QSpinBox::valueChanged, this, &SolverDock::edited);
    for (QDoubleSpinBox* s : {m_patchSize, m_threshold, m_minEdge, m_convergence})
        connect(s, &QDoubleSpinBox::valueChanged, this, &SolverDock::edited);
    connect(m_adaptive, &QGroupBox::toggled, this, &SolverDock::edited);
    connect(m_anchoring, &QCheckBox::toggled, this, &SolverDock::edited);
    connect(m_visibility, &QComboBox::activated, this, &SolverDock::edited);
    connect(m_regions, &QComboBox::activated, this, &SolverDock::edited);

    for (QDoubleSpinBox* s : {m_exposure, m_gamma})
        connect(s, &QDoubleSpinBox::valueChanged, this, &SolverDock::displayEdited);
    for (QCheckBox* c : {m_ambient, m_falseColour, m_mesh})
        connect(c, &QCheckBox::toggled, this, &SolverDock::displayEdited);
    connect(m_falseScale, &QComboBox::activated, this, &SolverDock::displayEdited);

    connect(m_document, &SceneDocument::settingsChanged, this, &SolverDock::refresh);
    connect(m_document, &SceneDocument::sceneReset, this, &SolverDock::refresh);
    setDisplay(m_display);
    refresh();
}

void SolverDock::refresh()
{
    m_refreshing = true;
    const model::SolverSettings& s = m_document->scene().solver;
    const QSignalBlocker b1(m_hemicube), b2(m_patchSize), b3(m_elementsPerPatch), b4(m_adaptive), b5(m_threshold),
        b6(m_minEdge), b7(m_anchoring), b8(m_maxIterations), b9(m_convergence), b10(m_visibility), b11(m_regions),
        b12(m_preset);
    m_hemicube->setValue(s.hemicube);
    m_patchSize->setValue(s.patchSize);
    m_elementsPerPatch->setValue(s.elementsPerPatch);
    m_adaptive->setChecked(s.adaptive.enabled);
    m_threshold->setValue(s.adaptive.threshold);
    m_minEdge->setValue(s.adaptive.minEdge);
    m_anchoring->setChecked(s.adaptive.anchoring);
    m_maxIterations->setValue(s.maxIterations);
    m_convergence->setValue(s.convergence);
    m_visibility->setCurrentIndex(m_visibility->findData(int(s.visibility)));
    m_regions->setCurrentIndex(m_regions->findData(int(s.regions)));
    const std::optional<SolverPreset> preset = presetOf(s);
    m_preset->setCurrentIndex(preset ? m_preset->findData(int(*preset)) : 0);
    m_refreshing = false;
}

bool SolverDock::applySettings(const model::SolverSettings& settings)
{
    if (settings == m_document->scene().solver)
        return true;
    const bool ok = m_document->push(new SetSolverSettings(m_document, settings));
    if (!ok)
        refresh(); // show the value the scene kept
    return ok;
}

void SolverDock::applyPreset(SolverPreset preset)
{
    applySettings(editor::applyPreset(m_document->scene().solver, preset));
}

void SolverDock::edited()
{
    if (m_refreshing)
        return;
    // Only the value the user changed. The widgets show the others rounded to
    // their decimals or clamped to their ranges (a patch size of 0.1234 m reads
    // 0.123): taking them all would change values nobody touched.
    model::SolverSettings s = m_document->scene().solver;
    const QObject* from = sender();
    if (from == m_hemicube)
        s.hemicube = m_hemicube->value() + (m_hemicube->value() % 2); // even: the sides are N x N/2
    else if (from == m_patchSize)
        s.patchSize = m_patchSize->value();
    else if (from == m_elementsPerPatch)
        s.elementsPerPatch = m_elementsPerPatch->value();
    else if (from == m_adaptive)
        s.adaptive.enabled = m_adaptive->isChecked();
    else if (from == m_threshold)
        s.adaptive.threshold = m_threshold->value();
    else if (from == m_minEdge)
        s.adaptive.minEdge = m_minEdge->value();
    else if (from == m_anchoring)
        s.adaptive.anchoring = m_anchoring->isChecked();
    else if (from == m_maxIterations)
        s.maxIterations = m_maxIterations->value();
    else if (from == m_convergence)
        s.convergence = m_convergence->value();
    else if (from == m_visibility)
        s.visibility = model::Visibility(m_visibility->currentData().toInt());
    else if (from == m_regions)
        s.regions = model::RegionsMode(m_regions->currentData().toInt());
    applySettings(s);
}

void SolverDock::setStatus(const QString& text) { m_status->setText(text); }

QString SolverDock::status() const { return m_status->text(); }

void SolverDock::setDisplay(const PreviewDisplay& display)
{
    m_display = display;
    const QSignalBlocker b1(m_exposure), b2(m_gamma), b3(m_ambient), b4(m_falseColour), b5(m_falseScale), b6(m_mesh);
    m_exposure->setValue(display.exposure);
    m_gamma->setValue(display.gamma);
    m_ambient->setChecked(display.ambient);
    m_falseColour->setChecked(display.falseColour);
    m_falseScale->setCurrentIndex(m_falseScale->findData(int(display.falseColourScale)));
    m_falseScale->setEnabled(display.falseColour);
    m_mesh->setChecked(display.showMesh);
}

void SolverDock::displayEdited()
{
    PreviewDisplay d;
    d.exposure = m_exposure->value();
    d.gamma = m_gamma->value();
    d.ambient = m_ambient->isChecked();
    d.falseColour = m_falseColour->isChecked();
    d.falseColourScale = output::FalseColourScale(m_falseScale->currentData().toInt());
    d.showMesh = m_mesh->isChecked();
    m_falseScale->setEnabled(d.falseColour);
    if (d == m_display)
        return;
    m_display = d;
    emit displayChanged(d);
}

void SolverDock::setLegend(const std::optional<output::FalseColourLegend>& legend, double whiteReference)
{
    m_legend->setLegend(legend);
    m_legend->setVisible(legend.has_value());
    m_white->setText(legend ? QString() : tr("White at exposure 0: %1 W/m²").arg(whiteReference, 0, 'g', 3));
}

void SolverDock::setInspection(const QString& text) { m_inspection->setPlainText(text); }

// --- legend -------------------------------------------------------------------

LegendWidget::LegendWidget(QWidget* parent)
    : QWidget(parent)
{
    setMinimumHeight(44);
    setToolTip(tr("False colour: luminance of the displayed radiosity, W/m²"));
    setVisible(false);
}

void LegendWidget::setLegend(const std::optional<output::FalseColourLegend>& legend)
{
    m_legend = legend;
    update();
}

QSize LegendWidget::sizeHint() const { return {240, 48}; }

void LegendWidget::paintEvent(QPaintEvent*)
{
    if (!m_legend)
        return;
    QPainter painter(this);
    const QRect bar(8, 4, width() - 16, 16);
    for (int x = 0; x < bar.width(); ++x) {
        const glm::vec3 c = output::FalseColour::ramp(double(x) / std::max(1, bar.width() - 1));
        painter.setPen(QColor::fromRgbF(c.r, c.g, c.b));
        painter.drawLine(bar.left() + x, bar.top(), bar.left() + x, bar.bottom());
    }
    painter.setPen(palette().color(QPalette::WindowText));
    painter.drawRect(bar.adjusted(0, 0, -1, -1));
    const QFontMetrics metrics(font());
    for (const output::LegendTick& tick : m_legend->ticks) {
        const int x = bar.left() + int(tick.position * (bar.width() - 1));
        painter.drawLine(x, bar.bottom(), x, bar.bottom() + 4);
        const QString label = QString::fromStdString(tick.label);
        const int w = metrics.horizontalAdvance(label);
        painter.drawText(std::clamp(x - w / 2, 0, width() - w), bar.bottom() + 6 + metrics.ascent(), label);
    }
}

} // namespace regio::editor
