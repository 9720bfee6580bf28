#include "solver/solver.h"

#include "solver/resource_estimate.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace regio::solver {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

std::shared_ptr<SolutionMesh> makeMesh(const PreparedScene& prepared, int revision)
{
    auto mesh = std::make_shared<SolutionMesh>();
    mesh->revision = revision;
    mesh->vertices = prepared.vertices;
    mesh->triangles.reserve(prepared.elements.size());
    mesh->normals.reserve(prepared.elements.size());
    mesh->elementFace.reserve(prepared.elements.size());
    mesh->reflectance.reserve(prepared.elements.size());
    for (const Element& e : prepared.elements) {
        const Properties& p = prepared.properties[static_cast<size_t>(e.properties)];
        mesh->triangles.push_back(e.vertices);
        mesh->normals.push_back(e.normal);
        mesh->elementFace.push_back(p.face);
        mesh->reflectance.push_back(p.reflectance);
    }
    mesh->faceIds.reserve(prepared.faces.size());
    for (const InputFace& f : prepared.faces)
        mesh->faceIds.push_back(f.id);
    return mesh;
}

} // namespace

int workPercent(int iteration, int maxIterations, double unshot, double convergence)
{
    double done = maxIterations > 0 ? static_cast<double>(iteration) / maxIterations : 0.0;
    if (convergence > 0.0 && convergence < 1.0 && unshot > 0.0 && unshot < 1.0)
        done = std::max(done, std::log(unshot) / std::log(convergence));
    else if (convergence > 0.0 && unshot <= convergence)
        done = 1.0;
    return static_cast<int>(std::floor(100.0 * std::clamp(done, 0.0, 1.0)));
}

const char* stopReasonName(StopReason reason)
{
    switch (reason) {
    case StopReason::None: return "none";
    case StopReason::Converged: return "converged";
    case StopReason::MaxIterations: return "maxIterations";
    case StopReason::NothingToShoot: return "nothingToShoot";
    case StopReason::Cancelled: return "cancelled";
    }
    return "none";
}

model::Result<std::unique_ptr<Solver>> Solver::create(const model::Scene& scene, const SolverOptions& options)
{
    const auto start = Clock::now();
    const model::SolverSettings s = resolveSettings(scene.solver, options);
    if (model::Check runnable = checkRunnable(s); !runnable)
        return runnable.error();
    // Refused before preparation, which is where a mesh too fine for the
    // machine would take its memory.
    const ResourceEstimate estimate =
        estimateResources(scene, s, options.threads, std::uint64_t(options.formFactorCacheBytes));
    if (model::Check fits = checkResources(estimate, availableMemoryBytes()); !fits)
        return fits.error();

    model::Result<PreparedScene> prepared = prepareScene(scene, prepareOptionsFor(s, options.autoRegionPatchThreshold));
    if (!prepared)
        return model::Result<std::unique_ptr<Solver>>::failureOf(prepared);

    std::unique_ptr<Solver> solver(new Solver());
    solver->m_settings = s;
    model::Diagnostics warnings = prepared.takeDiagnostics();
    solver->m_prepared = std::move(*prepared);
    std::shared_ptr<SolutionMesh> initialMesh;
    if (s.adaptive.enabled) {
        solver->m_refinement = std::make_unique<AdaptiveRefinement>(solver->m_prepared, s.adaptive);
        // The shooter starts on the mesh split along contact lines and in
        // penumbrae, if any.
        if (solver->m_refinement->splitBeforeFirstShot() > 0) {
            ActiveScene active = solver->m_refinement->takeActiveScene();
            initialMesh = solver->anchoredMesh(active, 0);
            solver->m_prepared = std::move(active.scene);
        }
    }
    solver->m_shooting = std::make_unique<Shooting>(
        solver->m_prepared, s.hemicube, s.visibility,
        ShootingOptions{options.threads, options.formFactorCacheBytes, options.overrelaxation});
    solver->m_mesh = initialMesh ? std::move(initialMesh) : makeMesh(solver->m_prepared, 0);
    solver->m_stats.contactElements = solver->m_refinement ? solver->m_refinement->contactElements() : 0;
    solver->m_stats.penumbraElements = solver->m_refinement ? solver->m_refinement->penumbraElements() : 0;
    solver->m_stats.preprocessSeconds = secondsSince(start);
    {
        std::lock_guard<std::mutex> lock(solver->m_mutex);
        solver->updateStatsLocked();
    }
    return {std::move(solver), std::move(warnings)};
}

