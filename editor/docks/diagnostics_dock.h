#pragma once
// Live validation: the model's validateScene runs shortly after every change
// (debounced, so a drag validates once it pauses) and lists what it finds.
// Activating a row selects the offending element.
#include "editor/document/selection.h"

#include <QDockWidget>
#include <QTimer>

class QLabel;
class QTreeView;

namespace regio::editor {

class DiagnosticsModel;
class SceneDocument;

class DiagnosticsDock : public QDockWidget {
    Q_OBJECT
public:
    explicit DiagnosticsDock(SceneDocument* document, QWidget* parent = nullptr);

    DiagnosticsModel* model() const { return m_model; }
    QTreeView* view() const { return m_view; }
    // Validates now instead of after the debounce delay.
    void validateNow();

    // The element a diagnostic names: the innermost id of its path that
    // exists in the scene (face, else part, object, material or region).
    static Selection selectionFor(const model::Scene& scene, const std::vector<std::string>& idPath);

signals:
    void problemCountChanged(int errors, int warnings);
    void elementActivated(const Selection& selection);

private:
    void activate(const QModelIndex& index);

    SceneDocument* m_document;
    DiagnosticsModel* m_model;
    QTreeView* m_view;
    QLabel* m_summary;
    QTimer m_debounce;
};

} // namespace regio::editor
