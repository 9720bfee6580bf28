#pragma once
// Suggested BSP root orders. The paper uses "no heuristic" for the root patch
// of a regional BSP tree and relies on "a well-balanced BSP model supplied by
// a pre-radiosity modelling process" (§5.3), pointing at Thibault and Naylor
// (1987) for heuristics. This is that heuristic, offered to the author:
//
// Greedy, top down: at each subtree the root is the candidate face that
// minimises  splitWeight * splits + balanceWeight * |front - back|  over the
// polygons of that subtree (every face of a small subtree is a candidate,
// an evenly spread sample of a large one). The roots in the order they are
// chosen (pre-order, back subtree before front, as the solver builds) become
// a bspOrder that the solver's builder (buildRegionBsp: lowest rank first,
// unlisted faces after in scene order) reproduces node for node: a face chosen
// in one subtree ranks before every face chosen later, and the simulation
// honours an already listed face wherever it reappears, as the builder will.
//
// Only faces that have area inside the region box are listed (validation
// refuses other entries); a subtree holding only such outsiders gets them in
// scene order, exactly as the builder does with unlisted faces.
#include "model/result.h"
#include "model/scene.h"
#include "solver/authoring/bsp_figures.h"
#include "solver/prepare/face_polygon.h"
#include "solver/prepare/prepared_scene.h"

#include <span>
#include <string>
#include <vector>

namespace regio::solver {

struct SuggestOptions {
    // A split adds a fragment to the scene for good; imbalance only deepens
    // the tree. With these weights a split weighs as much as an imbalance of
    // 100 polygons: fewest splits first, balance decides among near-equals
    // (on the sample scenes 0.1 traded splits for depth, 0 gave deep trees).
    double splitWeight = 1.0;    // w1
    double balanceWeight = 0.01; // w2
    // A subtree with at most this many candidate faces tries each; a larger
    // one tries `sampleSize` of them, evenly spread in scene order.
    int exhaustiveLimit = 200;
    int sampleSize = 50;
};

struct BspOrderSuggestion {
    std::string regionId;
    std::vector<std::string> order; // the bspOrder to apply (face ids)
    BspFigures suggested;           // the tree `order` builds (predicted by the same splitting rules)
    BspFigures current;             // the region's tree with its current order, from prepareScene
};

// One region of the scene (authored mode). Refused when the region is unknown
// or the scene cannot be prepared (the first error is returned).
model::Result<BspOrderSuggestion> suggestBspOrder(const model::Scene& scene, const std::string& regionId,
                                                  const SuggestOptions& options = {});

// Every authored region, with one preparation (a scene without regions gives
// an empty list: its single tree has no order of its own to store).
model::Result<std::vector<BspOrderSuggestion>> suggestBspOrders(const model::Scene& scene,
                                                                const SuggestOptions& options = {});

// --- The greedy order of one region, for tests ----------------------------------

struct GreedyOrder {
    std::vector<int> faces; // face indices (PreparedScene::faces) in rank order
    BspFigures figures;     // of the tree that order builds
};

// The greedy order for one region's polygons (a cell of prepareBspInput).
// `listable[face]` says which faces may be named in the order; plane and face
// identity come from `properties`.
GreedyOrder greedyBspOrder(const std::vector<Properties>& properties, std::vector<FacePolygon> polygons,
                           std::span<const char> listable, const SuggestOptions& options = {});

} // namespace regio::solver
