#include "support/pointwise_reference.h"

#include "support/reference_geometry.h"

#include "model/geometry/geometry.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <stdexcept>

namespace regio::test {

using namespace reference;

// Buffers one thread reuses from call to call.
struct PointwiseReference::Scratch {
    std::vector<Vec3> clipped;
    std::vector<int> occluders;
    const SourceRadiosity* radiosity = nullptr; // stands in for the patches' values (gatheredBySource)
};

double pointToPolygonFormFactor(const Vec3& point, const Vec3& normal, std::span<const Vec3> polygon)
{
    std::vector<Vec3> clipped;
    return contourFormFactor(point, normal, polygon, clipped);
}

PointwiseReference::PointwiseReference(const model::Scene& scene, const PointwiseReferenceOptions& options)
    : m_options(options)
{
    buildFaces(scene);
    for (const auto& [faceId, size] : m_options.facePatchSizes) {
        if (faceIndex(faceId) < 0)
            throw std::invalid_argument("PointwiseReference: a patch size for " + faceId + ", which is no face");
        if (!(size > 0.0))
            throw std::invalid_argument("PointwiseReference: the patch size of " + faceId + " is not positive");
    }
    buildPatches();
    buildOccluders();
    markNearPatches();
    computeFormFactors();
    solve();
    refineNearPatches();
}

int PointwiseReference::faceIndex(const std::string& faceId) const
{
    for (std::size_t i = 0; i < m_faces.size(); ++i) {
        if (m_faces[i].id == faceId)
            return static_cast<int>(i);
    }
    return -1;
}

void PointwiseReference::buildFaces(const model::Scene& scene)
{
    for (const model::Object& object : scene.objects) {
        for (const model::Part& part : object.parts) {
            for (const model::Face& face : part.faces) {
                ReferenceFace f;
                f.id = face.id;
                const model::Material* material = scene.materialOf(part, face);
                if (material == nullptr)
                    throw std::invalid_argument("PointwiseReference: face " + face.id + " names no material");
                f.reflectance = material->reflectance;
                f.emission = material->emission;
                std::vector<Vec3> polygon = model::loopPositions(part.vertices, face.loop);
                const Vec3 normal = model::polygonNormal(polygon);
                const double area = polygon.size() >= 3 ? model::polygonArea(polygon) : 0.0;
                if (area > 1e-12 && glm::dot(normal, normal) > 0.5) {
                    f.normal = normal;
                    f.area = area;
                    // The mean height: the corners of a nearly planar face
                    // straddle its plane.
                    for (const Vec3& p : polygon)
                        f.offset += glm::dot(normal, p);
                    f.offset /= static_cast<double>(polygon.size());
                    planeFrame(polygon, normal, f.u, f.v);
                    f.boxMin = f.boxMax = polygon[0];
                    for (const Vec3& p : polygon) {
                        f.boxMin = glm::min(f.boxMin, p);
                        f.boxMax = glm::max(f.boxMax, p);
                    }
                    for (std::size_t k = 0; k < polygon.size(); ++k) {
                        const Vec3& a = polygon[k];
                        const Vec3& b = polygon[(k + 1) % polygon.size()];
                        const Vec3 m = glm::normalize(glm::cross(normal, b - a));
                        f.edgeNormals.push_back(m);
                        f.edgeOffsets.push_back(glm::dot(m, a));
                    }
                    f.polygon = std::move(polygon);
                }
                m_faces.push_back(std::move(f));
            }
        }
    }
    // Faces resting on each other: the same plane, opposite normals,
    // overlapping boxes (covered() decides point by point).
    for (std::size_t i = 0; i < m_faces.size(); ++i) {
        ReferenceFace& f = m_faces[i];
        for (std::size_t j = 0; j < m_faces.size(); ++j) {
            const ReferenceFace& g = m_faces[j];
            if (i == j || f.area <= 0.0 || g.area <= 0.0)
                continue;
            if (glm::dot(f.normal, g.normal) > -1.0 + 1e-9 || std::abs(f.offset + g.offset) > 1e-6)
                continue;
            if (glm::all(glm::lessThanEqual(f.boxMin, g.boxMax + 1e-6)) &&
                glm::all(glm::lessThanEqual(g.boxMin, f.boxMax + 1e-6)))
                f.coveredBy.push_back(static_cast<int>(j));
        }
    }
}

bool PointwiseReference::covered(int face, const Vec3& point) const
{
    for (int other : m_faces[static_cast<std::size_t>(face)].coveredBy) {
        const ReferenceFace& g = m_faces[static_cast<std::size_t>(other)];
        bool inside = true;
        for (std::size_t k = 0; k < g.edgeNormals.size() && inside; ++k)
            inside = glm::dot(g.edgeNormals[k], point) > g.edgeOffsets[k] + kEdgeTolerance;
        if (inside)
            return true;
    }
    return false;
}

void PointwiseReference::buildPatches()
{
    std::vector<Vec3> points;
    for (std::size_t fi = 0; fi < m_faces.size(); ++fi) {
        ReferenceFace& f = m_faces[fi];
        f.firstPatch = static_cast<int>(m_patches.size());
        if (f.area <= 0.0)
            continue;
        const auto own = m_options.facePatchSizes.find(f.id);
        const double size = own != m_options.facePatchSizes.end() ? own->second : m_options.patchSize;
        double s0 = 0.0, s1 = 0.0, t0 = 0.0, t1 = 0.0;
        extent(f.polygon, f.u, s0, s1);
        extent(f.polygon, f.v, t0, t1);
        const int nu = std::max(1, static_cast<int>(std::ceil((s1 - s0) / size - 1e-9)));
        const int nv = std::max(1, static_cast<int>(std::ceil((t1 - t0) / size - 1e-9)));
        for (std::vector<Vec3>& cell : splitGrid(f.polygon, f.u, f.v, nu, nv)) {
            ReferencePatch p;
            p.face = static_cast<int>(fi);
            p.area = model::polygonArea(cell);
            p.centroid = model::polygonCentroid(cell);
            p.boxMin = p.boxMax = cell[0];
            for (const Vec3& q : cell) {
                p.size = std::max(p.size, 2.0 * glm::length(q - p.centroid));
                p.boxMin = glm::min(p.boxMin, q);
                p.boxMax = glm::max(p.boxMax, q);
            }
            p.polygon = std::move(cell);
            // The form factor samples are receivers of the contour formula
            // first: cell centres. The gather's are ray ends only: jittered.
            const auto samplesOf = [&](int perSide, std::optional<std::uint64_t> seed,
                                       std::vector<ReferenceSample>& out) {
                stratifiedPoints(p.polygon, f.normal, f.u, f.v, perSide, seed, points);
                for (const Vec3& q : points)
                    out.push_back({q, covered(static_cast<int>(fi), q)});
            };
            samplesOf(m_options.samplesPerSide, std::nullopt, p.samples);
            samplesOf(m_options.nearSamplesPerSide, std::nullopt, p.nearSamples);
            const bool emits = maxComponent(f.emission) > 0.0;
            samplesOf(emits ? m_options.emitterRaysPerSide : m_options.gatherRaysPerSide, mix64(m_patches.size()),
                      p.gatherSamples);
            const auto open = std::count_if(p.nearSamples.begin(), p.nearSamples.end(),
                                            [](const ReferenceSample& s) { return !s.covered; });
            p.visibleArea = p.area * static_cast<double>(open) / static_cast<double>(p.nearSamples.size());
            m_patches.push_back(std::move(p));
        }
        f.patchCount = static_cast<int>(m_patches.size()) - f.firstPatch;
    }
}

void PointwiseReference::buildOccluders()
{
    const std::size_t n = m_faces.size();
    m_occluders.assign(n * n, {});
    m_interacts.assign(n * n, 0);
    // Signed distances of a face's corners from a plane: their range.
    const auto range = [](const ReferenceFace& f, const ReferenceFace& plane, double& lo, double& hi) {
        lo = hi = glm::dot(plane.normal, f.polygon[0]) - plane.offset;
        for (const Vec3& p : f.polygon) {
            lo = std::min(lo, glm::dot(plane.normal, p) - plane.offset);
            hi = std::max(hi, glm::dot(plane.normal, p) - plane.offset);
        }
    };
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = 0; j < n; ++j) {
            const ReferenceFace& fi = m_faces[i];
            const ReferenceFace& fj = m_faces[j];
            if (i == j || fi.area <= 0.0 || fj.area <= 0.0)
                continue;
            double lo = 0.0, hi = 0.0, lo2 = 0.0, hi2 = 0.0;
            range(fj, fi, lo, hi);
            range(fi, fj, lo2, hi2);
            // Light goes from the front of j to the front of i: some of each
            // must lie in front of the other.
            if (hi <= kPlaneTolerance || hi2 <= kPlaneTolerance)
                continue;
            m_interacts[i * n + j] = 1;
            for (std::size_t g = 0; g < n; ++g) {
                const ReferenceFace& fg = m_faces[g];
                if (g == i || g == j || fg.area <= 0.0)
                    continue;
                // A ray from i to j runs in front of both planes: an occluder
                // wholly behind (or on) either cannot stop it ...
                range(fg, fi, lo, hi);
                range(fg, fj, lo2, hi2);
                if (hi <= kPlaneTolerance || hi2 <= kPlaneTolerance)
                    continue;
                // ... nor can one whose plane has both faces on one side.
                double ilo = 0.0, ihi = 0.0, jlo = 0.0, jhi = 0.0;
                range(fi, fg, ilo, ihi);
                range(fj, fg, jlo, jhi);
                if (std::min(ilo, jlo) >= -kPlaneTolerance || std::max(ihi, jhi) <= kPlaneTolerance)
                    continue;
                m_occluders[i * n + j].push_back(static_cast<int>(g));
            }
        }
    }
}

