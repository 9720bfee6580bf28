#pragma once
// Progressive refinement radiosity, shooting variant (Cohen et al. 1988, as
// the paper's §5.6 iterates it). One shot: the patch with the most unshot
// power (area x unshot radiosity, by luminance) places a hemicube at its
// centre, the visibility fills the item buffer, delta form factors are summed
// per receiving element and
//     dB_j = rho_j * dB_i * F_ij * A_i / A_j           (per channel)
// is added to each receiver's radiosity and unshot radiosity. A patch's unshot
// radiosity is the area-weighted mean of its elements'.
//
// Energy is booked exactly (watts = W/m^2 x m^2, per channel):
//     emitted = absorbed + unshot + escaped
// where a shot's power P_i = A_i dB_i splits into what each receiver absorbs,
// (1 - rho_j) P_i F_ij, what it reflects back into the unshot pool, rho_j P_i
// F_ij, and what lands on no receiver, P_i (1 - sum_j F_ij): the sky of an open
// scene and the backs of surfaces.
//
// Overrelaxation (Gortler, Cohen & Slusallek 1993; the overshooting of Feda &
// Purgathofer 1992 in its simplest form): a shot sends w times the patch's
// unshot power, w = 1.2 by default, and leaves (1 - w) of it unshot, a
// negative amount that a later shot of the patch takes back. A patch gets
// ahead of the light it would receive later, so the unshot power falls
// faster: the sample scenes converge in 30-45 % fewer shots (the step of
// successive overrelaxation applied to Southwell's iteration, which
// progressive refinement is). The books stay exact (the extra power is taken
// from the unshot pool), the answer is the same fixed point, and with some
// unshot power negative, "most unshot power" and the convergence measure
// take magnitudes. w = 1 is the classic progressive refinement; above about
// 1.4 the shots grow again here. Emitting patches shoot with w = 1: what they
// hold is mostly their own emission, far more than comes back to them, and
// a light cut into many patches (solver/prepare/meshing.h) would otherwise
// shoot each of them twice, the second time only to take its debt back.
//
// A patch is shot many times in a long solve (its unshot power comes back
// with every shot that reaches it), and its view never changes on a fixed
// mesh. So the form factors of its first shot, a sparse row (the elements it
// sees and F_ij of each), are kept within a memory budget and a later shot of
// the same patch reuses them instead of rendering the hemicube again: the
// same numbers, so the same result to the last bit. The rows are dropped when
// the mesh changes (adaptive subdivision). A patch in a narrow gap (a
// ceiling over a lamp hung just under it) or behind a narrow face (a wall
// behind a table's leg) renders from several points and keeps each point's
// factors (shooter_points.h).
//
// The lights' shots render a hemicube twice as fine as the others (at most
// kLightHemicubeMaxResolution, never coarser than the scene's). They draw
// the direct light, whose shadows and penumbrae the final picture shows
// sharpest, and each light is cut into many small patches (meshing.h), so
// an element 1 cm across half a metre from a light covers two pixels of a
// 200 hemicube from each of them: what each patch gives it depends on where
// the pixels fall, and its value is off by several per cent in a penumbra.
// Four times the pixels bring that down about five times (the error of a
// sum of n pixels goes as n^(-3/4), Cohen and Greenberg 1985), for shots
// that are a few per cent of a solve: on the Cornell box 128 of 2193, and
// no slower as a whole (the finer direct light splits fewer elements on
// noise). The later shots carry reflected light, smooth, and keep the
// scene's resolution.
#include "solver/prepare/prepared_scene.h"
#include "solver/shooting/energy_balance.h"
#include "solver/shooting/near_field.h"
#include "solver/shooting/row_arena.h"
#include "solver/shooting/shooter_points.h"
#include "solver/visibility/hemicube.h"
#include "solver/visibility/hemicube_renderer.h"
#include "solver/visibility/item_buffer.h"

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <vector>

