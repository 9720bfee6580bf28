#pragma once
// The solver API the editor and the batch command drive.
//
//   auto built = Solver::create(scene, options);   // prepares once, copies what it needs
//   if (!built.solver) report(built.diagnostics);
//   built.solver->step(10);                        // exactly 10 shots (fewer only if nothing is left)
//   built.solver->run(progress, cancel);           // until converged, maxIterations or cancel
//   SolutionSnapshot s = built.solver->snapshot(); // from any thread, also while run() works
//
// The solver never touches the model::Scene after create(): it works on its
// own PreparedScene. run() and step() belong to one thread at a time;
// snapshot(), stats() and faceResults() may be called from any thread.
#include "model/diagnostic.h"
#include "model/scene.h"
#include "solver/shooting/adaptive_refinement.h"
#include "solver/prepare/prepare.h"
#include "solver/prepare/prepared_scene.h"
#include "solver/shooting/shooting.h"
#include "solver/visibility/visibility.h"

#include <array>
#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace regio::solver {

// Overrides of the scene's own solver settings; empty = the scene's value.
struct SolverOptions {
    std::optional<int> hemicube;
    std::optional<int> maxIterations;
    std::optional<double> convergence;
    std::optional<double> patchSize;
    std::optional<int> elementsPerPatch;
    std::optional<VisibilityMode> visibility;
    std::optional<RegionsMode> regions;
    // Adaptive subdivision (§5.7); empty = scene.solver.adaptive.
    std::optional<bool> adaptive;
    std::optional<double> adaptiveThreshold;
    std::optional<double> adaptiveMinEdge;
    std::optional<bool> adaptiveAnchoring;
    int autoRegionPatchThreshold = 256;
};

// The settings a solver actually runs with, after overrides.
struct EffectiveSettings {
    int hemicube = 150;
    int maxIterations = 500;
    double convergence = 0.001;
    double patchSize = 0.5;
    int elementsPerPatch = 4;
    VisibilityMode visibility = VisibilityMode::Painter;
    RegionsMode regions = RegionsMode::Authored;
    model::AdaptiveSettings adaptive; // when the mesh is refined: solver/shooting/adaptive_refinement.h
};

enum class StopReason { None, Converged, MaxIterations, NothingToShoot, Cancelled };
const char* stopReasonName(StopReason reason);

struct SolverStats {
    int iterations = 0;
    int patches = 0;
    int elements = 0;        // active elements the shooter works on
    int adaptiveRounds = 0;  // §5.7 refinement rounds that split elements
    EnergyBalance energy;
    Rgb ambient{0.0};
    double unshotRatio = 0.0; // largest unshot / emitted over the emitting channels
    StopReason stop = StopReason::None;
    double preprocessSeconds = 0.0;
    double shootSeconds = 0.0;
    double adaptiveSeconds = 0.0; // spent refining the mesh (not part of shootSeconds)
};

// The element mesh, shared between snapshots until the mesh changes.
struct SolutionMesh {
    int revision = 0;                          // changes whenever the mesh does
    std::vector<Vec3> vertices;
    std::vector<std::array<int, 3>> triangles; // per element, CCW from its normal
    std::vector<Vec3> normals;                 // per element
    std::vector<int> elementFace;              // per element: index into faceIds
    std::vector<Rgb> reflectance;              // per element
    std::vector<std::string> faceIds;          // the input faces of the file, scene order
    // After adaptive subdivision (§5.7) with anchoring: the conforming
    // triangulation of the elements (a coarse element next to finer ones is
    // fanned through their vertices on its edges, the "special edges" of the
    // paper's Figure 5), each triangle with the element whose value it shows.
    // Empty before the first refinement and with anchoring off: then the
    // triangles above are what there is.
    std::vector<std::array<int, 3>> anchoredTriangles;
    std::vector<int> anchoredElement;
};

struct SolutionSnapshot {
    std::shared_ptr<const SolutionMesh> mesh;
    std::vector<Rgb> radiosity; // per element, W/m^2
    SolverStats stats;
    // Radiosity plus the ambient term (Cohen et al. 1988), for early pictures.
    Rgb displayRadiosity(size_t element) const
    {
        return radiosity[element] + mesh->reflectance[element] * stats.ambient;
    }
};

struct FaceResult {
    std::string id;  // face id of the file
    double area = 0.0;
    Rgb radiosity{0.0}; // area-weighted mean over the face's elements
};

class Solver {
public:
    struct CreateResult {
        std::unique_ptr<Solver> solver; // empty when the scene could not be prepared
        model::Diagnostics diagnostics;
    };
    // Prepares the scene (regional tree, BSP trees, meshing) and sets up the
    // shooting state. Diagnostics carry preparation errors and warnings.
    static CreateResult create(const model::Scene& scene, const SolverOptions& options = {});

    Solver(const Solver&) = delete;
    Solver& operator=(const Solver&) = delete;
    ~Solver();

    const EffectiveSettings& settings() const { return m_settings; }
    // The scene the shooter works on (the active elements once subdivided).
    // Not synchronised with a running solve.
    const PreparedScene& prepared() const { return m_prepared; }

    // Shoots up to n times (fewer only when no unshot power is left), ignoring
    // maxIterations and convergence, with the refinement rounds that fall
    // between the shots. Returns the number of shots done.
    int step(int n = 1);

    using Progress = std::function<void(const SolverStats&)>;
    // Shoots until the unshot/emitted ratio falls below `convergence`, the
    // iteration count reaches maxIterations or `cancel` becomes true (then
    // the shot under way is abandoned: within one partial hemicube render,
    // far below 100 ms; a refinement round stops at its next slice and is
    // finished before the next shot). `progress` is called after every shot.
    StopReason run(const Progress& progress, const std::atomic<bool>& cancel);

    bool converged() const;
    SolverStats stats() const;
    SolutionSnapshot snapshot() const;
    std::vector<FaceResult> faceResults() const;

    // Read access for tests and tools; not synchronised with a running solve.
    const Shooting& shooting() const { return *m_shooting; }

private:
    Solver() = default;
    void updateStatsLocked();
    // Before a shot: the §5.7 refinement round that is due, if any, and the
    // hand-over of the grown mesh. false = cancelled (resumed next time).
    bool refineIfDue(const std::atomic<bool>* cancel);
    void noteShot();

    std::unique_ptr<AdaptiveRefinement> m_refinement; // empty when adaptive subdivision is off
    bool m_handOverPending = false; // a round split elements; the shooter has not got them yet

    EffectiveSettings m_settings;
    PreparedScene m_prepared;
    std::unique_ptr<Shooting> m_shooting;
    std::shared_ptr<const SolutionMesh> m_mesh;

    // Guards m_stats, m_mesh, m_prepared while it is replaced and the shooting
    // results while they are written.
    mutable std::mutex m_mutex;
    SolverStats m_stats;
};

} // namespace regio::solver
