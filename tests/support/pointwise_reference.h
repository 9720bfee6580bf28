#pragma once
// An independent pointwise radiosity reference for the tests: the radiosity
// at any point of a scene's surfaces, computed with nothing of the solver (no
// hemicube, no BSP tree, no solver meshing), so that the solver's pictures can
// be measured against it point by point.
//
// The method is the classical gathering one (Goral et al. 1984) with analytic
// point-to-polygon form factors (Lambert's contour formula, brought to
// radiosity by Nishita and Nakamae 1985 and Baum, Rushmeier and Winget 1989)
// and ray-cast visibility:
//   1. every input face is cut into a grid of its own small convex patches,
//      about `patchSize` on a side and clipped to the face;
//   2. the form factor patch i -> patch j is the point-to-polygon form factor
//      averaged over points of i (cell centres of a grid over the patch: the
//      midpoint rule), each times the fraction of rays from that point to
//      the points of j that no face blocks;
//   3. B = E + rho F B is solved per channel by Gauss-Seidel;
//   4. patches near another face they exchange light with (corners, a
//      block's foot) get their radiosity at a few points inside them,
//      gathered as in 5 from the patch solution;
//   5. the radiosity at a point is gathered once more from every patch
//      (radiosityAt): B_j x F(point -> patch j) x the fraction of rays that
//      reach it, patches near the point cut finer and valued from 4, so that
//      contact shadows and corners are resolved below the patch size.
//
// Surfaces are opaque from both sides and reflect and emit from their front
// side only. A face that rests on another one, coplanar and facing the other
// way (a block's bottom on the floor), covers it: points of the floor under
// the block are "covered" and take no part in the patch averages.
//
// How good it is: on the Cornell box sample the default options agree with
// 2 cm patches and twice the rays and cuts to a median 0.06 % and a 99th
// percentile 1.1 % of luminance (beside the blocks' feet 90th percentile
// 0.9 %), and the final gather with a cosine-weighted Monte Carlo gather of
// the same patch values to the Monte Carlo noise (under 1 %).
//
// Deterministic: the ray ends of the final gather are jittered by a hash of
// their indices, every other point is fixed; nothing is global, results do
// not depend on the thread count. Compile it optimised (it is a library of
// its own for that, tests/support/CMakeLists.txt): the work is number
// crunching.
#include "model/scene.h"
#include "model/types.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <span>
#include <string>
#include <vector>

