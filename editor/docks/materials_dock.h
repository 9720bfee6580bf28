#pragma once
// The scene's materials: a list with swatches, and for the current one its
// name, reflectance and emission, each as a colour picker plus numbers.
// Every edit is an undo command; scrubbing a value merges into one step.
#include "model/types.h"

#include <QDockWidget>

class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QPushButton;

namespace regio::editor {

class Authoring;
class ColourButton;
class SceneDocument;
class VectorEditor;

class MaterialsDock : public QDockWidget {
    Q_OBJECT
public:
    MaterialsDock(SceneDocument* document, Authoring* authoring, QWidget* parent = nullptr);

    QListWidget* list() const { return m_list; }
    VectorEditor* reflectanceEditor() const { return m_reflectance; }
    VectorEditor* emissionEditor() const { return m_emission; }
    std::string currentMaterial() const;

private:
    void rebuildList();
    void refreshEditors();
    void setReflectance(const model::Rgb& value);
    void setEmission(const model::Rgb& value);

    SceneDocument* m_document;
    Authoring* m_authoring;
    QListWidget* m_list;
    QLineEdit* m_name;
    QLabel* m_id;
    ColourButton* m_reflectanceColour;
    VectorEditor* m_reflectance;
    ColourButton* m_emissionColour;
    VectorEditor* m_emission;
    QDoubleSpinBox* m_emissionStrength;
    QPushButton* m_assign;
    QPushButton* m_remove;
    QWidget* m_editors;
    bool m_refreshing = false;
};

} // namespace regio::editor
