// The outputs' picture with the lights' direct part exact
// (output/exact_direct.h): the reflected part smoothed as before, the direct
// part exact at every corner, triangles cut at their edges' midpoints
// without T-vertices or lost area, no new corner within a file reader's
// welding distance of another, and the direct part shown as far as the
// lights have shot.
#include "output/exact_direct.h"

#include "output/vertex_radiosity.h"
#include "solver/picture/direct_light.h"
#include "solver/prepare/prepare.h"
#include "solver/shooting/near_field.h"
#include "support/lit_mesh_sampling.h"
#include "support/prepared_scenes.h"
#include "support/solver_test_scenes.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

using namespace regio;
using namespace regio::output;
using namespace regio::solver;

namespace {

PreparedScene prepare(const model::Scene& scene, double patchSize)
{
    PrepareOptions options;
    options.patchSize = patchSize;
    options.elementsPerPatch = 4;
    return test::prepared(scene, options);
}

// A 2 x 2 floor facing up, a lamp 0.4 x 0.4 at height 1.5 facing down and a
// block standing on the floor beside the lamp's foot: an umbra, a penumbra
// and full light on the floor.
model::Scene lampBlockFloor(bool lit = true)
{
    model::Scene scene;
    test::addMaterial(scene, "grey", {0.5, 0.5, 0.5});
    test::addMaterial(scene, "lamp", {0.5, 0.5, 0.5}, lit ? model::Rgb(4.0, 4.0, 4.0) : model::Rgb(0.0));
    test::addPolygon(scene, "floor", {{-1, 0, -1}, {-1, 0, 1}, {1, 0, 1}, {1, 0, -1}}, "grey");
    test::addPolygon(scene, "lamp", {{-0.2, 1.5, -0.2}, {0.2, 1.5, -0.2}, {0.2, 1.5, 0.2}, {-0.2, 1.5, 0.2}}, "lamp");
    test::addBox(scene, "block", {0.2, 0.0, -0.2}, {0.5, 0.6, 0.2}, "grey");
    return scene;
}

// Per element: the mean of the direct part over it (the midpoint rule the
// shading uses), plus `reflected`.
std::vector<model::Rgb> directMeans(const PreparedScene& prepared, const DirectLight& direct,
                                    const model::Rgb& reflected)
{
    std::vector<model::Rgb> values;
    for (const Element& e : prepared.elements) {
        model::Rgb mean(0.0);
        for (size_t k = 0; k < 3; ++k)
            mean += direct.radiosity(e.properties, 0.5 * (prepared.vertices[size_t(e.vertices[k])] +
                                                          prepared.vertices[size_t(e.vertices[(k + 1) % 3])])) /
                    3.0;
        values.push_back(mean + reflected);
    }
    return values;
}

// Per face of the mesh: its triangles' area.
std::map<int, double> areaPerFace(const LitMesh& mesh)
{
    std::map<int, double> area;
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        const glm::vec3 a = mesh.positions[mesh.indices[3 * t]], b = mesh.positions[mesh.indices[3 * t + 1]],
                        c = mesh.positions[mesh.indices[3 * t + 2]];
        area[mesh.triangleFace[t]] += 0.5 * double(glm::length(glm::cross(b - a, c - a)));
    }
    return area;
}

// Pairs of corners closer than `distance` but not at one place, by a sweep
// along x.
size_t closePairs(const LitMesh& mesh, double distance)
{
    std::vector<size_t> order(mesh.vertexCount());
    for (size_t v = 0; v < order.size(); ++v)
        order[v] = v;
    std::sort(order.begin(), order.end(),
              [&](size_t a, size_t b) { return mesh.positions[a].x < mesh.positions[b].x; });
    size_t pairs = 0;
    for (size_t i = 0; i < order.size(); ++i)
        for (size_t j = i + 1; j < order.size(); ++j) {
            const glm::dvec3 p(mesh.positions[order[i]]), q(mesh.positions[order[j]]);
            if (q.x - p.x >= distance)
                break;
            const double d = glm::length(q - p);
            if (d > 1e-6 && d < distance)
                ++pairs;
        }
    return pairs;
}

} // namespace

