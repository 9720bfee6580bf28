// Coplanar surfaces of opposite orientation share a BSP node, and inside it
// the painter's order decides which one a hemicube sees (Visibility::render):
// back faces of open parts first, then the receivers, then back faces of
// solids. A thin two-sided wall thus receives on both sides, while a face
// lying on a solid receives nothing where it touches it.
#include "solver/solver.h"
#include "support/sample_scenes.h"
#include "support/solver_test_scenes.h"

#include <gtest/gtest.h>

#include <map>
#include <string>

using namespace regio;
using namespace regio::solver;
using model::Vec3;

namespace {

std::map<std::string, FaceResult> solve(const model::Scene& scene, model::Visibility mode, double convergence = 2e-3)
{
    SolverOptions options;
    options.hemicube = 100;
    options.visibility = mode;
    options.maxIterations = 100000;
    options.convergence = convergence;
    options.adaptive = false; // what is painted where, on the mesh as meshed
    auto built = Solver::create(scene, options);
    EXPECT_TRUE(built.ok()) << (built.diagnostics().empty() ? "" : built.diagnostics()[0].message);
    std::map<std::string, FaceResult> out;
    if (!built.ok())
        return out;
    std::atomic<bool> cancel{false};
    EXPECT_EQ((*built)->run({}, cancel), StopReason::Converged);
    for (FaceResult& f : (*built)->faceResults())
        out[f.id] = f;
    return out;
}

// A room 4 x 2.5 x 4 with a lamp in the middle of the ceiling and a wall of
// no thickness under it, in the plane x = 2 (so the scene is symmetric about
// that wall). `onePart`: the wall is one part with a face on each side;
// otherwise two one-face parts back to back.
model::Scene thinWallRoom(bool onePart)
{
    model::Scene scene;
    test::addMaterial(scene, "grey", {0.6, 0.6, 0.6});
    test::addMaterial(scene, "lamp", {0.5, 0.5, 0.5}, {20.0, 20.0, 20.0});
    test::addBox(scene, "room", {0, 0, 0}, {4, 2.5, 4}, "grey", true);
    const double ly = 2.45;
    test::addPolygon(scene, "lamp", {{1.5, ly, 1.5}, {2.5, ly, 1.5}, {2.5, ly, 2.5}, {1.5, ly, 2.5}}, "lamp");
    const std::vector<Vec3> px{{2, 0, 1}, {2, 1.5, 1}, {2, 1.5, 3}, {2, 0, 3}}; // normal +x
    if (onePart) {
        model::Part part;
        part.id = "wall.part";
        part.material = "grey";
        part.vertices = px;
        part.faces.push_back({"wall.px", {0, 1, 2, 3}, ""});
        part.faces.push_back({"wall.nx", {3, 2, 1, 0}, ""});
        scene.objects.push_back({"wall", "", {part}});
    } else {
        test::addPolygon(scene, "wallA", px, "grey");
        test::addPolygon(scene, "wallB", {px[3], px[2], px[1], px[0]}, "grey");
    }
    scene.solver.patchSize = 0.25;
    scene.solver.elementsPerPatch = 1;
    return scene;
}

void expectBothSidesLit(const model::Scene& scene, const std::string& a, const std::string& b)
{
    for (model::Visibility mode : {model::Visibility::Painter, model::Visibility::ZBuffer}) {
        const auto faces = solve(scene, mode);
        const FaceResult& fa = faces.at(a);
        const FaceResult& fb = faces.at(b);
        for (int c = 0; c < 3; ++c) {
            // Lit from the lamp above (about 0.36 W/m^2; 0 if a side were blocked).
            EXPECT_GT(fa.radiosity[c], 0.1) << a << " " << model::visibilityName(mode);
            // The scene is symmetric about the wall: both sides alike.
            EXPECT_NEAR(fa.radiosity[c], fb.radiosity[c], 0.03 * fb.radiosity[c]) << model::visibilityName(mode);
        }
    }
}

} // namespace