namespace regio::solver {

enum class ShotResult { Shot, NothingToShoot, Cancelled };

// How much memory the kept form-factor rows may take by default.
inline constexpr std::size_t kDefaultFormFactorCacheBytes = std::size_t{1024} << 20;

// How much of its unshot power a patch shoots (see the top of this file).
inline constexpr double kDefaultOverrelaxation = 1.2;

// How a Shooting runs. Threads and kept rows change no result; the
// overrelaxation changes the path to the answer, not the answer.
struct ShootingOptions {
    int threads = 0; // hemicube render threads (HemicubeRenderer); 0 = every core
    std::size_t formFactorCacheBytes = kDefaultFormFactorCacheBytes; // 0 = render every shot
    double overrelaxation = kDefaultOverrelaxation;                  // 1 = classic progressive refinement
    bool finerLightHemicubes = true; // the lights' shots at lightHemicubeResolution (see the top of the file)
};

// The finest hemicube a light's shot renders (top face 1024^2: 12 MB of ids
// and depths a painter).
inline constexpr int kLightHemicubeMaxResolution = 1024;

// The lights' hemicube resolution for a scene's `resolution`: twice it, at
// most kLightHemicubeMaxResolution, and never below `resolution`.
int lightHemicubeResolution(int resolution);

class Shooting {
public:
    // Keeps a reference to `scene`, which must outlive it; starts with every
    // element's radiosity and unshot radiosity at its emission.
    Shooting(const PreparedScene& scene, int hemicubeResolution, model::Visibility mode,
             const ShootingOptions& options = {});

    // One shot of the patch with the most unshot power. The hemicube is
    // rendered without any lock; `applyLock`, when given, is held only while
    // the results are written (so another thread can copy them meanwhile). A
    // cancelled shot changes nothing.
    ShotResult shoot(const std::atomic<bool>* cancel = nullptr, std::mutex* applyLock = nullptr);

    int iterations() const { return m_iterations; }
    // The patch that would shoot next; -1 if no patch has unshot power.
    int selectShooter() const;

    const std::vector<Rgb>& radiosity() const { return m_radiosity; }
    const std::vector<Rgb>& unshotRadiosity() const { return m_unshot; }
    // Unshot power of each patch (area-weighted sum of its elements').
    const std::vector<Rgb>& patchUnshotPower() const { return m_patchPower; }

    // After the mesh grew or was regrouped (adaptive subdivision, §5.7): the
    // per-element state in the scene's new element order. Patch powers and
    // area sums are recomputed; the energy books keep what was absorbed and
    // escaped, so new elements must carry unshot power that came from old ones.
    void replaceElementState(std::vector<Rgb> radiosity, std::vector<Rgb> unshot);

    // The books; their unshot power sums the patches' (see m_patchUnshot).
    EnergyBalance energy() const;
    // Largest unshot / emitted power over the channels that emit (0 if none).
    double unshotRatio() const { return unshotRatio(energy()); }
    // The same from books already summed.
    double unshotRatio(const EnergyBalance& books) const;
    // Cohen et al. 1988: the unshot power spread uniformly with the mean
    // reflectance's interreflection factor 1/(1 - rho_avg); displaying
    // B_j + rho_j * ambient gives a plausible picture after few shots.
    Rgb ambient() const { return ambient(energy()); }
    Rgb ambient(const EnergyBalance& books) const;

    // Form factors of the last shot from its shooter to every element (F_ij),
    // and what it lost: the fractions that hit nothing and back faces.
    int lastShooter() const { return m_lastShooter; }
    std::vector<double> lastFormFactors() const;
    double lastEscapedFraction() const { return m_lastRow ? m_lastRow->escaped : 0.0; }
    double lastBlockedFraction() const { return m_lastRow ? m_lastRow->blocked : 0.0; }

