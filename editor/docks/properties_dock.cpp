#include "editor/docks/properties_dock.h"

#include "editor/docks/vector_editor.h"
#include "editor/document/commands/material_commands.h"
#include "editor/document/commands/object_commands.h"
#include "editor/document/commands/part_commands.h"
#include "editor/document/commands/region_commands.h"
#include "editor/document/commands/solver_settings_commands.h"
#include "editor/document/qt_conversions.h"
#include "editor/document/scene_document.h"
#include "editor/objects/authoring.h"
#include "editor/viewport/scene_mesh.h"

#include <QComboBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QScrollArea>
#include <QStackedWidget>
#include <QVBoxLayout>

#include <glm/gtc/matrix_transform.hpp>

namespace regio::editor {

namespace {

enum Page { ScenePage, ElementPage, FacePage, MaterialPage, RegionPage };

QLabel* infoLabel(QWidget* parent)
{
    auto* label = new QLabel(parent);
    label->setWordWrap(true);
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    return label;
}

} // namespace

PropertiesDock::PropertiesDock(SceneDocument* document, Authoring* authoring, QWidget* parent)
    : QDockWidget(tr("Properties"), parent)
    , m_document(document)
    , m_authoring(authoring)
{
    setObjectName(QStringLiteral("PropertiesDock"));
    m_pages = new QStackedWidget(this);
    m_pages->addWidget(buildScenePage());
    m_pages->addWidget(buildElementPage());
    m_pages->addWidget(buildFacePage());
    m_pages->addWidget(buildMaterialPage());
    m_pages->addWidget(buildRegionPage());
    auto* scroll = new QScrollArea(this);
    scroll->setWidget(m_pages);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    setWidget(scroll);

    for (auto signal : {&SceneDocument::selectionChanged, &SceneDocument::objectsChanged,
                        &SceneDocument::geometryChanged, &SceneDocument::materialsChanged,
                        &SceneDocument::regionsChanged, &SceneDocument::settingsChanged, &SceneDocument::cameraChanged})
        connect(document, signal, this, &PropertiesDock::refresh);
    refresh();
}

int PropertiesDock::currentPage() const { return m_pages->currentIndex(); }

// --- pages ---------------------------------------------------------------------

QWidget* PropertiesDock::buildScenePage()
{
    auto* page = new QWidget(this);
    auto* layout = new QVBoxLayout(page);
    // The solver's settings live in the Solver panel only: one place to
    // read and change them, beside the preview they drive.
    auto* solver = new QGroupBox(tr("Solver"), page);
    auto* solverLayout = new QVBoxLayout(solver);
    QLabel* note = infoLabel(solver);
    note->setText(tr("The hemicube, the mesh and when to stop are set in the Solver panel, beside the preview."));
    solverLayout->addWidget(note);
    auto* showSolver = new QPushButton(tr("Show Solver Panel"), solver);
    showSolver->setObjectName(QStringLiteral("showSolverPanel"));
    connect(showSolver, &QPushButton::clicked, this, &PropertiesDock::solverPanelRequested);
    solverLayout->addWidget(showSolver);
    layout->addWidget(solver);

    auto* camera = new QGroupBox(tr("Scene camera"), page);
    auto* cameraLayout = new QVBoxLayout(camera);
    m_cameraInfo = infoLabel(camera);
    cameraLayout->addWidget(m_cameraInfo);
    auto* store = new QPushButton(tr("Store Current View"), camera);
    connect(store, &QPushButton::clicked, this, [this] { m_authoring->storeViewAsSceneCamera(); });
    cameraLayout->addWidget(store);
    auto* clear = new QPushButton(tr("Clear"), camera);
    connect(clear, &QPushButton::clicked, this, [this] {
        if (m_document->scene().camera)
            m_document->push(new SetSceneCamera(m_document, std::nullopt));
    });
    cameraLayout->addWidget(clear);
    layout->addWidget(camera);
    layout->addStretch();
    return page;
}

QWidget* PropertiesDock::buildElementPage()
{
    auto* page = new QWidget(this);
    auto* layout = new QVBoxLayout(page);
    m_elementTitle = new QLabel(page);
    m_elementTitle->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_elementTitle);
    auto* form = new QFormLayout;
    m_name = new QLineEdit(page);
    m_name->setPlaceholderText(tr("(no name)"));
    connect(m_name, &QLineEdit::editingFinished, this, [this] {
        const Selection& s = m_document->selection();
        if (m_refreshing || s.ids.size() != 1)
            return;
        const std::string id = s.ids.front();
        const std::string name = toStd(m_name->text());
        const model::Scene& scene = m_document->scene();
        if (s.kind == SelectionKind::Object && scene.findObject(id) && scene.findObject(id)->name != name)
            m_document->push(new SetObjectName(m_document, id, name));
        else if (s.kind == SelectionKind::Part && scene.findPart(id) && scene.findPart(id)->name != name)
            m_document->push(new SetPartName(m_document, id, name));
    });
    form->addRow(tr("Name:"), m_name);
    m_partMaterial = new QComboBox(page);
    m_partMaterialLabel = new QLabel(tr("Material:"), page);
    connect(m_partMaterial, &QComboBox::activated, this, [this] {
        if (!m_refreshing)
            m_authoring->assignMaterial(toStd(m_partMaterial->currentData().toString()));
    });
    form->addRow(m_partMaterialLabel, m_partMaterial);
    layout->addLayout(form);
    m_elementInfo = infoLabel(page);
    layout->addWidget(m_elementInfo);

