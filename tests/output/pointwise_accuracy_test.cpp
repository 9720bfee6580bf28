// The lit mesh the editor shows, measured point by point against the
// independent pointwise reference (tests/support/pointwise_reference.h) on
// the Cornell box: the solver's own settings, solved to 0.1 % unshot, the
// smooth vertex radiosity of paper §6 and the flat element values.
//
// The solver is right per face; its Gouraud-shaded picture is not right
// everywhere: blotches in the open, light leaking at a block's foot, dark
// rings along edges. The test prints the error statistics (the test log shows
// them) and guards what holds today against regressions.
#include "output/exact_direct.h"
#include "output/lit_mesh.h"
#include "output/vertex_radiosity.h"
#include "solver/solver.h"
#include "support/lit_mesh_sampling.h"
#include "support/pointwise_reference.h"
#include "support/sample_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <set>
#include <vector>

using namespace regio;
using namespace regio::test;

namespace {

// Relative luminance errors of one picture, overall and beside contact lines.
struct Sample {
    const SurfacePoint* where = nullptr;
    double reference = 0.0; // luminance, W/m^2
    double shown = 0.0;
    double error() const { return std::abs(shown - reference) / reference; }
};

struct Summary {
    size_t count = 0;
    double median = 0.0, p90 = 0.0, p99 = 0.0, worst = 0.0;
};

Summary summarize(const std::vector<Sample>& samples, bool contactOnly)
{
    std::vector<double> errors;
    for (const Sample& s : samples) {
        if (!contactOnly || s.where->kind == SurfacePoint::Kind::Contact)
            errors.push_back(s.error());
    }
    Summary summary;
    summary.count = errors.size();
    if (errors.empty())
        return summary;
    std::sort(errors.begin(), errors.end());
    const auto at = [&](double q) {
        return errors[static_cast<size_t>(std::lround(q * static_cast<double>(errors.size() - 1)))];
    };
    summary.median = at(0.5);
    summary.p90 = at(0.9);
    summary.p99 = at(0.99);
    summary.worst = errors.back();
    return summary;
}

void print(const char* label, const Summary& s)
{
    std::printf("  %-24s %5zu points   median %6.2f %%   90th %6.2f %%   99th %6.2f %%   worst %7.2f %%\n", label,
                s.count, 100.0 * s.median, 100.0 * s.p90, 100.0 * s.p99, 100.0 * s.worst);
}

void printWorst(const char* label, std::vector<Sample> samples, size_t count)
{
    std::sort(samples.begin(), samples.end(), [](const Sample& a, const Sample& b) { return a.error() > b.error(); });
    std::printf("  worst points, %s:\n", label);
    const char* kinds[] = {"grid", "edge", "contact"};
    for (size_t i = 0; i < std::min(count, samples.size()); ++i) {
        const Sample& s = samples[i];
        std::printf("    %-20s %-7s (%.4f, %.4f, %.4f)   shown %8.4f   reference %8.4f   %+7.1f %%\n",
                    s.where->face.c_str(), kinds[static_cast<int>(s.where->kind)], s.where->point.x, s.where->point.y,
                    s.where->point.z, s.shown, s.reference, 100.0 * (s.shown - s.reference) / s.reference);
    }
}

// The flat value at each point against the reference's mean over the
// element that shows it: over the centroids of the element cut into 4 x 4
// similar triangles (16 of equal area), those that no solid covers.
std::vector<Sample> elementMeans(const output::LitMesh& flat, const std::vector<SurfacePoint>& points,
                                 const PointwiseReference& reference, const glm::vec3& ambient)
{
    const LitMeshProbe probe(flat);
    std::map<size_t, size_t> firstGather; // element -> its first point in gather
    std::vector<GatherPoint> gather;
    std::vector<std::optional<size_t>> shownBy(points.size());
    for (size_t i = 0; i < points.size(); ++i) {
        shownBy[i] = probe.triangleAt(points[i].face, points[i].point);
        if (!shownBy[i] || firstGather.count(*shownBy[i]))
            continue;
        firstGather[*shownBy[i]] = gather.size();
        const int face = reference.faceIndex(points[i].face);
        const auto [a, b, c] = probe.corners(*shownBy[i]);
        const auto at = [&](double u, double v) {
            gather.push_back({face, a + (b - a) * (u / 4) + (c - a) * (v / 4)});
        };
        for (int u = 0; u < 4; ++u)
            for (int v = 0; u + v < 4; ++v) {
                at(u + 1.0 / 3.0, v + 1.0 / 3.0); // the sub-triangle pointing like the element
                if (u + v < 3)
                    at(u + 2.0 / 3.0, v + 2.0 / 3.0); // the one upside down beside it
            }
    }
    const std::vector<Rgb> values = reference.radiosityAt(gather);
    std::vector<Sample> samples;
    for (size_t i = 0; i < points.size(); ++i) {
        if (!shownBy[i])
            continue;
        double sum = 0.0;
        int count = 0;
        for (size_t k = firstGather[*shownBy[i]], end = k + 16; k < end; ++k)
            if (!reference.covered(gather[k].face, gather[k].point)) {
                sum += luminance(values[k]);
                ++count;
            }
        if (count > 0)
            samples.push_back({&points[i], sum / count,
                               luminance(*probe.displayRadiosityAt(points[i].face, points[i].point, ambient))});
    }
    return samples;
}

double secondsBetween(std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b)
{
    return std::chrono::duration<double>(b - a).count();
}

} // namespace