void PointwiseReference::markNearPatches()
{
    // The distance from a point to a face's polygon: to its plane above the
    // inside, else to the nearest edge.
    const auto distance = [](const ReferenceFace& g, const Vec3& p) {
        const double height = glm::dot(g.normal, p) - g.offset;
        const Vec3 q = p - g.normal * height;
        bool inside = true;
        for (std::size_t k = 0; k < g.edgeNormals.size() && inside; ++k)
            inside = glm::dot(g.edgeNormals[k], q) >= g.edgeOffsets[k];
        if (inside)
            return std::abs(height);
        double nearest = 1e300;
        for (std::size_t k = 0; k < g.polygon.size(); ++k) {
            const Vec3& a = g.polygon[k];
            const Vec3 e = g.polygon[(k + 1) % g.polygon.size()] - a;
            const double t = std::clamp(glm::dot(p - a, e) / glm::dot(e, e), 0.0, 1.0);
            nearest = std::min(nearest, glm::length(p - (a + e * t)));
        }
        return nearest;
    };
    for (ReferencePatch& p : m_patches) {
        for (std::size_t g = 0; g < m_faces.size() && !p.near; ++g) {
            if (interacts(p.face, static_cast<int>(g)))
                p.near = distance(m_faces[g], p.centroid) - 0.5 * p.size < m_options.nearDistance * p.size;
        }
    }
}

