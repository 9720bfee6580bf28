// The error picture of docs/accuracy.md: where the lit mesh that the editor
// shows and the outputs write (smooth, the lights' direct part exact)
// differs from the independent pointwise reference
// (tests/support/pointwise_reference.h).
//
//   accuracy_pictures SCENE.json OUT.png [CELL_METRES [REFERENCE_PATCH_METRES [PICTURE [FACE...]]]]
//
// REFERENCE_PATCH_METRES may name faces of their own patch size after it,
// "0.1,lamp.panel.py=0.02,ceiling.middle=0.02": a narrow gap cut fine in a
// room cut coarse (PointwiseReferenceOptions::facePatchSizes).
// SCENE.json may also be "furnished-room": the small furnished room of
// docs/accuracy.md, generated (tests/support/furnished_room.h, seed 1, six
// objects in a room of 5 x 2.5 x 4 m, its lamps 2 cm under the ceiling) with
// a camera in a corner.
// PICTURE is "exact" (the default: what the outputs draw) or "smooth" (the
// smooth vertex radiosity alone, what the editor's preview draws).
//
// solves the scene with its own settings to 0.1 % unshot, cuts every face
// into square cells (1 cm by default), gathers the reference at each cell's
// centre, and renders the cells from the scene's camera in false colour: the
// relative luminance error |shown - reference| / reference, 0 to 50 %
// (larger errors take the end colour). Cells under a solid (the floor under
// a block) are left out. Prints the error statistics of the cells and, per
// face, how many are off by more than 10 % (too bright / too dark) and the
// mean over the face's cells (over a 1 cm grid on a face narrower than four
// cells, whose cells would not stand for it) of the picture and of the
// elements' flat values against the reference's. The
// reference's patches are 3 cm by default; a room of several metres needs
// coarser ones (10 cm: minutes), its cost growing with the square of their
// number.
//
// With ACCURACY_CELLS_CSV=PATH in the environment, every cell's face, centre,
// shown and reference luminance go to PATH as CSV.
//
// Each FACE (an id) named after PICTURE is split by source: at up to 120
// points of a 1 cm grid on it (of the cells, when finer), the reference's
// final gather face by face, once with the reference's own radiosities and
// once with Regio's elements' in their place
// (PointwiseReference::gatheredBySource), against the picture's value
// there, and per source face what Regio's shots from it brought the face
// (the solve then runs shot by shot) against the reference's gather of
// Regio's radiosity of it. Where Regio's value is off but the reference's
// gather of Regio's sources is not, the error is in Regio's transport into
// the face, and the last column says from where; where both are, in the
// sources.
#include "model/io/scene_json.h"
#include "output/false_colour.h"
#include "output/legend_overlay.h"
#include "output/lit_mesh.h"
#include "output/png_writer.h"
#include "output/software_render.h"
#include "output/vertex_radiosity.h"
#include "solver/solver.h"
#include "support/furnished_room.h"
#include "support/lit_mesh_sampling.h"
#include "support/pointwise_reference.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

using namespace regio;

