// Adaptive subdivision with anchoring (solver/shooting/adaptive_subdivision.h, paper
// §5.7 and Figure 5): fine elements where the radiosity changes, a graded and
// conforming mesh, conserved area and unshot power, paintable pieces.
#include "solver/prepare/pieces.h"
#include "solver/prepare/prepare.h"
#include "solver/shooting/adaptive_subdivision.h"
#include "solver/shooting/shooting.h"
#include "support/adaptive_mesh_checks.h"
#include "support/sample_scenes.h"
#include "support/solver_test_scenes.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

using namespace regio;
using namespace regio::solver;
using model::Vec3;
using test::countTVertices;
using test::preparedFloor;
using test::shortestEdge;

namespace {

constexpr double kStepX = 1.3; // the shadow edge of the synthetic field
constexpr double kMinEdge = 0.06;
constexpr double kThreshold = 0.25;

// A 6 m x 3 m floor.
PreparedScene floorScene() { return preparedFloor({{"floor", {{0, 0, 0}, {6, 0, 0}, {6, 3, 0}, {0, 3, 0}}}}); }

// Lit on one side of x = kStepX, in shadow on the other.
Rgb stepField(const Vec3& p) { return p.x < kStepX ? Rgb{1.0, 0.9, 0.8} : Rgb{10.0, 9.0, 8.0}; }

std::vector<Rgb> sampleField(const PreparedScene& s)
{
    std::vector<Rgb> out;
    for (const Element& e : s.elements)
        out.push_back(stepField(e.centroid));
    return out;
}

// Subdivides by the criterion on the synthetic field until nothing is selected.
void refineOnField(AdaptiveMesh& mesh, double minEdge = kMinEdge)
{
    for (int pass = 0; pass < 12; ++pass) {
        const std::vector<int> selected =
            mesh.selectBySubdivisionCriterion(sampleField(mesh.scene()), kThreshold, minEdge);
        if (selected.empty())
            return;
        mesh.subdivide(selected, minEdge);
    }
    ADD_FAILURE() << "the subdivision did not settle";
}

AdaptiveMesh makeMesh(PreparedScene& s, bool anchoring)
{
    std::vector<Rgb> radiosity = sampleField(s);
    std::vector<Rgb> unshot;
    for (size_t i = 0; i < s.elements.size(); ++i)
        unshot.push_back(Rgb{0.1 + 0.01 * double(i % 7), 0.2, 0.05 * double(i % 3)});
    return AdaptiveMesh(s, std::move(radiosity), std::move(unshot), anchoring);
}

double triangleArea(const PreparedScene& s, const std::array<int, 3>& v)
{
    const Vec3 a = s.vertices[size_t(v[0])], b = s.vertices[size_t(v[1])], c = s.vertices[size_t(v[2])];
    return 0.5 * glm::length(glm::cross(b - a, c - a));
}

// Active elements sharing a piece of edge, found geometrically (all pairs).
bool shareEdgePart(const PreparedScene& s, const Element& x, const Element& y)
{
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const Vec3 a = s.vertices[size_t(x.vertices[size_t(i)])],
                       b = s.vertices[size_t(x.vertices[size_t((i + 1) % 3)])];
            const Vec3 c = s.vertices[size_t(y.vertices[size_t(j)])],
                       d = s.vertices[size_t(y.vertices[size_t((j + 1) % 3)])];
            const Vec3 ab = glm::normalize(b - a);
            const auto onLine = [&](const Vec3& p) { return glm::length(glm::cross(p - a, ab)) < 1e-9; };
            if (!onLine(c) || !onLine(d))
                continue;
            const double t0 = glm::dot(c - a, ab), t1 = glm::dot(d - a, ab), len = glm::length(b - a);
            const double lo = std::max(0.0, std::min(t0, t1)), hi = std::min(len, std::max(t0, t1));
            if (hi - lo > 1e-9)
                return true;
        }
    return false;
}

} // namespace