void PointwiseReference::occludersInBox(int receiverFace, int sourceFace, const Vec3& lo, const Vec3& hi,
                                        std::vector<int>& out) const
{
    out.clear();
    for (int g : occluders(receiverFace, sourceFace)) {
        const ReferenceFace& f = m_faces[static_cast<std::size_t>(g)];
        if (glm::all(glm::lessThanEqual(f.boxMin, hi + 1e-6)) && glm::all(glm::lessThanEqual(lo - 1e-6, f.boxMax)))
            out.push_back(g);
    }
}

bool PointwiseReference::blocked(const Vec3& a, const Vec3& b, std::span<const int> candidates) const
{
    for (int g : candidates) {
        const ReferenceFace& f = m_faces[static_cast<std::size_t>(g)];
        const double da = glm::dot(f.normal, a) - f.offset;
        const double db = glm::dot(f.normal, b) - f.offset;
        if (!((da > 0.0 && db < 0.0) || (da < 0.0 && db > 0.0)))
            continue;
        const Vec3 p = a + (b - a) * (da / (da - db));
        bool inside = true;
        for (std::size_t k = 0; k < f.edgeNormals.size() && inside; ++k)
            inside = glm::dot(f.edgeNormals[k], p) >= f.edgeOffsets[k] - kEdgeTolerance;
        if (inside)
            return true;
    }
    return false;
}

