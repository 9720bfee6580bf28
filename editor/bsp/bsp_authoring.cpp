#include "editor/bsp/bsp_authoring.h"

#include "editor/bsp/bsp_layers.h"
#include "editor/bsp/bsp_order_dock.h"
#include "editor/bsp/painter_playback.h"
#include "editor/document/commands/bsp_order_commands.h"
#include "editor/document/qt_conversions.h"
#include "editor/document/scene_document.h"
#include "editor/viewport/viewport.h"
#include "model/geometry/region_clip.h"

#include <QAction>
#include <QApplication>
#include <QMenu>

#include <algorithm>

namespace regio::editor {

namespace {

model::Box3 regionBox(const model::Region& region)
{
    model::Box3 box;
    box.min = region.min;
    box.max = region.max;
    box.empty = false;
    return box;
}

// Validation's rule: an order may only name faces with area inside the box.
bool faceInRegion(const model::Scene& scene, const model::Region& region, const std::string& faceId)
{
    const model::Scene::FaceLocation at = scene.locateFace(faceId);
    if (!at.valid())
        return false;
    const model::Part& part = scene.objects[size_t(at.object)].parts[size_t(at.part)];
    const std::vector<model::Vec3> loop = model::loopPositions(part.vertices, part.faces[size_t(at.face)].loop);
    return model::faceTouchesRegionBox(loop, regionBox(region));
}

double sceneSize(const solver::PreparedScene* prepared)
{
    return prepared && !prepared->bounds.empty ? glm::length(prepared->bounds.size()) : 1.0;
}

} // namespace

BspAuthoring::BspAuthoring(SceneDocument* document, Viewport* viewport, QWidget* dockParent)
    : QObject(dockParent)
    , m_document(document)
    , m_viewport(viewport)
    , m_analyser(new BspAnalyser(document, this))
    , m_playback(new PainterPlayback(document, viewport, this))
{
    m_suggestAction = new QAction(tr("&Suggest Order"), this);
    m_suggestAction->setStatusTip(
        tr("Compute a low-split root order for the region and compare it with the current one"));
    connect(m_suggestAction, &QAction::triggered, this, &BspAuthoring::suggestOrder);
    m_applyAction = new QAction(tr("&Apply Suggested Order"), this);
    connect(m_applyAction, &QAction::triggered, this, &BspAuthoring::applySuggestion);
    m_discardAction = new QAction(tr("&Discard Suggested Order"), this);
    connect(m_discardAction, &QAction::triggered, this, &BspAuthoring::discardSuggestion);
    m_fragmentsAction = new QAction(tr("Show &Fragments"), this);
    m_fragmentsAction->setCheckable(true);
    m_fragmentsAction->setStatusTip(tr("Draw the region's BSP fragments: splits orange, region cuts cyan"));
    connect(m_fragmentsAction, &QAction::toggled, this, &BspAuthoring::setShowFragments);
    m_insertPickAction = new QAction(tr("&Pick Face to Insert"), this);
    m_insertPickAction->setCheckable(true);
    m_insertPickAction->setStatusTip(tr("Click faces in the viewport to add them to the region's BSP order"));
    connect(m_insertPickAction, &QAction::triggered, this, [this](bool on) {
        if (on)
            startInsertPick();
        else
            cancelTools();
    });
    m_insertSelectedAction = new QAction(tr("Insert &Selected Faces"), this);
    connect(m_insertSelectedAction, &QAction::triggered, this, &BspAuthoring::insertSelectedFaces);
    m_playPointAction = new QAction(tr("Painter Order from &Point…"), this);
    m_playPointAction->setStatusTip(
        tr("Click a surface: the elements are painted in the solver's back-to-front order from there"));
    connect(m_playPointAction, &QAction::triggered, this, [this] { startPlaybackPick(false); });
    m_playPatchAction = new QAction(tr("Painter Order from Pa&tch…"), this);
    m_playPatchAction->setStatusTip(tr("Click a surface: the patch there shoots, as in the solver"));
    connect(m_playPatchAction, &QAction::triggered, this, [this] { startPlaybackPick(true); });
    m_stopPlaybackAction = new QAction(tr("S&top Painter Order"), this);
    connect(m_stopPlaybackAction, &QAction::triggered, m_playback, &PainterPlayback::stop);

    m_dock = new BspOrderDock(this, document, dockParent);

    connect(document, &SceneDocument::regionsChanged, this, &BspAuthoring::onRegionsChanged);
    connect(document, &SceneDocument::sceneReset, this, &BspAuthoring::onRegionsChanged);
    connect(document, &SceneDocument::selectionChanged, this, &BspAuthoring::onSelectionChanged);
    // A suggestion describes the scene it was computed on; any change drops it.
    for (auto signal : {&SceneDocument::objectsChanged, &SceneDocument::geometryChanged, &SceneDocument::regionsChanged,
                        &SceneDocument::sceneReset})
        connect(document, signal, this, [this] {
            if (m_suggestion)
                discardSuggestion();
        });
    connect(m_analyser, &BspAnalyser::analysed, this, [this] {
        // Node indices belong to the previous preparation.
        setHighlightedNode(-1);
        updateFragmentLayer();
    });
    connect(m_playback, &PainterPlayback::changed, this, &BspAuthoring::updateActions);
    onRegionsChanged();
}

BspAuthoring::~BspAuthoring()
{
    // The guarded pointer is read once: each read may find the viewport gone.
    Viewport* viewport = m_viewport;
    if (viewport && (viewport->tool() == m_insertTool.get() || viewport->tool() == m_playbackTool.get()))
        viewport->setTool(nullptr);
}

QString BspAuthoring::fragmentLayerName() { return QStringLiteral("bsp.fragments"); }
QString BspAuthoring::nodeLayerName() { return QStringLiteral("bsp.node"); }

void BspAuthoring::populateBspMenu(QMenu* menu)
{
    menu->addAction(m_suggestAction);
    menu->addAction(m_applyAction);
    menu->addAction(m_discardAction);
    menu->addSeparator();
    menu->addAction(m_insertPickAction);
    menu->addAction(m_insertSelectedAction);
    menu->addSeparator();
    menu->addAction(m_fragmentsAction);
    menu->addSeparator();
    menu->addAction(m_playPointAction);
    menu->addAction(m_playPatchAction);
    menu->addAction(m_stopPlaybackAction);
    updateActions();
}

void BspAuthoring::updateActions()
{
    const bool region = !m_region.empty();
    m_suggestAction->setEnabled(region);
    m_applyAction->setEnabled(m_suggestion.has_value());
    m_discardAction->setEnabled(m_suggestion.has_value());
    m_fragmentsAction->setChecked(m_showFragments);
    m_insertPickAction->setEnabled(region);
    m_insertPickAction->setChecked(insertPickActive());
    m_insertSelectedAction->setEnabled(region && !m_document->selection().empty());
    m_stopPlaybackAction->setEnabled(m_playback->active() || playbackPickActive());
}

// --- region ---------------------------------------------------------------------

void BspAuthoring::setCurrentRegion(const std::string& regionId)
{
    if (regionId == m_region || !m_document->scene().findRegion(regionId))
        return;
    m_region = regionId;
    if (m_suggestion)
        discardSuggestion();
    setHighlightedNode(-1);
    updateFragmentLayer();
    updateActions();
    emit currentRegionChanged(toQString(m_region));
}

std::vector<std::string> BspAuthoring::currentOrder() const
{
    const model::Region* region = m_document->scene().findRegion(m_region);
    return region ? region->bspOrder : std::vector<std::string>{};
}

void BspAuthoring::onRegionsChanged()
{
    const model::Scene& scene = m_document->scene();
    if (!m_region.empty() && scene.findRegion(m_region))
        return;
    m_region = scene.regions.empty() ? std::string() : scene.regions.front().id;
    if (insertPickActive() && m_region.empty())
        m_viewport->setTool(nullptr);
    updateActions();
    emit currentRegionChanged(toQString(m_region));
}

void BspAuthoring::onSelectionChanged()
{
    const Selection& selection = m_document->selection();
    if (selection.kind == SelectionKind::Region && selection.ids.size() == 1)
        setCurrentRegion(selection.ids.front());
    updateActions();
}

// --- edits ---------------------------------------------------------------------

bool BspAuthoring::moveEntry(int from, int to)
{
    const int count = int(currentOrder().size());
    if (from == to || from < 0 || to < 0 || from >= count || to >= count)
        return false;
    return m_document->push(new MoveBspEntry(m_document, m_region, from, to));
}

bool BspAuthoring::moveToTop(int index) { return moveEntry(index, 0); }

bool BspAuthoring::removeEntry(int index)
{
    if (index < 0 || index >= int(currentOrder().size()))
        return false;
    return m_document->push(new RemoveBspEntry(m_document, m_region, index));
}

bool BspAuthoring::insertFace(const std::string& faceId, int index)
{
    const model::Scene& scene = m_document->scene();
    const model::Region* region = scene.findRegion(m_region);
    if (!region)
        return false;
    if (std::find(region->bspOrder.begin(), region->bspOrder.end(), faceId) != region->bspOrder.end()) {
        emit statusMessage(tr("%1 is already in the BSP order of %2").arg(toQString(faceId), toQString(m_region)));
        return false;
    }
    if (!faceInRegion(scene, *region, faceId)) {
        emit statusMessage(tr("%1 is not inside region %2").arg(toQString(faceId), toQString(m_region)));
        return false;
    }
    if (!m_document->push(new InsertBspEntry(m_document, m_region, faceId, index)))
        return false;
    emit statusMessage(tr("Added %1 to the BSP order of %2").arg(toQString(faceId), toQString(m_region)));
    return true;
}

int BspAuthoring::insertSelectedFaces()
{
    const model::Scene& scene = m_document->scene();
    const model::Region* region = scene.findRegion(m_region);
    if (!region)
        return 0;
    std::vector<std::string> faces;
    for (const std::string& face : selectedFaceIds(scene, m_document->selection()))
        if (std::find(region->bspOrder.begin(), region->bspOrder.end(), face) == region->bspOrder.end() &&
            faceInRegion(scene, *region, face))
            faces.push_back(face);
    if (faces.empty()) {
        emit statusMessage(tr("No selected face can be added to the BSP order of %1").arg(toQString(m_region)));
        return 0;
    }
    const std::string regionId = m_region;
    m_document->beginMacro(
        tr("Add %n face(s) to the BSP order of %1", nullptr, int(faces.size())).arg(toQString(regionId)));
    for (const std::string& face : faces)
        m_document->push(new InsertBspEntry(m_document, regionId, face));
    return m_document->endMacro() ? int(faces.size()) : 0;
}

// --- suggestion ----------------------------------------------------------------

bool BspAuthoring::suggestOrder()
{
    if (m_region.empty())
        return false;
    QApplication::setOverrideCursor(Qt::WaitCursor);
    auto result = solver::suggestBspOrder(m_document->scene(), m_region);
    QApplication::restoreOverrideCursor();
    if (!result) {
        emit statusMessage(tr("No suggestion: %1").arg(toQString(result.error().message)));
        return false;
    }
    m_suggestion = std::move(*result);
    updateActions();
    emit suggestionChanged();
    return true;
}

bool BspAuthoring::applySuggestion()
{
    if (!m_suggestion)
        return false;
    const solver::BspOrderSuggestion suggestion = std::move(*m_suggestion);
    m_suggestion.reset();
    const bool ok = m_document->push(new SetBspOrder(m_document, suggestion.regionId, suggestion.order));
    updateActions();
    emit suggestionChanged();
    return ok;
}

void BspAuthoring::discardSuggestion()
{
    if (!m_suggestion)
        return;
    m_suggestion.reset();
    updateActions();
    emit suggestionChanged();
}

// --- views -----------------------------------------------------------------------

void BspAuthoring::setShowFragments(bool on)
{
    if (on == m_showFragments)
        return;
    m_showFragments = on;
    updateFragmentLayer();
    updateActions();
    emit viewsChanged();
}

void BspAuthoring::updateFragmentLayer()
{
    if (!m_viewport)
        return;
    const BspAnalysis& analysis = m_analyser->current();
    const int region = analysis.preparedRegion(m_region);
    if (!m_showFragments || !analysis.prepared || !analysis.scene) {
        m_viewport->removeLayer(fragmentLayerName());
        return;
    }
    // A scene without regions is one tree: show all of it.
    const bool whole = m_document->scene().regions.empty();
    if (region < 0 && !whole) {
        m_viewport->removeLayer(fragmentLayerName());
        return;
    }
    m_viewport->setLayer(fragmentLayerName(),
                         buildFragmentLayer(*analysis.scene, *analysis.prepared, whole ? -1 : region));
}

void BspAuthoring::setHighlightedNode(int node)
{
    const BspAnalysis& analysis = m_analyser->current();
    if (!analysis.prepared || node < 0 || size_t(node) >= analysis.prepared->nodes.size())
        node = -1;
    if (node == m_node)
        return;
    m_node = node;
    updateNodeLayer();
    emit viewsChanged();
}

void BspAuthoring::updateNodeLayer()
{
    if (!m_viewport)
        return;
    const BspAnalysis& analysis = m_analyser->current();
    if (m_node < 0 || !analysis.prepared) {
        m_viewport->removeLayer(nodeLayerName());
        return;
    }
    m_viewport->setLayer(nodeLayerName(), buildNodePlaneLayer(*analysis.prepared, m_node));
}

// --- tools -----------------------------------------------------------------------

void BspAuthoring::startInsertPick()
{
    if (m_region.empty() || !m_viewport)
        return;
    if (!m_insertTool)
        m_insertTool = std::make_unique<FacePickTool>(
            m_document, [this](const PickHit& hit) { insertFace(hit.faceId); },
            [this] {
                updateActions();
                emit viewsChanged();
            });
    m_viewport->setTool(m_insertTool.get());
    emit statusMessage(tr("Click faces to add them to the BSP order of %1; Esc ends").arg(toQString(m_region)));
    updateActions();
    emit viewsChanged();
}

void BspAuthoring::startPlaybackPick(bool fromPatch)
{
    if (!m_viewport)
        return;
    m_playbackFromPatch = fromPatch;
    if (!m_playbackTool)
        m_playbackTool = std::make_unique<FacePickTool>(
            m_document, [this](const PickHit& hit) { startPlaybackAt(hit, m_playbackFromPatch); },
            [this] {
                updateActions();
                emit viewsChanged();
            },
            true);
    m_viewport->setTool(m_playbackTool.get());
    emit statusMessage(fromPatch ? tr("Click a surface: its patch shoots") : tr("Click a surface to paint from there"));
    updateActions();
    emit viewsChanged();
}

bool BspAuthoring::insertPickActive() const
{
    const Viewport* viewport = m_viewport;
    return m_insertTool && viewport && viewport->tool() == m_insertTool.get();
}
bool BspAuthoring::playbackPickActive() const
{
    const Viewport* viewport = m_viewport;
    return m_playbackTool && viewport && viewport->tool() == m_playbackTool.get();
}

void BspAuthoring::cancelTools()
{
    if (insertPickActive() || playbackPickActive())
        m_viewport->setTool(nullptr);
}

bool BspAuthoring::startPlaybackAt(const PickHit& hit, bool fromPatch)
{
    const auto prepared = m_playback->prepared();
    if (!prepared) {
        emit statusMessage(tr("The scene cannot be prepared; see the diagnostics"));
        return false;
    }
    bool ok;
    if (fromPatch)
        ok = m_playback->startFromPatch(m_playback->patchAt(hit.faceId, hit.point));
    else
        ok = m_playback->startFromPoint(eyeAbovePick(hit, sceneSize(prepared.get())));
    if (ok)
        emit statusMessage(tr("Painter order: %n element(s), back to front", nullptr, m_playback->stepCount()));
    return ok;
}

} // namespace regio::editor
