// Smooth vertex radiosity (paper §6): element values averaged at the vertices
// of each plane-and-material group, T-vertex-free output for Gouraud shading.
#include "output/vertex_radiosity.h"

#include "solver/prepare/prepare.h"
#include "support/furnished_room.h"
#include "support/solver_test_scenes.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <chrono>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

using namespace regio;
using namespace regio::output;
using namespace regio::solver;
using namespace regio::test;

namespace {

PreparedScene prepare(const model::Scene& scene, double patchSize, int elementsPerPatch = 4)
{
    PrepareOptions options;
    options.patchSize = patchSize;
    options.elementsPerPatch = elementsPerPatch;
    model::Result<PreparedScene> r = prepareScene(scene, options);
    if (!r.ok())
        throw std::runtime_error("test scene does not prepare");
    return std::move(*r);
}

// A floor rectangle [x0, x1] x [y0, y1] at z = 0 facing +z.
void addFloor(model::Scene& scene, const std::string& id, double x0, double x1, double y0, double y1,
              const std::string& material)
{
    addPolygon(scene, id, {{x0, y0, 0}, {x1, y0, 0}, {x1, y1, 0}, {x0, y1, 0}}, material);
}

int faceIndex(const PreparedScene& scene, const std::string& id)
{
    for (size_t i = 0; i < scene.faces.size(); ++i)
        if (scene.faces[i].id == id)
            return static_cast<int>(i);
    return -1;
}

// Element values from a function of the element.
template <typename F>
std::vector<Rgb> elementValues(const PreparedScene& scene, F&& f)
{
    std::vector<Rgb> v;
    for (const Element& e : scene.elements)
        v.push_back(f(e));
    return v;
}

double triangleArea(const LitMesh& m, size_t t)
{
    const glm::dvec3 a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
                     c = m.positions[m.indices[3 * t + 2]];
    return 0.5 * glm::length(glm::cross(b - a, c - a));
}

// Undirected edges of the output by vertex index, with their use counts.
// Vertices are shared only within a group, so this is per group.
std::map<std::pair<uint32_t, uint32_t>, int> edgeUses(const LitMesh& m)
{
    std::map<std::pair<uint32_t, uint32_t>, int> uses;
    for (size_t t = 0; t < m.triangleCount(); ++t)
        for (size_t c = 0; c < 3; ++c) {
            const uint32_t a = m.indices[3 * t + c], b = m.indices[3 * t + (c + 1) % 3];
            ++uses[{std::min(a, b), std::max(a, b)}];
        }
    return uses;
}

// Vertices lying strictly inside an edge used by a single triangle: the
// T-vertices a Gouraud-shaded picture would show as cracks.
int hangingVertices(const LitMesh& m)
{
    int hanging = 0;
    for (const auto& [edge, n] : edgeUses(m)) {
        if (n != 1)
            continue;
        const glm::dvec3 a = m.positions[edge.first], b = m.positions[edge.second];
        const glm::dvec3 d = b - a;
        for (size_t v = 0; v < m.vertexCount(); ++v) {
            if (v == edge.first || v == edge.second ||
                glm::dot(glm::dvec3(m.normals[v]), glm::dvec3(m.normals[edge.first])) < 0.999 ||
                m.reflectance[v] != m.reflectance[edge.first])
                continue;
            const glm::dvec3 p = m.positions[v];
            const double t = glm::dot(p - a, d) / glm::dot(d, d);
            if (t > 1e-4 && t < 1.0 - 1e-4 && glm::length(p - (a + d * t)) < 1e-5)
                ++hanging;
        }
    }
    return hanging;
}

// Two touching floor pieces of one material: a 1 m square and a 1 x 2 m
// rectangle beside it. Their common side is meshed from each piece on its
// own (1 m and 2 m sides divided independently), so the elements meet with
// T-vertices there. The union is an L of area 3 and perimeter 8.
PreparedScene tJunctionFloor()
{
    model::Scene scene;
    addMaterial(scene, "grey", {0.5, 0.5, 0.5});
    addFloor(scene, "small", 0, 1, 0, 1, "grey");
    addFloor(scene, "large", 1, 2, 0, 2, "grey");
    return prepare(scene, 0.3);
}

Rgb ramp(const Vec3& p) { return Rgb(1.0 + 2.0 * p.x, 3.0 - 1.0 * p.y, 2.0 + 0.5 * p.x + 0.5 * p.y); }

} // namespace

