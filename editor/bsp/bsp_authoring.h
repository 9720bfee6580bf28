#pragma once
// BSP root orders (paper §5.3) as an authoring feature: the BSP menu, the BSP
// order dock, the fragment and node-plane layers, the face pick tools and the
// painter-order playback. Every edit is one undo command on the document
// (editor/document/commands/bsp_order_commands.h), so orders are saved with the scene
// and reproduced exactly by regio-solve. The public edits work without the
// dock, so tests drive the same code the dock's buttons do.
#include "editor/bsp/bsp_analysis.h"
#include "editor/bsp/face_pick_tool.h"
#include "solver/authoring/bsp_suggest.h"

#include <QObject>
#include <QPointer>
#include <QString>

#include <memory>
#include <optional>
#include <string>
#include <vector>

class QAction;
class QMenu;
class QWidget;

namespace regio::editor {

class BspOrderDock;
class PainterPlayback;
class SceneDocument;
class Viewport;

class BspAuthoring : public QObject {
    Q_OBJECT
public:
    BspAuthoring(SceneDocument* document, Viewport* viewport, QWidget* dockParent);
    ~BspAuthoring() override;

    BspOrderDock* dock() const { return m_dock; }
    BspAnalyser* analyser() const { return m_analyser; }
    PainterPlayback* playback() const { return m_playback; }
    void populateBspMenu(QMenu* menu);

    // --- the region being edited -------------------------------------------
    // Empty when the scene has no regions.
    const std::string& currentRegion() const { return m_region; }
    void setCurrentRegion(const std::string& regionId);
    // The current region's order (empty when none).
    std::vector<std::string> currentOrder() const;

    // --- edits (each one undo step; false if refused or nothing to do) -----
    bool moveEntry(int from, int to);
    bool moveToTop(int index);
    bool removeEntry(int index);
    // Inserts at `index` (-1 = append). Refused for faces already listed and
    // faces that have no area inside the region box (validation's rule).
    bool insertFace(const std::string& faceId, int index = -1);
    // The selected faces (faces of selected parts and objects) that can be
    // inserted, appended in scene order as one undo step. Returns how many.
    int insertSelectedFaces();

    // --- suggested order -----------------------------------------------------
    // Computes the suggestion for the current region; it is shown, not applied.
    bool suggestOrder();
    const std::optional<solver::BspOrderSuggestion>& suggestion() const { return m_suggestion; }
    bool applySuggestion(); // SetBspOrder: one undo step
    void discardSuggestion();

    // --- views ----------------------------------------------------------------
    bool fragmentsShown() const { return m_showFragments; }
    void setShowFragments(bool on);
    // The BSP node (index into the analysis' prepared scene) whose plane is
    // highlighted; -1 = none.
    int highlightedNode() const { return m_node; }
    void setHighlightedNode(int node);

    // Tools: the next click on a face inserts it / starts a playback there
    // (a free point nudged off the face, or the patch under the click).
    void startInsertPick();
    void startPlaybackPick(bool fromPatch);
    bool insertPickActive() const;
    bool playbackPickActive() const;
    void cancelTools();
    // What a playback pick does with a hit (the tool calls it; tests too).
    bool startPlaybackAt(const PickHit& hit, bool fromPatch);

    // Layer names in the viewport.
    static QString fragmentLayerName();
    static QString nodeLayerName();

signals:
    void currentRegionChanged(const QString& regionId);
    void suggestionChanged();
    void viewsChanged(); // fragments shown, node highlighted, tools
    void statusMessage(const QString& message);

private:
    void onRegionsChanged();
    void onSelectionChanged();
    void updateFragmentLayer();
    void updateNodeLayer();
    void updateActions();

    SceneDocument* m_document;
    // Destroyed before this object when the window closes.
    QPointer<Viewport> m_viewport;
    BspAnalyser* m_analyser;
    PainterPlayback* m_playback;
    BspOrderDock* m_dock;
    std::string m_region;
    std::optional<solver::BspOrderSuggestion> m_suggestion;
    bool m_showFragments = false;
    int m_node = -1;
    std::unique_ptr<FacePickTool> m_insertTool;
    std::unique_ptr<FacePickTool> m_playbackTool;
    bool m_playbackFromPatch = false;

    QAction* m_suggestAction = nullptr;
    QAction* m_applyAction = nullptr;
    QAction* m_discardAction = nullptr;
    QAction* m_fragmentsAction = nullptr;
    QAction* m_insertPickAction = nullptr;
    QAction* m_insertSelectedAction = nullptr;
    QAction* m_playPointAction = nullptr;
    QAction* m_playPatchAction = nullptr;
    QAction* m_stopPlaybackAction = nullptr;
};

} // namespace regio::editor