TEST(ExactDirect, WithoutLightsItIsTheSmoothMesh)
{
    const PreparedScene prepared = prepare(lampBlockFloor(false), 0.2);
    std::vector<model::Rgb> values;
    for (const Element& e : prepared.elements)
        values.push_back(model::Rgb(0.1 + e.centroid.x * e.centroid.x));
    const ExactDirectShading shading(prepared);
    EXPECT_FALSE(shading.hasLights());
    const LitMesh exact = shading.litMesh(values), smooth = smoothLitMesh(prepared, values);
    EXPECT_EQ(exact.positions, smooth.positions);
    EXPECT_EQ(exact.indices, smooth.indices);
    EXPECT_EQ(exact.radiosity, smooth.radiosity);
}

TEST(ExactDirect, TheReflectedPartIsSmoothedAndTheDirectPartIsExactAtEveryCorner)
{
    // Element values: the mean of the direct part over the element (the
    // midpoint rule the shading uses) plus an even 0.3 of reflected light.
    // Then every corner shows 0.3 plus the exact direct part: nothing of
    // the lamp in the block's umbra, and the penumbra's bend where it is.
    const PreparedScene prepared = prepare(lampBlockFloor(), 0.2);
    const DirectLight direct(prepared);
    const std::vector<model::Rgb> values = directMeans(prepared, direct, model::Rgb(0.3));
    const ExactDirectShading shading(prepared);
    ASSERT_TRUE(shading.hasLights());
    const LitMesh mesh = shading.litMesh(values);
    std::vector<int> faceOf(mesh.vertexCount(), -1);
    for (size_t t = 0; t < mesh.triangleCount(); ++t)
        for (size_t k = 0; k < 3; ++k)
            faceOf[mesh.indices[3 * t + k]] = mesh.triangleFace[t];
    const auto faceNamed = [&](const std::string& id) {
        for (size_t f = 0; f < prepared.faces.size(); ++f)
            if (prepared.faces[f].id == id)
                return int(f);
        return -1;
    };
    const int floor = faceNamed("floor.face"), lamp = faceNamed("lamp.face");
    int inUmbra = 0, inPenumbra = 0, inFullLight = 0;
    for (size_t v = 0; v < mesh.vertexCount(); ++v) {
        ASSERT_GE(faceOf[v], 0);
        const model::Rgb d = direct.radiosity(faceOf[v], model::Vec3(mesh.positions[v]));
        EXPECT_NEAR(mesh.radiosity[v].x, 0.3 + d.x, 1e-5 * (1.0 + d.x)) << "corner " << v << " of face " << faceOf[v];
        if (faceOf[v] == floor) {
            const double unhidden = 0.5 * 4.0 *
                                    pointToPolygonFormFactor(model::Vec3(mesh.positions[v]), {0, 1, 0},
                                                             prepared.faces[size_t(lamp)].polygon);
            (d.x == 0.0 ? inUmbra : (d.x < 0.98 * unhidden ? inPenumbra : inFullLight)) += 1;
        }
    }
    EXPECT_GT(inUmbra, 0);
    EXPECT_GT(inPenumbra, 0);
    EXPECT_GT(inFullLight, 0);
}