Solver::~Solver() = default;

void Solver::updateStatsLocked()
{
    m_stats.iterations = m_shooting->iterations();
    m_stats.renderedShots = m_shooting->renderedShots();
    m_stats.patches = static_cast<int>(m_prepared.patches.size());
    m_stats.elements = static_cast<int>(m_prepared.elements.size());
    m_stats.energy = m_shooting->energy();
    m_stats.ambient = m_shooting->ambient(m_stats.energy);
    m_stats.unshotRatio = m_shooting->unshotRatio(m_stats.energy);
}

void Solver::noteShot()
{
    if (!m_refinement)
        return;
    bool emits = false;
    if (const int shooter = m_shooting->lastShooter(); shooter >= 0) {
        const Patch& p = m_prepared.patches[static_cast<size_t>(shooter)];
        emits = m_prepared.properties[static_cast<size_t>(p.properties)].emits();
    }
    m_refinement->noteShot(m_shooting->iterations(), emits);
}

bool Solver::refineIfDue(const std::atomic<bool>* cancel)
{
    if (!m_refinement || (!m_handOverPending && !m_refinement->roundDue()))
        return true;
    // Seen from other threads while the round works (the editor's status).
    struct Refining {
        std::atomic<bool>& flag;
        explicit Refining(std::atomic<bool>& f)
            : flag(f)
        {
            flag.store(true);
        }
        ~Refining() { flag.store(false); }
    } busy(m_refining);
    const auto start = Clock::now();
    if (!m_handOverPending) {
        // Only this thread writes the shooter's arrays: reading them unlocked is safe.
        const AdaptiveRefinement::Outcome outcome =
            m_refinement->runRound(m_shooting->radiosity(), m_shooting->unshotRadiosity(), cancel);
        if (outcome != AdaptiveRefinement::Outcome::Refined) {
            std::lock_guard<std::mutex> lock(m_mutex);
            m_stats.adaptiveSeconds += secondsSince(start);
            return outcome != AdaptiveRefinement::Outcome::Cancelled;
        }
        m_handOverPending = true;
        // The hand-over below cannot stop part-way: a cancel that came during
        // the splits leaves it for the next call, before the next shot.
        if (cancel && cancel->load()) {
            std::lock_guard<std::mutex> lock(m_mutex);
            m_stats.adaptiveSeconds += secondsSince(start);
            return false;
        }
    }
    // The new active scene and its mesh are built without the lock; readers
    // keep seeing the previous mesh with its radiosity until the swap.
    ActiveScene active = m_refinement->takeActiveScene();
    std::shared_ptr<SolutionMesh> mesh = anchoredMesh(active, m_mesh->revision + 1);
    std::lock_guard<std::mutex> lock(m_mutex);
    // Assigned in place: the shooter and its visibility refer to m_prepared.
    m_prepared = std::move(active.scene);
    m_shooting->replaceElementState(std::move(active.radiosity), std::move(active.unshot));
    m_mesh = std::move(mesh);
    m_handOverPending = false;
    m_stats.adaptiveRounds = m_refinement->rounds();
    m_stats.adaptiveSeconds += secondsSince(start);
    updateStatsLocked();
    return true;
}