    auto* transform = new QGroupBox(tr("Transform"), page);
    auto* tform = new QFormLayout(transform);
    m_position = new VectorEditor(transform, -1e5, 1e5, 4, 0.1, tr(" m"));
    m_position->setToolTip(tr("Centre of the selection's bounding box; editing it moves the selection"));
    connect(m_position, &VectorEditor::valueEdited, this, [this](const model::Vec3& centre) {
        const model::Box3 box =
            boundsOfFaces(m_document->scene(), selectedFaceIds(m_document->scene(), m_document->selection()));
        if (box.empty)
            return;
        const model::Vec3 delta = centre - box.center();
        if (glm::length(delta) > 0.0)
            m_authoring->transformSelection(glm::translate(glm::dmat4(1.0), delta), tr("Move"));
    });
    tform->addRow(tr("Centre:"), m_position);

    m_rotate = new VectorEditor(transform, -360.0, 360.0, 2, 15.0, QStringLiteral("°"));
    auto* rotate = new QPushButton(tr("Rotate"), transform);
    connect(rotate, &QPushButton::clicked, this, [this] {
        const model::Box3 box =
            boundsOfFaces(m_document->scene(), selectedFaceIds(m_document->scene(), m_document->selection()));
        const model::Vec3 degrees = m_rotate->value();
        if (box.empty || degrees == model::Vec3(0.0))
            return;
        const model::Vec3 c = box.center();
        glm::dmat4 m = glm::translate(glm::dmat4(1.0), c);
        // Applied x first, then y, then z, about the selection's centre.
        m = glm::rotate(m, glm::radians(degrees.z), model::Vec3(0, 0, 1));
        m = glm::rotate(m, glm::radians(degrees.y), model::Vec3(0, 1, 0));
        m = glm::rotate(m, glm::radians(degrees.x), model::Vec3(1, 0, 0));
        m = glm::translate(m, -c);
        if (m_authoring->transformSelection(m, tr("Rotate")))
            m_rotate->setValue(model::Vec3(0.0));
    });
    tform->addRow(tr("Rotate by:"), m_rotate);
    tform->addRow(QString(), rotate);