TEST(ExactDirect, TrianglesAreCutAtTheirEdgesMidpointsWithoutTVerticesOrLostArea)
{
    const PreparedScene prepared = prepare(lampBlockFloor(), 0.2);
    const std::vector<model::Rgb> values(prepared.elements.size(), model::Rgb(0.2));
    const LitMesh smooth = smoothLitMesh(prepared, values), exact = exactDirectLitMesh(prepared, values);
    // Every edge cut once (up to four triangles each), some again where the
    // direct part bends.
    EXPECT_GT(exact.triangleCount(), 3 * smooth.triangleCount());
    const std::map<int, double> before = areaPerFace(smooth), after = areaPerFace(exact);
    ASSERT_EQ(before.size(), after.size());
    for (const auto& [face, area] : before)
        EXPECT_NEAR(after.at(face), area, 1e-6 * area) << face;
    // No corner of a face lies inside an edge of another triangle of that
    // face: the cut edges are cut on both sides.
    for (size_t t = 0; t < exact.triangleCount(); ++t)
        for (size_t k = 0; k < 3; ++k) {
            const glm::dvec3 a(exact.positions[exact.indices[3 * t + k]]);
            const glm::dvec3 b(exact.positions[exact.indices[3 * t + (k + 1) % 3]]);
            for (size_t u = 0; u < exact.triangleCount(); ++u) {
                if (exact.triangleFace[u] != exact.triangleFace[t])
                    continue;
                for (size_t j = 0; j < 3; ++j) {
                    const glm::dvec3 p(exact.positions[exact.indices[3 * u + j]]);
                    const double s = glm::dot(p - a, b - a) / glm::dot(b - a, b - a);
                    if (s > 1e-4 && s < 1 - 1e-4) {
                        EXPECT_GT(glm::length(a + s * (b - a) - p), 1e-6) << "T-vertex on triangle " << t;
                    }
                }
            }
        }
}

TEST(ExactDirect, WhereTheDirectPartBendsTheTrianglesAreCutFiner)
{
    // A lamp's emitting top 2 cm under a ceiling: the light it gives the
    // ceiling falls from half its value at the lamp's outline to a
    // twentieth 5 cm outside, within one element of a 0.5 m mesh. With each
    // element holding its direct part's mean alone, the picture between the
    // corners must follow the exact value across the outline: within 10 %
    // of the value there plus a hundredth of the brightest (3.2 %; with
    // every edge cut once and no more, 390 %).
    model::Scene scene;
    test::addMaterial(scene, "grey", {0.5, 0.5, 0.5});
    test::addMaterial(scene, "lamp", {0.5, 0.5, 0.5}, model::Rgb(4.0));
    test::addPolygon(scene, "ceiling", {{-1, 2, -1}, {1, 2, -1}, {1, 2, 1}, {-1, 2, 1}}, "grey");
    test::addPolygon(scene, "lamp", {{-0.3, 1.98, -0.3}, {-0.3, 1.98, 0.3}, {0.3, 1.98, 0.3}, {0.3, 1.98, -0.3}},
                     "lamp");
    const PreparedScene prepared = prepare(scene, 0.5);
    const DirectLight direct(prepared);
    const std::vector<model::Rgb> values = directMeans(prepared, direct, model::Rgb(0.0));
    const LitMesh mesh = exactDirectLitMesh(prepared, values);
    const test::LitMeshProbe probe(mesh);
    int ceiling = -1;
    for (size_t f = 0; f < prepared.faces.size(); ++f)
        if (prepared.faces[f].id == "ceiling.face")
            ceiling = int(f);
    ASSERT_GE(ceiling, 0);
    const double brightest = direct.radiosity(ceiling, {0.0, 2.0, 0.0}).x;
    double worst = 0.0;
    for (double x = 0.15; x <= 0.55; x += 0.0025) {
        const model::Vec3 p(x, 2.0, 0.0123);
        const double exact = direct.radiosity(ceiling, p).x;
        const std::optional<model::Rgb> shown = probe.displayRadiosityAt("ceiling.face", p, glm::vec3(0.0f));
        ASSERT_TRUE(shown.has_value());
        worst = std::max(worst, std::abs(shown->x - exact) / (exact + 0.01 * brightest));
    }
    EXPECT_LT(worst, 0.1);
}

