#include "solver/shooting/near_field.h"

#include "solver/shooting/edge_angle.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <span>

namespace regio::solver {

namespace {

// At most this many corners (a clipped polygon has one more than it had).
constexpr size_t kMaxCorners = kMaxContourCorners;

double formFactorOf(const Vec3& x, const Vec3& n, std::span<const Vec3> polygon)
{
    // Clip to the half-space in front of the point's plane (a hair above it);
    // no memory is allocated: this runs for every near receiver of a row.
    constexpr double kAbove = 1e-9;
    std::array<Vec3, kMaxCorners + 1> unit;
    size_t count = 0;
    const size_t n0 = std::min(polygon.size(), kMaxCorners);
    const auto add = [&](const Vec3& p) {
        const Vec3 d = p - x;
        const double length = glm::length(d);
        if (length > 0.0 && count <= kMaxCorners)
            unit[count++] = d / length;
    };
    for (size_t i = 0; i < n0; ++i) {
        const Vec3& p = polygon[i];
        const Vec3& q = polygon[(i + 1) % n0];
        const double dp = glm::dot(n, p - x) - kAbove, dq = glm::dot(n, q - x) - kAbove;
        if (dp >= 0.0)
            add(p);
        if ((dp >= 0.0) != (dq >= 0.0))
            add(p + (q - p) * (dp / (dp - dq)));
    }
    if (count < 3)
        return 0.0;
    double sum = 0.0;
    for (size_t i = 0; i < count; ++i) {
        const Vec3& a = unit[i];
        const Vec3& b = unit[(i + 1) % count];
        const Vec3 c = glm::cross(a, b);
        const double sine = glm::length(c);
        if (sine <= 0.0)
            continue;
        sum += edgeAngle(sine, glm::dot(a, b)) * glm::dot(n, c) / sine;
    }
    return std::abs(sum) / (2.0 * std::numbers::pi);
}

// F(from -> to) between two elements close to each other, by the contour
// formula taken at the centroid of the smaller one: it is the mean over that
// element of a point-to-polygon factor, and the midpoint rule is good only
// where the domain is small next to the distance and to the other polygon.
// A ceiling element 50 cm across, 2 cm above a lamp's element 12 cm across,
// sees from its centroid anything from none of the lamp element to all of it,
// a factor off by up to sixteen times; from the lamp element's centroid it
// covers the view alike wherever it lies.
template <typename Corner>
double nearFactor(const Element& from, const Element& to, const Corner& corner, bool centroidOnly = false)
{
    const bool atReceiver = to.area <= from.area;
    const Element& point = atReceiver ? to : from; // where the factor is taken
    const Element& seen = atReceiver ? from : to;
    const std::array<Vec3, 3> polygon{corner(seen.vertices[0]), corner(seen.vertices[1]), corner(seen.vertices[2])};
    const Vec3 a = corner(point.vertices[0]), b = corner(point.vertices[1]), c = corner(point.vertices[2]);
    // Far from the other plane next to its size, the element's centroid
    // will do (what the four points would change falls with the square of
    // size / distance, a quarter of it here); closer, the centroids of its four halved-edge
    // sub-triangles: the midpoint rule on them, for gaps down to a few per
    // cent of an element.
    const double distance = std::abs(glm::dot(seen.normal, point.centroid - polygon[0]));
    const double size = std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
    double mean = 0.0;
    if (centroidOnly || size < 0.25 * distance) {
        mean = formFactorOf(point.centroid, point.normal, polygon);
    } else {
        for (const Vec3& x :
             {(4.0 * a + b + c) / 6.0, (a + 4.0 * b + c) / 6.0, (a + b + 4.0 * c) / 6.0, point.centroid})
            mean += formFactorOf(x, point.normal, polygon) / 4.0;
    }
    return atReceiver ? mean * to.area / from.area : mean; // reciprocity
}

// The shooter's elements tile it and share corners and edges: from one point
// of a receiver, the direction to a corner and the contour formula's term of
// an edge serve every element that has them (nine elements of a patch have
// 10 corners and 18 edges, not 27 and 27). Built once per row.
struct ShooterMesh {
    std::vector<int> corners;                                   // scene vertex indices
    std::vector<std::array<int, 2>> edges;                      // local corner indices
    std::vector<std::array<std::pair<int, bool>, 3>> ofElement; // edge, reversed; in the element's order

