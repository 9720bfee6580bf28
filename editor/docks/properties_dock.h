#pragma once
// Numeric editing of the selection: names and materials, the transform
// (position of the selection's centre, rotate, scale) of objects and parts,
// face facts, region boxes, and the solver settings when nothing is selected.
#include <QDockWidget>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QSpinBox;
class QStackedWidget;

namespace regio::editor {

class Authoring;
class SceneDocument;
class VectorEditor;

class PropertiesDock : public QDockWidget {
    Q_OBJECT
public:
    PropertiesDock(SceneDocument* document, Authoring* authoring, QWidget* parent = nullptr);

    // The widgets, for tests.
    VectorEditor* positionEditor() const { return m_position; }
    QLineEdit* nameEdit() const { return m_name; }
    int currentPage() const;

signals:
    // The user asked for the solver's settings (the Solver panel).
    void solverPanelRequested();

private:
    QWidget* buildScenePage();
    QWidget* buildElementPage();
    QWidget* buildFacePage();
    QWidget* buildMaterialPage();
    QWidget* buildRegionPage();
    void refresh();
    void refreshScene();
    void refreshElement();
    void refreshFace();
    void refreshMaterial();
    void refreshRegion();
    void fillMaterialCombo(QComboBox* combo, const std::string& current, const QString& emptyLabel);

    SceneDocument* m_document;
    Authoring* m_authoring;
    QStackedWidget* m_pages;
    bool m_refreshing = false;

    // scene page
    QLabel* m_cameraInfo;

    // object / part page
    QLabel* m_elementTitle;
    QLineEdit* m_name;
    QComboBox* m_partMaterial;
    QLabel* m_partMaterialLabel;
    QLabel* m_elementInfo;
    VectorEditor* m_position;
    VectorEditor* m_rotate;
    VectorEditor* m_scale;

    // face page
    QLabel* m_faceTitle;
    QComboBox* m_faceMaterial;
    QLabel* m_faceInfo;

    // material page
    QLabel* m_materialInfo;

    // region page
    QLabel* m_regionTitle;
    QLineEdit* m_regionName;
    VectorEditor* m_regionMin;
    VectorEditor* m_regionMax;
    QLabel* m_regionInfo;
};

} // namespace regio::editor