TEST(VertexRadiosity, UniformlyLitPlaneHasUniformVertexValues)
{
    model::Scene scene;
    addMaterial(scene, "grey", {0.5, 0.5, 0.5});
    addFloor(scene, "floor", 0, 2, 0, 2, "grey");
    const PreparedScene prepared = prepare(scene, 0.25);
    const Rgb value(3.0, 2.0, 1.0);
    const LitMesh mesh = smoothLitMesh(prepared, elementValues(prepared, [&](const Element&) { return value; }));
    EXPECT_FALSE(!checkLitMesh(mesh).ok());
    ASSERT_FALSE(mesh.empty());
    for (const glm::vec3& r : mesh.radiosity) {
        EXPECT_NEAR(r.x, 3.0, 1e-5);
        EXPECT_NEAR(r.y, 2.0, 1e-5);
        EXPECT_NEAR(r.z, 1.0, 1e-5);
    }
}

TEST(VertexRadiosity, VerticesAreSharedWithinOnePlaneAndMaterial)
{
    model::Scene scene;
    addMaterial(scene, "grey", {0.5, 0.5, 0.5});
    addFloor(scene, "floor", 0, 1, 0, 1, "grey");
    const PreparedScene prepared = prepare(scene, 0.25);
    const LitMesh smooth = smoothLitMesh(prepared, elementValues(prepared, [](const Element&) { return Rgb(1.0); }));
    // A conforming grid of elements: far fewer vertices than three per element.
    EXPECT_LT(smooth.vertexCount(), prepared.elements.size());
    EXPECT_EQ(smooth.triangleCount(), prepared.elements.size());
}

TEST(VertexRadiosity, LinearRampIsReproducedAtInteriorVertices)
{
    model::Scene scene;
    addMaterial(scene, "grey", {0.5, 0.5, 0.5});
    addFloor(scene, "floor", 0, 1, 0, 1, "grey");
    const PreparedScene prepared = prepare(scene, 0.1);
    const LitMesh mesh =
        smoothLitMesh(prepared, elementValues(prepared, [](const Element& e) { return ramp(e.centroid); }));
    int interior = 0;
    double worst = 0.0;
    for (size_t v = 0; v < mesh.vertexCount(); ++v) {
        const glm::dvec3 p = mesh.positions[v];
        if (p.x < 1e-6 || p.x > 1 - 1e-6 || p.y < 1e-6 || p.y > 1 - 1e-6)
            continue;
        ++interior;
        worst = std::max(worst, glm::length(glm::dvec3(mesh.radiosity[v]) - ramp(p)));
    }
    EXPECT_GT(interior, 20);
    // Elements are about 0.05 m and the ramp rises about 2.3 per metre, so
    // an element's own value misses a corner's by up to ~0.07; the average
    // around the vertex is far closer.
    EXPECT_LT(worst, 0.02);
}

// Where small elements meet large ones, a vertex on the line between them
// takes from both sides alike: its value is the average of the elements
// around it weighted by their angles there, not by their areas (which let
// the large elements, whose means come from farther away, outweigh the small
// ones beside the vertex).
TEST(VertexRadiosity, AVertexWhereSmallElementsMeetLargeOnesTakesFromBothSidesAlike)
{
    model::Scene scene;
    addMaterial(scene, "grey", {0.5, 0.5, 0.5});
    addFloor(scene, "coarse", 0, 1, 0, 1, "grey"); // elements 0.125 m square
    addFloor(scene, "fine", 1, 1.1, 0, 1, "grey"); // elements 0.05 x 0.125 m
    const PreparedScene prepared = prepare(scene, 0.3);
    const int fine = faceIndex(prepared, "fine.face");
    ASSERT_GE(fine, 0);
    const std::vector<Rgb> values = elementValues(prepared, [&](const Element& e) {
        return prepared.properties[size_t(e.properties)].face == fine ? Rgb(0.0) : Rgb(1.0);
    });
    SmoothingOptions averageOnly;
    averageOnly.extrapolateBoundary = false;
    averageOnly.meanPreservingPasses = 0;
    const LitMesh mesh = smoothLitMesh(prepared, values, averageOnly);
    int onTheLine = 0;
    for (size_t v = 0; v < mesh.vertexCount(); ++v) {
        const glm::dvec3 p = mesh.positions[v];
        if (std::abs(p.x - 1.0) > 1e-6 || p.y < 1e-6 || p.y > 1 - 1e-6)
            continue;
        ++onTheLine;
        EXPECT_NEAR(mesh.radiosity[v].x, 0.5, 1e-6) << "at y = " << p.y;
    }
    EXPECT_EQ(onTheLine, 7);
}