    ShooterMesh(const PreparedScene& scene, const Patch& patch)
    {
        std::vector<std::array<int, 3>> local;
        for (int s = 0; s < patch.elementCount; ++s) {
            const Element& from = scene.elements[size_t(patch.firstElement + s)];
            std::array<int, 3> l{};
            for (size_t i = 0; i < 3; ++i) {
                const auto found = std::find(corners.begin(), corners.end(), from.vertices[i]);
                l[i] = int(found - corners.begin());
                if (found == corners.end())
                    corners.push_back(from.vertices[i]);
            }
            local.push_back(l);
        }
        for (const std::array<int, 3>& l : local) {
            std::array<std::pair<int, bool>, 3> own{};
            for (size_t i = 0; i < 3; ++i) {
                const int a = l[i], b = l[(i + 1) % 3];
                const std::array<int, 2> key{std::min(a, b), std::max(a, b)};
                const auto found = std::find(edges.begin(), edges.end(), key);
                own[i] = {int(found - edges.begin()), a > b};
                if (found == edges.end())
                    edges.push_back(key);
            }
            ofElement.push_back(own);
        }
    }
};

// Scratch for nearFactors, one per thread.
struct SharedScratch {
    std::vector<Vec3> unit;
    std::vector<char> inFront;
    std::vector<double> term;
    std::array<std::vector<double>, 4> at; // the shared factors at each of a receiver's points
};

// formFactorOf(x, n, element s) for every element s of the shooter whose
// corners all lie in front of x's plane (the same numbers, bit for bit: the
// same directions, and an edge's term for the other orientation is exactly
// its negation); NaN for the others, which formFactorOf takes whole.
void sharedFormFactors(const PreparedScene& scene, const ShooterMesh& mesh, const Vec3& x, const Vec3& n,
                       SharedScratch& scratch, std::vector<double>& out)
{
    constexpr double kAbove = 1e-9; // as formFactorOf
    const size_t corners = mesh.corners.size();
    scratch.unit.resize(corners);
    scratch.inFront.resize(corners);
    for (size_t k = 0; k < corners; ++k) {
        const Vec3 d = scene.vertices[size_t(mesh.corners[k])] - x;
        const double length = glm::length(d);
        scratch.inFront[k] = glm::dot(n, d) - kAbove >= 0.0 && length > 0.0;
        if (scratch.inFront[k])
            scratch.unit[k] = d / length;
    }
    // Every edge with both corners in front: those are the edges of the
    // elements taken here.
    scratch.term.resize(mesh.edges.size());
    for (size_t k = 0; k < mesh.edges.size(); ++k) {
        const auto [first, second] = mesh.edges[k];
        if (!scratch.inFront[size_t(first)] || !scratch.inFront[size_t(second)])
            continue;
        const Vec3& a = scratch.unit[size_t(first)];
        const Vec3& b = scratch.unit[size_t(second)];
        const Vec3 c = glm::cross(a, b);
        const double sine = glm::length(c);
        scratch.term[k] = sine <= 0.0 ? 0.0 : edgeAngle(sine, glm::dot(a, b)) * glm::dot(n, c) / sine;
    }
    out.resize(mesh.ofElement.size());
    for (size_t s = 0; s < mesh.ofElement.size(); ++s) {
        double sum = 0.0;
        bool whole = true;
        for (const auto& [edge, reversed] : mesh.ofElement[s]) {
            const std::array<int, 2>& e = mesh.edges[size_t(edge)];
            if (!scratch.inFront[size_t(e[0])] || !scratch.inFront[size_t(e[1])]) {
                whole = false;
                break;
            }
            sum += reversed ? -scratch.term[size_t(edge)] : scratch.term[size_t(edge)];
        }
        out[s] = whole ? std::abs(sum) / (2.0 * std::numbers::pi) : std::numeric_limits<double>::quiet_NaN();
    }
}

// nearFactor(from, e) for every element `from` of the shooter into
// `factors`, the same numbers: where e is no larger than the shooter's
// element the contour formula is taken at e's points against each of them,
// and those points are shared.
void nearFactors(const PreparedScene& scene, const Patch& patch, const ShooterMesh& mesh, const Element& e,
                 SharedScratch& scratch, std::vector<double>& factors)
{
    const auto corner = [&](int v) { return scene.vertices[size_t(v)]; };
    const Vec3 a = corner(e.vertices[0]), b = corner(e.vertices[1]), c = corner(e.vertices[2]);
    const double size = std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
    const std::array<Vec3, 4> points{(4.0 * a + b + c) / 6.0, (a + 4.0 * b + c) / 6.0, (a + b + 4.0 * c) / 6.0,
                                     e.centroid};
    std::array<bool, 4> done{}; // the shared factors at each point are computed when first wanted
    const auto shared = [&](size_t i, size_t s) {
        if (!done[i]) {
            sharedFormFactors(scene, mesh, points[i], e.normal, scratch, scratch.at[i]);
            done[i] = true;
        }
        return scratch.at[i][s];
    };
    factors.assign(size_t(patch.elementCount), 0.0);
    for (int s = 0; s < patch.elementCount; ++s) {
        const Element& from = scene.elements[size_t(patch.firstElement + s)];
        if (e.area > from.area) {
            factors[size_t(s)] = nearFactor(from, e, corner);
            continue;
        }
        const std::array<Vec3, 3> polygon{corner(from.vertices[0]), corner(from.vertices[1]), corner(from.vertices[2])};
        const auto formFactorAt = [&](size_t i) {
            const double f = shared(i, size_t(s));
            return std::isnan(f) ? formFactorOf(points[i], e.normal, polygon) : f;
        };
        const double distance = std::abs(glm::dot(from.normal, e.centroid - polygon[0]));
        double mean = 0.0;
        if (size < 0.25 * distance) {
            mean = formFactorAt(3);
        } else {
            for (size_t i = 0; i < 4; ++i)
                mean += formFactorAt(i) / 4.0;
        }
        factors[size_t(s)] = mean * e.area / from.area;
    }
}

// A receiver on a face facing the shooter's, beyond the shooter's longest
// edge (near_field.h): the hemicube tells what share of it the shooter's
// centre sees, the contour formula what the whole shooter gives it, and the
// point-to-point kernel (cos cos / r^2) how that splits among the shooter's
// elements, which send their own power. Appends its terms, none when the
// contour formula sees nothing of it. `weights` is scratch space.
void appendFacingTerms(const PreparedScene& scene, const Patch& patch, const Element& whole, const Element& e,
                       double hemicubeFactor, std::uint32_t entry, std::vector<NearTerm>& near,
                       std::vector<double>& weights)
{
    const auto corner = [&](int v) { return scene.vertices[size_t(v)]; };
    const std::array<Vec3, 3> seen{corner(e.vertices[0]), corner(e.vertices[1]), corner(e.vertices[2])};
    const double atCentre = formFactorOf(patch.centroid, whole.normal, seen); // what the hemicube stands for
    if (atCentre <= 0.0)
        return;
    const double exact = nearFactor(whole, e, corner); // F(shooter -> e)
    weights.assign(size_t(patch.elementCount), 0.0);
    double kernels = 0.0; // the area-weighted mean weight
    for (int s = 0; s < patch.elementCount; ++s) {
        const Element& from = scene.elements[size_t(patch.firstElement + s)];
        const Vec3 d = e.centroid - from.centroid;
        const double r2 = glm::dot(d, d);
        weights[size_t(s)] =
            std::max(0.0, glm::dot(from.normal, d)) * std::max(0.0, -glm::dot(e.normal, d)) / (r2 * r2);
        kernels += weights[size_t(s)] * from.area / patch.area;
    }
    if (exact <= 0.0 || kernels <= 0.0)
        return;
    const double scale = hemicubeFactor / atCentre * exact / kernels;
    for (int s = 0; s < patch.elementCount; ++s)
        near.push_back({entry, s, scale * weights[size_t(s)]});
}

} // namespace

double pointToPolygonFormFactor(const Vec3& x, const Vec3& n, const std::vector<Vec3>& polygon)
{
    return formFactorOf(x, n, polygon);
}

void correctNearField(const PreparedScene& scene, int shooter, const std::vector<std::uint32_t>& elements,
                      std::vector<double>& factors, std::vector<NearTerm>& near, std::vector<double>& farScale,
                      const ParallelFor& parallelFor, const SeenShare& seenShare)
{
    farScale.clear();
    const Patch& patch = scene.patches[size_t(shooter)];
    const auto corner = [&](int v) { return scene.vertices[size_t(v)]; };
    double reach = 0.0;
    for (int i = 0; i < 3; ++i)
        reach = std::max(reach,
                         glm::length(corner(patch.vertices[size_t((i + 1) % 3)]) - corner(patch.vertices[size_t(i)])));
    const std::vector<int>& facingFaces = scene.faces[size_t(patch.properties)].facing;
    Element whole; // the shooter as one polygon
    whole.vertices = patch.vertices;
    whole.area = patch.area;
    whole.centroid = patch.centroid;
    whole.normal = scene.properties[size_t(patch.properties)].plane.normal;

    // Which receivers are near (cheap, in order), then their terms (the
    // contour formula: most of the time, so on several threads when the
    // caller offers them), then the books (in order). Each receiver's terms
    // depend on it alone and are joined in the receivers' order, so the row
    // is the same, bit for bit, however many threads took part.
    double total = 0.0;                              // the hemicube's factors of every receiver
    std::vector<std::pair<size_t, bool>> candidates; // (row entry, facing rather than within reach)
    for (size_t k = 0; k < elements.size(); ++k) {
        total += factors[k];
        const Element& e = scene.elements[elements[k]];
        const double distance = glm::length(e.centroid - patch.centroid);
        if (distance < reach)
            candidates.emplace_back(k, false);
        else if (distance < kFacingReach * reach &&
                 std::binary_search(facingFaces.begin(), facingFaces.end(), e.properties))
            candidates.emplace_back(k, true);
    }
    if (candidates.empty())
        return;
    // Chunks of candidates: each computes its receivers' terms into its own
    // list. Small, so that the threads share a shooter's few dozen near
    // receivers evenly.
    constexpr size_t kChunk = 4;
    const size_t chunks = (candidates.size() + kChunk - 1) / kChunk;
    std::vector<std::vector<NearTerm>> terms(chunks);
    const ShooterMesh mesh(scene, patch);
    const auto computeChunks = [&](size_t firstChunk, size_t endChunk) {
        std::vector<double> weights;  // scratch for appendFacingTerms
        std::vector<double> fromEach; // F(from -> e) for each element of the shooter
        SharedScratch scratch;
        for (size_t c = firstChunk; c < endChunk; ++c) {
            std::vector<NearTerm>& out = terms[c];
            for (size_t i = c * kChunk; i < std::min(candidates.size(), (c + 1) * kChunk); ++i) {
                const auto [k, facing] = candidates[i];
                const Element& e = scene.elements[elements[k]];
                if (facing) {
                    appendFacingTerms(scene, patch, whole, e, factors[k], std::uint32_t(k), out, weights);
                    continue;
                }
                // The form factor from each shooter element: this close, the
                // gradient across the shooter matters.
                nearFactors(scene, patch, mesh, e, scratch, fromEach);
                for (int s = 0; s < patch.elementCount; ++s) {
                    double factor = fromEach[size_t(s)];
                    if (seenShare && factor > 0.0)
                        factor *= seenShare(std::uint32_t(k), s);
                    if (factor > 0.0)
                        out.push_back({std::uint32_t(k), s, factor});
                }
            }
        }
    };
    if (parallelFor && chunks > 1)
        parallelFor(chunks, computeChunks);
    else
        computeChunks(0, chunks);

    const size_t first = near.size();
    for (const std::vector<NearTerm>& t : terms)
        near.insert(near.end(), t.begin(), t.end());
    if (near.size() == first)
        return; // the contour formula sees none of them: keep the hemicube's factors
    std::vector<double> perElement(size_t(patch.elementCount), 0.0);
    double hemicube = 0.0; // the hemicube's factors of the near receivers
    std::uint32_t last = std::numeric_limits<std::uint32_t>::max();
    for (size_t t = first; t < near.size(); ++t) {
        perElement[size_t(near[t].shooterElement)] += near[t].factor;
        if (near[t].entry != last) { // a receiver's terms are consecutive
            last = near[t].entry;
            hemicube += factors[last];
            factors[last] = 0.0;
        }
    }
    const double far = total - hemicube; // and of the far ones
    if (far <= 0.0) {
        // Every receiver is near: each element of the shooter hands on the
        // hemicube's total, shared by its own contour factors.
        for (size_t t = first; t < near.size(); ++t)
            near[t].factor *= perElement[size_t(near[t].shooterElement)] > 0.0
                                  ? hemicube / perElement[size_t(near[t].shooterElement)]
                                  : 0.0;
        return;
    }
    // The near receivers keep the contour formula's factors; what each
    // element of the shooter gives them more or less than the hemicube saw
    // comes out of its share for the far receivers. So every element of the
    // shooter sends the hemicube's total, whatever its unshot radiosity.
    farScale.assign(size_t(patch.elementCount), 1.0);
    for (size_t s = 0; s < perElement.size(); ++s) {
        double nearTotal = perElement[s];
        if (nearTotal > total) {
            // More than the hemicube saw in all (never on the samples):
            // the near receivers get everything, scaled down to it.
            for (size_t t = first; t < near.size(); ++t)
                if (size_t(near[t].shooterElement) == s)
                    near[t].factor *= total / nearTotal;
            nearTotal = total;
        }
        farScale[s] = (total - nearTotal) / far;
    }
}

} // namespace regio::solver