namespace {

constexpr double kLargestShownError = 50.0; // percent: the top of the ramp

struct Cell {
    int face = -1; // index into the reference's faces
    model::Vec3 centre{0.0};
    model::Vec3 corners[4];
};

// Square cells of `size` over every face whose centre lies inside it.
std::vector<Cell> cellsOf(const std::vector<test::FaceGeometry>& faces, const test::PointwiseReference& reference,
                          double size)
{
    std::vector<Cell> cells;
    for (const test::FaceGeometry& f : faces) {
        const int face = reference.faceIndex(f.id);
        if (face < 0)
            continue;
        const model::Vec3 u = glm::normalize(f.polygon[1] - f.polygon[0]);
        const model::Vec3 v = glm::cross(f.normal, u);
        const auto [s0, s1, t0, t1] = test::extentAlong(f, u, v);
        for (double s = s0; s < s1; s += size) {
            for (double t = t0; t < t1; t += size) {
                Cell c;
                c.face = face;
                const model::Vec3 origin = f.polygon[0] + u * s + v * t;
                c.centre = origin + (u + v) * (0.5 * size);
                if (test::insideDistance(f, c.centre) <= 0.0 || reference.covered(face, c.centre))
                    continue;
                // Counter-clockwise around the face's normal (u, v, n is right-handed).
                c.corners[0] = origin;
                c.corners[1] = origin + u * size;
                c.corners[2] = origin + (u + v) * size;
                c.corners[3] = origin + v * size;
                cells.push_back(c);
            }
        }
    }
    return cells;
}

double percentile(std::vector<double> v, double q)
{
    if (v.empty())
        return 0.0;
    std::sort(v.begin(), v.end());
    return v[std::min(v.size() - 1, static_cast<size_t>(q * static_cast<double>(v.size())))];
}

// The small furnished room, seen from a corner under the ceiling.
model::Result<model::Scene> furnishedRoomWithCamera()
{
    model::Scene room = test::furnishedRoom(1, 6, {5.0, 2.5, 4.0});
    room.camera = model::Camera{{0.3, 2.2, 0.3}, {3.6, 0.8, 3.0}, {0.0, 1.0, 0.0}, 75.0};
    return room;
}

// What Regio's shots brought each of `faces` (ids), by the face of the
// shooting patch: luminance x area of the radiosity each shot added,
// summed over the solve (adaptive subdivision keeps a face's
// area-weighted sum, so the sums carry over a round).
using ShotsBySource = std::map<std::string, std::map<std::string, double>>;

// The sum of weight(element) x area over the elements of the face `id`.
template <class Weight>
double sumOverFace(const solver::PreparedScene& prepared, const std::string& id, Weight&& weight)
{
    double sum = 0.0;
    for (const solver::InputFace& f : prepared.faces)
        if (f.id == id)
            for (int e : f.elements)
                sum += weight(e) * prepared.elements[size_t(e)].area;
    return sum;
}

ShotsBySource solveRecordingSources(solver::Solver& solver, const std::vector<std::string>& faces)
{
    const auto sums = [&] {
        std::vector<double> out;
        const std::vector<model::Rgb>& b = solver.shooting().radiosity();
        for (const std::string& id : faces)
            out.push_back(sumOverFace(solver.prepared(), id, [&](int e) { return solver::luminance(b[size_t(e)]); }));
        return out;
    };
    ShotsBySource shots;
    while (!solver.converged() && solver.stats().iterations < solver.settings().maxIterations) {
        const std::vector<double> before = sums();
        if (solver.step(1) != 1)
            break;
        const std::vector<double> after = sums();
        const solver::PreparedScene& prepared = solver.prepared();
        const int patch = solver.shooting().lastShooter();
        const std::string& source = prepared.faces[size_t(prepared.patches[size_t(patch)].properties)].id;
        for (size_t t = 0; t < faces.size(); ++t)
            shots[faces[t]][source] += after[t] - before[t];
    }
    return shots;
}

// Prints the split by source of `faceId` (see the top of the file).
void splitBySource(const std::string& faceId, const std::vector<test::FaceGeometry>& faces,
                   const test::PointwiseReference& reference, const test::LitMeshProbe& shown,
                   const test::LitMeshProbe& elements, const glm::vec3& ambient, double step,
                   const std::map<std::string, double>& shots, double area)
{
    const int face = reference.faceIndex(faceId);
    const auto geometry = std::find_if(faces.begin(), faces.end(), [&](const auto& f) { return f.id == faceId; });
    if (face < 0 || geometry == faces.end()) {
        std::printf("%s: no such face\n", faceId.c_str());
        return;
    }
    std::vector<model::Vec3> points;
    for (const Cell& c : cellsOf({*geometry}, reference, step))
        points.push_back(c.centre);
    const size_t stride = points.size() / 120 + 1;
    const std::vector<test::ReferenceFace>& sources = reference.faces();
    const test::ReferenceFace& receiver = sources[static_cast<size_t>(face)];
    // Regio's element values at a point of a source (without the ambient
    // term: what its shots carried).
    const test::PointwiseReference::SourceRadiosity regio = [&](int source, const model::Vec3& at) {
        return elements.displayRadiosityAt(sources[static_cast<size_t>(source)].id, at, glm::vec3(0.0f))
            .value_or(model::Rgb{0.0});
    };
    double truth = 0.0, regioShown = 0.0, gatherOfRegio = 0.0;
    std::vector<double> fromReference(sources.size(), 0.0), fromRegio(sources.size(), 0.0);
    size_t count = 0;
    for (size_t i = 0; i < points.size(); i += stride, ++count) {
        const model::Vec3& p = points[i];
        const std::vector<model::Rgb> own = reference.gatheredBySource(face, p);
        const std::vector<model::Rgb> theirs = reference.gatheredBySource(face, p, regio);
        model::Rgb sumOwn{0.0}, sumTheirs{0.0};
        for (size_t k = 0; k < sources.size(); ++k) {
            fromReference[k] += test::luminance(receiver.reflectance * own[k]);
            fromRegio[k] += test::luminance(receiver.reflectance * theirs[k]);
            sumOwn += own[k];
            sumTheirs += theirs[k];
        }
        // radiosityAt(face, p), without gathering it a third time.
        truth += test::luminance(receiver.emission + receiver.reflectance * sumOwn);
        regioShown += test::luminance(shown.displayRadiosityAt(faceId, p, ambient).value_or(model::Rgb{0.0}));
        gatherOfRegio += test::luminance(receiver.emission + receiver.reflectance * sumTheirs);
    }
    if (count == 0 || truth <= 0.0)
        return;
    std::printf("%s, %zu points: Regio %+.2f %%, the reference's gather of Regio's sources %+.2f %%\n", faceId.c_str(),
                count, 100.0 * (regioShown - truth) / truth, 100.0 * (gatherOfRegio - truth) / truth);
    std::printf("    %-29s %-17s %-27s %s\n", "source", "share of the face", "Regio's source radiosity",
                "Regio's shots from it against the gather of it");
    std::vector<size_t> order(sources.size());
    for (size_t k = 0; k < order.size(); ++k)
        order[k] = k;
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return fromReference[a] > fromReference[b]; });
    for (size_t i = 0; i < std::min<size_t>(8, order.size()) && fromReference[order[i]] > 0.0; ++i) {
        const size_t k = order[i];
        const auto shot = shots.find(sources[k].id);
        const double delivered = (shot == shots.end() ? 0.0 : shot->second) / area,
                     gathered = fromRegio[k] / static_cast<double>(count);
        std::printf("    from %-24s %9.1f %% %+21.2f %% %+30.2f %% (%+.2f %% of the face)\n", sources[k].id.c_str(),
                    100.0 * fromReference[k] / truth, 100.0 * (fromRegio[k] - fromReference[k]) / fromReference[k],
                    gathered > 0.0 ? 100.0 * (delivered - gathered) / gathered : 0.0,
                    100.0 * (delivered - gathered) / (truth / static_cast<double>(count)));
    }
}