TEST(CoplanarOrder, AThinTwoSidedWallOfOnePartReceivesOnBothSides)
{
    expectBothSidesLit(thinWallRoom(true), "wall.px", "wall.nx");
}

TEST(CoplanarOrder, TwoOneSidedWallsBackToBackReceiveOnBothSides)
{
    expectBothSidesLit(thinWallRoom(false), "wallA.face", "wallB.face");
}

TEST(CoplanarOrder, ABoxStandingOnABoxLeavesNoLightOnTheFacesThatTouch)
{
    // The two-light sample's small box stands on the big one: its bottom
    // faces into the big box everywhere, and shooters inside the big box's
    // footprint (floor patches whose centre lies under it) must not light it.
    const model::Scene scene = test::loadSample("two-lights-room");
    const auto faces = solve(scene, model::Visibility::Painter, 5e-3);
    const FaceResult& bottom = faces.at("boxes.small.ny");
    EXPECT_GT(bottom.area, 0.0);
    for (int c = 0; c < 3; ++c)
        EXPECT_EQ(bottom.radiosity[c], 0.0) << "channel " << c;
    EXPECT_GT(faces.at("boxes.small.py").radiosity[0], 0.1) << "the box itself is lit";
}

TEST(CoplanarOrder, AFaceOnASolidIsLeftOutWhereItTouchesAndLitElsewhere)
{
    // A plate lying on a box and overhanging it: where the two touch, neither
    // is meshed (solver/prepare/covered_parts.h); the plate's bottom is lit
    // from below where it overhangs.
    model::Scene scene;
    test::addMaterial(scene, "grey", {0.6, 0.6, 0.6});
    test::addMaterial(scene, "lamp", {0.5, 0.5, 0.5}, {20.0, 20.0, 20.0});
    test::addBox(scene, "room", {0, 0, 0}, {4, 2.5, 4}, "grey", true);
    test::addPolygon(scene, "lamp", {{1.5, 2.45, 1.5}, {2.5, 2.45, 1.5}, {2.5, 2.45, 2.5}, {1.5, 2.45, 2.5}}, "lamp");
    test::addBox(scene, "block", {1.5, 0, 1.5}, {2.5, 1.0, 2.5}, "grey");
    // The plate's bottom covers the block's top and 0.5 m around it.
    test::addBox(scene, "plate", {1.0, 1.0, 1.0}, {3.0, 1.05, 3.0}, "grey");
    scene.solver.patchSize = 0.25;
    scene.solver.elementsPerPatch = 1;
    SolverOptions options;
    options.hemicube = 100;
    options.maxIterations = 100000;
    options.convergence = 2e-3;
    options.adaptive = false; // the 0.25 m mesh stays aligned to the contact square
    auto built = Solver::create(scene, options);
    ASSERT_TRUE(built.ok());
    std::atomic<bool> cancel{false};
    ASSERT_EQ((*built)->run({}, cancel), StopReason::Converged);
    const SolutionSnapshot snap = (*built)->snapshot();
    const PreparedScene& p = (*built)->prepared();
    double inside = 0.0, outside = 0.0;
    int insideCount = 0, outsideCount = 0;
    for (const InputFace& f : p.faces) {
        if (f.id != "plate.body.ny" && f.id != "block.body.py")
            continue;
        for (int e : f.elements) {
            const Vec3 c = p.elements[size_t(e)].centroid;
            const bool over = c.x > 1.5 && c.x < 2.5 && c.z > 1.5 && c.z < 2.5;
            // Elements inside the contact square.
            if (over) {
                inside += snap.radiosity[size_t(e)].g;
                ++insideCount;
            } else if (f.id == "plate.body.ny") {
                outside += snap.radiosity[size_t(e)].g;
                ++outsideCount;
            }
        }
    }
    EXPECT_EQ(insideCount, 0) << "the contact square is covered on both faces";
    EXPECT_EQ(inside, 0.0);
    ASSERT_GT(outsideCount, 0);
    EXPECT_GT(outside / outsideCount, 0.05) << "the overhang is lit from the floor";
}