TEST(AdaptiveSubdivision, AShadowStepGetsFineElementsAlongItAndNoneOnTheFlatPart)
{
    PreparedScene s = floorScene();
    AdaptiveMesh mesh = makeMesh(s, true);
    refineOnField(mesh);
    int fineAtStep = 0;
    for (int e : mesh.activeElements()) {
        const Element& el = s.elements[size_t(e)];
        double lo = 1e300, hi = -1e300;
        for (int v : el.vertices) {
            lo = std::min(lo, s.vertices[size_t(v)].x);
            hi = std::max(hi, s.vertices[size_t(v)].x);
        }
        const int level = mesh.hierarchy()[size_t(e)].level;
        if (lo < kStepX && hi > kStepX) {
            // Straddling the step: split until minEdge stops it.
            EXPECT_FALSE(mesh.canSplit(e, kMinEdge)) << "element " << e << " on the step could still be split";
            EXPECT_GE(level, 3);
            ++fineAtStep;
        }
        if (el.centroid.x > kStepX + 2.0 || el.centroid.x < kStepX - 2.0) {
            EXPECT_EQ(level, 0) << "element at x = " << el.centroid.x << " on the flat part was split";
        }
    }
    EXPECT_GT(fineAtStep, 10);
}

TEST(AdaptiveSubdivision, NoElementGetsAnEdgeShorterThanMinEdge)
{
    for (double minEdge : {0.06, 0.2}) {
        PreparedScene s = floorScene();
        AdaptiveMesh mesh = makeMesh(s, true);
        refineOnField(mesh, minEdge);
        int maxLevel = 0;
        for (int e : mesh.activeElements()) {
            EXPECT_GE(shortestEdge(s, s.elements[size_t(e)]), minEdge * (1 - 1e-9));
            maxLevel = std::max(maxLevel, mesh.hierarchy()[size_t(e)].level);
        }
        EXPECT_GT(maxLevel, 0);
        for (int e : mesh.activeElements())
            if (shortestEdge(s, s.elements[size_t(e)]) < 2 * minEdge) {
                EXPECT_TRUE(mesh.split(e, minEdge).empty()) << "a split below minEdge was not refused";
            }
    }
}

TEST(AdaptiveSubdivision, ANonPositiveMinEdgeIsRejectedInsteadOfRefiningWithoutEnd)
{
    PreparedScene s = floorScene();
    AdaptiveMesh mesh = makeMesh(s, true);
    const size_t before = s.elements.size();
    EXPECT_THROW(mesh.split(0, 0.0), std::invalid_argument);
    EXPECT_THROW(mesh.selectBySubdivisionCriterion(sampleField(s), kThreshold, -1.0), std::invalid_argument);
    EXPECT_EQ(s.elements.size(), before);
}

TEST(AdaptiveSubdivision, WithAnchoringTheOutputHasNoTVerticesAndTheGradingIsTwoToOne)
{
    PreparedScene s = floorScene();
    AdaptiveMesh mesh = makeMesh(s, true);
    refineOnField(mesh);
    const std::vector<OutputTriangle> out = mesh.outputTriangles();
    EXPECT_EQ(countTVertices(s, out), 0);
    // Some coarse elements were anchored through T-vertices, as one unit each.
    int anchored = 0;
    for (int e : mesh.activeElements()) {
        anchored += mesh.tVertices(e).empty() ? 0 : 1;
        EXPECT_LE(mesh.tVertices(e).size(), 2u) << "elements with three midpoints are split";
        for (int n : mesh.neighbours(e))
            EXPECT_LE(std::abs(mesh.hierarchy()[size_t(e)].level - mesh.hierarchy()[size_t(n)].level), 1);
    }
    EXPECT_GT(anchored, 0);
    // Topologically conforming: every interior output edge has exactly one
    // triangle on each side, boundary edges lie on the floor's outline.
    std::map<std::pair<int, int>, int> directed;
    for (const OutputTriangle& t : out)
        for (int k = 0; k < 3; ++k)
            ++directed[{t.vertices[size_t(k)], t.vertices[size_t((k + 1) % 3)]}];
    for (const auto& [edge, count] : directed) {
        EXPECT_EQ(count, 1);
        if (!directed.count({edge.second, edge.first})) {
            const Vec3 a = s.vertices[size_t(edge.first)], b = s.vertices[size_t(edge.second)];
            const bool onOutline =
                (a.x == 0 && b.x == 0) || (a.x == 6 && b.x == 6) || (a.y == 0 && b.y == 0) || (a.y == 3 && b.y == 3);
            EXPECT_TRUE(onOutline) << "open edge inside the floor";
        }
    }
}

