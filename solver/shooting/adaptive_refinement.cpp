#include "solver/shooting/adaptive_refinement.h"

#include "solver/prepare/near_outlines.h"
#include "solver/shooting/contact_lines.h"
#include "solver/shooting/penumbrae.h"

#include <algorithm>
#include <numeric>

namespace regio::solver {

AdaptiveRefinement::AdaptiveRefinement(const PreparedScene& initial, const model::AdaptiveSettings& settings,
                                       const RefinementPolicy& policy)
    : m_settings(settings)
    , m_policy(policy)
    , m_hierarchy(initial)
    , m_initialElements(static_cast<int>(initial.elements.size()))
    , m_activeElements(static_cast<int>(initial.elements.size()))
{
}

AdaptiveRefinement::~AdaptiveRefinement() = default;

void AdaptiveRefinement::noteShot(int iteration, bool shooterEmits)
{
    if (shooterEmits || (m_policy.roundInterval > 0 && iteration % m_policy.roundInterval == 0))
        m_due = true;
}

int AdaptiveRefinement::roundLimit() const
{
    const int round = std::max(1, m_round ? m_roundsStarted : m_roundsStarted + 1);
    const double share = std::min(1.0, double(round) / double(std::max(1, m_policy.maxRounds)));
    const int start = m_initialElements + m_contactElements + m_penumbraElements;
    return start + static_cast<int>((elementLimit() - start) * share);
}

int AdaptiveRefinement::splitBeforeFirstShot()
{
    if (m_mesh)
        return 0;
    const std::vector<std::vector<int>> contacts =
        m_policy.contactPasses > 0 ? contactFaces(m_hierarchy) : std::vector<std::vector<int>>{};
    const std::vector<std::vector<std::vector<Vec3>>> outlines =
        m_policy.outlinePasses > 0 ? nearOutlines(m_hierarchy) : std::vector<std::vector<std::vector<Vec3>>>{};
    const std::vector<Penumbra> bands = m_policy.penumbraPasses > 0 ? penumbrae(m_hierarchy) : std::vector<Penumbra>{};
    const auto none = [](const auto& perFace) {
        return std::all_of(perFace.begin(), perFace.end(), [](const auto& lines) { return lines.empty(); });
    };
    if (bands.empty() && none(contacts) && none(outlines))
        return 0;
    // Before the first shot every element holds its emission, radiosity and
    // unshot alike (as Shooting starts).
    std::vector<Rgb> emission(m_hierarchy.elements.size());
    for (size_t e = 0; e < emission.size(); ++e)
        emission[e] = m_hierarchy.properties[size_t(m_hierarchy.elements[e].properties)].emission;
    m_mesh = std::make_unique<AdaptiveMesh>(m_hierarchy, emission, emission, m_settings.anchoring);
    m_sourceElement.resize(emission.size());
    std::iota(m_sourceElement.begin(), m_sourceElement.end(), 0);
    int contactSplits = 0;
    for (int pass = 0; pass < m_policy.contactPasses && !contacts.empty(); ++pass) {
        const int done = m_mesh->subdivide(elementsOnContactLines(*m_mesh, contacts), m_settings.minEdge);
        if (done == 0)
            break;
        contactSplits += done;
    }
    for (int pass = 0; pass < m_policy.outlinePasses && !none(outlines); ++pass) {
        const int done = m_mesh->subdivide(elementsOnNearOutlines(*m_mesh, outlines), m_settings.minEdge);
        if (done == 0)
            break;
        contactSplits += done;
    }
    const int penumbraSplits = splitPenumbrae(bands);
    // Each split makes one active element four.
    m_contactElements = 3 * contactSplits;
    m_penumbraElements = 3 * penumbraSplits;
    m_activeElements += m_contactElements + m_penumbraElements;
    return contactSplits + penumbraSplits;
}

int AdaptiveRefinement::splitPenumbrae(const std::vector<Penumbra>& bands)
{
    const double minEdge = m_settings.minEdge * m_policy.penumbraMinEdge;
    int budget = static_cast<int>(m_policy.penumbraShare * (m_policy.growthLimit - 1.0) * m_initialElements);
    int splits = 0;
    for (int pass = 0; pass < m_policy.penumbraPasses && !bands.empty(); ++pass) {
        // The brightest lights' bands first; a band whose elements no longer
        // fit the budget is left whole (a band split halfway would grade
        // across the middle of the penumbra).
        std::vector<char> taken(m_mesh->scene().elements.size(), 0);
        std::vector<int> chosen;
        for (const Penumbra& band : bands) {
            std::vector<int> elements;
            for (int e : elementsInPenumbra(*m_mesh, band))
                if (!taken[size_t(e)] && m_mesh->canSplit(e, minEdge))
                    elements.push_back(e);
            if (3 * static_cast<int>(chosen.size() + elements.size()) > budget)
                continue;
            for (int e : elements)
                taken[size_t(e)] = 1;
            chosen.insert(chosen.end(), elements.begin(), elements.end());
        }
        const int done = m_mesh->subdivide(chosen, minEdge);
        if (done == 0)
            break;
        splits += done;
        budget -= 3 * done;
    }
    return splits;
}

void AdaptiveRefinement::startRound(std::span<const Rgb> radiosity, std::span<const Rgb> unshot)
{
    // The hand-over: the shooter's state goes back into the hierarchy first.
    if (!m_mesh) {
        m_mesh = std::make_unique<AdaptiveMesh>(m_hierarchy, std::vector<Rgb>(radiosity.begin(), radiosity.end()),
                                                std::vector<Rgb>(unshot.begin(), unshot.end()), m_settings.anchoring);
        m_sourceElement.resize(radiosity.size());
        std::iota(m_sourceElement.begin(), m_sourceElement.end(), 0);
    } else {
        m_mesh->setActiveState(m_sourceElement, radiosity, unshot);
    }
    Round round;
    round.active = m_mesh->activeElements();
    m_round = std::move(round);
    ++m_roundsStarted;
}

bool AdaptiveRefinement::selectSlice()
{
    Round& round = *m_round;
    const size_t end =
        std::min(round.active.size(), round.scanned + static_cast<size_t>(std::max(1, m_policy.selectSliceSize)));
    // The §5.7 criterion (AdaptiveMesh::selectBySubdivisionCriterion), with
    // the contrast kept for the ranking. The mesh does not change while the
    // round selects, so slices judge exactly what one pass would.
    for (; round.scanned < end; ++round.scanned) {
        const int e = round.active[round.scanned];
        const double c = m_mesh->contrast(e, m_mesh->radiosity());
        if (c > m_settings.threshold && m_mesh->canSplit(e, m_settings.minEdge))
            round.selected.emplace_back(c, e);
    }
    return round.scanned < round.active.size();
}

AdaptiveRefinement::Outcome AdaptiveRefinement::runRound(std::span<const Rgb> radiosity, std::span<const Rgb> unshot,
                                                         const std::atomic<bool>* cancel)
{
    m_due = false;
    if (!m_round) {
        if (m_roundsStarted >= m_policy.maxRounds || m_activeElements >= elementLimit())
            return Outcome::Settled;
        startRound(radiosity, unshot);
    }
    Round& round = *m_round;
    // Every call does at least one slice of work before it looks at the flag,
    // so a solve cancelled over and over still gets through its round.
    const auto cancelled = [cancel] { return cancel && cancel->load(); };
    while (selectSlice())
        if (cancelled())
            return Outcome::Cancelled;
    if (!round.ranked) {
        // Sharpest borders first (see the top of the header): the budget may
        // end the round before every candidate is split.
        std::sort(round.selected.begin(), round.selected.end(), [](const auto& a, const auto& b) {
            return a.first != b.first ? a.first > b.first : a.second < b.second;
        });
        round.candidates.reserve(round.selected.size());
        for (const auto& [contrast, e] : round.selected)
            round.candidates.push_back(e);
        round.selected = {};
        round.active = {};
        round.ranked = true;
    }
    const size_t slice = static_cast<size_t>(std::max(1, m_policy.sliceSize));
    const int limit = roundLimit();
    while (round.next < round.candidates.size() && m_activeElements < limit) {
        const size_t count = std::min(slice, round.candidates.size() - round.next);
        const int splits =
            m_mesh->subdivide(std::span<const int>(round.candidates).subspan(round.next, count), m_settings.minEdge);
        // Each split makes one active element four.
        m_activeElements += 3 * splits;
        round.splits += splits;
        round.next += count;
        if (round.next < round.candidates.size() && m_activeElements < limit && cancelled())
            return Outcome::Cancelled;
    }
    const int splits = round.splits;
    m_round.reset();
    if (splits == 0)
        return Outcome::Settled;
    ++m_rounds;
    return Outcome::Refined;
}

ActiveScene AdaptiveRefinement::takeActiveScene()
{
    ActiveScene active = m_mesh->activeScene();
    m_sourceElement = active.sourceElement;
    return active;
}

} // namespace regio::solver