TEST(VertexRadiosity, ExtrapolationBringsBoundaryValuesCloserToTheRamp)
{
    model::Scene scene;
    addMaterial(scene, "grey", {0.5, 0.5, 0.5});
    addFloor(scene, "floor", 0, 1, 0, 1, "grey");
    const PreparedScene prepared = prepare(scene, 0.1);
    const std::vector<Rgb> values = elementValues(prepared, [](const Element& e) { return ramp(e.centroid); });
    SmoothingOptions average;
    average.extrapolateBoundary = false;
    const LitMesh plain = smoothLitMesh(prepared, values, average);
    const LitMesh extrapolated = smoothLitMesh(prepared, values);
    ASSERT_EQ(plain.vertexCount(), extrapolated.vertexCount());
    double plainError = 0.0, extrapolatedError = 0.0;
    for (size_t v = 0; v < plain.vertexCount(); ++v) {
        const glm::dvec3 p = plain.positions[v];
        const bool edge = p.x < 1e-6 || p.x > 1 - 1e-6 || p.y < 1e-6 || p.y > 1 - 1e-6;
        if (!edge)
            continue;
        plainError += glm::length(glm::dvec3(plain.radiosity[v]) - ramp(p));
        extrapolatedError += glm::length(glm::dvec3(extrapolated.radiosity[v]) - ramp(p));
    }
    EXPECT_LT(extrapolatedError, 0.5 * plainError);
}

TEST(VertexRadiosity, DefaultsExtrapolateBoundariesPreserveMeansOnceAndDoNotSmoothNeighbours)
{
    const SmoothingOptions defaults;
    EXPECT_TRUE(defaults.extrapolateBoundary);
    EXPECT_EQ(defaults.meanPreservingPasses, 1);
    EXPECT_EQ(defaults.neighbourPasses, 0);
}

// Where an umbra meets the light the radiosity bends: flat on one side,
// rising on the other. The average around a vertex on the umbra's side takes
// light from the lit elements beyond the bend; the mean-preserving pass moves
// every vertex by what its triangles miss of their elements' values (each
// element's value is the mean of the light over it, as the solver's are).
TEST(VertexRadiosity, TheMeanPreservingPassFollowsTheBendWhereAnUmbraMeetsTheLight)
{
    model::Scene scene;
    addMaterial(scene, "grey", {0.5, 0.5, 0.5});
    addFloor(scene, "floor", 0, 1, 0, 1, "grey");
    const PreparedScene prepared = prepare(scene, 0.1);
    const auto light = [](const Vec3& p) { return 0.1 + 2.0 * std::max(0.0, p.x - 0.43); };
    // Each element's mean of the light, over a barycentric grid of its triangle.
    const std::vector<Rgb> values = elementValues(prepared, [&](const Element& e) {
        const Vec3& a = prepared.vertices[size_t(e.vertices[0])];
        const Vec3& b = prepared.vertices[size_t(e.vertices[1])];
        const Vec3& c = prepared.vertices[size_t(e.vertices[2])];
        constexpr int n = 24;
        double sum = 0.0;
        int count = 0;
        for (int i = 0; i < n; ++i)
            for (int j = 0; i + j < n; ++j) {
                const double u = (i + 1.0 / 3.0) / n, v = (j + 1.0 / 3.0) / n;
                sum += light(a + u * (b - a) + v * (c - a));
                ++count;
                if (i + j + 1 < n) {
                    const double u2 = (i + 2.0 / 3.0) / n, v2 = (j + 2.0 / 3.0) / n;
                    sum += light(a + u2 * (b - a) + v2 * (c - a));
                    ++count;
                }
            }
        return Rgb(sum / count);
    });
    SmoothingOptions averaged;
    averaged.meanPreservingPasses = 0;
    const LitMesh before = smoothLitMesh(prepared, values, averaged);
    const LitMesh after = smoothLitMesh(prepared, values);
    ASSERT_EQ(before.vertexCount(), after.vertexCount());

    // At the vertices within two elements of the bend.
    double errorBefore = 0.0, errorAfter = 0.0;
    int near = 0;
    for (size_t v = 0; v < before.vertexCount(); ++v) {
        const glm::dvec3 p = before.positions[v];
        if (std::abs(p.x - 0.43) > 0.1)
            continue;
        ++near;
        errorBefore += std::abs(double(before.radiosity[v].x) - light(p));
        errorAfter += std::abs(double(after.radiosity[v].x) - light(p));
    }
    ASSERT_GT(near, 20);
    // Measured: a mean error of 0.0027 averaged, 0.0019 with the pass.
    EXPECT_LT(errorAfter, 0.8 * errorBefore);

    // Over the whole floor, the triangles' means come closer to their elements'.
    const auto meanMiss = [&](const LitMesh& m) {
        double miss = 0.0;
        for (size_t t = 0; t < m.triangleCount(); ++t) {
            const glm::dvec3 centre =
                (glm::dvec3(m.positions[m.indices[3 * t]]) + glm::dvec3(m.positions[m.indices[3 * t + 1]]) +
                 glm::dvec3(m.positions[m.indices[3 * t + 2]])) /
                3.0;
            const double shown = (double(m.radiosity[m.indices[3 * t]].x) + m.radiosity[m.indices[3 * t + 1]].x +
                                  m.radiosity[m.indices[3 * t + 2]].x) /
                                 3.0;
            miss += triangleArea(m, t) * std::abs(shown - light(centre));
        }
        return miss;
    };
    EXPECT_LT(meanMiss(after), meanMiss(before));
    // A flat field stays flat, so the umbra stays at its value.
    for (size_t v = 0; v < after.vertexCount(); ++v)
        if (after.positions[v].x < 0.3f) {
            EXPECT_NEAR(after.radiosity[v].x, 0.1f, 1e-6f);
        }
}