TEST(AdaptiveSubdivision, WithoutAnchoringTVerticesRemainAndNoGradingSplitIsMade)
{
    PreparedScene s = floorScene();
    AdaptiveMesh mesh = makeMesh(s, false);
    refineOnField(mesh);
    EXPECT_GT(countTVertices(s, mesh.outputTriangles()), 0);
    PreparedScene graded = floorScene();
    AdaptiveMesh anchored = makeMesh(graded, true);
    refineOnField(anchored);
    EXPECT_LT(mesh.activeElements().size(), anchored.activeElements().size());
}

TEST(AdaptiveSubdivision, OutputTrianglesCoverEachElementExactlyOnce)
{
    PreparedScene s = floorScene();
    AdaptiveMesh mesh = makeMesh(s, true);
    refineOnField(mesh);
    std::map<int, double> covered;
    for (const OutputTriangle& t : mesh.outputTriangles()) {
        EXPECT_GT(triangleArea(s, t.vertices), 1e-12) << "degenerate output triangle";
        const Vec3 n = glm::cross(s.vertices[size_t(t.vertices[1])] - s.vertices[size_t(t.vertices[0])],
                                  s.vertices[size_t(t.vertices[2])] - s.vertices[size_t(t.vertices[0])]);
        EXPECT_GT(glm::dot(n, s.elements[size_t(t.element)].normal), 0.0) << "output triangle not CCW";
        covered[t.element] += triangleArea(s, t.vertices);
    }
    EXPECT_EQ(covered.size(), mesh.activeElements().size());
    for (const auto& [e, area] : covered)
        EXPECT_NEAR(area, s.elements[size_t(e)].area, 1e-12 * s.elements[size_t(e)].area);
}

TEST(AdaptiveSubdivision, AreaAndUnshotPowerAreConservedAndRadiosityKeepsTheParentsMean)
{
    PreparedScene s = floorScene();
    AdaptiveMesh mesh = makeMesh(s, true);
    const auto totals = [&] {
        double area = 0.0;
        Rgb power{0.0};
        for (int e : mesh.activeElements()) {
            area += s.elements[size_t(e)].area;
            power += mesh.unshot()[size_t(e)] * s.elements[size_t(e)].area;
        }
        return std::make_pair(area, power);
    };
    const auto [area0, power0] = totals();
    refineOnField(mesh);
    const auto [area1, power1] = totals();
    EXPECT_NEAR(area1, area0, 1e-12 * area0);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(power1[c], power0[c], 1e-12 * power0[c]);
    for (size_t e = 0; e < mesh.hierarchy().size(); ++e) {
        const ElementLevel& node = mesh.hierarchy()[e];
        if (node.active())
            continue;
        Rgb mean{0.0};
        for (int child : node.children) {
            mean += mesh.radiosity()[size_t(child)] * s.elements[size_t(child)].area;
            for (int c = 0; c < 3; ++c)
                EXPECT_GE(mesh.radiosity()[size_t(child)][c], 0.0);
        }
        mean /= s.elements[e].area;
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(mean[c], mesh.radiosity()[e][c], 1e-12 * std::max(1.0, mesh.radiosity()[e][c]));
    }
}

TEST(AdaptiveSubdivision, ChildrenInterpolateTowardsTheBrighterNeighbour)
{
    PreparedScene s = floorScene();
    AdaptiveMesh mesh = makeMesh(s, false);
    // An element in the shadow next to a lit one: its children nearer the lit
    // side get more than those on the far side.
    int e = -1;
    for (int i : mesh.activeElements())
        if (s.elements[size_t(i)].centroid.x < kStepX)
            for (int n : mesh.neighbours(i))
                if (s.elements[size_t(n)].centroid.x > kStepX)
                    e = i;
    ASSERT_GE(e, 0);
    ASSERT_EQ(mesh.split(e, kMinEdge).size(), 1u);
    double lo = 1e300, hi = -1e300;
    for (int child : mesh.hierarchy()[size_t(e)].children) {
        lo = std::min(lo, mesh.radiosity()[size_t(child)].x);
        hi = std::max(hi, mesh.radiosity()[size_t(child)].x);
    }
    EXPECT_GT(hi, lo);
}