TEST(PointwiseAccuracy, LitMeshProbeInterpolatesTheTriangleOfTheFaceBarycentrically)
{
    output::LitMesh mesh;
    mesh.faceIds = {"floor", "wall"};
    const auto corner = [&](glm::vec3 p, float value) {
        mesh.positions.push_back(p);
        mesh.normals.push_back({0.0f, 1.0f, 0.0f});
        mesh.radiosity.push_back(glm::vec3(value));
        mesh.reflectance.push_back(glm::vec3(0.5f));
        mesh.indices.push_back(static_cast<uint32_t>(mesh.positions.size() - 1));
    };
    corner({0, 0, 0}, 0.0f);
    corner({0, 0, 1}, 1.0f);
    corner({1, 0, 0}, 2.0f);
    mesh.triangleFace.push_back(0);
    const LitMeshProbe probe(mesh);
    // (0.25, 0, 0.5): weights 0.25, 0.5, 0.25 of the corners.
    const std::optional<Rgb> value = probe.displayRadiosityAt("floor", {0.25, 0.0, 0.5}, glm::vec3(0.0f));
    ASSERT_TRUE(value.has_value());
    EXPECT_NEAR(value->x, 0.5 * 1.0 + 0.25 * 2.0, 1e-6);
    // The ambient term is weighted by the reflectance, as the display does.
    EXPECT_NEAR(probe.displayRadiosityAt("floor", {0.25, 0.0, 0.5}, glm::vec3(2.0f))->x, 1.0 + 0.5 * 2.0, 1e-6);
    EXPECT_FALSE(probe.displayRadiosityAt("floor", {0.8, 0.0, 0.8}, glm::vec3(0.0f)).has_value());
    EXPECT_FALSE(probe.displayRadiosityAt("wall", {0.25, 0.0, 0.5}, glm::vec3(0.0f)).has_value());
    EXPECT_EQ(probe.triangleAt("floor", {0.25, 0.0, 0.5}), std::optional<size_t>(0));
    EXPECT_FALSE(probe.triangleAt("floor", {0.8, 0.0, 0.8}).has_value());
}