void PointwiseReference::computeFormFactors()
{
    const std::size_t n = m_patches.size();
    const double eps = m_options.surfaceOffset;
    struct Entry {
        int to = 0;
        double forward = 0.0;  // F_ij, i the row
        double backward = 0.0; // F_ji
    };
    // Each unordered pair once, from its lower index: the rays between the
    // two sample sets serve both directions.
    std::vector<std::vector<Entry>> upper(n);
    struct RowScratch {
        PointwiseReference::Scratch base;
        std::vector<double> fromI, fromJ;
        std::vector<char> frontOfI, frontOfJ;
        std::vector<signed char> rayBlocked;
    };
    parallelFor<RowScratch>(n, m_options.threads, [&](std::size_t i, RowScratch& s) {
        const ReferencePatch& pi = m_patches[i];
        const ReferenceFace& fi = m_faces[static_cast<std::size_t>(pi.face)];
        for (std::size_t j = i + 1; j < n; ++j) {
            const ReferencePatch& pj = m_patches[j];
            const ReferenceFace& fj = m_faces[static_cast<std::size_t>(pj.face)];
            if (!interacts(pi.face, pj.face))
                continue;
            const auto inFront = [](std::span<const Vec3> polygon, const ReferenceFace& plane) {
                return std::any_of(polygon.begin(), polygon.end(), [&](const Vec3& p) {
                    return glm::dot(plane.normal, p) - plane.offset > kPlaneTolerance;
                });
            };
            if (!inFront(pj.polygon, fi) || !inFront(pi.polygon, fj))
                continue;
            const std::vector<ReferenceSample>& si = pi.formFactorSamples();
            const std::vector<ReferenceSample>& sj = pj.formFactorSamples();
            // The contour formula from every open sample of one patch to the other.
            s.fromI.assign(si.size(), 0.0);
            s.fromJ.assign(sj.size(), 0.0);
            s.frontOfJ.assign(si.size(), 0);
            s.frontOfI.assign(sj.size(), 0);
            std::size_t openI = 0, openJ = 0;
            bool any = false;
            for (std::size_t a = 0; a < si.size(); ++a) {
                s.frontOfJ[a] = glm::dot(fj.normal, si[a].point) - fj.offset > kPlaneTolerance;
                if (si[a].covered)
                    continue;
                ++openI;
                if (s.frontOfJ[a])
                    s.fromI[a] = contourFormFactor(si[a].point, fi.normal, pj.polygon, s.base.clipped);
                any = any || s.fromI[a] > 0.0;
            }
            for (std::size_t b = 0; b < sj.size(); ++b) {
                s.frontOfI[b] = glm::dot(fi.normal, sj[b].point) - fi.offset > kPlaneTolerance;
                if (sj[b].covered)
                    continue;
                ++openJ;
                if (s.frontOfI[b])
                    s.fromJ[b] = contourFormFactor(sj[b].point, fj.normal, pi.polygon, s.base.clipped);
                any = any || s.fromJ[b] > 0.0;
            }
            if (!any)
                continue;
            occludersInBox(pi.face, pj.face, glm::min(pi.boxMin, pj.boxMin), glm::max(pi.boxMax, pj.boxMax),
                           s.base.occluders);
            // Rays between the two sample sets, cast only when a direction needs them.
            s.rayBlocked.assign(si.size() * sj.size(), -1);
            const auto isBlocked = [&](std::size_t a, std::size_t b) {
                signed char& known = s.rayBlocked[a * sj.size() + b];
                if (known < 0)
                    known =
                        blocked(si[a].point + fi.normal * eps, sj[b].point + fj.normal * eps, s.base.occluders) ? 1 : 0;
                return known == 1;
            };
            const bool clear = s.base.occluders.empty();
            double forward = 0.0, backward = 0.0;
            for (std::size_t a = 0; a < si.size(); ++a) {
                if (s.fromI[a] <= 0.0)
                    continue;
                double seen = 0.0, total = 0.0;
                for (std::size_t b = 0; b < sj.size() && !clear; ++b) {
                    if (!s.frontOfI[b])
                        continue;
                    total += 1.0;
                    seen += isBlocked(a, b) ? 0.0 : 1.0;
                }
                forward += s.fromI[a] * (total > 0.0 ? seen / total : 1.0);
            }
            for (std::size_t b = 0; b < sj.size(); ++b) {
                if (s.fromJ[b] <= 0.0)
                    continue;
                double seen = 0.0, total = 0.0;
                for (std::size_t a = 0; a < si.size() && !clear; ++a) {
                    if (!s.frontOfJ[a])
                        continue;
                    total += 1.0;
                    seen += isBlocked(a, b) ? 0.0 : 1.0;
                }
                backward += s.fromJ[b] * (total > 0.0 ? seen / total : 1.0);
            }
            forward = openI > 0 ? forward / static_cast<double>(openI) : 0.0;
            backward = openJ > 0 ? backward / static_cast<double>(openJ) : 0.0;
            if (forward > 0.0 || backward > 0.0)
                upper[i].push_back({static_cast<int>(j), forward, backward});
        }
    });

    // Compressed rows. Row i receives the pairs of lower rows (in increasing
    // order) before its own higher ones, so its columns come out sorted.
    std::vector<std::size_t> counts(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
        for (const Entry& e : upper[i]) {
            if (e.forward > 0.0)
                ++counts[i];
            if (e.backward > 0.0)
                ++counts[static_cast<std::size_t>(e.to)];
        }
    }
    m_rowStart.assign(n + 1, 0);
    for (std::size_t i = 0; i < n; ++i)
        m_rowStart[i + 1] = m_rowStart[i] + counts[i];
    m_columns.assign(m_rowStart[n], 0);
    m_values.assign(m_rowStart[n], 0.0);
    std::vector<std::size_t> fill(m_rowStart.begin(), m_rowStart.end() - 1);
    for (std::size_t i = 0; i < n; ++i) {
        for (const Entry& e : upper[i]) {
            const auto j = static_cast<std::size_t>(e.to);
            if (e.forward > 0.0) {
                m_columns[fill[i]] = e.to;
                m_values[fill[i]++] = e.forward;
            }
            if (e.backward > 0.0) {
                m_columns[fill[j]] = static_cast<int>(i);
                m_values[fill[j]++] = e.backward;
            }
        }
        upper[i] = {};
    }
}