    m_scale = new VectorEditor(transform, 0.001, 1000.0, 4, 0.1);
    m_scale->setValue(model::Vec3(1.0));
    auto* scale = new QPushButton(tr("Scale"), transform);
    connect(scale, &QPushButton::clicked, this, [this] {
        const model::Box3 box =
            boundsOfFaces(m_document->scene(), selectedFaceIds(m_document->scene(), m_document->selection()));
        const model::Vec3 factors = m_scale->value();
        if (box.empty || factors == model::Vec3(1.0))
            return;
        const model::Vec3 c = box.center();
        const glm::dmat4 m = glm::translate(glm::scale(glm::translate(glm::dmat4(1.0), c), factors), -c);
        if (m_authoring->transformSelection(m, tr("Scale")))
            m_scale->setValue(model::Vec3(1.0));
    });
    tform->addRow(tr("Scale by:"), m_scale);
    tform->addRow(QString(), scale);
    layout->addWidget(transform);
    layout->addStretch();
    return page;
}

QWidget* PropertiesDock::buildFacePage()
{
    auto* page = new QWidget(this);
    auto* layout = new QVBoxLayout(page);
    m_faceTitle = new QLabel(page);
    m_faceTitle->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_faceTitle);
    auto* form = new QFormLayout;
    m_faceMaterial = new QComboBox(page);
    connect(m_faceMaterial, &QComboBox::activated, this, [this] {
        if (!m_refreshing)
            m_authoring->assignMaterial(toStd(m_faceMaterial->currentData().toString()));
    });
    form->addRow(tr("Material:"), m_faceMaterial);
    layout->addLayout(form);
    m_faceInfo = infoLabel(page);
    layout->addWidget(m_faceInfo);
    layout->addStretch();
    return page;
}

QWidget* PropertiesDock::buildMaterialPage()
{
    auto* page = new QWidget(this);
    auto* layout = new QVBoxLayout(page);
    m_materialInfo = infoLabel(page);
    layout->addWidget(m_materialInfo);
    layout->addStretch();
    return page;
}

QWidget* PropertiesDock::buildRegionPage()
{
    auto* page = new QWidget(this);
    auto* layout = new QVBoxLayout(page);
    m_regionTitle = new QLabel(page);
    layout->addWidget(m_regionTitle);
    auto* form = new QFormLayout;
    m_regionName = new QLineEdit(page);
    m_regionName->setPlaceholderText(tr("(no name)"));
    connect(m_regionName, &QLineEdit::editingFinished, this, [this] {
        const Selection& s = m_document->selection();
        if (m_refreshing || s.ids.size() != 1)
            return;
        const model::Region* region = m_document->scene().findRegion(s.ids.front());
        if (region && region->name != toStd(m_regionName->text()))
            m_document->push(new SetRegionName(m_document, region->id, toStd(m_regionName->text())));
    });
    form->addRow(tr("Name:"), m_regionName);
    m_regionMin = new VectorEditor(page, -1e5, 1e5, 4, 0.1, tr(" m"));
    m_regionMax = new VectorEditor(page, -1e5, 1e5, 4, 0.1, tr(" m"));
    auto commitBox = [this] {
        const Selection& s = m_document->selection();
        if (m_refreshing || s.ids.size() != 1)
            return;
        m_document->push(new SetRegionBox(m_document, s.ids.front(), m_regionMin->value(), m_regionMax->value()));
    };
    connect(m_regionMin, &VectorEditor::valueEdited, this, commitBox);
    connect(m_regionMax, &VectorEditor::valueEdited, this, commitBox);
    form->addRow(tr("Minimum:"), m_regionMin);
    form->addRow(tr("Maximum:"), m_regionMax);
    layout->addLayout(form);
    m_regionInfo = infoLabel(page);
    layout->addWidget(m_regionInfo);
    layout->addStretch();
    return page;
}

// --- refresh -------------------------------------------------------------------