TEST(PointwiseAccuracy, CornellBoxLitMeshAgainstTheReference)
{
    using Clock = std::chrono::steady_clock;
    const model::Scene scene = loadSample("cornell-box");

    // The solver with the scene's own settings, to 0.1 % unshot.
    const auto start = Clock::now();
    solver::SolverOptions options;
    options.maxIterations = 1000000;
    options.convergence = 0.001;
    auto built = solver::Solver::create(scene, options);
    ASSERT_TRUE(built.ok());
    solver::Solver& solver = **built;
    const std::atomic<bool> cancel{false};
    EXPECT_EQ(solver.run({}, cancel), solver::StopReason::Converged);
    const solver::SolutionSnapshot snapshot = solver.snapshot();
    const solver::PreparedScene& prepared = solver.prepared();
    ASSERT_EQ(prepared.elements.size(), snapshot.radiosity.size());
    const output::LitMesh smooth = output::smoothLitMesh(prepared, snapshot.radiosity);
    const output::LitMesh flat = output::litMeshFromSolution(prepared, snapshot.radiosity);
    // What the outputs draw: the smooth picture with the lights' direct
    // part exact, on triangles cut in four.
    const output::LitMesh exact = output::exactDirectLitMesh(prepared, snapshot.radiosity);
    const glm::vec3 ambient(snapshot.stats.ambient); // what is not shot yet, as the display adds it
    const auto solved = Clock::now();

    // At 2 cm patches: at the default 3 cm the reference's own mean over the
    // short block's dark side is 0.3 % off its value at 2 cm, a third of the
    // 1 % that the per-face check below allows.
    PointwiseReferenceOptions referenceOptions;
    referenceOptions.patchSize = 0.02;
    const PointwiseReference reference(scene, referenceOptions);
    const auto referenced = Clock::now();

    // A 3 cm grid 1 cm inside every face, rows 1.5 cm inside every edge, and
    // rows 1 and 2 cm beside the blocks' feet on the floor and on the blocks.
    const std::vector<FaceGeometry> faces = faceGeometry(scene);
    std::vector<SurfacePoint> candidates = gridPoints(faces, 0.03, 0.01);
    for (const SurfacePoint& p : edgePoints(faces, 0.03, 0.015))
        candidates.push_back(p);
    for (const SurfacePoint& p : contactPoints(faces, 0.02, {0.01, 0.02}, 0.015))
        candidates.push_back(p);
    std::vector<SurfacePoint> points;
    std::vector<GatherPoint> gather;
    for (const SurfacePoint& p : candidates) {
        const int face = reference.faceIndex(p.face);
        ASSERT_GE(face, 0) << p.face;
        if (reference.covered(face, p.point)) // the floor under a block
            continue;
        points.push_back(p);
        gather.push_back({face, p.point});
    }
    const std::vector<Rgb> expected = reference.radiosityAt(gather);
    const auto gathered = Clock::now();

    const auto measure = [&](const output::LitMesh& mesh) {
        const LitMeshProbe probe(mesh);
        std::vector<Sample> samples;
        for (size_t i = 0; i < points.size(); ++i) {
            const std::optional<Rgb> shown = probe.displayRadiosityAt(points[i].face, points[i].point, ambient);
            EXPECT_TRUE(shown.has_value())
                << points[i].face << " " << points[i].point.x << " " << points[i].point.y << " " << points[i].point.z;
            if (shown)
                samples.push_back({&points[i], luminance(expected[i]), luminance(*shown)});
        }
        return samples;
    };
    const std::vector<Sample> smoothSamples = measure(smooth);
    const std::vector<Sample> flatSamples = measure(flat);
    const std::vector<Sample> exactSamples = measure(exact);
    const Summary exactAll = summarize(exactSamples, false), exactContact = summarize(exactSamples, true);
    const Summary smoothAll = summarize(smoothSamples, false), smoothContact = summarize(smoothSamples, true);
    const Summary flatAll = summarize(flatSamples, false), flatContact = summarize(flatSamples, true);
    const auto measured = Clock::now();

    // An element's flat value stands for its mean, so it is also judged
    // against the reference's mean over the element that shows each point:
    // one value cannot follow a gradient across the element, but it can be
    // the right mean.
    const std::vector<Sample> elementMeanSamples = elementMeans(flat, points, reference, ambient);
    const Summary meanAll = summarize(elementMeanSamples, false), meanContact = summarize(elementMeanSamples, true);
    const auto averaged = Clock::now();

    const size_t contacts = static_cast<size_t>(std::count_if(
        points.begin(), points.end(), [](const SurfacePoint& p) { return p.kind == SurfacePoint::Kind::Contact; }));
    std::printf(
        "Cornell box: %d elements (%d shots), reference %zu patches (%d Gauss-Seidel sweeps), "
        "%zu points (%zu beside contact lines)\n",
        snapshot.stats.elements, snapshot.stats.iterations, reference.patches().size(), reference.iterations(),
        points.size(), contacts);
    std::printf("relative luminance error |shown - reference| / reference:\n");
    print("smooth, all points", smoothAll);
    print("smooth, contact lines", smoothContact);
    print("exact direct, all points", exactAll);
    print("exact direct, contact lines", exactContact);
    print("flat, all points", flatAll);
    print("flat, contact lines", flatContact);
    std::printf("flat against the reference's mean over the element that shows the point:\n");
    print("element means, all", meanAll);
    print("element means, contact", meanContact);
    // The faces a solid stands on or that stand on one: those with points
    // beside contact lines.
    std::set<std::string> touching;
    for (const SurfacePoint& p : points)
        if (p.kind == SurfacePoint::Kind::Contact)
            touching.insert(p.face);
    const auto tooBright = [&](const std::vector<Sample>& samples) {
        std::map<std::string, size_t> perFace;
        for (const Sample& s : samples)
            if (touching.count(s.where->face) && s.shown > 1.05 * s.reference)
                ++perFace[s.where->face];
        return perFace;
    };
    const auto total = [](const std::map<std::string, size_t>& perFace) {
        size_t sum = 0;
        for (const auto& [face, count] : perFace)
            sum += count;
        return sum;
    };
    const std::map<std::string, size_t> smoothBright = tooBright(smoothSamples);
    const size_t smoothTooBright = total(smoothBright);
    std::printf("points of faces touching a solid more than 5 %% too bright: smooth %zu (", smoothTooBright);
    for (const auto& [face, count] : smoothBright)
        std::printf(" %s %zu", face.c_str(), count);
    const size_t exactTooBright = total(tooBright(exactSamples));
    std::printf(" ), exact direct %zu, flat %zu\n", exactTooBright, total(tooBright(flatSamples)));
    {
        std::vector<Sample> bright;
        for (const Sample& s : smoothSamples)
            if (touching.count(s.where->face) && s.shown > 1.05 * s.reference)
                bright.push_back(s);
        printWorst("smooth, of faces touching a solid, more than 5 % too bright", bright, bright.size());
    }
    printWorst("smooth", smoothSamples, 8);
    printWorst("exact direct", exactSamples, 8);
    printWorst("flat", flatSamples, 5);
    printWorst("flat against the element's mean", elementMeanSamples, 5);
    // Per face: the mean over a 1 cm grid (uniform, so the area-weighted
    // mean) of the smooth picture against the reference's.
    std::vector<SurfacePoint> cells;
    std::vector<GatherPoint> cellGather;
    for (const SurfacePoint& p : gridPoints(faces, 0.01, 0.005)) {
        const int face = reference.faceIndex(p.face);
        if (!reference.covered(face, p.point)) {
            cells.push_back(p);
            cellGather.push_back({face, p.point});
        }
    }
    const std::vector<Rgb> cellExpected = reference.radiosityAt(cellGather);
    struct FaceMeans {
        std::map<std::string, std::pair<double, double>> sums; // per face: shown, reference
        std::string worst;
        double worstError = 0.0;
    };
    const auto faceMeans = [&](const output::LitMesh& mesh) {
        FaceMeans means;
        const LitMeshProbe probe(mesh);
        for (size_t i = 0; i < cells.size(); ++i)
            if (const std::optional<Rgb> shown = probe.displayRadiosityAt(cells[i].face, cells[i].point, ambient)) {
                means.sums[cells[i].face].first += luminance(*shown);
                means.sums[cells[i].face].second += luminance(cellExpected[i]);
            }
        for (const auto& [face, sums] : means.sums)
            if (const double error = sums.first / sums.second - 1.0; std::abs(error) > std::abs(means.worstError)) {
                means.worst = face;
                means.worstError = error;
            }
        return means;
    };
    const FaceMeans smoothFaces = faceMeans(smooth), exactFaces = faceMeans(exact);
    std::printf(
        "per face, the mean over %zu points of a 1 cm grid: worst smooth %s %+.2f %%, exact direct %s %+.2f %%\n",
        cells.size(), smoothFaces.worst.c_str(), 100.0 * smoothFaces.worstError, exactFaces.worst.c_str(),
        100.0 * exactFaces.worstError);
    std::printf(
        "seconds: solve and lit meshes %.2f, reference %.2f, gather %.2f, lit mesh lookups %.2f, "
        "element means %.2f\n",
        secondsBetween(start, solved), secondsBetween(solved, referenced), secondsBetween(referenced, gathered),
        secondsBetween(gathered, measured), secondsBetween(measured, averaged));
    std::fflush(stdout);

    ASSERT_GT(smoothAll.count, 2000u);
    ASSERT_GT(smoothContact.count, 200u);
    // Guards of what holds today, with some margin: the test fails when the
    // picture gets worse. Measured with the sample's settings (hemicube 200,
    // nine elements a patch), lights cut at a quarter of the patch size,
    // faces meshed only where no solid covers them and cut along the shadow
    // lines at the blocks' feet, near receivers given the contour formula's
    // factors and boundary vertices extrapolated (smooth), elements down to
    // half the smallest edge near the blocks' foot corners, one
    // mean-preserving pass over the vertex values (smooth), facing faces
    // with the contour formula three patches out, hemicubes turned about
    // the normal by where the patch lies, the elements along the blocks'
    // feet (every element with a corner on them) split twice before the
    // first shot, the lamp's shots at a hemicube of 400, the elements in
    // the blocks' penumbrae split twice before the first shot, vertex
    // values weighted by the elements' angles and not extrapolated beside a
    // shadow corner (smooth), the floor's shadow lines kept as patch edges,
    // against the reference at 2 cm patches: median 0.39 %, 90th percentile
    // 1.51 %, 99th 3.59 %, worst 14 %; beside contact lines median 0.84 %,
    // 90th 2.18 %, 99th 4.7 %, worst 9.2 %. Flat: median 1.46 %, 90th
    // 4.78 %; beside contact lines median 1.9 %. (Shadow lines flipped away
    // where the pieces' strips meet: 0.39, 1.49, 3.60, worst 17; beside
    // contact lines 0.82, 2.31, 4.7, worst 9.2. Extrapolated beside shadow corners too: 0.39, 1.48, 3.60, worst 37,
    // a dark point at the tall block's corner; beside contact lines 0.82,
    // 2.21, 4.7, worst 9.2. Vertex values weighted by area: 0.40, 1.58, 4.23, worst 33; beside
    // contact lines 0.83, 2.58, 5.6, worst 9.2. Only the elements with an edge on the
    // feet split: 0.40, 1.59, 4.15, worst 33; beside contact lines 0.92,
    // 2.61, 6.7, worst 8.6; flat 1.47, 4.84, 1.9. Without the penumbrae's
    // splits: 0.40, 1.68, 4.7, worst 27; beside
    // contact lines 1.01, 2.87, 8.6, worst 17; flat 1.46, 4.83, 1.9.
    // The lamp at 200 as the rest: 0.47, 1.92, 5.2, worst 29; beside
    // contact lines 1.15, 3.01, 8.7, worst 19; flat 1.80, 5.45, 2.2.
    // Without the splits along the feet: 0.47, 1.95, 6.7,
    // worst 29; beside contact lines 1.30, 3.96, 14.8, worst 26, the 99th
    // percentile the third worst of 224 points, which the turn of the
    // hemicubes moved between 11 and 16 %; flat 1.82, 5.7, 2.5.
    // Hemicubes along the patches' edges, against the same reference:
    // 0.63, 2.25, 6.7, worst 27; beside contact lines 1.41, 4.24, 12.9;
    // flat 1.96, 6.9, beside contact lines 2.9. Against the reference at
    // 3 cm patches, as the figures below: 0.62, 2.19, 6.4, worst 28; 1.28,
    // 3.95, 11.2; flat 2.0, 6.9, 2.9. Without the facing faces: 0.72,
    // 2.51, 6.4, worst 29; beside contact lines 1.55, 4.0, 11.4; the tall
    // block's dark side -1.5 % per face. Without the mean-preserving
    // pass: 0.75, 2.97, 8.1, worst 43; beside contact lines 1.5, 4.7, 16.
    // Without the finer corners: 0.76,
    // 2.97, 9.9, worst 97; beside contact lines 1.8, 5.5, 27; flat 2.1, 6.7,
    // beside contact lines 2.7. Hemicube 150: 0.85, 3.0, 8.9, 1.8, 4.8;
    // flat 2.6, 8.9, 3.8. Without the shadow lines: 0.83, 3.1, 13, worst
    // 225, 1.5, 5.9. Boundary vertices averaged instead: 0.87, 3.5, 19, 2.0,
    // 12. Before the lights were cut finer, with four elements a patch and
    // the near receivers scaled to the hemicube's total: 1.7, 5.8, 24, 3.6,
    // 16; flat 3.2, 10.6, 5.0. Faces meshed whole, no near field: 2.1, 11.4,
    // 45.5, 15.2, 42.6; flat 4.1, 18.5, 17.6.) The reference itself is good
    // to a few tenths of a per cent per face at 2 cm patches
    // (tests/support/pointwise_reference.h).
    //
    // The targets of the smooth picture, all met: median <= 1 %, 90th
    // percentile <= 3 %, 99th percentile <= 10 %, and beside contact lines
    // 90th percentile <= 10 %.
    EXPECT_LT(smoothAll.median, 0.01);
    EXPECT_LT(smoothAll.p90, 0.03);
    EXPECT_LT(smoothAll.p99, 0.10);
    EXPECT_LT(smoothContact.median, 0.025);
    EXPECT_LT(smoothContact.p90, 0.05);
    EXPECT_LT(smoothContact.p99, 0.07);
    EXPECT_LT(smoothContact.worst, 0.12);
    EXPECT_LT(smoothAll.worst, 0.25);
    // Not yet the target (none): 5 points, all of the floor, the worst
    // +8.4 % (4 before the shadow lines were kept as patch edges, the worst
    // +15.1 %; 5 before the vertex values were weighted by angle, 6 before the elements with only
    // a corner on a contact line were split too, 15 before the penumbrae
    // were split, 14 of those of the floor).
    EXPECT_LE(smoothTooBright, 6u);
    // What the outputs draw, the lights' direct part exact on triangles cut
    // in four (output/exact_direct.h): median 0.37 %, 90th percentile
    // 1.41 %, 99th 3.32 %, worst 10.1 %; beside contact lines 0.83, 2.21,
    // 5.3, worst 8.7 %; and no point of a face touching a solid more than
    // 5 % too bright: every target met.
    EXPECT_LT(exactAll.median, 0.01);
    EXPECT_LT(exactAll.p90, 0.03);
    EXPECT_LT(exactAll.p99, 0.10);
    EXPECT_LT(exactContact.p90, 0.10);
    EXPECT_LT(exactAll.worst, 0.15);
    EXPECT_EQ(exactTooBright, 0u);
    EXPECT_LT(flatAll.median, 0.02);
    EXPECT_LT(flatAll.p90, 0.065);
    EXPECT_LT(flatContact.median, 0.04);
    // The flat values as the elements' means, against the reference's mean
    // over each element (median 0.63 %, 90th percentile 2.03 %, 99th 5.6 %,
    // worst 18 %; beside contact lines 1.21, 3.8, 7.5 %): the smooth
    // picture's targets, met.
    EXPECT_LT(meanAll.median, 0.01);
    EXPECT_LT(meanAll.p90, 0.03);
    EXPECT_LT(meanAll.p99, 0.10);
    EXPECT_LT(meanContact.p90, 0.10);
    // Per face within 1 % (the target; the worst is a side of the short
    // block, +0.75 %; -0.75 % before the shadow lines were kept as patch
    // edges, -0.76 % with the vertex values weighted by area,
    // -0.79 % before the penumbrae were split, -0.76 % with
    // the lamp at 200, -0.77 % before the splits along the feet, -0.93 %
    // with hemicubes along the patches' edges).
    EXPECT_EQ(smoothFaces.sums.size(), faces.size() - 2) << "every face but the blocks' bottoms";
    EXPECT_LT(std::abs(smoothFaces.worstError), 0.01) << smoothFaces.worst;
    EXPECT_LT(std::abs(exactFaces.worstError), 0.01) << exactFaces.worst;
}