TEST(ExactDirect, NoNewCornerComesWithinAMillimetreOfAnother)
{
    // A file reader that welds corners closer than a millimetre (the
    // importer does) must find the cut mesh as it finds the smooth one. A
    // strip 2 mm wide (a shelf's edge) is meshed into triangles whose long
    // sides' midpoints lie 1 mm apart.
    model::Scene scene = lampBlockFloor();
    test::addPolygon(scene, "strip", {{-0.5, 0.8, 0.5}, {-0.5, 0.8, 0.502}, {0.5, 0.8, 0.502}, {0.5, 0.8, 0.5}},
                     "grey");
    const PreparedScene prepared = prepare(scene, 0.05);
    const std::vector<model::Rgb> values(prepared.elements.size(), model::Rgb(0.2));
    const LitMesh smooth = smoothLitMesh(prepared, values), exact = exactDirectLitMesh(prepared, values);
    EXPECT_GT(exact.vertexCount(), 2 * smooth.vertexCount());
    EXPECT_EQ(closePairs(exact, 1.25e-3), closePairs(smooth, 1.25e-3));
    // The preview's picture, which no reader sees, is cut without that
    // search: here that brings corners closer.
    const LitMesh screen = ExactDirectShading(prepared, {}, nullptr, CutFor::Screen).litMesh(values);
    EXPECT_GT(screen.vertexCount(), exact.vertexCount());
    EXPECT_GT(closePairs(screen, 1.25e-3), closePairs(smooth, 1.25e-3));
}

TEST(ExactDirect, TheDirectShareIsWhatTheLightsHaveShotOfTheirEmission)
{
    const PreparedScene prepared = prepare(lampBlockFloor(), 0.2);
    std::vector<model::Rgb> unshot(prepared.elements.size(), model::Rgb(0.0));
    EXPECT_DOUBLE_EQ(directShare(prepared, unshot), 1.0);
    // Before the first shot every light element holds its emission unshot;
    // what the others hold does not count.
    for (size_t e = 0; e < unshot.size(); ++e)
        unshot[e] =
            prepared.properties[size_t(prepared.elements[e].properties)].emits() ? model::Rgb(4.0) : model::Rgb(7.0);
    EXPECT_DOUBLE_EQ(directShare(prepared, unshot), 0.0);
    for (model::Rgb& u : unshot)
        u *= 0.25;
    EXPECT_NEAR(directShare(prepared, unshot), 0.75, 1e-12);
    // Without lights there is nothing to wait for.
    const PreparedScene dark = prepare(lampBlockFloor(false), 0.2);
    EXPECT_DOUBLE_EQ(directShare(dark, std::vector<model::Rgb>(dark.elements.size(), model::Rgb(1.0))), 1.0);
}

TEST(ExactDirect, ACacheServesTheNextMeshOfTheSameSceneWithTheSameValues)
{
    const PreparedScene prepared = prepare(lampBlockFloor(), 0.2);
    std::vector<model::Rgb> values;
    for (const Element& e : prepared.elements)
        values.push_back(model::Rgb(0.2 + 0.1 * e.centroid.z));
    DirectCache cache;
    const LitMesh first = ExactDirectShading(prepared, {}, &cache).litMesh(values);
    const size_t places = cache.size();
    EXPECT_GT(places, 0u);
    // The same mesh again: every place known, nothing added, the same mesh.
    const LitMesh again = ExactDirectShading(prepared, {}, &cache).litMesh(values);
    EXPECT_EQ(cache.size(), places);
    EXPECT_EQ(again.radiosity, first.radiosity);
    EXPECT_EQ(again.radiosity, exactDirectLitMesh(prepared, values).radiosity);
}

TEST(ExactDirect, AWrongValueCountIsRefused)
{
    const PreparedScene prepared = prepare(lampBlockFloor(), 0.2);
    const std::vector<model::Rgb> values(prepared.elements.size() + 1, model::Rgb(1.0));
    EXPECT_THROW(exactDirectLitMesh(prepared, values), std::invalid_argument);
    EXPECT_THROW(ExactDirectShading(prepared).litMesh(values), std::invalid_argument);
}
