#pragma once
// Adaptive subdivision with anchoring (paper §5.7, Figure 5; Baum et al. 1991).
//
// After shooting, elements whose radiosity differs from an edge neighbour's
// by more than a relative threshold (on luminance) are split into 4 through
// their edge midpoints, never below a smallest edge length. The mesh of every
// input face is kept as a hierarchy inside the PreparedScene itself: a split
// element stays in `elements` but becomes inactive (it has children), its
// four children and any new midpoint vertices are appended to `elements` and
// `vertices`, and InputFace::elements always lists the face's active leaves.
//
// Topology: per input face, a map from each edge (sorted vertex pair) to the
// active elements that have exactly that edge, plus the midpoint created on
// an edge and, for a half edge, the edge it halves. A neighbour across an
// edge is found by walking these maps (finer neighbours through midpoints,
// coarser ones through the halved edge), never by searching all elements.
// A midpoint is shared by the elements on both sides of its edge: splitting
// the neighbour later reuses the same vertex index, so no crack can open.
//
// Partner faces: where two faces lie side by side in one plane with one
// material (solver/shooting/coplanar_partners.h), the elements along their
// common outline are each other's neighbours too (partnersAcross): the
// criterion compares across it, new children interpolate across it, and the
// grading holds across it by size, since the levels of two faces' meshes are
// not comparable.
//
// Anchoring (the switch in the constructor):
//   - 2:1 grading: before an element of level L is split, every neighbour of
//     level < L is split first (recursively), so no element ever borders one
//     more than one level finer. Across a partner face's outline, every
//     element whose edge there is longer than the element's own edge is
//     split first, so the children border nothing more than twice their
//     size. An element whose three edges all carry
//     midpoints is split as well (its anchored fan would be as fine anyway).
//   - Conforming output: a coarse element with midpoints (T-vertices) on its
//     edges stays ONE radiosity unit, but outputTriangles() triangulates it
//     through them (a fan from one midpoint: the "special edge" of Figure 5),
//     so the triangles painted and exported have no T-vertices.
// With anchoring off neither happens: the output is the elements themselves
// and T-vertices remain (to show what anchoring is for).
//
// The shooter needs patches whose elements are contiguous and no inactive
// element: activeScene() gives that copy (active leaves regrouped by patch,
// pieces rebuilt with buildPieces) with the map back to this hierarchy.
#include "model/scene.h"
#include "solver/prepare/prepared_scene.h"
#include "solver/shooting/coplanar_partners.h"

#include <array>
#include <cstdint>
#include <span>
#include <unordered_map>
#include <utility>
#include <vector>

namespace regio::solver {

// Place of an element in the subdivision hierarchy (parallel to
// PreparedScene::elements). Level 0 = an element of the initial mesh.
struct ElementLevel {
    int level = 0;
    int parent = -1;
    std::array<int, 4> children{-1, -1, -1, -1}; // [corner a, corner b, corner c, centre]
    bool active() const { return children[0] < 0; }
};

// A triangle of the conforming output: corners (indices into the scene's
// vertices, CCW from the face normal) and the element whose radiosity it shows.
struct OutputTriangle {
    std::array<int, 3> vertices{};
    int element = -1;
};

// The active leaves as a scene the shooter can use (see the top of the file).
struct ActiveScene {
    PreparedScene scene;
    std::vector<int> sourceElement; // element of `scene` -> element of the hierarchy
    std::vector<Rgb> radiosity;     // in `scene`'s element order
    std::vector<Rgb> unshot;
};

class AdaptiveMesh {
public:
    // `radiosity` and `unshot` (W/m^2) are per element of `scene`, in its
    // order. The scene is grown in place and must outlive this object.
    // `anchoring` is model::AdaptiveSettings::anchoring.
    // Throws std::invalid_argument when the counts do not match.
    AdaptiveMesh(PreparedScene& scene, std::vector<Rgb> radiosity, std::vector<Rgb> unshot, bool anchoring = true);

    const PreparedScene& scene() const { return m_scene; }
    bool anchoring() const { return m_anchoring; }
    const std::vector<ElementLevel>& hierarchy() const { return m_levels; }
    bool isActive(int element) const { return m_levels[size_t(element)].active(); }
    std::vector<int> activeElements() const;

    // Per element of the hierarchy (inactive ones keep their last values).
    const std::vector<Rgb>& radiosity() const { return m_radiosity; }
    const std::vector<Rgb>& unshot() const { return m_unshot; }
    // New state after shooting on the active scene, per hierarchy element.
    void setState(std::vector<Rgb> radiosity, std::vector<Rgb> unshot);
    // The same from the shooter's arrays on an ActiveScene (its element
    // order): each value goes to the hierarchy element it came from.
    void setActiveState(std::span<const int> sourceElement, std::span<const Rgb> radiosity,
                        std::span<const Rgb> unshot);