std::shared_ptr<SolutionMesh> Solver::anchoredMesh(const ActiveScene& active, int revision) const
{
    std::shared_ptr<SolutionMesh> mesh = makeMesh(active.scene, revision);
    if (m_settings.adaptive.anchoring) {
        std::vector<int> activeIndex(m_refinement->mesh().hierarchy().size(), -1);
        for (size_t i = 0; i < active.sourceElement.size(); ++i)
            activeIndex[size_t(active.sourceElement[i])] = int(i);
        for (const OutputTriangle& t : m_refinement->mesh().outputTriangles()) {
            mesh->anchoredTriangles.push_back(t.vertices);
            mesh->anchoredElement.push_back(activeIndex[size_t(t.element)]);
        }
    }
    return mesh;
}

int Solver::step(int n)
{
    int done = 0;
    for (; done < n; ++done) {
        refineIfDue(nullptr);
        const auto start = Clock::now();
        const ShotResult r = m_shooting->shoot(nullptr, &m_mutex);
        std::lock_guard<std::mutex> lock(m_mutex);
        m_stats.shootSeconds += secondsSince(start);
        if (r != ShotResult::Shot) {
            m_stats.stop = StopReason::NothingToShoot;
            break;
        }
        updateStatsLocked();
        noteShot();
    }
    return done;
}

bool Solver::converged() const
{
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_stats.unshotRatio < m_settings.convergence;
}

StopReason Solver::run(const Progress& progress, const std::atomic<bool>& cancel)
{
    StopReason reason = StopReason::None;
    while (reason == StopReason::None) {
        {
            std::lock_guard<std::mutex> lock(m_mutex);
            if (cancel.load())
                reason = StopReason::Cancelled;
            else if (m_stats.unshotRatio < m_settings.convergence)
                reason = StopReason::Converged;
            else if (m_stats.iterations >= m_settings.maxIterations)
                reason = StopReason::MaxIterations;
        }
        if (reason != StopReason::None)
            break;
        if (!refineIfDue(&cancel)) {
            reason = StopReason::Cancelled;
            break;
        }
        const auto start = Clock::now();
        const ShotResult r = m_shooting->shoot(&cancel, &m_mutex);
        SolverStats copy;
        {
            std::lock_guard<std::mutex> lock(m_mutex);
            m_stats.shootSeconds += secondsSince(start);
            if (r == ShotResult::Shot) {
                updateStatsLocked();
                noteShot();
            } else {
                reason = r == ShotResult::Cancelled ? StopReason::Cancelled : StopReason::NothingToShoot;
            }
            copy = m_stats;
        }
        if (r == ShotResult::Shot && progress)
            progress(copy);
    }
    std::lock_guard<std::mutex> lock(m_mutex);
    m_stats.stop = reason;
    return reason;
}

void Solver::extendIterationLimit(int shots)
{
    std::lock_guard<std::mutex> lock(m_mutex);
    m_settings.maxIterations = m_stats.iterations + std::max(1, shots);
}

SolverStats Solver::stats() const
{
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_stats;
}

SolutionSnapshot Solver::snapshot() const
{
    SolutionSnapshot s;
    std::lock_guard<std::mutex> lock(m_mutex);
    s.mesh = m_mesh;
    s.radiosity = m_shooting->radiosity();
    s.stats = m_stats;
    return s;
}

std::vector<FaceResult> Solver::faceResults() const
{
    std::vector<FaceResult> out;
    std::lock_guard<std::mutex> lock(m_mutex);
    out.reserve(m_prepared.faces.size());
    const std::vector<Rgb>& b = m_shooting->radiosity();
    for (const InputFace& f : m_prepared.faces) {
        FaceResult r;
        r.id = f.id;
        r.area = f.area;
        double area = 0.0;
        for (int e : f.elements) {
            const double a = m_prepared.elements[static_cast<size_t>(e)].area;
            r.radiosity += b[static_cast<size_t>(e)] * a;
            area += a;
        }
        if (area > 0.0)
            r.radiosity /= area;
        out.push_back(std::move(r));
    }
    return out;
}

} // namespace regio::solver