double PointwiseReference::formFactor(std::size_t from, std::size_t to) const
{
    const auto begin = m_columns.begin() + static_cast<std::ptrdiff_t>(m_rowStart[from]);
    const auto end = m_columns.begin() + static_cast<std::ptrdiff_t>(m_rowStart[from + 1]);
    const auto at = std::lower_bound(begin, end, static_cast<int>(to));
    if (at == end || *at != static_cast<int>(to))
        return 0.0;
    return m_values[static_cast<std::size_t>(at - m_columns.begin())];
}

void PointwiseReference::solve()
{
    // Gauss-Seidel (as Cohen and Greenberg 1985 solve the radiosity system):
    // every patch takes the newest values of the others at once.
    const std::size_t n = m_patches.size();
    std::vector<Rgb> b(n);
    for (std::size_t i = 0; i < n; ++i)
        b[i] = m_faces[static_cast<std::size_t>(m_patches[i].face)].emission;
    m_iterations = 0;
    while (m_iterations < m_options.maxIterations) {
        ++m_iterations;
        double change = 0.0, largest = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            const ReferenceFace& f = m_faces[static_cast<std::size_t>(m_patches[i].face)];
            Rgb gathered(0.0);
            for (std::size_t k = m_rowStart[i]; k < m_rowStart[i + 1]; ++k)
                gathered += m_values[k] * b[static_cast<std::size_t>(m_columns[k])];
            const Rgb next = f.emission + f.reflectance * gathered;
            change = std::max(change, maxComponent(glm::abs(next - b[i])));
            largest = std::max(largest, maxComponent(next));
            b[i] = next;
        }
        if (change <= m_options.tolerance * largest)
            break;
    }
    for (std::size_t i = 0; i < n; ++i)
        m_patches[i].radiosity = b[i];
}

