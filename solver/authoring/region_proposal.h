#pragma once
// Proposed regions for a scene: the paper leaves region placement to "someone
// else (perhaps a more clever fellow)" (§3) and otherwise offers a
// patch-count subdivision of space (the solver's RegionsMode::Auto). This
// heuristic looks for what an author would do instead: axis-aligned planes
// that pass between the parts, so that no part is cut (§3, "placement of
// individual objects or small groups of objects into unambiguously defined
// subspaces").
//
// Faces lying on the scene's bounding box (the room's walls, floor and
// ceiling) form the shell: every plane crosses them and the solver clips them
// at the separating planes at the price of one piece per region, so they do
// not block a plane. Every other part is an item with the bounding box of its
// non-shell faces. Starting from the scene bounds, the items' boxes are swept
// along each axis; a gap where no item box reaches across is a possible plane
// (in the middle of the gap). The most balanced plane (estimated patches on
// either side, shell included) over the three axes splits the group; ties go
// to the wider gap, then the lower axis. A group stops splitting when its
// estimated patches are at most the threshold (the same measure as the auto
// mode) or when it holds one item. A group above the threshold with no gap
// (parts spread so that every plane hits one) is cut where the plane crosses
// the fewest parts, preferring planes that leave at least a quarter of the
// patches on each side; those parts are returned as straddling, for
// model::clipPartToRegions. With cutParts off such a group stays whole.
//
// The leaf boxes tile the scene bounds (touching, never overlapping), so the
// regional tree always separates them; each gets the suggested BSP order of
// its contents (solver/authoring/bsp_suggest.h). The planes are chosen by
// counting patches; what they cost the BSP trees is measured afterwards, and
// a proposal that costs more fragments than fewer cuts, or than one region,
// gives way to those (RegionProposalOptions::neverWorseThanOneRegion).
#include "model/diagnostic.h"
#include "model/result.h"
#include "model/scene.h"
#include "solver/authoring/bsp_figures.h"
#include "solver/authoring/bsp_suggest.h"

#include <optional>
#include <string>
#include <vector>

namespace regio::solver {

struct RegionProposalOptions {
    // Same meaning and default as PrepareOptions::autoRegionPatchThreshold.
    int patchThreshold = kAutoRegionPatchThreshold;
    std::optional<double> patchSize; // empty = the scene's solver settings
    // When a group above the threshold has no gap: true cuts it where the
    // plane crosses the fewest parts, false keeps it whole (no part but the
    // shell is ever cut). On the generated room of 100 objects cutting 9
    // parts gave 37 regions and 1500 fragments against 3 regions and 2472.
    bool cutParts = true;
    bool suggestOrders = true; // fill each region's bspOrder with the suggested order
    // Never more BSP fragments than one region around everything with its
    // suggested order: the sweep also competes with itself cutting no part
    // and with that one region, and the fewest fragments win. Off: the
    // sweep as it is (for tests of where it puts its planes).
    bool neverWorseThanOneRegion = true;
    SuggestOptions suggest;
};

struct RegionProposal {
    // Regions "region-1", "region-2", ... (fresh ids for this scene), to
    // replace the scene's own; their boxes tile the scene bounds.
    std::vector<model::Region> regions;
    // Parts the planes cross (the shell, or a part no gap could avoid): the
    // candidates for model::clipPartToRegions.
    std::vector<std::string> straddlingParts;
    // The scene with these regions, prepared by the solver (authored mode).
    SceneBspFigures figures;
    // The fragments of one region around everything with its suggested
    // order, where the proposal compared with it; -1 otherwise.
    int singleRegionFragments = -1;
};

// Refused when the scene cannot be prepared (its errors). A scene without
// faces gives an empty proposal.
model::Result<RegionProposal> proposeRegions(const model::Scene& scene, const RegionProposalOptions& options = {});

// The scene with `regions` instead of its own (for previews and comparisons).
model::Scene withRegions(const model::Scene& scene, std::vector<model::Region> regions);

} // namespace regio::solver
