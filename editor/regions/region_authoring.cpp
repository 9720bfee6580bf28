#include "editor/regions/region_authoring.h"

#include "editor/docks/diagnostics_dock.h"
#include "editor/docks/diagnostics_model.h"
#include "editor/document/commands/region_clip_command.h"
#include "editor/document/commands/region_commands.h"
#include "editor/document/qt_conversions.h"
#include "editor/document/scene_document.h"
#include "editor/objects/authoring.h"
#include "editor/regions/region_box_tool.h"
#include "editor/regions/region_figures.h"
#include "editor/regions/region_layers.h"
#include "editor/regions/regions_dock.h"
#include "editor/viewport/scene_mesh.h"
#include "editor/viewport/viewport.h"
#include "model/geometry/region_clip.h"

#include <QAction>
#include <QApplication>
#include <QItemSelectionModel>
#include <QMenu>
#include <QTreeView>

#include <cmath>

namespace regio::editor {

namespace {

QString layerName(const char* name) { return QString::fromLatin1(name); }

} // namespace

RegionAuthoring::RegionAuthoring(SceneDocument* document, Viewport* viewport, Authoring* authoring,
                                 DiagnosticsDock* diagnostics, QWidget* dialogParent)
    : QObject(dialogParent)
    , m_document(document)
    , m_viewport(viewport)
    , m_authoring(authoring)
    , m_diagnostics(diagnostics)
    , m_dialogParent(dialogParent)
    , m_tool(new RegionBoxTool(document, viewport, this))
    , m_figures(new RegionFiguresWatcher(document, this))
{
    m_draw = new QAction(tr("&Region Tool"), this);
    m_draw->setCheckable(true);
    m_draw->setShortcut(QKeySequence(Qt::SHIFT | Qt::Key_R));
    m_draw->setStatusTip(tr("Draw a region box in the viewport and resize the selected one by its face handles"));
    connect(m_draw, &QAction::toggled, m_tool, &RegionBoxTool::setActive);
    connect(m_tool, &RegionBoxTool::activeChanged, m_draw, &QAction::setChecked);
    connect(m_tool, &RegionBoxTool::statusMessage, this, &RegionAuthoring::statusMessage);

    m_aroundSelection = new QAction(tr("Region Around &Selection"), this);
    m_aroundSelection->setStatusTip(
        tr("Add a region box around the selected parts (the whole scene when nothing "
           "is selected)"));
    connect(m_aroundSelection, &QAction::triggered, this, &RegionAuthoring::addRegionAroundSelection);
    m_rename = new QAction(tr("Re&name Region…"), this);
    connect(m_rename, &QAction::triggered, this, [this] {
        if (m_document->selection().kind == SelectionKind::Region && m_authoring)
            m_authoring->renameSelection();
    });
    m_delete = new QAction(tr("&Delete Region"), this);
    connect(m_delete, &QAction::triggered, this, [this] {
        if (m_document->selection().kind == SelectionKind::Region && m_authoring)
            m_authoring->deleteSelection();
    });

    m_clipSelected = new QAction(tr("&Clip Selected Parts to Regions"), this);
    m_clipSelected->setStatusTip(
        tr("Cut each selected part that straddles region boundaries into one piece per "
           "region"));
    connect(m_clipSelected, &QAction::triggered, this, &RegionAuthoring::clipSelectedParts);

    m_propose = new QAction(tr("&Propose Automatic Regions"), this);
    m_propose->setStatusTip(tr("Suggest region boxes whose planes pass between the parts, with their BSP figures"));
    connect(m_propose, &QAction::triggered, this, &RegionAuthoring::proposeRegions);
    m_accept = new QAction(tr("&Accept Proposed Regions"), this);
    m_accept->setStatusTip(tr("Replace the scene's regions by the proposed ones"));
    connect(m_accept, &QAction::triggered, this, &RegionAuthoring::acceptProposal);
    m_discard = new QAction(tr("D&iscard Proposed Regions"), this);
    connect(m_discard, &QAction::triggered, this, &RegionAuthoring::discardProposal);

    m_showBoxes = new QAction(tr("Show Region &Boxes"), this);
    m_showBoxes->setCheckable(true);
    m_showBoxes->setChecked(true);
    connect(m_showBoxes, &QAction::toggled, this, &RegionAuthoring::updateBoxesLayer);
    m_colourByRegion = new QAction(tr("&Colour Parts by Region"), this);
    m_colourByRegion->setCheckable(true);
    m_colourByRegion->setStatusTip(tr("Each face in its region's colour; grey outside every region"));
    connect(m_colourByRegion, &QAction::toggled, this, &RegionAuthoring::updateColoursLayer);
    m_showPlanes = new QAction(tr("Show &Separating Planes"), this);
    m_showPlanes->setCheckable(true);
    m_showPlanes->setStatusTip(tr("The planes of the solver's regional tree between the region boxes"));
    connect(m_showPlanes, &QAction::toggled, this, &RegionAuthoring::updatePlanesLayer);

    m_dock = new RegionsDock(document, m_figures, {m_draw, m_aroundSelection, m_rename, m_delete}, dialogParent);
    connect(m_dock, &RegionsDock::separatingPlaneSelected, this, [this](int node) {
        m_highlightedPlane = node;
        if (node >= 0 && !m_showPlanes->isChecked())
            m_showPlanes->setChecked(true); // updates the layer
        else
            updatePlanesLayer();
    });

    connect(document, &SceneDocument::regionsChanged, this, [this] {
        updateBoxesLayer();
        updateColoursLayer();
        updatePlanesLayer();
        updateActions();
    });
    auto geometry = [this] {
        updateColoursLayer();
        updatePlanesLayer(); // the cells follow the scene's extent
        if (m_proposal) {
            discardProposal();
            emit statusMessage(tr("The scene changed: the proposed regions were discarded"));
        }
    };
    connect(document, &SceneDocument::objectsChanged, this, geometry);
    connect(document, &SceneDocument::geometryChanged, this, geometry);
    connect(document, &SceneDocument::sceneReset, this, [this] {
        discardProposal();
        updateBoxesLayer();
        updateColoursLayer();
        updatePlanesLayer();
        updateActions();
    });
    connect(document, &SceneDocument::selectionChanged, this, [this] {
        updateBoxesLayer();
        updateActions();
    });
    connect(viewport, &Viewport::viewChanged, this, &RegionAuthoring::uploadColoursLayer);

    if (m_diagnostics) {
        // The fix where a diagnostic has one: right click on a straddling part's entry.
        QTreeView* view = m_diagnostics->view();
        auto* fix = new QAction(tr("Clip Part to Regions"), view);
        fix->setObjectName(QStringLiteral("ClipPartToRegionsFix"));
        fix->setStatusTip(tr("Cut the straddling part into one piece per region"));
        view->setContextMenuPolicy(Qt::ActionsContextMenu);
        view->addAction(fix);
        auto currentPart = [this, view] {
            const model::Diagnostic* d = m_diagnostics->model()->at(view->currentIndex());
            return d ? clippablePartOf(d->idPath) : std::string();
        };
        auto refresh = [fix, currentPart] { fix->setEnabled(!currentPart().empty()); };
        connect(view->selectionModel(), &QItemSelectionModel::currentChanged, fix, refresh);
        connect(m_diagnostics->model(), &QAbstractItemModel::modelReset, fix, refresh);
        connect(fix, &QAction::triggered, this, [this, currentPart] {
            const std::string part = currentPart();
            if (!part.empty())
                clipPartsToRegions({part});
        });
        refresh();
    }

    updateBoxesLayer();
    updateActions();
}

RegionAuthoring::~RegionAuthoring() = default;

void RegionAuthoring::populateRegionsMenu(QMenu* menu)
{
    menu->addAction(m_draw);
    menu->addAction(m_aroundSelection);
    menu->addAction(m_rename);
    menu->addAction(m_delete);
    menu->addSeparator();
    menu->addAction(m_clipSelected);
    menu->addSeparator();
    menu->addAction(m_propose);
    menu->addAction(m_accept);
    menu->addAction(m_discard);
    menu->addSeparator();
    menu->addAction(m_showBoxes);
    menu->addAction(m_colourByRegion);
    menu->addAction(m_showPlanes);
    menu->addSeparator();
    menu->addAction(m_dock->toggleViewAction());
}

void RegionAuthoring::updateActions()
{
    const Selection& s = m_document->selection();
    const bool regionSelected = s.kind == SelectionKind::Region && !s.empty();
    m_rename->setEnabled(regionSelected && s.ids.size() == 1);
    m_delete->setEnabled(regionSelected);
    bool clippable = false;
    if (!m_document->scene().regions.empty())
        for (const std::string& id : selectedPartIds(m_document->scene(), s))
            if (const model::Part* part = m_document->scene().findPart(id);
                part && model::partStraddlesRegions(m_document->scene(), *part)) {
                clippable = true;
                break;
            }
    m_clipSelected->setEnabled(clippable);
    m_accept->setEnabled(m_proposal.has_value() && !m_proposal->regions.empty());
    m_discard->setEnabled(m_proposal.has_value());
}

// --- edits ---------------------------------------------------------------------

bool RegionAuthoring::addRegionAroundSelection()
{
    const model::Scene& scene = m_document->scene();
    const std::vector<std::string> faces = selectedFaceIds(scene, m_document->selection());
    model::Box3 box = faces.empty() ? model::Box3{} : boundsOfFaces(scene, faces);
    if (box.empty) {
        box = model::Box3{};
        for (const model::Object& object : scene.objects)
            for (const model::Part& part : object.parts)
                for (const model::Vec3& v : part.vertices)
                    box.extend(v);
    }
    if (box.empty) {
        emit statusMessage(tr("The scene is empty: draw a region with the region tool"));
        return false;
    }
    const GizmoSnap& snap = m_viewport->snap();
    const double pad = snap.enabled && snap.step > 0.0 ? 0.5 * snap.step : 0.05;
    model::Region region;
    region.id = scene.uniqueId("region");
    for (int a = 0; a < 3; ++a) {
        double lo = box.min[a], hi = box.max[a];
        if (hi - lo < 1e-6) // a flat selection still gets a box with a thickness
            lo -= pad, hi += pad;
        if (snap.enabled && snap.step > 0.0) { // outwards to the grid
            lo = std::floor(lo / snap.step + 1e-9) * snap.step;
            hi = std::ceil(hi / snap.step - 1e-9) * snap.step;
        }
        region.min[a] = lo;
        region.max[a] = hi;
    }
    const std::string id = region.id;
    if (!m_document->push(new AddRegion(m_document, std::move(region))))
        return false;
    m_document->setSelection(Selection::single(SelectionKind::Region, id));
    return true;
}

bool RegionAuthoring::clipPartsToRegions(const std::vector<std::string>& partIds)
{
    std::vector<std::string> straddling;
    for (const std::string& id : partIds)
        if (const model::Part* part = m_document->scene().findPart(id);
            part && model::partStraddlesRegions(m_document->scene(), *part))
            straddling.push_back(id);
    if (straddling.empty()) {
        emit statusMessage(tr("No selected part straddles a region boundary"));
        return false;
    }
    std::vector<std::string> pieces;
    bool ok = true;
    if (straddling.size() == 1) {
        auto* command = new ClipPartToRegions(m_document, straddling.front());
        ok = m_document->push(command);
        if (ok)
            pieces = command->pieces();
    } else {
        m_document->beginMacro(tr("Clip %n part(s) to regions", nullptr, int(straddling.size())));
        for (const std::string& id : straddling) {
            auto* command = new ClipPartToRegions(m_document, id);
            if (!m_document->push(command)) {
                ok = false;
                break;
            }
            const std::vector<std::string> made = command->pieces();
            pieces.insert(pieces.end(), made.begin(), made.end());
        }
        ok = m_document->endMacro() && ok;
    }
    if (!ok)
        return false;
    m_document->setSelection(Selection::of(SelectionKind::Part, pieces));
    emit statusMessage(tr("Clipped to regions: %n piece(s)", nullptr, int(pieces.size())));
    return true;
}

bool RegionAuthoring::clipSelectedParts()
{
    return clipPartsToRegions(selectedPartIds(m_document->scene(), m_document->selection()));
}

std::string RegionAuthoring::clippablePartOf(const std::vector<std::string>& idPath) const
{
    const model::Scene& scene = m_document->scene();
    if (scene.regions.empty())
        return {};
    for (auto it = idPath.rbegin(); it != idPath.rend(); ++it)
        if (const model::Part* part = scene.findPart(*it))
            return model::partStraddlesRegions(scene, *part) ? part->id : std::string();
    return {};
}

bool RegionAuthoring::proposeRegions()
{
    QApplication::setOverrideCursor(Qt::WaitCursor);
    const model::Scene& scene = m_document->scene();
    model::Result<solver::RegionProposal> proposed = solver::proposeRegions(scene);
    // The figures of the scene as it is, beside the proposal's.
    std::optional<solver::BspComparison> now = m_figures->comparison();
    if (!now || m_figures->stale())
        now = solver::compareWithSingleBsp(scene);
    QApplication::restoreOverrideCursor();

    if (!proposed || proposed->regions.empty()) {
        const QString reason = proposed ? tr("no regions could be proposed") : toQString(proposed.error().message);
        emit statusMessage(tr("No proposal: %1").arg(reason));
        discardProposal();
        return false;
    }
    solver::RegionProposal& proposal = *proposed;
    QString text = tr("<b>Proposed: %n region(s)</b>", nullptr, int(proposal.regions.size())) + QStringLiteral("<br>") +
                   tr("%1 fragments, %2 splits, depth %3")
                       .arg(proposal.figures.fragments)
                       .arg(proposal.figures.splits)
                       .arg(proposal.figures.maxDepth);
    if (now && now->authored && !scene.regions.empty())
        text += QStringLiteral("<br>") +
                tr("Current regions: %1 fragments, %2 splits").arg(now->authored->fragments).arg(now->authored->splits);
    if (now && now->baseline)
        text += QStringLiteral("<br>") +
                tr("Single BSP: %1 fragments, %2 splits").arg(now->baseline->fragments).arg(now->baseline->splits);
    if (!proposal.straddlingParts.empty())
        text += QStringLiteral("<br>") +
                tr("%n part(s) cross the proposed planes; after accepting, clip them from the Diagnostics "
                   "panel or the Regions menu.",
                   nullptr, int(proposal.straddlingParts.size()));
    m_viewport->setLayer(layerName(kRegionProposalLayer), buildProposalLayer(proposal.regions));
    m_proposal = std::move(proposal);
    m_dock->showProposal(text, m_accept, m_discard);
    m_dock->show();
    m_dock->raise();
    updateActions();
    emit statusMessage(tr("Proposed %n region(s): accept or discard them in the Regions panel", nullptr,
                          int(m_proposal->regions.size())));
    return true;
}

bool RegionAuthoring::acceptProposal()
{
    if (!m_proposal || m_proposal->regions.empty())
        return false;
    const std::vector<model::Region> regions = m_proposal->regions;
    const std::vector<model::Region> existing = m_document->scene().regions;
    m_proposal.reset(); // before the edit: the change signals must not discard it again
    m_viewport->removeLayer(layerName(kRegionProposalLayer));
    m_dock->hideProposal();
    m_document->beginMacro(tr("Accept %n proposed region(s)", nullptr, int(regions.size())));
    bool ok = true;
    for (auto it = existing.rbegin(); it != existing.rend() && ok; ++it)
        ok = m_document->push(new RemoveRegion(m_document, it->id));
    for (const model::Region& region : regions) {
        if (!ok)
            break;
        ok = m_document->push(new AddRegion(m_document, region));
    }
    ok = m_document->endMacro() && ok;
    updateActions();
    if (ok)
        emit statusMessage(tr("Accepted %n region(s)", nullptr, int(regions.size())));
    return ok;
}

void RegionAuthoring::discardProposal()
{
    const bool had = m_proposal.has_value();
    m_proposal.reset();
    m_viewport->removeLayer(layerName(kRegionProposalLayer));
    if (m_dock)
        m_dock->hideProposal();
    if (had)
        updateActions();
}

// --- layers ----------------------------------------------------------------------

void RegionAuthoring::updateBoxesLayer()
{
    const QString name = layerName(kRegionBoxesLayer);
    if (!m_showBoxes->isChecked()) {
        m_viewport->removeLayer(name);
        return;
    }
    const Selection& s = m_document->selection();
    m_viewport->setLayer(name,
                         buildRegionBoxesLayer(m_document->scene(),
                                               s.kind == SelectionKind::Region ? s.ids : std::vector<std::string>{}));
}

void RegionAuthoring::updateColoursLayer()
{
    m_colouredFaces.clear();
    if (m_colourByRegion->isChecked())
        m_colouredFaces = colourFacesByRegion(m_document->scene());
    uploadColoursLayer();
}

void RegionAuthoring::uploadColoursLayer()
{
    const QString name = layerName(kRegionColoursLayer);
    if (!m_colourByRegion->isChecked()) {
        m_viewport->removeLayer(name);
        return;
    }
    // Like the viewport's own surfaces: without back faces when it hides them,
    // so rooms can be looked into from outside.
    const Camera& camera = m_viewport->camera();
    const Viewer viewer{camera.eye(), camera.forward(), camera.orthographic()};
    m_viewport->setLayer(name,
                         buildPartsByRegionLayer(m_colouredFaces, m_viewport->cullBackFaces() ? &viewer : nullptr));
}

void RegionAuthoring::updatePlanesLayer()
{
    const QString name = layerName(kSeparatingPlanesLayer);
    if (!m_showPlanes->isChecked()) {
        m_viewport->removeLayer(name);
        return;
    }
    m_viewport->setLayer(name, buildSeparatingPlanesLayer(regionalTreeOf(m_document->scene()), m_highlightedPlane));
}

} // namespace regio::editor