void PointwiseReference::refineNearPatches()
{
    const int n = m_options.refineSplit;
    if (n <= 0)
        return;
    struct Job {
        std::size_t patch = 0;
        int cell = 0;
        Vec3 centre{0.0};
    };
    std::vector<Job> jobs;
    for (std::size_t i = 0; i < m_patches.size(); ++i) {
        ReferencePatch& p = m_patches[i];
        if (!p.near || p.visibleArea <= 0.0)
            continue;
        const ReferenceFace& f = m_faces[static_cast<std::size_t>(p.face)];
        p.refined.assign(static_cast<std::size_t>(n * n), p.radiosity);
        std::vector<int> cells;
        const std::vector<std::vector<Vec3>> parts = splitGrid(p.polygon, f.u, f.v, n, n, &cells);
        for (std::size_t k = 0; k < parts.size(); ++k) {
            const Vec3 centre = model::polygonCentroid(parts[k]);
            if (!covered(p.face, centre))
                jobs.push_back({i, cells[k], centre});
        }
    }
    // Every value is gathered from the patch solution alone, so the order
    // of the work does not matter.
    std::vector<Rgb> values(jobs.size());
    parallelFor<Scratch>(jobs.size(), m_options.threads, [&](std::size_t k, Scratch& scratch) {
        values[k] = gatherAt(m_patches[jobs[k].patch].face, jobs[k].centre, false, scratch);
    });
    for (std::size_t k = 0; k < jobs.size(); ++k)
        m_patches[jobs[k].patch].refined[static_cast<std::size_t>(jobs[k].cell)] = values[k];
}

Rgb PointwiseReference::refinedAt(const ReferencePatch& patch, const Vec3& point) const
{
    const ReferenceFace& f = m_faces[static_cast<std::size_t>(patch.face)];
    const int n = m_options.refineSplit;
    const auto cell = [&](const Vec3& axis) {
        double lo = 0.0, hi = 0.0;
        extent(patch.polygon, axis, lo, hi);
        const double at = std::floor((glm::dot(axis, point) - lo) / (hi - lo) * n);
        return std::clamp(static_cast<int>(at), 0, n - 1);
    };
    return patch.refined[static_cast<std::size_t>(cell(f.u) * n + cell(f.v))];
}

Rgb PointwiseReference::gatherPolygon(int face, const Vec3& point, const ReferencePatch& patch,
                                      std::span<const Vec3> polygon, std::span<const ReferenceSample> samples,
                                      double size, int depth, std::uint64_t seed, bool refined, Scratch& scratch) const
{
    const ReferenceFace& f = m_faces[static_cast<std::size_t>(face)];
    const ReferenceFace& source = m_faces[static_cast<std::size_t>(patch.face)];
    if (depth < m_options.gatherDepth &&
        glm::length(point - vertexMean(polygon)) < m_options.gatherNearDistance * size) {
        // Near the point the form factor and the visibility change quickly
        // across the patch: cut it and gather from the parts.
        const int split = m_options.gatherSplit;
        Rgb sum(0.0);
        std::vector<Vec3> points;
        std::vector<ReferenceSample> partSamples;
        std::uint64_t part = 0;
        for (const std::vector<Vec3>& piece : splitGrid(polygon, source.u, source.v, split, split)) {
            const std::uint64_t partSeed = mix64(seed ^ mix64(++part));
            stratifiedPoints(piece, source.normal, source.u, source.v, m_options.gatherRaysPerSide, partSeed, points);
            partSamples.clear();
            for (const Vec3& q : points)
                partSamples.push_back({q, false});
            sum += gatherPolygon(face, point, patch, piece, partSamples, size / split, depth + 1, partSeed, refined,
                                 scratch);
        }
        return sum;
    }
    const Rgb radiosity = scratch.radiosity ? (*scratch.radiosity)(patch.face, vertexMean(polygon))
                          : depth > 0 && refined && !patch.refined.empty() ? refinedAt(patch, vertexMean(polygon))
                                                                           : patch.radiosity;
    const double form = contourFormFactor(point, f.normal, polygon, scratch.clipped);
    if (form <= 0.0)
        return Rgb(0.0);
    Vec3 lo = point, hi = point;
    for (const Vec3& q : polygon) {
        lo = glm::min(lo, q);
        hi = glm::max(hi, q);
    }
    occludersInBox(face, patch.face, lo, hi, scratch.occluders);
    if (scratch.occluders.empty())
        return radiosity * form;
    // Rays to the points in front of the tangent plane: what lies behind it
    // has no share in the form factor either.
    const Vec3 origin = point + f.normal * m_options.surfaceOffset;
    double seen = 0.0, total = 0.0;
    for (const ReferenceSample& s : samples) {
        if (glm::dot(f.normal, s.point - point) <= kPlaneTolerance)
            continue;
        total += 1.0;
        if (!blocked(origin, s.point + source.normal * m_options.surfaceOffset, scratch.occluders))
            seen += 1.0;
    }
    return radiosity * (form * (total > 0.0 ? seen / total : 1.0));
}