    // Active elements sharing (a part of) the edge k (corner k to corner k+1)
    // of an active element, or any of its edges.
    std::vector<int> neighboursAcross(int element, int edge) const;
    std::vector<int> neighbours(int element) const;
    // Active elements of partner faces (see the top of the file) sharing a
    // part of the edge k, or of any edge, of an active element.
    std::vector<int> partnersAcross(int element, int edge) const;
    std::vector<int> partners(int element) const;
    // Vertices lying inside the element's edges (its T-vertices), in order
    // around the element.
    std::vector<int> tVertices(int element) const;
    // The element's corners with its T-vertices in order between them.
    std::vector<int> boundaryLoop(int element) const;

    // Near a shadow corner (PreparedScene::shadowCorners: a solid's foot
    // corner, where the shadow lines of its rising edge meet) elements may
    // split to kShadowCornerEdge x minEdge, within kShadowCornerReach x
    // minEdge of the corner. Every line of the edge's penumbra starts at the
    // corner, so the wedge between the umbra and full light is narrower than
    // an element of minEdge for a few minEdges around it, and the light
    // rises across it faster than such elements follow (on the Cornell box
    // the floor 2-5 cm in front of the short block's corner read up to 97 %
    // too bright; 43 % with these, docs/accuracy.md). Farther out the
    // hemicube's pixels, not the elements, limit what finer elements could
    // show (§7: too fine a mesh aliases).
    static constexpr double kShadowCornerReach = 5.0;
    static constexpr double kShadowCornerEdge = 0.5;
    // The smallest edge a split of the element may make: minEdge, or less
    // near a shadow corner (above).
    double smallestEdgeAt(int element, double minEdge) const;

    // Whether split(element, minEdge) would split it: it is active, its
    // children's edges are at least smallestEdgeAt(element, minEdge) long and (anchoring) the grading
    // splits it needs are allowed too. Throws std::invalid_argument unless
    // minEdge is a positive length (so do split and the selection).
    bool canSplit(int element, double minEdge) const;
    // Splits the element into 4 (after the grading splits it needs). Returns
    // every element split, in order; empty when refused.
    std::vector<int> split(int element, double minEdge);
    // Splits every listed element still active, then (anchoring) the elements
    // with midpoints on all three edges. Returns the number of splits.
    int subdivide(std::span<const int> elements, double minEdge);

    // The largest relative luminance difference between the element and an
    // edge neighbour or partner, |L_e - L_n| / max(|L_e|, |L_n|) (0 without neighbours).
    // `radiosity` is per hierarchy element.
    double contrast(int element, std::span<const Rgb> radiosity) const;
    // §5.7 criterion: the active elements whose luminance differs from an
    // edge neighbour's by more than `threshold` relative to the larger of the
    // two, and that may still be split. `radiosity` is per hierarchy element.
    std::vector<int> selectBySubdivisionCriterion(std::span<const Rgb> radiosity, double threshold,
                                                  double minEdge) const;

    // One round of §5.7 with the scene's settings (threshold, minEdge; the
    // anchoring switch is the constructor's): select, then subdivide.
    // Returns the number of splits (0 = the mesh is settled).
    int refine(std::span<const Rgb> radiosity, const model::AdaptiveSettings& settings);

    // The triangles to paint and export (anchored fans when anchoring is on).
    std::vector<OutputTriangle> outputTriangles() const;

    ActiveScene activeScene() const;

private:
    using EdgeKey = std::uint64_t;
    struct FaceTopology {
        std::unordered_map<EdgeKey, std::vector<int>> sides; // edge -> active elements having it
        std::unordered_map<EdgeKey, int> midpoint;           // edge -> vertex at its middle
        std::unordered_map<EdgeKey, EdgeKey> halfOf;         // half edge -> the edge it halves
    };

    int faceOf(int element) const;
    void addEdges(int element);
    void removeEdges(int element);
    int midpoint(int face, int a, int b);
    void collectFiner(const FaceTopology& t, int a, int b, int exclude, std::vector<int>& out) const;
    void collectInside(const FaceTopology& t, int a, int b, std::vector<int>& out) const;
    bool canSplitImpl(int element, double minEdge, int depth) const;
    // The corners of the element's edge k (corner k to corner k + 1).
    std::pair<const Vec3&, const Vec3&> edgeEnds(int element, int edge) const;
    // visit(partner element, c, d) for every edge cd of an active element of a
    // partner face that shares a part of the element's edge k.
    template <typename Visit>
    void forEachPartnerEdge(int element, int edge, Visit visit) const;
    // The partners that must be split before the element (anchoring).
    std::vector<int> coarserPartners(int element) const;
    bool onSharedOutline(int face, int element) const;
    void splitNow(int element);

    PreparedScene& m_scene;
    bool m_anchoring;
    std::vector<ElementLevel> m_levels;
    std::vector<Rgb> m_radiosity;
    std::vector<Rgb> m_unshot;
    std::vector<FaceTopology> m_faces;
    // Per face: the outline it shares with partner faces, and its active
    // elements with an edge on it (kept up to date by splitNow).
    std::vector<std::vector<SharedOutline>> m_shared;
    std::vector<std::vector<int>> m_rim;
};

} // namespace regio::solver