void PropertiesDock::refresh()
{
    m_refreshing = true;
    const Selection& s = m_document->selection();
    switch (s.kind) {
    case SelectionKind::None:
        m_pages->setCurrentIndex(ScenePage);
        refreshScene();
        break;
    case SelectionKind::Object:
    case SelectionKind::Part:
        m_pages->setCurrentIndex(ElementPage);
        refreshElement();
        break;
    case SelectionKind::Face:
        m_pages->setCurrentIndex(FacePage);
        refreshFace();
        break;
    case SelectionKind::Material:
        m_pages->setCurrentIndex(MaterialPage);
        refreshMaterial();
        break;
    case SelectionKind::Region:
        m_pages->setCurrentIndex(RegionPage);
        refreshRegion();
        break;
    }
    m_refreshing = false;
}

void PropertiesDock::refreshScene()
{
    const model::Scene& scene = m_document->scene();
    if (scene.camera)
        m_cameraInfo->setText(tr("Eye %1, looking at %2, field of view %3°")
                                  .arg(formatVector(scene.camera->position), formatVector(scene.camera->target),
                                       formatNumber(scene.camera->fovY)));
    else
        m_cameraInfo->setText(tr("None: the view frames the whole scene when it opens."));
}

void PropertiesDock::fillMaterialCombo(QComboBox* combo, const std::string& current, const QString& emptyLabel)
{
    combo->clear();
    if (!emptyLabel.isEmpty())
        combo->addItem(emptyLabel, QString());
    for (const model::Material& m : m_document->scene().materials) {
        QPixmap swatch(12, 12);
        const bool emits = m.emission.r + m.emission.g + m.emission.b > 0.0;
        swatch.fill(emits ? emissionDisplayColor(m.emission) : linearToColor(m.reflectance));
        combo->addItem(QIcon(swatch), toQString(m.name.empty() ? m.id : m.name + " (" + m.id + ")"), toQString(m.id));
    }
    const int index = combo->findData(toQString(current));
    combo->setCurrentIndex(index >= 0 ? index : -1);
}

void PropertiesDock::refreshElement()
{
    const model::Scene& scene = m_document->scene();
    const Selection& s = m_document->selection();
    const bool single = s.ids.size() == 1;
    const bool isObject = s.kind == SelectionKind::Object;
    const std::vector<std::string> parts = selectedPartIds(scene, s);
    int faces = 0, vertices = 0;
    for (const std::string& id : parts) {
        const model::Part* part = scene.findPart(id);
        faces += int(part->faces.size());
        vertices += int(part->vertices.size());
    }
    if (single)
        m_elementTitle->setText(
            (isObject ? tr("<b>Object</b> %1") : tr("<b>Part</b> %1")).arg(toQString(s.ids.front()).toHtmlEscaped()));
    else
        m_elementTitle->setText(isObject ? tr("<b>%n objects</b>", nullptr, int(s.ids.size()))
                                         : tr("<b>%n parts</b>", nullptr, int(s.ids.size())));
    m_name->setEnabled(single);
    std::string name;
    if (single)
        name = isObject ? scene.findObject(s.ids.front())->name : scene.findPart(s.ids.front())->name;
    m_name->setText(toQString(name));

    // The material box shows the parts' common material, if they share one.
    std::string common;
    bool shared = !parts.empty();
    for (const std::string& id : parts) {
        const std::string& m = scene.findPart(id)->material;
        if (&id == &parts.front())
            common = m;
        else if (m != common)
            shared = false;
    }
    fillMaterialCombo(m_partMaterial, shared ? common : std::string(), {});
    m_partMaterial->setEnabled(!scene.materials.empty());
    m_elementInfo->setText(tr("%n part(s)", nullptr, int(parts.size())) + QStringLiteral(", ") +
                           tr("%n face(s)", nullptr, faces) + QStringLiteral(", ") +
                           tr("%n vertices", nullptr, vertices));
    const model::Box3 box = boundsOfFaces(scene, selectedFaceIds(scene, s));
    if (!box.empty) {
        m_position->setValue(box.center());
        m_elementInfo->setText(m_elementInfo->text() + QLatin1Char('\n') +
                               tr("Size %1 m").arg(formatVector(box.size())));
    }
}