Rgb PointwiseReference::radiosityAt(int face, const Vec3& point) const
{
    Scratch scratch;
    return gatherAt(face, point, true, scratch);
}

Rgb PointwiseReference::gatherAt(int face, const Vec3& point, bool refined, Scratch& scratch,
                                 std::vector<Rgb>* bySource) const
{
    const ReferenceFace& f = m_faces[static_cast<std::size_t>(face)];
    if (f.area <= 0.0)
        return f.emission;
    Rgb gathered(0.0);
    for (std::size_t j = 0; j < m_patches.size(); ++j) {
        const ReferencePatch& p = m_patches[j];
        if ((maxComponent(p.radiosity) <= 0.0 && p.refined.empty()) || !interacts(face, p.face))
            continue;
        const ReferenceFace& source = m_faces[static_cast<std::size_t>(p.face)];
        // A patch sends light from its front only, and only what lies in
        // front of the point arrives.
        if (glm::dot(source.normal, point) - source.offset <= kPlaneTolerance)
            continue;
        if (std::none_of(p.polygon.begin(), p.polygon.end(),
                         [&](const Vec3& q) { return glm::dot(f.normal, q - point) > kPlaneTolerance; }))
            continue;
        const Rgb part =
            gatherPolygon(face, point, p, p.polygon, p.gatherSamples, p.size, 0, mix64(j), refined, scratch);
        gathered += part;
        if (bySource)
            (*bySource)[static_cast<std::size_t>(p.face)] += part;
    }
    return f.emission + f.reflectance * gathered;
}

std::vector<Rgb> PointwiseReference::gatheredBySource(int face, const Vec3& point,
                                                      const SourceRadiosity& radiosity) const
{
    std::vector<Rgb> bySource(m_faces.size(), Rgb(0.0));
    Scratch scratch;
    if (radiosity)
        scratch.radiosity = &radiosity;
    gatherAt(face, point, true, scratch, &bySource);
    return bySource;
}

Rgb PointwiseReference::radiosityAt(const std::string& faceId, const Vec3& point) const
{
    const int face = faceIndex(faceId);
    if (face < 0)
        throw std::invalid_argument("PointwiseReference: no face " + faceId);
    return radiosityAt(face, point);
}

std::vector<Rgb> PointwiseReference::radiosityAt(std::span<const GatherPoint> points) const
{
    std::vector<Rgb> values(points.size());
    parallelFor<Scratch>(points.size(), m_options.threads, [&](std::size_t i, Scratch& scratch) {
        values[i] = gatherAt(points[i].face, points[i].point, true, scratch);
    });
    return values;
}

double PointwiseReference::visibility(const Vec3& from, const Vec3& fromNormal, std::span<const Vec3> polygon,
                                      const Vec3& polygonNormal, int raysPerSide) const
{
    Vec3 u(0.0), v(0.0);
    planeFrame(polygon, polygonNormal, u, v);
    std::vector<Vec3> points;
    stratifiedPoints(polygon, polygonNormal, u, v, raysPerSide, std::uint64_t{0}, points);
    std::vector<int> everyFace;
    for (std::size_t g = 0; g < m_faces.size(); ++g) {
        if (m_faces[g].area > 0.0)
            everyFace.push_back(static_cast<int>(g));
    }
    const Vec3 origin = from + fromNormal * m_options.surfaceOffset;
    double seen = 0.0, total = 0.0;
    for (const Vec3& q : points) {
        if (glm::dot(fromNormal, q - from) <= kPlaneTolerance)
            continue;
        total += 1.0;
        if (!blocked(origin, q + polygonNormal * m_options.surfaceOffset, everyFace))
            seen += 1.0;
    }
    return total > 0.0 ? seen / total : 1.0;
}

} // namespace regio::test