namespace regio::test {

using model::Rgb;
using model::Vec3;

// The form factor from a differential area at `point` with unit normal
// `normal` to a planar convex polygon (either orientation): Lambert's contour
// formula F = 1/(2 pi) sum_i gamma_i n . (R_i x R_i+1) / |R_i x R_i+1|, with
// R_i the vectors from the point to the corners and gamma_i the angle an edge
// subtends, over the polygon clipped to the half-space in front of the point's
// tangent plane (what lies behind it does not count). Pure geometry: whether
// the polygon emits towards the point is the caller's concern.
double pointToPolygonFormFactor(const Vec3& point, const Vec3& normal, std::span<const Vec3> polygon);

struct PointwiseReferenceOptions {
    double patchSize = 0.03; // metres: the edge of the grid cells faces are cut into
    // Faces (by id) cut into a grid of their own size instead: a narrow gap
    // fine, the rest of a room coarse, at a fraction of the cost of every
    // face fine (the cost grows with the square of the patch count).
    std::map<std::string, double> facePatchSizes;
    // Points per patch (the centres of n x n cells over it) for the
    // patch-to-patch form factors: each point is a receiver of the contour
    // formula and an end of the visibility rays (one ray from every point of
    // one patch to every point of the other).
    int samplesPerSide = 2;
    // The same for patches closer than nearDistance patch sizes to a face
    // they exchange light with (corners, contact lines), where the form
    // factors change quickly across a patch. Chosen per patch, not per pair:
    // a patch averages all its form factors over the same points, so that
    // they add up to what its points see (1 in a closed room).
    int nearSamplesPerSide = 4;
    double nearDistance = 1.0;
    // The final gather: a patch (or a part of it) closer to the point than
    // gatherNearDistance times its size is cut into gatherSplit x gatherSplit
    // parts, down to gatherDepth levels; every part is seen through
    // gatherRaysPerSide^2 rays.
    double gatherNearDistance = 2.0;
    int gatherSplit = 2;
    int gatherDepth = 3;
    int gatherRaysPerSide = 3;
    // The rays to a whole patch of an emitting face: direct light is the
    // brightest and sharpest-edged part of what a point gathers, and its
    // penumbrae want more rays than the soft indirect light.
    int emitterRaysPerSide = 8;
    // After the solve, the patches near a face they exchange light with get
    // their radiosity on a finer grid, refineSplit x refineSplit values
    // gathered at the cell centres from the patch solution (0 = off). The
    // final gather takes its near field from those: beside a contact line
    // the radiosity of the neighbouring face changes too fast across a patch
    // for one value per patch.
    int refineSplit = 2;
    // Ray ends are moved this far (metres) off their surface along its normal.
    double surfaceOffset = 1e-6;
    // Gauss-Seidel stops when no patch changed by more than this times the
    // largest radiosity.
    double tolerance = 1e-9;
    int maxIterations = 100000;
    int threads = 2; // for the form factors and the batch gather; 0 = every core
};

// An input face as the reference sees it.
struct ReferenceFace {
    std::string id;
    std::vector<Vec3> polygon; // counter-clockwise seen from `normal`; empty for a face of no area
    Vec3 normal{0.0};          // unit, the front side
    double offset = 0.0;       // plane: dot(normal, p) = offset
    Vec3 u{0.0}, v{0.0};       // in-plane frame: u along the longest edge, v = normal x u
    Rgb reflectance{0.0};
    Rgb emission{0.0};
    double area = 0.0;
    Vec3 boxMin{0.0}, boxMax{0.0};
    // Inward in-plane unit normals of the edges: p is inside when
    // dot(edgeNormals[k], p) >= edgeOffsets[k] for every k.
    std::vector<Vec3> edgeNormals;
    std::vector<double> edgeOffsets;
    std::vector<int> coveredBy; // coplanar faces facing the other way that touch it
    int firstPatch = 0;
    int patchCount = 0;
};

struct ReferenceSample {
    Vec3 point{0.0};
    bool covered = false; // under a face that rests on this one
};

struct ReferencePatch {
    int face = -1;
    std::vector<Vec3> polygon; // convex, counter-clockwise seen from the face's normal
    double area = 0.0;
    double visibleArea = 0.0; // area not covered (estimated from the near samples)
    Vec3 centroid{0.0};
    double size = 0.0; // diameter: twice the largest distance of a corner from the centroid
    Vec3 boxMin{0.0}, boxMax{0.0};
    std::vector<ReferenceSample> samples;       // samplesPerSide^2 (fewer where the patch is a sliver)
    std::vector<ReferenceSample> nearSamples;   // nearSamplesPerSide^2
    std::vector<ReferenceSample> gatherSamples; // gatherRaysPerSide^2 (emitterRaysPerSide^2 on emitters)
    bool near = false;                          // near a face it exchanges light with: uses nearSamples
    Rgb radiosity{0.0};                         // mean over the samples that are not covered
    // Near patches: the radiosity at the centres of a refineSplit^2 grid over
    // the patch's extent (index i * refineSplit + j, i along the face's u);
    // the patch's value where a cell is empty or covered. Empty otherwise.
    std::vector<Rgb> refined;

    const std::vector<ReferenceSample>& formFactorSamples() const { return near ? nearSamples : samples; }
};

// A point of the final gather: a face (index into faces()) and a point on it.
struct GatherPoint {
    int face = -1;
    Vec3 point{0.0};
};

class PointwiseReference {
public:
    // Meshes the scene, computes the form factors and solves. Throws
    // std::invalid_argument when a face names no existing material, or
    // options.facePatchSizes names no face or a size that is not positive.
    explicit PointwiseReference(const model::Scene& scene, const PointwiseReferenceOptions& options = {});

    const PointwiseReferenceOptions& options() const { return m_options; }
    // The input faces in scene order (objects, parts, faces).
    const std::vector<ReferenceFace>& faces() const { return m_faces; }
    // Index of the face with this id in faces(), -1 if there is none.
    int faceIndex(const std::string& faceId) const;

    const std::vector<ReferencePatch>& patches() const { return m_patches; }
    // F_ij: the fraction of what leaves the visible part of patch i that
    // arrives at patch j, so that B_i = E_i + rho_i sum_j F_ij B_j.
    double formFactor(std::size_t from, std::size_t to) const;
    // Gauss-Seidel sweeps until the tolerance was met.
    int iterations() const { return m_iterations; }
    // Non-zero form factors.
    std::size_t formFactorCount() const { return m_columns.size(); }