void PropertiesDock::refreshFace()
{
    const model::Scene& scene = m_document->scene();
    const Selection& s = m_document->selection();
    if (s.ids.size() != 1) {
        m_faceTitle->setText(tr("<b>%n faces</b>", nullptr, int(s.ids.size())));
        fillMaterialCombo(m_faceMaterial, {}, tr("(the part's material)"));
        m_faceMaterial->setCurrentIndex(-1);
        m_faceInfo->clear();
        return;
    }
    const auto at = scene.locateFace(s.ids.front());
    const model::Part& part = scene.objects[size_t(at.object)].parts[size_t(at.part)];
    const model::Face& face = part.faces[size_t(at.face)];
    m_faceTitle->setText(tr("<b>Face</b> %1").arg(toQString(face.id).toHtmlEscaped()));
    fillMaterialCombo(m_faceMaterial, face.material,
                      tr("(the part's: %1)").arg(part.material.empty() ? tr("none") : toQString(part.material)));
    bool validLoop = face.loop.size() >= 3;
    for (int i : face.loop)
        validLoop = validLoop && i >= 0 && i < int(part.vertices.size());
    if (!validLoop) {
        m_faceInfo->setText(tr("The face's vertex loop is broken."));
        return;
    }
    const auto loop = model::loopPositions(part.vertices, face.loop);
    m_faceInfo->setText(tr("Part %1\n%n vertices", nullptr, int(loop.size())).arg(toQString(part.id)) +
                        QLatin1Char('\n') + tr("Area %1 m²").arg(formatNumber(model::polygonArea(loop))) +
                        QLatin1Char('\n') + tr("Normal %1").arg(formatVector(model::polygonNormal(loop))) +
                        QLatin1Char('\n') + tr("Centroid %1").arg(formatVector(model::polygonCentroid(loop))) +
                        QLatin1Char('\n') +
                        tr("Off its plane by at most %1 m").arg(formatNumber(model::planarityDeviation(loop), 3)));
}

void PropertiesDock::refreshMaterial()
{
    const model::Scene& scene = m_document->scene();
    const Selection& s = m_document->selection();
    int parts = 0, faces = 0;
    for (const model::Object& object : scene.objects)
        for (const model::Part& part : object.parts) {
            parts += s.contains(part.material);
            for (const model::Face& face : part.faces)
                faces += s.contains(face.material);
        }
    m_materialInfo->setText(tr("<b>Material</b> %1<br>Used as the default of %2 part(s) and by %3 face(s) of their own."
                               "<br>Edit its colours in the Materials panel.")
                                .arg(toQString(s.ids.size() == 1 ? s.ids.front() : std::string()).toHtmlEscaped())
                                .arg(parts)
                                .arg(faces));
}

void PropertiesDock::refreshRegion()
{
    const model::Scene& scene = m_document->scene();
    const Selection& s = m_document->selection();
    const model::Region* region = s.ids.size() == 1 ? scene.findRegion(s.ids.front()) : nullptr;
    m_regionName->setEnabled(region != nullptr);
    m_regionMin->setEnabled(region != nullptr);
    m_regionMax->setEnabled(region != nullptr);
    if (!region) {
        m_regionTitle->setText(tr("<b>%n regions</b>", nullptr, int(s.ids.size())));
        m_regionInfo->clear();
        return;
    }
    m_regionTitle->setText(tr("<b>Region</b> %1").arg(toQString(region->id).toHtmlEscaped()));
    m_regionName->setText(toQString(region->name));
    m_regionMin->setValue(region->min);
    m_regionMax->setValue(region->max);
    m_regionInfo->setText(tr("BSP order: %n face(s)", nullptr, int(region->bspOrder.size())));
}

} // namespace regio::editor
