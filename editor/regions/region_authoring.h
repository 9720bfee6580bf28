#pragma once
// Region authoring: the Regions menu and everything behind it. The paper
// leaves placing regions to "someone else" (§3); this is where the author
// does it and sees what it costs:
//  - the region tool (draw a box, resize it by its face handles),
//  - the Regions dock (contents and BSP fragments per region, the regional tree),
//  - viewport layers: translucent boxes, faces coloured by region, the
//    separating planes of the regional tree (§5.2),
//  - "Clip Part to Regions", the fix for a straddling part, also offered on
//    the diagnostics dock's entries,
//  - automatic regions (solver/authoring/region_proposal.h) previewed with their
//    figures before they are accepted (one undo step) or discarded.
// Every edit is public and works without dialogs, so tests drive the same
// code paths the menus do.
#include "editor/regions/region_layers.h"
#include "model/scene.h"
#include "solver/authoring/region_proposal.h"

#include <QObject>

#include <optional>
#include <string>
#include <vector>

class QAction;
class QMenu;
class QWidget;

namespace regio::editor {

class Authoring;
class DiagnosticsDock;
class RegionBoxTool;
class RegionFiguresWatcher;
class RegionsDock;
class SceneDocument;
class Viewport;

class RegionAuthoring : public QObject {
    Q_OBJECT
public:
    // `authoring` renames and deletes; `diagnostics` (may be null) gets the
    // clip fix in its context menu.
    RegionAuthoring(SceneDocument* document, Viewport* viewport, Authoring* authoring, DiagnosticsDock* diagnostics,
                    QWidget* dialogParent);
    ~RegionAuthoring() override;

    void populateRegionsMenu(QMenu* menu);
    RegionsDock* dock() const { return m_dock; }
    RegionBoxTool* tool() const { return m_tool; }
    RegionFiguresWatcher* figures() const { return m_figures; }

    QAction* drawAction() const { return m_draw; }
    QAction* showBoxesAction() const { return m_showBoxes; }
    QAction* colourByRegionAction() const { return m_colourByRegion; }
    QAction* showPlanesAction() const { return m_showPlanes; }
    QAction* proposeAction() const { return m_propose; }
    QAction* acceptAction() const { return m_accept; }
    QAction* discardAction() const { return m_discard; }
    QAction* clipSelectedAction() const { return m_clipSelected; }

    // --- edits (each one undo step; false if nothing was done) -----------
    // A region around the selected parts' bounds (or the whole scene), selected.
    bool addRegionAroundSelection();
    // Clips each given part that straddles region boundaries.
    bool clipPartsToRegions(const std::vector<std::string>& partIds);
    bool clipSelectedParts();

    // Computes a proposal and shows it (layer and dock panel); false when the
    // scene cannot be prepared (the reason goes to the status bar).
    bool proposeRegions();
    const std::optional<solver::RegionProposal>& proposal() const { return m_proposal; }
    // Replaces the scene's regions by the proposal's: one undo step.
    bool acceptProposal();
    void discardProposal();

    // The clip fix for a diagnostic's element: the straddling part it names,
    // or empty when the clip cannot fix it.
    std::string clippablePartOf(const std::vector<std::string>& idPath) const;

    void updateActions();

signals:
    void statusMessage(const QString& message);

private:
    void updateBoxesLayer();
    void updateColoursLayer(); // after a scene change: recolours the faces
    void uploadColoursLayer(); // after a view change: the faces seen from the front
    void updatePlanesLayer();

    SceneDocument* m_document;
    Viewport* m_viewport;
    Authoring* m_authoring;
    DiagnosticsDock* m_diagnostics;
    QWidget* m_dialogParent;
    RegionBoxTool* m_tool;
    RegionFiguresWatcher* m_figures;
    RegionsDock* m_dock = nullptr;
    std::optional<solver::RegionProposal> m_proposal;
    int m_highlightedPlane = -1;
    std::vector<ColouredFace> m_colouredFaces;

    QAction* m_draw = nullptr;
    QAction* m_aroundSelection = nullptr;
    QAction* m_rename = nullptr;
    QAction* m_delete = nullptr;
    QAction* m_clipSelected = nullptr;
    QAction* m_propose = nullptr;
    QAction* m_accept = nullptr;
    QAction* m_discard = nullptr;
    QAction* m_showBoxes = nullptr;
    QAction* m_colourByRegion = nullptr;
    QAction* m_showPlanes = nullptr;
};

} // namespace regio::editor