    // The radiosity (W/m^2 per channel) leaving the front of face `face` at
    // `point` (on the face): its emission plus its reflectance times what it
    // gathers from every patch.
    Rgb radiosityAt(int face, const Vec3& point) const;
    // The same by face id; throws std::invalid_argument for an unknown id.
    Rgb radiosityAt(const std::string& faceId, const Vec3& point) const;
    // Many points at once, on options().threads threads.
    std::vector<Rgb> radiosityAt(std::span<const GatherPoint> points) const;

    // The fraction of rays from `from` (moved off its surface along
    // `fromNormal`) to stratified points of `polygon` (moved off along
    // `polygonNormal`) that no face of the scene blocks; raysPerSide^2 rays,
    // those to points behind `from`'s tangent plane left out. 1 when none is left.
    double visibility(const Vec3& from, const Vec3& fromNormal, std::span<const Vec3> polygon,
                      const Vec3& polygonNormal, int raysPerSide) const;

    // Whether `point` of face `face` lies under a face that rests on it.
    bool covered(int face, const Vec3& point) const;

    // What `point` of face `face` gathers from each face of the scene
    // (index as faces(); B x F x V summed over the face's patches, before
    // the receiver's reflectance): radiosityAt is its emission plus its
    // reflectance times their sum. `radiosity`, when given, stands in for
    // the patches' own values: radiosity(source face, point of the source)
    // at the middle of each patch or part that the gather takes, e.g.
    // another solution's, so that that solution's error at the point splits
    // into what its sources have wrong and what its transport does.
    using SourceRadiosity = std::function<Rgb(int face, const Vec3& point)>;
    std::vector<Rgb> gatheredBySource(int face, const Vec3& point, const SourceRadiosity& radiosity = {}) const;

private:
    struct Scratch; // buffers one thread reuses from call to call

    void buildFaces(const model::Scene& scene);
    void buildPatches();
    void buildOccluders();
    void markNearPatches();
    void computeFormFactors();
    void solve();
    void refineNearPatches();

    const std::vector<int>& occluders(int receiverFace, int sourceFace) const
    {
        return m_occluders[static_cast<std::size_t>(receiverFace) * m_faces.size() +
                           static_cast<std::size_t>(sourceFace)];
    }
    bool interacts(int receiverFace, int sourceFace) const
    {
        return m_interacts[static_cast<std::size_t>(receiverFace) * m_faces.size() +
                           static_cast<std::size_t>(sourceFace)] != 0;
    }
    // Whether the segment a-b crosses one of `candidates` (face indices).
    bool blocked(const Vec3& a, const Vec3& b, std::span<const int> candidates) const;
    // The occluders of the face pair whose boxes meet the box lo-hi.
    void occludersInBox(int receiverFace, int sourceFace, const Vec3& lo, const Vec3& hi, std::vector<int>& out) const;
    // B x F x V from the convex `polygon`, all or part of `patch`, to `point`
    // of face `face`, cut finer near the point (the final gather); the parts
    // take their B from the patch's refined values when `refined`.
    Rgb gatherPolygon(int face, const Vec3& point, const ReferencePatch& patch, std::span<const Vec3> polygon,
                      std::span<const ReferenceSample> samples, double size, int depth, std::uint64_t seed,
                      bool refined, Scratch& scratch) const;
    Rgb gatherAt(int face, const Vec3& point, bool refined, Scratch& scratch,
                 std::vector<Rgb>* bySource = nullptr) const;
    // The refined value of the patch's cell that holds `point`.
    Rgb refinedAt(const ReferencePatch& patch, const Vec3& point) const;

    PointwiseReferenceOptions m_options;
    std::vector<ReferenceFace> m_faces;
    std::vector<ReferencePatch> m_patches;
    std::vector<std::vector<int>> m_occluders; // per (receiver face, source face)
    std::vector<char> m_interacts;             // per (receiver face, source face)
    // The form factors, compressed rows: row i holds columns[rowStart[i] ..
    // rowStart[i+1]) in increasing order.
    std::vector<std::size_t> m_rowStart;
    std::vector<int> m_columns;
    std::vector<double> m_values;
    int m_iterations = 0;
};

} // namespace regio::test