    // Shots that rendered a hemicube and shots that reused a kept row.
    int renderedShots() const { return m_renderedShots; }
    int reusedShots() const { return m_iterations - m_renderedShots; }
    std::size_t formFactorCacheBytes() const { return m_cacheBytes; }
    int threads() const { return m_renderer.threads(); }
    // How the threads share a render (HemicubeRenderer): kept after the first shots.
    RenderSplit renderSplit() const { return m_renderer.split(); }
    // Over both renderers (the lights' and the others').
    VisibilityStats visibilityStats() const;
    int hemicubeResolution() const { return m_hemicube.resolution(); }
    // What the lights' shots render (= hemicubeResolution() when not finer).
    int lightHemicubeResolution() const
    {
        return m_lightRenderer ? m_lightHemicube.resolution() : m_hemicube.resolution();
    }
    // What a shot of `patch` renders: the lights' resolution or the scene's.
    int shotResolution(int patch) const;

private:
    // A shooter's form factors: the elements it reaches, ascending, with F_ij
    // (a view: of the arena for a kept row, of m_built for one that is not).
    // The far factors are kept in single precision: a row is a third smaller
    // (8 bytes a receiver instead of 12), which the kernel's zeroing of
    // fresh memory and every shot's pass over the row pay for; a form
    // factor read to 7 digits moves no result beyond the solve's tolerance,
    // and the books stay exact, since a shot sends and counts the same
    // values.
    struct FormFactorRow {
        std::span<const std::uint32_t> elements;
        std::span<const float> factors;   // empty for a row of several points
        std::span<const NearTerm> near;   // receivers close to the shooter (near_field.h)
        std::span<const double> farScale; // per shooter element (near_field.h); empty = 1
        // A patch shot from several points (shooter_points.h): per receiver
        // what each point saw of it, pointFactors[k * points + p] (the far
        // receivers; `factors` is then empty), and
        // farScale[s * points + p] what element s's power carries through
        // point p.
        int points = 1;
        std::span<const float> pointFactors;
        double escaped = 0.0;
        double blocked = 0.0;
        std::size_t bytes() const
        {
            return elements.size_bytes() + factors.size_bytes() + near.size_bytes() + farScale.size_bytes() +
                   pointFactors.size_bytes();
        }
    };
    // Where a rendered row is built.
    struct RowStorage {
        std::vector<std::uint32_t> elements;
        std::vector<double> factors;
        std::vector<NearTerm> near;
        std::vector<double> farScale;
        std::vector<double> pointFactors;
        // factors and pointFactors as the row holds them (FormFactorRow)
        std::vector<float> rowFactors;
        std::vector<float> rowPointFactors;
    };
    // The row of `shooter`: kept, or rendered now (and kept if it fits).
    // Null when cancelled.
    const FormFactorRow* rowOf(int shooter, const std::atomic<bool>* cancel);
    // m_patchUnshot and m_patchMagnitude taken afresh from the elements: of
    // every patch, or of one.
    void sumPatchBooks();
    void sumPatchBooks(int patch);
    void packReceivers(); // m_receivers from the scene's elements
    // out = the delta form factor sums per item id of `buffer`, summed in
    // two halves of its rows on the renderer's threads (always two, so the
    // sums are the same to the last bit for any thread count).
    void accumulate(HemicubeRenderer& renderer, const ItemBuffer& buffer, const Hemicube& hemicube,
                    std::vector<double>& out);
    // The patch's face emits (a light's patch): it shoots without overshoot, at the lights' resolution.
    bool emits(int patch) const;
    void dropRows();

    const PreparedScene& m_scene;
    Hemicube m_hemicube;
    HemicubeRenderer m_renderer;
    ItemBuffer m_buffer;
    // The lights' finer hemicube, its renderer and buffer (none when not finer).
    Hemicube m_lightHemicube;
    std::unique_ptr<HemicubeRenderer> m_lightRenderer;
    std::optional<ItemBuffer> m_lightBuffer;
    std::size_t m_cacheBudget = 0;
    std::size_t m_cacheBytes = 0;
    std::vector<FormFactorRow> m_rows; // per patch; kept (in m_arena) when m_kept[p]
    std::vector<char> m_kept;
    RowArena m_arena;
    RowStorage m_built;     // the row rendered last
    FormFactorRow m_unkept; // a view of it, when it did not fit the budget
    const FormFactorRow* m_lastRow = nullptr;
    int m_renderedShots = 0;

    std::vector<Rgb> m_radiosity; // per element, W/m^2
    std::vector<Rgb> m_unshot;    // per element, W/m^2
    // What applying a row reads of each receiving element, packed: an
    // Element is 80 bytes, and fetching it was most of a reused shot's time.
    struct Receiver {
        double area = 0.0;
        int patch = -1;
        int properties = -1;
    };
    std::vector<Receiver> m_receivers; // per element
    double m_overrelaxation = 1.0;
    std::vector<Rgb> m_elementPower; // the shooter's elements' share of a shot
    std::vector<Rgb> m_patchPower;   // per patch, W
    // Per patch, the area-weighted sums of its elements' unshot radiosity
    // and of its magnitude, kept up to date by every change of an element's
    // unshot radiosity, so that the books need no walk over every element
    // after each shot. A patch's sums are taken afresh when it shoots.
    std::vector<Rgb> m_patchUnshot;                   // W
    std::vector<Rgb> m_patchMagnitude;                // W
    std::vector<double> m_perItem;                    // delta form factor sums per item id
    std::vector<double> m_secondHalf;                 // the sums of an item buffer's second half of rows
    std::vector<std::vector<double>> m_perPointItems; // the same per point of a patch shot from several
    std::vector<Rgb> m_pointPower;                    // what each point of such a patch sends

    Rgb m_emitted{0.0};
    Rgb m_absorbed{0.0};
    Rgb m_escaped{0.0};
    double m_totalArea = 0.0;
    Rgb m_meanReflectance{0.0};
    int m_iterations = 0;

    int m_lastShooter = -1;
};

} // namespace regio::solver
