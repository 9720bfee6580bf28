#pragma once
// The solver dock: every solver setting of the
// scene, edited through SetSolverSettings (undoable, saved in the file),
// presets and the dry run; Run / Pause / Stop / Reset and "live"; the display
// controls of the preview (exposure, gamma, ambient, false colour with its
// legend, element mesh) and what the inspector found.
#include "editor/preview/preview_display.h"
#include "editor/preview/solver_presets.h"
#include "model/scene.h"

#include <QDockWidget>

#include <optional>

class QAction;
class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QGroupBox;
class QLabel;
class QPlainTextEdit;
class QSpinBox;

namespace regio::editor {

class LegendWidget;
class SceneDocument;

class SolverDock : public QDockWidget {
    Q_OBJECT
public:
    struct Actions {
        QAction *run, *continueSolve, *pause, *stop, *reset, *live, *dryRun, *inspect, *hemicube;
    };
    SolverDock(SceneDocument* document, const Actions& actions, QWidget* parent = nullptr);

    const PreviewDisplay& display() const { return m_display; }
    void setDisplay(const PreviewDisplay& display);
    void setLegend(const std::optional<output::FalseColourLegend>& legend, double whiteReference);
    void setInspection(const QString& text);
    // Where the solve is and why it stopped (the status bar's text).
    void setStatus(const QString& text);
    QString status() const;

    // Pushes one SetSolverSettings (what every control of the dock does).
    bool applySettings(const model::SolverSettings& settings);
    void applyPreset(SolverPreset preset);

signals:
    void displayChanged(const regio::editor::PreviewDisplay& display);

private:
    void refresh();
    void edited();
    void displayEdited();

    SceneDocument* m_document;
    PreviewDisplay m_display;
    bool m_refreshing = false;

    QComboBox* m_preset = nullptr;
    QSpinBox* m_hemicube = nullptr;
    QDoubleSpinBox* m_patchSize = nullptr;
    QSpinBox* m_elementsPerPatch = nullptr;
    QGroupBox* m_adaptive = nullptr;
    QDoubleSpinBox* m_threshold = nullptr;
    QDoubleSpinBox* m_minEdge = nullptr;
    QCheckBox* m_anchoring = nullptr;
    QSpinBox* m_maxIterations = nullptr;
    QDoubleSpinBox* m_convergence = nullptr;
    QComboBox* m_visibility = nullptr;
    QComboBox* m_regions = nullptr;

    QDoubleSpinBox* m_exposure = nullptr;
    QDoubleSpinBox* m_gamma = nullptr;
    QCheckBox* m_ambient = nullptr;
    QCheckBox* m_falseColour = nullptr;
    QComboBox* m_falseScale = nullptr;
    QCheckBox* m_mesh = nullptr;
    LegendWidget* m_legend = nullptr;
    QLabel* m_white = nullptr;
    QLabel* m_status = nullptr;
    QPlainTextEdit* m_inspection = nullptr;
};

// The false-colour ramp with its ticks, drawn with QPainter.
class LegendWidget : public QWidget {
    Q_OBJECT
public:
    explicit LegendWidget(QWidget* parent = nullptr);
    void setLegend(const std::optional<output::FalseColourLegend>& legend);
    const std::optional<output::FalseColourLegend>& legend() const { return m_legend; }
    QSize sizeHint() const override;

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    std::optional<output::FalseColourLegend> m_legend;
};

} // namespace regio::editor