// "0.1" or "0.1,FACE=0.02,...": the patch size, then faces of their own.
bool parsePatchSizes(const std::string& text, test::PointwiseReferenceOptions& options)
{
    std::size_t start = 0;
    bool first = true;
    while (start <= text.size()) {
        const std::size_t end = std::min(text.find(',', start), text.size());
        const std::string item = text.substr(start, end - start);
        const std::size_t equals = item.find('=');
        if (first != (equals == std::string::npos))
            return false;
        char* rest = nullptr;
        const char* number = first ? item.c_str() : item.c_str() + equals + 1;
        const double metres = std::strtod(number, &rest);
        if (rest == number || *rest != '\0' || !(metres > 0.0))
            return false;
        if (first)
            options.patchSize = metres;
        else
            options.facePatchSizes[item.substr(0, equals)] = metres;
        first = false;
        start = end + 1;
    }
    return true;
}

} // namespace

int main(int argc, char** argv)
{
    if (argc < 3) {
        std::fprintf(stderr,
                     "usage: accuracy_pictures SCENE.json OUT.png [CELL_METRES [REFERENCE_PATCH_METRES "
                     "[exact|smooth [FACE...]]]]\n");
        return 2;
    }
    const double cellSize = argc > 3 ? std::atof(argv[3]) : 0.01;
    test::PointwiseReferenceOptions referenceOptions;
    if (argc > 4 && !parsePatchSizes(argv[4], referenceOptions)) {
        std::fprintf(stderr, "the reference's patch sizes are METRES[,FACE=METRES...]\n");
        return 2;
    }
    const std::string pictureKind = argc > 5 ? argv[5] : "exact";
    if (pictureKind != "exact" && pictureKind != "smooth") {
        std::fprintf(stderr, "the picture is \"exact\" or \"smooth\"\n");
        return 2;
    }
    if (!(cellSize > 0.0)) {
        std::fprintf(stderr, "the cell size must be a positive number of metres\n");
        return 2;
    }
    model::Result<model::Scene> loaded =
        std::string(argv[1]) == "furnished-room" ? furnishedRoomWithCamera() : model::loadSceneFile(argv[1]);
    if (!loaded.ok()) {
        std::fprintf(stderr, "cannot read %s\n", argv[1]);
        return 1;
    }
    const model::Scene& scene = *loaded;
    if (!scene.camera) {
        std::fprintf(stderr, "%s has no camera\n", argv[1]);
        return 1;
    }

    solver::SolverOptions options;
    options.maxIterations = 100000000;
    options.convergence = 0.001;
    auto built = solver::Solver::create(scene, options);
    if (!built.ok()) {
        std::fprintf(stderr, "the scene cannot be solved\n");
        return 1;
    }
    const std::atomic<bool> cancel{false};
    const std::vector<std::string> splitFaces(argv + std::min(argc, 6), argv + argc);
    ShotsBySource shots;
    if (splitFaces.empty())
        (*built)->run({}, cancel);
    else
        shots = solveRecordingSources(**built, splitFaces);
    const solver::SolutionSnapshot snapshot = (*built)->snapshot();
    const output::LitMesh lit = pictureKind == "exact"
                                    ? output::litMeshForOutput((*built)->prepared(), snapshot.radiosity, true)
                                    : output::smoothLitMesh((*built)->prepared(), snapshot.radiosity);
    const glm::vec3 ambient(snapshot.stats.ambient);
    const test::LitMeshProbe probe(lit);
    const output::LitMesh flat = output::litMeshFromSolution((*built)->prepared(), snapshot.radiosity);
    const test::LitMeshProbe flatProbe(flat);

    std::unique_ptr<const test::PointwiseReference> gathered;
    try {
        gathered = std::make_unique<const test::PointwiseReference>(scene, referenceOptions);
    } catch (const std::invalid_argument& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 2;
    }
    const test::PointwiseReference& reference = *gathered;
    const std::vector<test::FaceGeometry> faces = test::faceGeometry(scene);
    const std::vector<Cell> cells = cellsOf(faces, reference, cellSize);
    std::vector<test::GatherPoint> gather;
    for (const Cell& c : cells)
        gather.push_back({c.face, c.centre});
    const std::vector<model::Rgb> expected = reference.radiosityAt(gather);

    // One quad per cell carrying its error (percent) as a grey "radiosity",
    // whose luminance is the error itself.
    output::LitMesh picture;
    for (const test::FaceGeometry& f : faces)
        picture.faceIds.push_back(f.id);
    std::vector<double> errors;
    // Where the large errors are: per face, the cells off by more than 10 %,
    // too bright and too dark.
    std::map<std::string, std::pair<int, int>> largeByFace;
    // Per face, the mean luminance over its cells: smooth picture, flat
    // elements and reference (the cells are of one size, so these are
    // area-weighted means).
    struct Means {
        double smooth = 0.0, flat = 0.0, reference = 0.0;
    };
    std::map<std::string, Means> meanByFace;
    const auto addToMean = [&](const std::string& id, const model::Vec3& at, double shown, double truth) {
        meanByFace[id].smooth += shown;
        meanByFace[id].flat += test::luminance(flatProbe.displayRadiosityAt(id, at, ambient).value_or(model::Rgb{0.0}));
        meanByFace[id].reference += truth;
    };
    // A face narrower than four cells (a table's leg 6 cm wide in 5 cm
    // cells holds one row of them, off its middle) takes its mean over a
    // grid of 1 cm instead.
    const double fineStep = std::min(cellSize, 0.01);
    std::vector<Cell> fine;
    for (const test::FaceGeometry& f : faces) {
        const model::Vec3 u = glm::normalize(f.polygon[1] - f.polygon[0]);
        const auto [s0, s1, t0, t1] = test::extentAlong(f, u, glm::cross(f.normal, u));
        if (std::min(s1 - s0, t1 - t0) < 4.0 * cellSize) {
            const std::vector<Cell> grid = cellsOf({f}, reference, fineStep);
            fine.insert(fine.end(), grid.begin(), grid.end());
        }
    }
    std::vector<test::GatherPoint> fineGather;
    for (const Cell& c : fine)
        fineGather.push_back({c.face, c.centre});
    const std::vector<model::Rgb> fineExpected = reference.radiosityAt(fineGather);
    std::map<int, bool> fineFaces;
    for (size_t i = 0; i < fine.size(); ++i) {
        fineFaces[fine[i].face] = true;
        const std::string& id = reference.faces()[static_cast<size_t>(fine[i].face)].id;
        const std::optional<model::Rgb> shown = probe.displayRadiosityAt(id, fine[i].centre, ambient);
        if (shown && test::luminance(fineExpected[i]) > 0.0)
            addToMean(id, fine[i].centre, test::luminance(*shown), test::luminance(fineExpected[i]));
    }
    // Every cell's value, for a closer look than the picture gives.
    std::FILE* cellsCsv = nullptr;
    if (const char* path = std::getenv("ACCURACY_CELLS_CSV")) {
        cellsCsv = std::fopen(path, "w");
        if (!cellsCsv) {
            std::fprintf(stderr, "cannot write %s\n", path);
            return 1;
        }
        std::fprintf(cellsCsv, "face,x,y,z,shown,reference\n");
    }
    for (size_t i = 0; i < cells.size(); ++i) {
        const Cell& c = cells[i];
        const std::string& id = reference.faces()[static_cast<size_t>(c.face)].id;
        const std::optional<model::Rgb> shown = probe.displayRadiosityAt(id, c.centre, ambient);
        const double truth = test::luminance(expected[i]);
        if (!shown || truth <= 0.0)
            continue;
        if (cellsCsv)
            std::fprintf(cellsCsv, "%s,%.4f,%.4f,%.4f,%.6g,%.6g\n", id.c_str(), c.centre.x, c.centre.y, c.centre.z,
                         test::luminance(*shown), truth);
        const double error = 100.0 * std::abs(test::luminance(*shown) - truth) / truth;
        errors.push_back(error);
        if (!fineFaces.contains(c.face))
            addToMean(id, c.centre, test::luminance(*shown), truth);
        if (error > 10.0) {
            auto& [bright, dark] = largeByFace[id];
            ++(test::luminance(*shown) > truth ? bright : dark);
        }
        const auto base = static_cast<uint32_t>(picture.positions.size());
        const model::Vec3& n = reference.faces()[static_cast<size_t>(c.face)].normal;
        for (const model::Vec3& corner : c.corners) {
            picture.positions.emplace_back(corner);
            picture.normals.emplace_back(n);
            picture.radiosity.emplace_back(static_cast<float>(error));
            picture.reflectance.emplace_back(0.0f);
        }
        for (uint32_t k : {0u, 1u, 2u, 0u, 2u, 3u})
            picture.indices.push_back(base + k);
        picture.triangleFace.push_back(c.face);
        picture.triangleFace.push_back(c.face);
    }

    if (cellsCsv)
        std::fclose(cellsCsv);

    const output::FalseColour ramp(output::FalseColourScale::Linear, 0.0, kLargestShownError);
    const output::DisplayColours colours =
        output::falseColours(picture, ramp, glm::vec3(0.0f), output::DisplayEncoding{});
    output::RenderOptions render;
    render.width = 800;
    render.height = 600;
    output::Image image = output::renderImage(picture, colours, *scene.camera, render);
    output::FalseColourLegend legend = ramp.legend();
    legend.quantity = "relative error";
    legend.unit = "%";
    output::drawLegend(image, legend);
    if (const model::Check written = output::writePng(argv[2], image); !written.ok()) {
        std::fprintf(stderr, "cannot write %s\n", argv[2]);
        return 1;
    }
    std::printf("%zu cells of %.3f m: median %.2f %%, 90th %.2f %%, 99th %.2f %%, worst %.1f %% -> %s\n", errors.size(),
                cellSize, percentile(errors, 0.5), percentile(errors, 0.9), percentile(errors, 0.99),
                percentile(errors, 1.0), argv[2]);
    std::printf("cells off by more than 10 %%, too bright / too dark:\n");
    for (const auto& [id, counts] : largeByFace)
        std::printf("  %-24s %5d / %5d\n", id.c_str(), counts.first, counts.second);
    std::printf(
        "per face, mean of the picture and of the elements against the reference's (over a 1 cm grid on "
        "faces narrower than four cells):\n");
    for (const auto& [id, sums] : meanByFace)
        std::printf("  %-24s %+6.2f %%  %+6.2f %%\n", id.c_str(),
                    100.0 * (sums.smooth - sums.reference) / sums.reference,
                    100.0 * (sums.flat - sums.reference) / sums.reference);
    for (const std::string& id : splitFaces) {
        // Of Regio's elements: what the shots' sums are over.
        const double area = sumOverFace((*built)->prepared(), id, [](int) { return 1.0; });
        splitBySource(id, faces, reference, probe, flatProbe, ambient, std::min(cellSize, 0.01), shots[id], area);
    }
    return 0;
}