// Beside a shadow corner (PreparedScene::shadowCorners) the light depends on
// the direction the corner is approached from: umbra on one side of a shadow
// line, light on the other. No single value at the corner is right there.
TEST(VertexRadiosity, AtAShadowCornerEveryElementKeepsItsOwnValue)
{
    model::Scene scene;
    addMaterial(scene, "grey", {0.5, 0.5, 0.5});
    addFloor(scene, "floor", 0, 1, 0, 1, "grey");
    PreparedScene prepared = prepare(scene, 0.25);
    const Vec3 corner{0.5, 0.5, 0.0};
    prepared.shadowCorners.push_back(corner);
    // Every element its own value.
    const std::vector<Rgb> values =
        elementValues(prepared, [n = 0.0](const Element&) mutable { return Rgb(n += 1.0); });
    std::set<float> around;
    for (size_t e = 0; e < prepared.elements.size(); ++e)
        for (int v : prepared.elements[e].vertices)
            if (glm::length(prepared.vertices[size_t(v)] - corner) < 1e-12)
                around.insert(float(values[e].x));
    ASSERT_GT(around.size(), 2u) << "the corner is inside the floor's mesh";

    const LitMesh mesh = smoothLitMesh(prepared, values);
    std::multiset<float> atCorner;
    for (size_t v = 0; v < mesh.vertexCount(); ++v)
        if (glm::length(glm::dvec3(mesh.positions[v]) - corner) < 1e-6)
            atCorner.insert(mesh.radiosity[v].x);
    EXPECT_EQ(std::set<float>(atCorner.begin(), atCorner.end()), around);
    EXPECT_EQ(atCorner.size(), around.size()) << "one vertex per element there";
    // Elsewhere nothing changed: the same mesh without the corner has one vertex there.
    prepared.shadowCorners.clear();
    const LitMesh plain = smoothLitMesh(prepared, values);
    EXPECT_EQ(plain.vertexCount() + around.size() - 1, mesh.vertexCount());
    EXPECT_EQ(plain.indices.size(), mesh.indices.size());
}