TEST(AdaptiveSubdivision, AParentAtOrSlightlyBelowZeroGivesFiniteChildrenWithItsValue)
{
    // Shooting can leave a channel a rounding hair below zero; the children's
    // gradient scaling must not divide by zero there.
    PreparedScene s = floorScene();
    std::vector<Rgb> radiosity(s.elements.size(), Rgb{0.0, -1e-18, 0.0});
    radiosity[1] = Rgb{5.0, 4.0, 3.0}; // a bright neighbour somewhere
    AdaptiveMesh mesh(s, radiosity, std::vector<Rgb>(s.elements.size(), Rgb{0.0}), false);
    for (int e : mesh.activeElements())
        if (e != 1 && mesh.canSplit(e, kMinEdge))
            mesh.split(e, kMinEdge);
    for (int e : mesh.activeElements()) {
        const Rgb& b = mesh.radiosity()[size_t(e)];
        EXPECT_TRUE(std::isfinite(b.x) && std::isfinite(b.y) && std::isfinite(b.z)) << "element " << e;
        if (mesh.hierarchy()[size_t(e)].parent >= 0 && mesh.hierarchy()[size_t(e)].parent != 1) {
            EXPECT_EQ(b.x, 0.0);
            EXPECT_EQ(b.y, -1e-18);
        }
    }
}

TEST(AdaptiveSubdivision, MidpointsAreSharedWithTheNeighbourAcrossTheEdge)
{
    PreparedScene s = floorScene();
    AdaptiveMesh mesh = makeMesh(s, false);
    // An inner edge: one neighbour across it.
    int e = -1;
    std::vector<int> across;
    for (int i : mesh.activeElements())
        if (across.empty()) {
            across = mesh.neighboursAcross(i, 0);
            e = i;
        }
    ASSERT_EQ(across.size(), 1u);
    const size_t verticesBefore = s.vertices.size();
    mesh.split(e, kMinEdge);
    EXPECT_EQ(s.vertices.size(), verticesBefore + 3);
    const std::vector<int> tv = mesh.tVertices(across.front());
    ASSERT_EQ(tv.size(), 1u);
    mesh.split(across.front(), kMinEdge);
    EXPECT_EQ(s.vertices.size(), verticesBefore + 5) << "the shared midpoint was created twice";
    // The midpoint is a corner of three children on each side (two corner
    // children and the centre one).
    int users = 0;
    for (int a : mesh.activeElements())
        for (int v : s.elements[size_t(a)].vertices)
            users += v == tv.front() ? 1 : 0;
    EXPECT_EQ(users, 6);
}

TEST(AdaptiveSubdivision, NeighbourLookupThroughTheEdgeMapAgreesWithGeometry)
{
    PreparedScene s = floorScene();
    AdaptiveMesh mesh = makeMesh(s, false);
    refineOnField(mesh);
    const std::vector<int> active = mesh.activeElements();
    for (int e : active) {
        std::vector<int> found = mesh.neighbours(e);
        std::vector<int> expected;
        for (int o : active)
            if (o != e && shareEdgePart(s, s.elements[size_t(e)], s.elements[size_t(o)]))
                expected.push_back(o);
        std::sort(found.begin(), found.end());
        EXPECT_EQ(found, expected) << "element " << e;
    }
}

TEST(AdaptiveSubdivision, FacesListTheirActiveLeavesAndParentsBecomeInactive)
{
    PreparedScene s = floorScene();
    AdaptiveMesh mesh = makeMesh(s, true);
    refineOnField(mesh);
    std::vector<int> listed = s.faces[0].elements;
    std::sort(listed.begin(), listed.end());
    EXPECT_EQ(listed, mesh.activeElements());
    for (size_t e = 0; e < mesh.hierarchy().size(); ++e) {
        const ElementLevel& node = mesh.hierarchy()[e];
        if (node.parent >= 0) {
            EXPECT_FALSE(mesh.isActive(node.parent));
            EXPECT_EQ(node.level, mesh.hierarchy()[size_t(node.parent)].level + 1);
            EXPECT_EQ(s.elements[e].patch, s.elements[size_t(node.parent)].patch);
        }
    }
}

