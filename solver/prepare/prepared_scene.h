#pragma once
// The prepared scene: everything the shooting loop needs, built once from a
// model::Scene by prepareScene() (solver/prepare/prepare.h) and never changed by it
// afterwards except through adaptive subdivision (see "Growing the mesh").
//
// Layout (paper Figure 1, flattened): flat std::vectors of plain structs that
// refer to each other by index (-1 = none), so the shooter can walk them
// thousands of times without chasing pointers, and the whole thing can be
// copied into a worker thread.
//
//   regionalNodes (the regional tree, §5.2)  -> leaves name a Region
//   regions        -> bspRoot names a BspNode (one BSP tree per region, §5.3)
//   nodes          -> [firstFragment, +fragmentCount) fragments on the node's plane
//                  -> [firstPiece,    +pieceCount)    the element pieces painted there
//   faces          -> [firstPatch, +patchCount) patches (§5.4), `elements`
//   patches        -> [firstElement, +elementCount) elements (§5.5)
//   elements       -> 3 indices into `vertices`
//   pieces         -> 3 indices into `pieceVertices`, and the element they belong to
//   every fragment, patch and element names its Properties (= its input face).
//
// Meshing is per INPUT face, not per fragment. The strip method (§5.4) is
// applied to the whole face (less the parts that solids standing on it
// cover: no element straddles a contact line, solver/prepare/covered_parts.h)
// and its patches are split into elements (§5.5);
// the regional clipping (§5.2) and the BSP splits (§5.3) do not touch that
// mesh. So the shooters (patches) and receivers (elements) are the same
// whatever the regions and the BSP root orders: regions change nothing but
// speed, as the paper promises (§3). Meshing each fragment on its own made the
// mesh, and with it the solution, depend on where the planes cut (up to 11 %
// per face on the two-light sample).
//
// The BSP split only decides how elements are PAINTED: every element is cut
// into "pieces", the parts of it lying in the cells of the BSP nodes that hold
// its face's fragments (solver/prepare/pieces.h). A piece is fan-triangulated, and the
// painter paints a node's pieces with the id of their element. An element cut
// by a plane thus appears in several nodes; its form factor is the sum over
// its pieces, exactly as if it had been painted whole in the right place.
//
// Ordering invariants the painter relies on:
//   - patches of one face and elements of one patch are contiguous.
//   - pieces of one node are contiguous: [firstPiece, +pieceCount), in four
//     groups (F = facing along the node plane's normal, O = the opposite
//     orientation; "solid" = the face belongs to a closed part, Properties::solid):
//         [ F solid | F open | O open | O solid ]
//     forwardPieces counts F, forwardSolidPieces the first group and
//     oppositeSolidPieces the last. From an eye in front of the node plane F
//     faces the eye and O shows its back, and the other way round from behind.
//     Back faces are still painted (as blockers with a "no receiver" id,
//     traversal.h), except the closed parts' where no pixel would show them
//     (solver/visibility/closed_back_faces.h). The groups let
//     the painter put coplanar receivers and blockers in the right order
//     (Visibility::render): open back faces first, then the receivers, then
//     solid back faces.
//
// Precision: positions are double (the BSP splits and the strip triangulation
// need it); the rasteriser converts to float in the shooter's frame.
//
// Growing the mesh: adaptive subdivision (§5.7, solver/shooting/) splits
// elements at run time: it builds a new PreparedScene whose element array is
// grouped by patch again (Patch::firstElement/elementCount stay ranges), the
// per-element solver arrays follow the same order
// (Shooting::replaceElementState), InputFace::elements is rebuilt and then
// the pieces with buildPieces (solver/prepare/pieces.h), which recomputes
// everything the painter needs from the elements.
#include "model/geometry/geometry.h"
#include "model/types.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace regio::solver {

using model::Box3;
using model::Plane;
using model::Rgb;
using model::Vec3;

// Attributes shared by every piece of one input face (the paper's Properties
// node, §5.3): split fragments, their patches and elements all point here.
// There is exactly one Properties per input face, at the same index as the
// face in PreparedScene::faces (hot data here, names and bookkeeping there).
struct Properties {
    Plane plane;          // the input face's plane; normal = the face's front side
    Rgb reflectance{0.0}; // diffuse coefficient per channel
    Rgb emission{0.0};    // radiant exitance per unit area (W/m^2 per channel)
    int face = -1;        // index into PreparedScene::faces (== this index)
    // The face belongs to a closed part with volume (a solid: every edge has
    // two faces, at least four faces). Where such a face shows its back on a
    // coplanar receiver, the receiver faces into the solid there (a box
    // standing on a box): the back face must win (Visibility::render).
    bool solid = false;

    // The face emits light in some channel (a light's patches are cut finer
    // and shoot without overshoot).
    bool emits() const { return emission.x > 0.0 || emission.y > 0.0 || emission.z > 0.0; }
};

// One face of the input scene, in scene order (objects, parts, faces). Faces
// the solver cannot use (zero area) are kept with area 0 and no elements, so
// per-face results can still be reported for every id of the file.
struct InputFace {
    std::string id;       // the face id of the file
    std::string objectId; // its object's id, and its material's (for exports that keep them)
    std::string materialId;
    int object = -1; // indices into model::Scene::objects / parts / faces
    int part = -1;
    int faceInPart = -1;
    double area = 0.0;         // area of the input polygon
    std::vector<Vec3> polygon; // the convex polygon the solver meshes (on the plane); empty if unused
    int firstPatch = 0;        // its patches: [firstPatch, firstPatch + patchCount)
    int patchCount = 0;
    std::vector<int> elements; // every element of this face (any order); none where a solid covers it
    // The faces in front of it across a gap of less than kFacingGapPatches
    // patch sizes (solver/prepare/facing_faces.h), ascending.
    std::vector<int> facing;
};