// A shadow corner on a face's outline (a block's foot corner on the floor's
// edge): the shadow lines from it run between the outline's vertices beside
// it and their inner neighbours, so those vertices are not extrapolated from
// across the jump from umbra to light; they keep their average.
TEST(VertexRadiosity, BesideAShadowCornerOnTheOutlineTheAverageIsNotExtrapolated)
{
    model::Scene scene;
    addMaterial(scene, "grey", {0.5, 0.5, 0.5});
    addFloor(scene, "floor", 0, 1, 0, 1, "grey");
    PreparedScene prepared = prepare(scene, 0.25); // vertices every 0.125 m
    // Umbra left of x = 0.5, light right of it.
    const std::vector<Rgb> values =
        elementValues(prepared, [](const Element& e) { return Rgb(e.centroid.x < 0.5 ? 0.1 : 1.0); });
    SmoothingOptions noMeans;
    noMeans.meanPreservingPasses = 0;
    const auto valueAt = [](const LitMesh& mesh, const Vec3& p) {
        for (size_t v = 0; v < mesh.vertexCount(); ++v)
            if (glm::length(glm::dvec3(mesh.positions[v]) - p) < 1e-6)
                return double(mesh.radiosity[v].x);
        return -1.0;
    };
    const Vec3 umbraSide{0.375, 0.0, 0.0}, lightSide{0.625, 0.0, 0.0};
    // Without the corner the edge's vertices are extrapolated, and the one
    // on the umbra's side takes the light beyond the jump for a gradient.
    const LitMesh plain = smoothLitMesh(prepared, values, noMeans);
    ASSERT_GE(valueAt(plain, umbraSide), 0.0);
    EXPECT_LT(valueAt(plain, umbraSide), 0.09);

    prepared.shadowCorners.push_back({0.5, 0.0, 0.0});
    const LitMesh mesh = smoothLitMesh(prepared, values, noMeans);
    EXPECT_NEAR(valueAt(mesh, umbraSide), 0.1, 1e-6);
    EXPECT_NEAR(valueAt(mesh, lightSide), 1.0, 1e-6);
    // One element farther along the edge, extrapolation as before.
    const Vec3 farther{0.25, 0.0, 0.0};
    EXPECT_NEAR(valueAt(mesh, farther), valueAt(plain, farther), 1e-6);
}

// A floor of two faces (split at x = 0.3) meets a wall of one along y = 0:
// each side divides the line at its own points. In the output, both meet
// vertex to vertex there, so no pixel falls between them.
TEST(VertexRadiosity, WhereAFloorMeetsAWallBothSidesShareEveryPointOfTheLine)
{
    model::Scene scene;
    addMaterial(scene, "grey", {0.5, 0.5, 0.5});
    addFloor(scene, "floor-a", 0, 0.3, 0, 1, "grey");
    addFloor(scene, "floor-b", 0.3, 1, 0, 1, "grey");
    // The wall in the plane y = 0, facing +y, standing on the floor's edge.
    addPolygon(scene, "wall", {{0, 0, 0}, {0, 0, 0.6}, {1, 0, 0.6}, {1, 0, 0}}, "grey");
    const PreparedScene prepared = prepare(scene, 0.25);
    const std::vector<Rgb> values = elementValues(prepared, [](const Element& e) { return ramp(e.centroid); });
    const LitMesh mesh = smoothLitMesh(prepared, values);
    const int wall = faceIndex(prepared, "wall.face");
    ASSERT_GE(wall, 0);
    // The segments of each side on the line y = 0, z = 0.
    std::multiset<std::pair<float, float>> floorSide, wallSide;
    std::set<float> floorPoints, wallPoints;
    for (size_t t = 0; t < mesh.triangleCount(); ++t)
        for (size_t c = 0; c < 3; ++c) {
            const glm::vec3 a = mesh.positions[mesh.indices[3 * t + c]];
            const glm::vec3 b = mesh.positions[mesh.indices[3 * t + (c + 1) % 3]];
            const bool onLine = std::abs(a.y) < 1e-6f && std::abs(a.z) < 1e-6f && std::abs(b.y) < 1e-6f &&
                                std::abs(b.z) < 1e-6f && a.x != b.x;
            if (!onLine)
                continue;
            const bool isWall = mesh.triangleFace[t] == wall;
            (isWall ? wallSide : floorSide).insert({std::min(a.x, b.x), std::max(a.x, b.x)});
            (isWall ? wallPoints : floorPoints).insert(a.x);
            (isWall ? wallPoints : floorPoints).insert(b.x);
        }
    EXPECT_GT(floorPoints.size(), 5u) << "the two floor faces divide the line at more points than the wall";
    EXPECT_EQ(floorPoints, wallPoints);
    EXPECT_EQ(floorSide, wallSide);
    // Each triangle along the line is fanned through the points it took.
    EXPECT_GT(mesh.triangleCount(), prepared.elements.size());
}