namespace {

struct GrownScene {
    std::string name;
    PreparedScene scene;
};

// Sample scenes (faces split by regions and BSP planes) with a diagonal
// shadow-like step over every face, refined by the §5.7 rounds.
std::vector<GrownScene> grownSamples(bool anchoring, std::vector<AdaptiveMesh>* meshes = nullptr)
{
    std::vector<std::pair<std::string, model::Scene>> inputs{{"cornell-box", test::loadSample("cornell-box")},
                                                             {"two-lights-room", test::loadSample("two-lights-room")},
                                                             {"random 3", test::randomRegionScene(3, 2, 2)}};
    std::vector<GrownScene> out;
    out.reserve(inputs.size());
    for (auto& [name, scene] : inputs) {
        EXPECT_FALSE(scene.objects.empty()) << name;
        model::Result<PreparedScene> r = prepareScene(scene);
        EXPECT_TRUE(r.ok()) << name;
        if (!r.ok())
            continue;
        out.push_back({name, std::move(*r)});
    }
    for (GrownScene& g : out) {
        PreparedScene& s = g.scene;
        const double step = 0.5 * (s.bounds.min.x + s.bounds.max.x + s.bounds.min.y + s.bounds.max.y);
        const auto field = [&] {
            std::vector<Rgb> r;
            for (const Element& e : s.elements)
                r.push_back(e.centroid.x + e.centroid.y < step ? Rgb{0.2, 0.3, 0.1} : Rgb{2.0, 2.5, 1.0});
            return r;
        };
        AdaptiveMesh mesh(s, field(), std::vector<Rgb>(s.elements.size(), Rgb{0.3, 0.2, 0.1}), anchoring);
        model::AdaptiveSettings settings;
        settings.threshold = kThreshold;
        settings.minEdge = 0.3 * shortestEdge(s, s.elements.front());
        settings.anchoring = anchoring;
        int rounds = 0;
        while (mesh.refine(field(), settings) > 0)
            ++rounds;
        EXPECT_GE(rounds, 1) << g.name;
        if (meshes)
            meshes->push_back(std::move(mesh));
    }
    return out;
}

} // namespace

TEST(AdaptiveSubdivision, RefiningSampleScenesKeepsEveryFaceConformingAndGraded)
{
    std::vector<AdaptiveMesh> meshes;
    std::vector<GrownScene> grown = grownSamples(true, &meshes);
    ASSERT_EQ(grown.size(), meshes.size());
    for (size_t i = 0; i < grown.size(); ++i) {
        const AdaptiveMesh& mesh = meshes[i];
        EXPECT_EQ(countTVertices(grown[i].scene, mesh.outputTriangles()), 0) << grown[i].name;
        int maxLevel = 0, seamPairs = 0;
        for (int e : mesh.activeElements()) {
            maxLevel = std::max(maxLevel, mesh.hierarchy()[size_t(e)].level);
            for (int n : mesh.neighbours(e))
                EXPECT_LE(std::abs(mesh.hierarchy()[size_t(e)].level - mesh.hierarchy()[size_t(n)].level), 1)
                    << grown[i].name;
            // Across the seam of coplanar faces (the Cornell box's ceiling
            // tiles), by the lengths of the edges that meet there: no element
            // made by a split borders one more than twice its size. (The
            // initial meshes of two faces may differ more: a shelf board's
            // 2 cm front beside the shelf's side.)
            const PreparedScene& s = grown[i].scene;
            const auto corner = [&](int element, int k) {
                return s.vertices[size_t(s.elements[size_t(element)].vertices[size_t(k % 3)])];
            };
            if (mesh.hierarchy()[size_t(e)].level == 0)
                continue;
            for (int n : mesh.partners(e))
                for (int k = 0; k < 3; ++k)
                    for (int j = 0; j < 3; ++j)
                        if (collinearOverlap(corner(e, k), corner(e, k + 1), corner(n, j), corner(n, j + 1)) > 0.0) {
                            ++seamPairs;
                            EXPECT_LE(glm::length(corner(n, j + 1) - corner(n, j)),
                                      2.0 * glm::length(corner(e, k + 1) - corner(e, k)) * (1.0 + 1e-9))
                                << grown[i].name;
                        }
        }
        EXPECT_GE(maxLevel, 1) << grown[i].name;
        if (grown[i].name == "two-lights-room") { // its three floor faces
            EXPECT_GT(seamPairs, 0);
        }
    }
}