// A convex piece of an input face after clipping by the separating planes
// (§5.2) and splitting by BSP planes (§5.3); it lies on its node's plane.
struct Fragment {
    int properties = -1;
    int node = -1;
    int region = -1;
    int firstPoint = 0; // polygon in PreparedScene::fragmentPoints, CCW seen
    int pointCount = 0; // from its properties' plane normal
    double area = 0.0;
};

// A triangle of the strip triangulation (§5.4): the shooting unit.
struct Patch {
    std::array<int, 3> vertices{}; // indices into PreparedScene::vertices, CCW from the normal
    int properties = -1;
    int node = -1;        // = node of its first element (a patch may span several nodes)
    int firstElement = 0; // its elements: [firstElement, firstElement + elementCount)
    int elementCount = 0;
    double area = 0.0;
    Vec3 centroid{0.0};
};

// A triangle of the element mesh (§5.5): receiver and blocker on the hemicube.
struct Element {
    std::array<int, 3> vertices{}; // indices into PreparedScene::vertices, CCW from the normal
    int patch = -1;
    int properties = -1;
    int node = -1; // node of its first piece (an element cut by a plane has pieces in several)
    double area = 0.0;
    Vec3 centroid{0.0};
    Vec3 normal{0.0}; // = properties' plane normal (copied for locality)
};

// A triangle of an element's part inside one BSP node's cell (see the top of
// this file). The pieces of one element cover exactly its area.
struct Piece {
    std::array<int, 3> vertices{}; // indices into PreparedScene::pieceVertices, CCW from the normal
    int element = -1;
};

// A node of a region's BSP tree (§5.3). All fragments on the node plane (both
// orientations) live here; children are node indices, -1 = empty half-space.
struct BspNode {
    Plane plane;    // plane of the first (root) fragment's face
    int front = -1; // subtree on the side the plane normal points to
    int back = -1;
    int region = -1;
    int firstFragment = 0, fragmentCount = 0, forwardFragments = 0;
    // The pieces painted at this node, grouped [F solid | F open | O open | O solid].
    int firstPiece = 0, pieceCount = 0, forwardPieces = 0;
    int forwardSolidPieces = 0, oppositeSolidPieces = 0;
};

struct RegionStats {
    int inputFaces = 0; // polygons that entered the region's BSP build (face pieces after regional clipping)
    int fragments = 0;  // fragments after BSP splitting
    int splits = 0;     // polygons cut in two by a BSP plane
    int depth = 0;      // nodes on the longest root-to-leaf path (0 = empty region)
    int nodes = 0;
};

struct Region {
    std::string id; // authored region id; "auto-<n>" for automatic regions; "scene" when there are none
    Box3 box;       // the region box (authored, automatic, or the scene bounds)
    // Bounds of what the region's cell actually holds. A face outside every
    // authored box still lands in some cell, so culling must use this, not `box`.
    Box3 bounds;
    int bspRoot = -1; // -1 = the cell holds nothing
    RegionStats stats;
};

// A node of the regional tree (§5.2). Inner: an axis-aligned separating plane
// coordinate[axis] = position; `front` holds the regions with the greater
// coordinate. Leaf: axis = -1 and `region` names the region.
struct RegionalNode {
    int axis = -1;
    double position = 0.0;
    int front = -1;
    int back = -1;
    int region = -1;
    bool isLeaf() const { return axis < 0; }
};

struct PrepareStats {
    int inputFaces = 0;   // faces of the scene with non-zero area
    int regionPieces = 0; // polygons after clipping by the separating planes
    int fragments = 0;    // after BSP splitting, all regions
    int splits = 0;       // BSP splits, all regions
    int maxDepth = 0;     // deepest region BSP tree
    int patches = 0;
    int elements = 0;
    int pieces = 0; // piece triangles painted (solver/prepare/pieces.h)
    // Element pieces that found no node holding their face (rounding). They
    // would be missing from the hemicube; tests assert there are none.
    int lostPieces = 0;
    double lostPieceArea = 0.0;
    double area = 0.0; // total element area (the input faces' area less what solids cover)
};

struct PreparedScene {
    std::vector<InputFace> faces;       // scene order
    std::vector<Properties> properties; // same index as faces

    std::vector<RegionalNode> regionalNodes;
    int regionalRoot = -1; // -1 only for an empty scene
    std::vector<Region> regions;

    std::vector<BspNode> nodes;
    std::vector<Fragment> fragments;
    std::vector<Vec3> fragmentPoints;
    std::vector<Vec3> vertices; // patch and element corners
    std::vector<Patch> patches;
    std::vector<Element> elements;
    // The pieces' corners: the mesh vertices and the split points of pieces,
    // numbered in the order the pieces first use them (solver/prepare/pieces.h).
    std::vector<Vec3> pieceVertices;
    std::vector<Piece> pieces;
    // The foot corners of solids where shadow lines begin
    // (solver/prepare/shadow_lines.h). The light around such a point depends
    // on the direction it is approached from (umbra on one side, full light
    // on the other), so the smooth output gives each element there its own
    // value at the point instead of one average.
    std::vector<Vec3> shadowCorners;

    Box3 bounds;            // of all geometry
    double patchSize = 0.5; // the settings it was meshed with
    int elementsPerPatch = 4;
    PrepareStats stats;
    // A number no other build of the pieces has had (buildPieces sets it):
    // what caches of the faces and pieces (Visibility's) compare to know
    // they are still those of this scene; a copy keeps it with the content.
    std::uint64_t piecesStamp = 0;
};

} // namespace regio::solver