TEST(VertexRadiosity, ExtrapolatedValuesAreNeverNegative)
{
    model::Scene scene;
    addMaterial(scene, "grey", {0.5, 0.5, 0.5});
    addFloor(scene, "floor", 0, 1, 0, 1, "grey");
    const PreparedScene prepared = prepare(scene, 0.25);
    // Dark at the edge x = 0, bright inside: extrapolation would go below 0.
    SmoothingOptions extrapolate;
    extrapolate.extrapolateBoundary = true;
    const LitMesh mesh = smoothLitMesh(
        prepared, elementValues(prepared, [](const Element& e) { return Rgb(e.centroid.x < 0.2 ? 0.0 : 10.0); }),
        extrapolate);
    for (const glm::vec3& r : mesh.radiosity)
        EXPECT_GE(r.x, 0.0f);
}

TEST(VertexRadiosity, CreaseOfABoxCornerIsNotAveragedAcross)
{
    model::Scene scene;
    addMaterial(scene, "grey", {0.5, 0.5, 0.5});
    addBox(scene, "room", {0, 0, 0}, {1, 1, 1}, "grey", true);
    const PreparedScene prepared = prepare(scene, 0.25);
    // Every wall uniform, each its own value.
    const LitMesh mesh = smoothLitMesh(
        prepared, elementValues(prepared, [&](const Element& e) {
            return Rgb(1.0 + static_cast<double>(prepared.properties[static_cast<size_t>(e.properties)].face));
        }));
    ASSERT_EQ(mesh.triangleCount(), prepared.elements.size());
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        const float expected = 1.0f + static_cast<float>(mesh.triangleFace[t]);
        for (size_t c = 0; c < 3; ++c)
            EXPECT_FLOAT_EQ(mesh.radiosity[mesh.indices[3 * t + c]].x, expected);
    }
    // The corner (0, 0, 0) exists once per wall meeting there.
    int corner = 0;
    for (const glm::vec3& p : mesh.positions)
        if (glm::length(p) < 1e-6f)
            ++corner;
    EXPECT_EQ(corner, 3);
}

TEST(VertexRadiosity, MaterialBoundaryKeepsBothValues)
{
    model::Scene scene;
    addMaterial(scene, "grey", {0.5, 0.5, 0.5});
    addMaterial(scene, "red", {0.6, 0.1, 0.1});
    addFloor(scene, "left", 0, 1, 0, 1, "grey");
    addFloor(scene, "right", 1, 2, 0, 1, "red");
    const PreparedScene prepared = prepare(scene, 0.25);
    const int left = faceIndex(prepared, "left.face");
    const LitMesh mesh = smoothLitMesh(
        prepared, elementValues(prepared, [&](const Element& e) { return Rgb(e.properties == left ? 1.0 : 4.0); }));
    int onSeamLow = 0, onSeamHigh = 0;
    for (size_t v = 0; v < mesh.vertexCount(); ++v) {
        if (std::abs(mesh.positions[v].x - 1.0f) > 1e-6f)
            continue;
        EXPECT_TRUE(mesh.radiosity[v].x == 1.0f || mesh.radiosity[v].x == 4.0f) << mesh.radiosity[v].x;
        (mesh.radiosity[v].x == 1.0f ? onSeamLow : onSeamHigh)++;
    }
    EXPECT_GT(onSeamLow, 1);
    EXPECT_EQ(onSeamLow, onSeamHigh);
}

TEST(VertexRadiosity, LampSetIntoACeilingOfEqualReflectanceKeepsItsBorder)
{
    model::Scene scene;
    addMaterial(scene, "white", {0.7, 0.7, 0.7});
    addMaterial(scene, "lamp", {0.7, 0.7, 0.7}, {20.0, 20.0, 20.0});
    addFloor(scene, "ceiling", 0, 1, 0, 1, "white");
    addFloor(scene, "lamp", 1, 2, 0, 1, "lamp");
    const PreparedScene prepared = prepare(scene, 0.25);
    const int ceiling = faceIndex(prepared, "ceiling.face");
    const LitMesh mesh = smoothLitMesh(
        prepared, elementValues(prepared, [&](const Element& e) { return Rgb(e.properties == ceiling ? 1.0 : 20.0); }));
    for (const glm::vec3& r : mesh.radiosity)
        EXPECT_TRUE(r.x == 1.0f || r.x == 20.0f) << r.x;
}

