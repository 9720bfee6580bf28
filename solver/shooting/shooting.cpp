#include "solver/shooting/shooting.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace regio::solver {

double luminance(const Rgb& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

namespace {
// Luminance of the magnitudes: the luminance itself for power that is
// nowhere negative (every shot without overrelaxation).
double magnitude(const Rgb& c) { return 0.2126 * std::abs(c.r) + 0.7152 * std::abs(c.g) + 0.0722 * std::abs(c.b); }
} // namespace

int lightHemicubeResolution(int resolution)
{
    const int scene = Hemicube(resolution).resolution();
    return std::max(scene, std::min(2 * scene, kLightHemicubeMaxResolution));
}

Shooting::Shooting(const PreparedScene& scene, int hemicubeResolution, model::Visibility mode,
                   const ShootingOptions& options)
    : m_scene(scene)
    , m_hemicube(hemicubeResolution)
    , m_renderer(scene, m_hemicube, mode, options.threads)
    , m_buffer(m_renderer.makeBuffer())
    // Unused (and kept smallest) when the lights render as the rest.
    , m_lightHemicube(options.finerLightHemicubes ? solver::lightHemicubeResolution(hemicubeResolution) : 2)
    , m_cacheBudget(options.formFactorCacheBytes)
    , m_arena(options.formFactorCacheBytes)
    , m_overrelaxation(options.overrelaxation)
{
    dropRows();
    const bool anyLight =
        std::any_of(scene.properties.begin(), scene.properties.end(), [](const Properties& p) { return p.emits(); });
    if (options.finerLightHemicubes && anyLight && m_lightHemicube.resolution() > m_hemicube.resolution()) {
        m_lightRenderer = std::make_unique<HemicubeRenderer>(scene, m_lightHemicube, mode, options.threads);
        m_lightBuffer.emplace(m_lightRenderer->makeBuffer());
    }
    const size_t elements = scene.elements.size();
    m_radiosity.assign(elements, Rgb{0.0});
    m_unshot.assign(elements, Rgb{0.0});
    m_patchPower.assign(scene.patches.size(), Rgb{0.0});
    Rgb reflectanceArea{0.0};
    for (size_t e = 0; e < elements; ++e) {
        const Element& el = scene.elements[e];
        const Properties& p = scene.properties[static_cast<size_t>(el.properties)];
        m_radiosity[e] = p.emission;
        m_unshot[e] = p.emission;
        m_emitted += p.emission * el.area;
        m_patchPower[static_cast<size_t>(el.patch)] += p.emission * el.area;
        m_totalArea += el.area;
        reflectanceArea += p.reflectance * el.area;
    }
    if (m_totalArea > 0.0)
        m_meanReflectance = reflectanceArea / m_totalArea;
    packReceivers();
    sumPatchBooks();
}

void Shooting::packReceivers()
{
    m_receivers.resize(m_scene.elements.size());
    for (size_t e = 0; e < m_scene.elements.size(); ++e) {
        const Element& el = m_scene.elements[e];
        m_receivers[e] = {el.area, el.patch, el.properties};
    }
}

void Shooting::sumPatchBooks()
{
    m_patchUnshot.assign(m_scene.patches.size(), Rgb{0.0});
    m_patchMagnitude.assign(m_scene.patches.size(), Rgb{0.0});
    for (size_t p = 0; p < m_scene.patches.size(); ++p)
        sumPatchBooks(static_cast<int>(p));
}

void Shooting::sumPatchBooks(int patch)
{
    const Patch& p = m_scene.patches[static_cast<size_t>(patch)];
    Rgb unshot{0.0}, magnitude{0.0};
    for (int e = p.firstElement; e < p.firstElement + p.elementCount; ++e) {
        const Rgb u = m_unshot[static_cast<size_t>(e)] * m_scene.elements[static_cast<size_t>(e)].area;
        unshot += u;
        magnitude += glm::abs(u);
    }
    m_patchUnshot[static_cast<size_t>(patch)] = unshot;
    m_patchMagnitude[static_cast<size_t>(patch)] = magnitude;
}

int Shooting::selectShooter() const
{
    int best = -1;
    double bestPower = 0.0;
    for (size_t p = 0; p < m_patchPower.size(); ++p) {
        const double power = magnitude(m_patchPower[p]);
        if (power > bestPower) {
            bestPower = power;
            best = static_cast<int>(p);
        }
    }
    // Every luminance weight is positive: a patch with power in any channel is found.
    return best;
}

bool Shooting::emits(int patch) const
{
    return m_scene.properties[static_cast<size_t>(m_scene.patches[static_cast<size_t>(patch)].properties)].emits();
}

int Shooting::shotResolution(int patch) const
{
    const bool light = patch >= 0 && static_cast<size_t>(patch) < m_scene.patches.size() && emits(patch);
    return light ? lightHemicubeResolution() : hemicubeResolution();
}

VisibilityStats Shooting::visibilityStats() const
{
    VisibilityStats stats = m_renderer.stats();
    if (m_lightRenderer)
        stats += m_lightRenderer->stats();
    return stats;
}

void Shooting::dropRows()
{
    m_rows.assign(m_scene.patches.size(), FormFactorRow{});
    m_kept.assign(m_scene.patches.size(), 0);
    m_arena.reset();
    m_cacheBytes = 0;
    m_lastRow = nullptr;
}

const Shooting::FormFactorRow* Shooting::rowOf(int shooter, const std::atomic<bool>* cancel)
{
    const auto p = static_cast<size_t>(shooter);
    if (m_kept[p])
        return &m_rows[p];

    const bool light = m_lightRenderer && emits(shooter);
    HemicubeRenderer& renderer = light ? *m_lightRenderer : m_renderer;
    ItemBuffer& buffer = light ? *m_lightBuffer : m_buffer;
    const Hemicube& hemicube = light ? m_lightHemicube : m_hemicube;
    const size_t elements = m_scene.elements.size();
    // A patch in a narrow gap or behind a narrow face sees the scene from
    // several points (shooter_points.h): each point's factors are kept
    // apart, the row's receivers come from their mean.
    const ShooterSite site = shooterSite(m_scene, shooter);
    const ShooterKind kind = site.kind;
    const std::vector<Vec3> points = shooterPoints(m_scene, shooter, site);
    if (points.size() == 1) {
        if (!renderer.render(shooterFrameOfPatch(m_scene, shooter), buffer, cancel))
            return nullptr;
        accumulate(renderer, buffer, hemicube, m_perItem);
    } else {
        const Vec3& normal = m_scene.properties[static_cast<size_t>(m_scene.patches[p].properties)].plane.normal;
        // In a gap, the face across it hides most of the scene from every
        // point: what lies in its shadow is not painted (the same pixels).
        Occluder occluder;
        if (const int across = site.gapFace; across >= 0)
            occluder = {m_scene.faces[static_cast<size_t>(across)].polygon,
                        m_scene.properties[static_cast<size_t>(across)].plane.normal};
        m_perPointItems.resize(points.size());
        for (size_t q = 0; q < points.size(); ++q) {
            if (!renderer.render(shooterFrameAt(points[q], normal), buffer, cancel, occluder))
                return nullptr;
            accumulate(renderer, buffer, hemicube, m_perPointItems[q]);
        }
        m_perItem.assign(elements + kFirstElementItem, 0.0);
        const double share = 1.0 / static_cast<double>(points.size());
        for (const std::vector<double>& items : m_perPointItems)
            for (size_t i = 0; i < m_perItem.size(); ++i)
                m_perItem[i] += items[i] * share;
    }
    ++m_renderedShots;

    RowStorage& built = m_built;
    built.elements.clear();
    built.factors.clear();
    built.near.clear();
    built.farScale.clear();
    built.pointFactors.clear();
    for (size_t j = 0; j < elements; ++j)
        if (const double f = m_perItem[j + kFirstElementItem]; f != 0.0) {
            built.elements.push_back(static_cast<std::uint32_t>(j));
            built.factors.push_back(f);
        }
    // Behind a narrow face, a near receiver is seen by the shooter's
    // elements whose points see it (shooter_points.h).
    std::vector<double> weights;
    SeenShare seen;
    if (points.size() > 1)
        weights = pointWeights(m_scene, shooter, points);
    if (kind == ShooterKind::BehindNarrowFace)
        seen = [&](std::uint32_t entry, int s) {
            return seenShare(m_scene, built.elements[entry], points, weights, s, m_perPointItems);
        };
    correctNearField(
        m_scene, shooter, built.elements, built.factors, built.near, built.farScale,
        [this](size_t count, const std::function<void(size_t, size_t)>& body) { m_renderer.parallelFor(count, body); },
        seen);
    if (points.size() > 1)
        splitFarShareByPoints(m_scene, shooter, weights, m_perPointItems, built.elements, built.near,
                              built.pointFactors, built.farScale);
    if (points.size() == 1)
        built.rowFactors.assign(built.factors.begin(), built.factors.end());
    else
        built.rowFactors.clear();
    built.rowPointFactors.assign(built.pointFactors.begin(), built.pointFactors.end());
    FormFactorRow row;
    row.elements = built.elements;
    row.factors = built.rowFactors;
    row.near = built.near;
    row.farScale = built.farScale;
    row.points = static_cast<int>(points.size());
    row.pointFactors = built.rowPointFactors;
    row.escaped = m_perItem[kEmptyItem];
    row.blocked = m_perItem[kBlockerItem];
    const std::size_t bytes = row.bytes();
    if (m_cacheBudget == 0 || m_cacheBytes + bytes > m_cacheBudget) {
        m_unkept = row;
        return &m_unkept;
    }
    FormFactorRow& kept = m_rows[p];
    kept = row;
    kept.elements = m_arena.keep(row.elements);
    kept.factors = m_arena.keep(row.factors);
    kept.near = m_arena.keep(row.near);
    kept.farScale = m_arena.keep(row.farScale);
    kept.pointFactors = m_arena.keep(row.pointFactors);
    m_cacheBytes += bytes;
    m_kept[p] = 1;
    return &kept;
}

void Shooting::accumulate(HemicubeRenderer& renderer, const ItemBuffer& buffer, const Hemicube& hemicube,
                          std::vector<double>& out)
{
    const size_t items = m_scene.elements.size() + kFirstElementItem;
    const int rows = buffer.rowCount();
    renderer.parallelFor(2, [&](size_t begin, size_t end) {
        for (size_t half = begin; half < end; ++half) {
            std::vector<double>& sums = half == 0 ? out : m_secondHalf;
            sums.assign(items, 0.0);
            buffer.accumulateRows(hemicube, sums, half == 0 ? 0 : rows / 2, half == 0 ? rows / 2 : rows);
        }
    });
    for (size_t i = 0; i < items; ++i)
        out[i] += m_secondHalf[i];
}

ShotResult Shooting::shoot(const std::atomic<bool>* cancel, std::mutex* applyLock)
{
    const int shooter = selectShooter();
    if (shooter < 0)
        return ShotResult::NothingToShoot;
    const FormFactorRow* row = rowOf(shooter, cancel);
    if (!row)
        return ShotResult::Cancelled;
    const Patch& patch = m_scene.patches[static_cast<size_t>(shooter)];

    std::unique_lock<std::mutex> lock;
    if (applyLock)
        lock = std::unique_lock<std::mutex>(*applyLock);

    // The shooter's power: the area-weighted sum of its elements' unshot radiosity.
    Rgb power{0.0};
    // Emitters shoot what they hold and no more: their unshot power is mostly
    // their own emission, far more than what comes back to them, so an
    // overshoot would only leave a debt that each of a light's patches must
    // shoot again to take back.
    const double omega = emits(shooter) ? 1.0 : m_overrelaxation;
    const double kept = 1.0 - omega; // of the shooter's unshot radiosity
    m_elementPower.clear();
    for (int e = patch.firstElement; e < patch.firstElement + patch.elementCount; ++e) {
        Rgb& unshot = m_unshot[static_cast<size_t>(e)];
        m_elementPower.push_back(unshot * m_scene.elements[static_cast<size_t>(e)].area * omega);
        power += unshot * m_scene.elements[static_cast<size_t>(e)].area;
        unshot = kept == 0.0 ? Rgb{0.0} : unshot * kept;
    }
    m_patchPower[static_cast<size_t>(shooter)] = kept == 0.0 ? Rgb{0.0} : power * kept;
    sumPatchBooks(shooter);
    power *= omega; // exactly 1 when nothing is kept

    // What the far receivers' factors apply to: the shooter's power, or with
    // near receivers each shooter element's power times its far share
    // (near_field.h).
    // A patch shot from several points sends through each point's factors
    // what its elements give that point (shooter_points.h).
    const size_t points = static_cast<size_t>(row->points);
    m_pointPower.assign(points, Rgb{0.0});
    if (row->farScale.empty())
        m_pointPower[0] = power;
    for (size_t s = 0; s < m_elementPower.size() && !row->farScale.empty(); ++s)
        for (size_t q = 0; q < points; ++q)
            m_pointPower[q] += m_elementPower[s] * row->farScale[s * points + q];
    Rgb received{0.0};
    // W arriving on element j: reflected into its radiosity and unshot
    // radiosity, the rest absorbed.
    const auto receive = [&](size_t j, const Rgb& incident) {
        const Receiver& el = m_receivers[j];
        const Rgb& rho = m_scene.properties[static_cast<size_t>(el.properties)].reflectance;
        const Rgb reflected = rho * incident;
        const Rgb delta = reflected / el.area; // dB_j = rho_j dB_i F_ij A_i / A_j
        m_radiosity[j] += delta;
        const Rgb before = m_unshot[j] * el.area;
        m_unshot[j] += delta;
        const Rgb after = m_unshot[j] * el.area;
        const auto p = static_cast<size_t>(el.patch);
        m_patchPower[p] += reflected;
        // Both as differences of the same products, so that where nothing
        // is negative the two sums stay equal to the last bit.
        m_patchUnshot[p] += after - before;
        m_patchMagnitude[p] += glm::abs(after) - glm::abs(before);
        m_absorbed += incident - reflected;
        received += incident;
    };
    if (points == 1)
        for (size_t k = 0; k < row->elements.size(); ++k)
            receive(row->elements[k], m_pointPower[0] * double(row->factors[k])); // from the whole shooter
    else
        for (size_t k = 0; k < row->elements.size(); ++k) {
            const float* f = row->pointFactors.data() + k * points;
            Rgb incident{0.0};
            for (size_t q = 0; q < points; ++q)
                incident += m_pointPower[q] * double(f[q]);
            if (incident != Rgb{0.0}) // a near receiver's far factors are 0
                receive(row->elements[k], incident);
        }
    // Near receivers: from each of the shooter's elements; a receiver's
    // terms are consecutive.
    for (size_t t = 0; t < row->near.size();) {
        const std::uint32_t entry = row->near[t].entry;
        Rgb incident{0.0};
        for (; t < row->near.size() && row->near[t].entry == entry; ++t)
            incident += m_elementPower[size_t(row->near[t].shooterElement)] * row->near[t].factor;
        receive(row->elements[entry], incident);
    }
    m_escaped += power - received;
    m_lastShooter = shooter;
    m_lastRow = row;
    ++m_iterations;
    return ShotResult::Shot;
}

std::vector<double> Shooting::lastFormFactors() const
{
    std::vector<double> f(m_scene.elements.size(), 0.0);
    if (!m_lastRow)
        return f;
    // Near receivers and the far share: the shooter's elements' values,
    // weighted by their share of its area.
    const Patch& patch = m_scene.patches[static_cast<size_t>(m_lastShooter)];
    const size_t points = static_cast<size_t>(m_lastRow->points);
    std::vector<double> farScale(points, m_lastRow->farScale.empty() ? 1.0 : 0.0);
    for (size_t s = 0; s < m_lastRow->farScale.size() / points; ++s)
        for (size_t q = 0; q < points; ++q)
            farScale[q] += m_lastRow->farScale[s * points + q] *
                           m_scene.elements[static_cast<size_t>(patch.firstElement) + s].area / patch.area;
    for (size_t k = 0; k < m_lastRow->elements.size(); ++k)
        for (size_t q = 0; q < points; ++q)
            f[m_lastRow->elements[k]] +=
                double(points == 1 ? m_lastRow->factors[k] : m_lastRow->pointFactors[k * points + q]) * farScale[q];
    for (const NearTerm& t : m_lastRow->near)
        f[m_lastRow->elements[t.entry]] +=
            t.factor * m_scene.elements[static_cast<size_t>(patch.firstElement + t.shooterElement)].area / patch.area;
    return f;
}

EnergyBalance Shooting::energy() const
{
    EnergyBalance e;
    e.emitted = m_emitted;
    e.absorbed = m_absorbed;
    e.escaped = m_escaped;
    for (size_t p = 0; p < m_patchUnshot.size(); ++p) {
        e.unshot += m_patchUnshot[p];
        e.unshotMagnitude += m_patchMagnitude[p];
    }
    return e;
}

double Shooting::unshotRatio(const EnergyBalance& books) const
{
    const Rgb& unshot = books.unshotMagnitude;
    double ratio = 0.0;
    for (int c = 0; c < 3; ++c)
        if (m_emitted[c] > 0.0)
            ratio = std::max(ratio, unshot[c] / m_emitted[c]);
    return ratio;
}

void Shooting::replaceElementState(std::vector<Rgb> radiosity, std::vector<Rgb> unshot)
{
    dropRows(); // the element and patch numbering changed
    m_radiosity = std::move(radiosity);
    m_unshot = std::move(unshot);
    m_patchPower.assign(m_scene.patches.size(), Rgb{0.0});
    m_totalArea = 0.0;
    Rgb reflectanceArea{0.0};
    for (size_t e = 0; e < m_scene.elements.size(); ++e) {
        const Element& el = m_scene.elements[e];
        m_patchPower[static_cast<size_t>(el.patch)] += m_unshot[e] * el.area;
        m_totalArea += el.area;
        reflectanceArea += m_scene.properties[static_cast<size_t>(el.properties)].reflectance * el.area;
    }
    if (m_totalArea > 0.0)
        m_meanReflectance = reflectanceArea / m_totalArea;
    packReceivers();
    sumPatchBooks();
}

Rgb Shooting::ambient(const EnergyBalance& books) const
{
    if (m_totalArea <= 0.0)
        return Rgb{0.0};
    const Rgb& unshot = books.unshot;
    Rgb result{0.0};
    for (int c = 0; c < 3; ++c) {
        const double rho = std::min(m_meanReflectance[c], 0.999);
        result[c] = unshot[c] / m_totalArea / (1.0 - rho);
    }
    return result;
}

} // namespace regio::solver