TEST(AdaptiveSubdivision, TheActiveSceneGroupsElementsByPatchAndItsPiecesCoverEveryElement)
{
    for (bool anchoring : {true, false}) {
        std::vector<AdaptiveMesh> meshes;
        std::vector<GrownScene> grown = grownSamples(anchoring, &meshes);
        for (size_t i = 0; i < grown.size(); ++i) {
            const AdaptiveMesh& mesh = meshes[i];
            const ActiveScene active = mesh.activeScene();
            const PreparedScene& a = active.scene;
            const std::string name = grown[i].name + (anchoring ? " anchored" : " not anchored");
            ASSERT_EQ(a.elements.size(), mesh.activeElements().size()) << name;
            EXPECT_GT(a.elements.size(), grown[i].scene.stats.elements) << name;
            EXPECT_EQ(a.stats.lostPieces, 0) << name;
            EXPECT_EQ(a.stats.lostPieceArea, 0.0) << name;
            for (size_t p = 0; p < a.patches.size(); ++p)
                for (int e = a.patches[p].firstElement; e < a.patches[p].firstElement + a.patches[p].elementCount; ++e)
                    EXPECT_EQ(a.elements[size_t(e)].patch, int(p)) << name;
            std::vector<double> pieceArea(a.elements.size(), 0.0);
            for (const Piece& piece : a.pieces) {
                const Vec3 p0 = a.pieceVertices[size_t(piece.vertices[0])],
                           p1 = a.pieceVertices[size_t(piece.vertices[1])],
                           p2 = a.pieceVertices[size_t(piece.vertices[2])];
                pieceArea[size_t(piece.element)] += 0.5 * glm::length(glm::cross(p1 - p0, p2 - p0));
            }
            for (size_t e = 0; e < a.elements.size(); ++e) {
                const double area = triangleArea(a, a.elements[e].vertices);
                EXPECT_NEAR(pieceArea[e], area, 1e-9 * area) << name << " element " << e;
                EXPECT_GE(a.elements[e].node, 0) << name;
                EXPECT_EQ(active.unshot[e], mesh.unshot()[size_t(active.sourceElement[e])]) << name;
                EXPECT_EQ(active.radiosity[e], mesh.radiosity()[size_t(active.sourceElement[e])]) << name;
            }
            size_t listed = 0;
            for (const InputFace& f : a.faces)
                listed += f.elements.size();
            EXPECT_EQ(listed, a.elements.size()) << name;
        }
    }
}

TEST(AdaptiveSubdivision, NeighbourLookupAgreesWithGeometryOnEveryFaceOfASampleScene)
{
    std::vector<AdaptiveMesh> meshes;
    std::vector<GrownScene> grown = grownSamples(false, &meshes);
    ASSERT_FALSE(grown.empty());
    const PreparedScene& s = grown[0].scene;
    const AdaptiveMesh& mesh = meshes[0];
    for (const InputFace& face : s.faces)
        for (int e : face.elements) {
            std::vector<int> found = mesh.neighbours(e);
            std::vector<int> expected;
            for (int o : face.elements)
                if (o != e && shareEdgePart(s, s.elements[size_t(e)], s.elements[size_t(o)]))
                    expected.push_back(o);
            std::sort(found.begin(), found.end());
            std::sort(expected.begin(), expected.end());
            EXPECT_EQ(found, expected) << grown[0].name << " element " << e;
        }
}