TEST(VertexRadiosity, TouchingFacesOfOnePlaneAndMaterialShareTheirSeam)
{
    model::Scene scene;
    addMaterial(scene, "grey", {0.5, 0.5, 0.5});
    addFloor(scene, "left", 0, 1, 0, 1, "grey");
    addFloor(scene, "right", 1, 2, 0, 1, "grey");
    const PreparedScene prepared = prepare(scene, 0.25);
    const int left = faceIndex(prepared, "left.face");
    const LitMesh mesh = smoothLitMesh(
        prepared, elementValues(prepared, [&](const Element& e) { return Rgb(e.properties == left ? 1.0 : 4.0); }));
    int onSeam = 0;
    for (size_t v = 0; v < mesh.vertexCount(); ++v) {
        if (std::abs(mesh.positions[v].x - 1.0f) > 1e-6f)
            continue;
        ++onSeam;
        EXPECT_GT(mesh.radiosity[v].x, 1.0f);
        EXPECT_LT(mesh.radiosity[v].x, 4.0f);
    }
    EXPECT_GT(onSeam, 1);
}

TEST(VertexRadiosity, PiecesMeetingWithTVerticesAreJoinedWithoutThem)
{
    const PreparedScene prepared = tJunctionFloor();
    const LitMesh flat = litMeshFromSolution(prepared, std::vector<Rgb>(prepared.elements.size(), Rgb(1.0)));
    const LitMesh mesh =
        smoothLitMesh(prepared, elementValues(prepared, [](const Element& e) { return ramp(e.centroid); }));
    EXPECT_FALSE(!checkLitMesh(mesh).ok());
    EXPECT_GT(mesh.triangleCount(), prepared.elements.size()) << "elements beside the seam were split at T-vertices";
    double boundaryLength = 0.0;
    for (const auto& [edge, uses] : edgeUses(mesh)) {
        EXPECT_LE(uses, 2);
        if (uses == 1)
            boundaryLength += glm::length(mesh.positions[edge.first] - mesh.positions[edge.second]);
    }
    // Only the floor's outline is open: every inner edge is shared by two.
    EXPECT_NEAR(boundaryLength, 8.0, 1e-4);
    EXPECT_EQ(hangingVertices(mesh), 0);
    EXPECT_GT(hangingVertices(flat), 0) << "the element mesh itself has T-vertices at the seam";
}

TEST(VertexRadiosity, TotalAreaIsPreserved)
{
    const PreparedScene prepared = tJunctionFloor();
    const LitMesh mesh = smoothLitMesh(prepared, std::vector<Rgb>(prepared.elements.size(), Rgb(1.0)));
    double area = 0.0;
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        EXPECT_GT(triangleArea(mesh, t), 0.0) << "no degenerate triangle";
        area += triangleArea(mesh, t);
    }
    EXPECT_NEAR(area, 3.0, 1e-5);
    EXPECT_NEAR(area, prepared.stats.area, 1e-5);
}

TEST(VertexRadiosity, OutputTrianglesFaceLikeTheirElements)
{
    const PreparedScene prepared = tJunctionFloor();
    const LitMesh mesh = smoothLitMesh(prepared, std::vector<Rgb>(prepared.elements.size(), Rgb(1.0)));
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        const glm::vec3 a = mesh.positions[mesh.indices[3 * t]], b = mesh.positions[mesh.indices[3 * t + 1]],
                        c = mesh.positions[mesh.indices[3 * t + 2]];
        EXPECT_GT(glm::dot(glm::cross(b - a, c - a), mesh.normals[mesh.indices[3 * t]]), 0.0f);
    }
}

TEST(VertexRadiosity, NeighbourSmoothingSoftensAShadowBorder)
{
    model::Scene scene;
    addMaterial(scene, "grey", {0.5, 0.5, 0.5});
    addFloor(scene, "floor", 0, 2, 0, 2, "grey");
    const PreparedScene prepared = prepare(scene, 0.25);
    const std::vector<Rgb> values =
        elementValues(prepared, [](const Element& e) { return Rgb(e.centroid.x < 1.0 ? 0.0 : 10.0); });
    SmoothingOptions smoothing;
    smoothing.neighbourPasses = 4;
    const LitMesh sharp = smoothLitMesh(prepared, values);
    const LitMesh soft = smoothLitMesh(prepared, values, smoothing);
    // A quarter metre into the shadow the default keeps it dark; smoothing bleeds light in.
    float sharpMax = 0.0f, softMax = 0.0f;
    for (size_t v = 0; v < sharp.vertexCount(); ++v)
        if (sharp.positions[v].x < 0.75f)
            sharpMax = std::max(sharpMax, sharp.radiosity[v].x);
    for (size_t v = 0; v < soft.vertexCount(); ++v)
        if (soft.positions[v].x < 0.75f)
            softMax = std::max(softMax, soft.radiosity[v].x);
    EXPECT_EQ(sharpMax, 0.0f);
    EXPECT_GT(softMax, 0.0f);
}

