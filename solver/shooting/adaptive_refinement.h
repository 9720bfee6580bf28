#pragma once
// When and how far the Solver refines its element mesh (paper §5.7: "after
// the subdivision ... establish the initial radiosity for new elements ... and
// process these elements by the standard iteration procedure").
//
// The paper leaves the schedule open; this one:
//   - A round becomes due after the shot of an emitting patch (direct light
//     draws the sharp shadow borders) and after every `roundInterval`-th shot
//     (the softer borders of reflected light). It runs right before the next
//     shot, so a solve that stops (converged, iteration limit) never ends with
//     new elements that only hold interpolated values, and step(n) and run()
//     with maxIterations = n refine identically.
//   - At most `maxRounds` rounds, and no round starts a slice once the active
//     element count has reached `growthLimit` x the initial count (the last
//     slice may overshoot by its splits and their grading splits, well under
//     1 % on the samples); round k may bring it to at most
//     initial + k/maxRounds of the allowed growth (what a round leaves unused
//     passes on), so the first light's round cannot take the budget of the
//     rounds after the other lights' shots. A round splits the selected
//     elements in order of falling contrast, so when the budget runs out the
//     sharpest borders (shadows) have been refined and the gentle falloff of
//     a large light has not.
//   - A round judges the criterion in slices of `selectSliceSize` elements
//     and splits in slices of `sliceSize` candidates, and looks at the cancel
//     flag after each slice (a few ms). A cancelled round keeps what it did
//     and resumes with the next slice before the next shot: the result is the
//     same as that of an uncancelled solve, only later.
//   - Before the first shot, the elements along contact lines (where a solid
//     stands on a face: solver/shooting/contact_lines.h) are split
//     `contactPasses` times, on top of the growth budget: the criterion
//     cannot see the fall-off there (no neighbour across the line), and
//     taken from the budget they would starve the first round. So are the
//     elements in the penumbrae of the solids standing on a face
//     (solver/shooting/penumbrae.h), `penumbraPasses` times down to
//     `penumbraMinEdge` x minEdge, the brightest lights' first, until they
//     would add more than `penumbraShare` of the growth budget: on the
//     Cornell box they take a fifth of it; on a hall of a hundred objects
//     under large lamps they take the whole share, and without it they
//     would quadruple the mesh before the first shot. And so are the
//     elements along the outline of a face hanging just in front of another
//     (a lamp 2 cm under the ceiling: solver/prepare/near_outlines.h),
//     `outlinePasses` times: the light that bounces in the gap falls off
//     across the outline within a few gap widths.
//
// New elements take their parent's values through AdaptiveMesh (radiosity
// interpolated from the parent and its neighbours, mean-preserving; unshot
// copied), so the shooter that was spent is carried by interpolation, never
// re-shot, and the energy books stay exact.
#include "model/scene.h"
#include "solver/prepare/prepared_scene.h"
#include "solver/shooting/adaptive_subdivision.h"
#include "solver/shooting/penumbrae.h"

#include <atomic>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace regio::solver {

struct RefinementPolicy {
    int roundInterval = 16;
    int maxRounds = 8;
    double growthLimit = 4.0;     // active elements <= growthLimit x initial elements
    int sliceSize = 64;           // candidates split between two looks at the cancel flag
    int selectSliceSize = 2048;   // elements judged by the criterion between two looks
    int contactPasses = 2;        // splits of the elements along contact lines before the first shot
    int outlinePasses = 3;        // splits of the elements along near outlines before the first shot
    int penumbraPasses = 2;       // splits of the elements in the solids' penumbrae before the first shot
    double penumbraMinEdge = 0.5; // x minEdge: the edges the penumbra splits go down to
    double penumbraShare = 0.25;  // of the growth budget (growthLimit - 1) x initial, at most
};

class AdaptiveRefinement {
public:
    // `initial` is the prepared scene the shooter starts on; it is copied
    // (the copy becomes the hierarchy the AdaptiveMesh grows).
    AdaptiveRefinement(const PreparedScene& initial, const model::AdaptiveSettings& settings,
                       const RefinementPolicy& policy = RefinementPolicy{});
    ~AdaptiveRefinement();

    // Before the first shot: splits the elements along contact lines and in
    // the solids' penumbrae (see the top of the file). Returns the number of
    // splits; when there were any, takeActiveScene() has the mesh to shoot on
    // (its radiosity and unshot the emission).
    int splitBeforeFirstShot();

    // After shot number `iteration` (1-based) of a patch that emits or not.
    void noteShot(int iteration, bool shooterEmits);
    // Whether a round is due (or an interrupted one waits to be finished).
    bool roundDue() const { return m_due || m_round.has_value(); }

    enum class Outcome { Settled, Refined, Cancelled };
    // Runs the due round, or resumes the interrupted one. `radiosity` and
    // `unshot` are the shooter's arrays on the current active scene (ignored
    // when resuming: no shot happened since). Refined: takeActiveScene() has
    // the new mesh. Settled: nothing was split (criterion met everywhere,
    // minEdge, or the budget).
    Outcome runRound(std::span<const Rgb> radiosity, std::span<const Rgb> unshot, const std::atomic<bool>* cancel);
    // The active scene after a Refined round, with its state, to hand to the
    // shooter (Shooting::replaceElementState).
    ActiveScene takeActiveScene();

    int rounds() const { return m_rounds; } // rounds that split something
    int initialElements() const { return m_initialElements; }
    // The elements split before the first shot come on top of the growth.
    int elementLimit() const
    {
        return static_cast<int>(m_initialElements * m_policy.growthLimit) + m_contactElements + m_penumbraElements;
    }
    // Active elements added along contact lines, and in penumbrae, before
    // the first shot.
    int contactElements() const { return m_contactElements; }
    int penumbraElements() const { return m_penumbraElements; }
    // What the round under way (or the next one) may grow the mesh to.
    int roundLimit() const;
    const AdaptiveMesh& mesh() const { return *m_mesh; }

private:
    // A round in its three phases, each resumable after a cancel: the
    // criterion over the active elements (in slices), the ranking, the splits.
    struct Round {
        std::vector<int> active;                      // active elements when the round began
        size_t scanned = 0;                           // of `active`, judged so far
        std::vector<std::pair<double, int>> selected; // (contrast, element) meeting the criterion
        bool ranked = false;
        std::vector<int> candidates; // hierarchy elements, by falling contrast
        size_t next = 0;
        int splits = 0;
    };
    int splitPenumbrae(const std::vector<Penumbra>& bands);
    void startRound(std::span<const Rgb> radiosity, std::span<const Rgb> unshot);
    // Judges the next slice of the round's active elements; false when all are.
    bool selectSlice();

    model::AdaptiveSettings m_settings;
    RefinementPolicy m_policy;
    PreparedScene m_hierarchy;
    std::unique_ptr<AdaptiveMesh> m_mesh;
    std::vector<int> m_sourceElement; // element of the active scene -> hierarchy element
    int m_initialElements = 0;
    int m_activeElements = 0;
    int m_contactElements = 0;
    int m_penumbraElements = 0;
    int m_roundsStarted = 0;
    int m_rounds = 0;
    bool m_due = false;
    std::optional<Round> m_round;
};

} // namespace regio::solver
