#pragma once
// File ▸ Import…: a model file (OBJ, glTF, FBX, ... through the importer)
// with the options of `regio-solve import`, imported in the background
// whenever an option changes, previewed (the report, the warnings and the
// scene in a viewport of its own) before it is accepted into a new scene or
// the open one.
#include "importer/import_model.h"

#include <QDialog>
#include <QFutureWatcher>
#include <QTimer>

#include <memory>
#include <optional>

class QCheckBox;
class QComboBox;
class QDialogButtonBox;
class QDoubleSpinBox;
class QLabel;
class QPlainTextEdit;
class QRadioButton;

namespace regio::editor {

class SceneDocument;
class Viewport;

// What one import gave: the scene and its report, or why it was refused.
struct ImportOutcome {
    std::optional<importer::Imported> imported;
    model::Diagnostics diagnostics; // warnings beside a scene, errors without one
};

class ImportDialog : public QDialog {
    Q_OBJECT
public:
    enum class Target { NewScene, OpenScene };

    // `canAddToOpenScene`: whether there is an open scene to import into.
    ImportDialog(const QString& path, bool canAddToOpenScene, QWidget* parent = nullptr);
    ~ImportDialog() override;

    importer::ImportOptions options() const;
    Target target() const;
    // The last finished import (empty while one runs or after a refusal).
    const std::optional<importer::Imported>& imported() const { return m_outcome.imported; }
    bool busy() const { return m_running; }
    // The summary shown above the preview, for tests.
    QString summary() const;

signals:
    void importFinished();

private:
    void scheduleImport();
    void startImport();
    void onFinished();
    void showOutcome();

    QString m_path;
    QDoubleSpinBox* m_scale;
    QComboBox* m_up;
    QDoubleSpinBox* m_angle;
    QDoubleSpinBox* m_distance; // millimetres
    QCheckBox* m_regions;
    QRadioButton* m_intoNew;
    QRadioButton* m_intoOpen;
    QLabel* m_summary;
    QPlainTextEdit* m_messages;
    SceneDocument* m_previewDocument;
    Viewport* m_preview;
    QDialogButtonBox* m_buttons;

    QTimer m_debounce;
    QFutureWatcher<ImportOutcome> m_watcher;
    bool m_running = false;
    bool m_again = false; // an option changed while an import ran
    ImportOutcome m_outcome;
};

} // namespace regio::editor