// The wiring a solver needs, end to end on the real shooter: shoot, grow the
// hierarchy, swap the scene the shooter refers to for the active scene, hand
// it the new state, shoot on. The energy books stay exact throughout.
TEST(AdaptiveSubdivision, ShootingOnTheGrownMeshKeepsTheEnergyBalanceExact)
{
    model::Scene room = test::loadSample("cornell-box");
    ASSERT_FALSE(room.objects.empty());
    room.solver.elementsPerPatch = 4; // elements of 5 cm: the 2 cm below allows splits
    model::Result<PreparedScene> r = prepareScene(room);
    ASSERT_TRUE(r.ok());
    PreparedScene shot = *r;                 // what the shooter sees (active leaves)
    PreparedScene hierarchy = std::move(*r); // grown by the AdaptiveMesh
    Shooting shooting(shot, 48, model::Visibility::Painter);
    for (int i = 0; i < 6; ++i)
        ASSERT_EQ(shooting.shoot(), ShotResult::Shot);

    const auto expectBalanced = [](const EnergyBalance& e, const char* when) {
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(e.absorbed[c] + e.unshot[c] + e.escaped[c], e.emitted[c], 1e-12 * e.emitted[c]) << when;
    };
    AdaptiveMesh mesh(hierarchy, shooting.radiosity(), shooting.unshotRadiosity(), true);
    model::AdaptiveSettings settings;
    settings.threshold = 0.3;
    settings.minEdge = 0.02;
    std::vector<int> source(shot.elements.size());
    for (size_t i = 0; i < source.size(); ++i)
        source[i] = int(i);
    for (int round = 0; round < 2; ++round) {
        const EnergyBalance before = shooting.energy();
        mesh.setActiveState(source, shooting.radiosity(), shooting.unshotRadiosity());
        ASSERT_GT(mesh.refine(mesh.radiosity(), settings), 0) << "round " << round;
        ActiveScene active = mesh.activeScene();
        EXPECT_EQ(active.scene.stats.lostPieces, 0);
        shot = std::move(active.scene);
        source = std::move(active.sourceElement);
        shooting.replaceElementState(std::move(active.radiosity), std::move(active.unshot));
        const EnergyBalance after = shooting.energy();
        for (int c = 0; c < 3; ++c) {
            EXPECT_EQ(after.emitted[c], before.emitted[c]);
            EXPECT_EQ(after.absorbed[c], before.absorbed[c]);
            EXPECT_NEAR(after.unshot[c], before.unshot[c], 1e-12 * before.emitted[c]) << "round " << round;
        }
        expectBalanced(after, "after growing the mesh");
        for (int i = 0; i < 4; ++i)
            ASSERT_EQ(shooting.shoot(), ShotResult::Shot);
        expectBalanced(shooting.energy(), "after shooting on the grown mesh");
    }
    EXPECT_GT(shot.elements.size(), hierarchy.stats.elements);
}

TEST(AdaptiveSubdivision, ElementsNearAShadowCornerMaySplitToHalfTheSmallestEdge)
{
    // A shadow corner on the step's border: within five minEdges of it
    // elements go down to half of minEdge, elsewhere along the border to
    // minEdge, and the mesh stays graded.
    PreparedScene s = floorScene();
    const Vec3 corner{kStepX, 1.5, 0.0};
    s.shadowCorners.push_back(corner);
    AdaptiveMesh mesh = makeMesh(s, true);
    refineOnField(mesh);
    double nearest = 1e300, elsewhere = 1e300;
    const auto near = [&](int e) {
        return glm::length(s.elements[size_t(e)].centroid - corner) < AdaptiveMesh::kShadowCornerReach * kMinEdge;
    };
    for (int e : mesh.activeElements()) {
        EXPECT_DOUBLE_EQ(mesh.smallestEdgeAt(e, kMinEdge),
                         near(e) ? AdaptiveMesh::kShadowCornerEdge * kMinEdge : kMinEdge);
        for (int n : mesh.neighbours(e))
            EXPECT_LE(std::abs(mesh.hierarchy()[size_t(e)].level - mesh.hierarchy()[size_t(n)].level), 1);
        // What a split made is judged by where its parent was.
        const int parent = mesh.hierarchy()[size_t(e)].parent;
        if (parent < 0)
            continue;
        double& shortest = near(parent) ? nearest : elsewhere;
        shortest = std::min(shortest, shortestEdge(s, s.elements[size_t(e)]));
    }
    EXPECT_LT(nearest, kMinEdge * (1.0 - 1e-9));
    EXPECT_GE(nearest, AdaptiveMesh::kShadowCornerEdge * kMinEdge * (1.0 - 1e-9));
    EXPECT_GE(elsewhere, kMinEdge * (1.0 - 1e-9));
}