TEST(VertexRadiosity, OutputChoiceGivesFlatOrSmoothMesh)
{
    const PreparedScene prepared = tJunctionFloor();
    const std::vector<Rgb> values(prepared.elements.size(), Rgb(2.0));
    const LitMesh flat = litMeshForOutput(prepared, values, false);
    const LitMesh smooth = litMeshForOutput(prepared, values, true);
    EXPECT_EQ(flat.vertexCount(), 3 * prepared.elements.size());
    EXPECT_LT(smooth.vertexCount(), flat.vertexCount());
    EXPECT_EQ(smooth.faceIds, flat.faceIds);
}

TEST(VertexRadiosity, WrongValueCountIsRefused)
{
    const PreparedScene prepared = tJunctionFloor();
    const std::vector<Rgb> values(prepared.elements.size() + 1, Rgb(2.0));
    EXPECT_THROW(smoothLitMesh(prepared, values), std::invalid_argument);
}

TEST(VertexRadiosity, FurnishedRoomOutputIsTVertexFreeAndKeepsItsArea)
{
    // Furniture planes split the floor, walls and each other into fragments
    // meshed independently: T-vertices everywhere in the element mesh.
    const PreparedScene prepared = prepare(test::furnishedRoom(7, 20), 0.5);
    const std::vector<Rgb> values = elementValues(prepared, [](const Element& e) { return ramp(e.centroid); });
    const auto start = std::chrono::steady_clock::now();
    const LitMesh mesh = smoothLitMesh(prepared, values);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    RecordProperty("elements", static_cast<int>(prepared.elements.size()));
    RecordProperty("triangles", static_cast<int>(mesh.triangleCount()));
    RecordProperty("milliseconds", static_cast<int>(seconds * 1000.0));
    EXPECT_FALSE(!checkLitMesh(mesh).ok());
    EXPECT_GE(mesh.triangleCount(), prepared.elements.size());
    for (const auto& [edge, uses] : edgeUses(mesh))
        EXPECT_LE(uses, 2);
    EXPECT_EQ(hangingVertices(mesh), 0);
    double area = 0.0;
    for (size_t t = 0; t < mesh.triangleCount(); ++t)
        area += triangleArea(mesh, t);
    EXPECT_NEAR(area, prepared.stats.area, 1e-6 * prepared.stats.area);
}

// The preview shades every frame of a solve with one SmoothShading built for
// the mesh: shading other values must give what a fresh build gives.
TEST(SmoothShading, OneShadingServesEveryRadiosityOfItsMesh)
{
    const PreparedScene prepared = prepare(test::furnishedRoom(7, 20), 0.5);
    const std::vector<Rgb> first = elementValues(prepared, [](const Element& e) { return ramp(e.centroid); });
    const std::vector<Rgb> second =
        elementValues(prepared, [](const Element& e) { return Rgb(e.centroid.x < 4.0 ? 0.5 : 7.0, 1.0, 2.0); });
    SmoothingOptions averaging;
    averaging.extrapolateBoundary = false;
    SmoothingOptions smoothing;
    smoothing.neighbourPasses = 2;
    for (const SmoothingOptions& options : {SmoothingOptions{}, averaging, smoothing}) {
        const SmoothShading shading(prepared, options);
        EXPECT_EQ(shading.elementCount(), prepared.elements.size());
        LitMesh mesh = shading.litMesh(first);
        const LitMesh fresh = smoothLitMesh(prepared, first, options);
        EXPECT_EQ(mesh.positions, fresh.positions);
        EXPECT_EQ(mesh.indices, fresh.indices);
        EXPECT_EQ(mesh.triangleFace, fresh.triangleFace);
        EXPECT_EQ(mesh.radiosity, fresh.radiosity);
        shading.shade(second, mesh.radiosity);
        EXPECT_EQ(mesh.radiosity, smoothLitMesh(prepared, second, options).radiosity);
        EXPECT_EQ(mesh.radiosity, shading.litMesh(second).radiosity);
    }
}

TEST(SmoothShading, ShadingTheWrongValueCountIsRefused)
{
    const PreparedScene prepared = tJunctionFloor();
    const SmoothShading shading(prepared);
    std::vector<glm::vec3> out;
    EXPECT_THROW(shading.shade(std::vector<Rgb>(prepared.elements.size() - 1, Rgb(1.0)), out), std::invalid_argument);
}
