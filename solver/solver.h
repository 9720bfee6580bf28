#pragma once
// The solver API the editor and the batch command drive.
//
//   auto built = Solver::create(scene, options);   // prepares once, copies what it needs
//   if (!built) report(built.diagnostics());
//   Solver& solver = **built;
//   solver.step(10);                               // exactly 10 shots (fewer only if nothing is left)
//   solver.run(progress, cancel);                  // until converged, maxIterations or cancel
//   SolutionSnapshot s = solver.snapshot();        // from any thread, also while run() works
//
// The solver never touches the model::Scene after create(): it works on its
// own PreparedScene. run() and step() belong to one thread at a time;
// snapshot(), stats() and faceResults() may be called from any thread.
#include "model/result.h"
#include "model/scene.h"
#include "solver/prepare/prepare.h"
#include "solver/prepare/prepared_scene.h"
#include "solver/settings.h"
#include "solver/shooting/adaptive_refinement.h"
#include "solver/shooting/shooting.h"
#include "solver/solution.h"

#include <array>
#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace regio::solver {

// How to solve: overrides of the scene's own settings (solver/settings.h),
// the patch-count threshold of automatic regions, and how the shots run
// (threads, kept form-factor rows: shooting.h), which changes no result.
struct SolverOptions : SettingsOverrides {
    int autoRegionPatchThreshold = kAutoRegionPatchThreshold;
    int threads = 0; // hemicube render threads; 0 = every core
    std::size_t formFactorCacheBytes = kDefaultFormFactorCacheBytes;
    double overrelaxation = kDefaultOverrelaxation; // ShootingOptions
};

class Solver {
public:
    // Resolves the settings (solver/settings.h), prepares the scene (regional
    // tree, BSP trees, meshing) and sets up the shooting state. The solver
    // comes with preparation's warnings; a scene that cannot be prepared
    // gives its errors.
    static model::Result<std::unique_ptr<Solver>> create(const model::Scene& scene, const SolverOptions& options = {});

    Solver(const Solver&) = delete;
    Solver& operator=(const Solver&) = delete;
    ~Solver();

    // The resolved settings it runs with.
    const model::SolverSettings& settings() const { return m_settings; }
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

    // Moves the iteration limit to `shots` past the shots done, so that run()
    // goes on after it stopped at the limit (the editor's Continue). Not
    // while run() works.
    void extendIterationLimit(int shots);

    // A refinement round (§5.7) is under way; from any thread.
    bool refining() const { return m_refining.load(); }

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
    // The mesh to show for an active scene the refinement handed over: its
    // elements, and with anchoring the conforming triangles (§5.7, Figure 5).
    std::shared_ptr<SolutionMesh> anchoredMesh(const ActiveScene& active, int revision) const;

    std::unique_ptr<AdaptiveRefinement> m_refinement; // empty when adaptive subdivision is off
    bool m_handOverPending = false;
    std::atomic<bool> m_refining{false}; // a round split elements; the shooter has not got them yet

    model::SolverSettings m_settings;
    PreparedScene m_prepared;
    std::unique_ptr<Shooting> m_shooting;
    std::shared_ptr<const SolutionMesh> m_mesh;

    // Guards m_stats, m_mesh, m_prepared while it is replaced and the shooting
    // results while they are written.
    mutable std::mutex m_mutex;
    SolverStats m_stats;
};

} // namespace regio::solver
