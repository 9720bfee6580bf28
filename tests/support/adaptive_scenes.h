#pragma once
// Scenes for the tests of adaptive subdivision driven by the solver.
#include "support/solver_test_scenes.h"

namespace regio::test {

// A room 3 x 2.5 x 4 with 0.25 m patches and a block 0.6 m across standing
// 0.2 m from its west wall ("room.body.nx"), its side "block.body.nx"
// facing it; closed.
inline model::Scene blockBesideWall()
{
    model::Scene scene;
    addMaterial(scene, "wall", Rgb{0.7});
    addBox(scene, "room", {0, 0, 0}, {3, 2.5, 4}, "wall", true);
    addBox(scene, "block", {0.2, 0, 1}, {0.8, 0.6, 1.6}, "wall");
    scene.solver.patchSize = 0.25;
    return scene;
}

// A 3 x 3 m floor, a 0.6 m box standing on it and a small lamp above, off to
// one side so the box casts a shadow across the floor. Open: what leaves the
// scene escapes.
inline model::Scene boxUnderLamp()
{
    model::Scene scene;
    addMaterial(scene, "grey", Rgb{0.5});
    addMaterial(scene, "lamp", Rgb{0.0}, Rgb{40.0});
    // Floor facing +y, lamp facing -y (corner order decides the side).
    addPolygon(scene, "floor", {{-1.5, 0.0, -1.5}, {-1.5, 0.0, 1.5}, {1.5, 0.0, 1.5}, {1.5, 0.0, -1.5}}, "grey");
    addBox(scene, "box", Vec3{-0.3, 0.0, -0.3}, Vec3{0.3, 0.6, 0.3}, "grey", false);
    addPolygon(scene, "lamp", {{-1.0, 1.5, -0.2}, {-0.6, 1.5, -0.2}, {-0.6, 1.5, 0.2}, {-1.0, 1.5, 0.2}}, "lamp");
    scene.solver.patchSize = 0.5;
    scene.solver.elementsPerPatch = 4;
    scene.solver.hemicube = 100;
    scene.solver.adaptive.enabled = true;
    scene.solver.adaptive.threshold = 0.3; // above the falloff between neighbours, below a shadow edge
    scene.solver.adaptive.minEdge = 0.04;
    return scene;
}

// A closed room (inward walls) with a block on the floor and a lamp under
// the ceiling: nothing can escape but through cracks.
inline model::Scene closedRoom()
{
    model::Scene scene;
    addMaterial(scene, "wall", {0.5, 0.6, 0.7});
    addMaterial(scene, "lamp", {0.5, 0.5, 0.5}, {5.0, 5.0, 5.0});
    addBox(scene, "room", {0, 0, 0}, {3, 2.5, 4}, "wall", true);
    addBox(scene, "block", {1, 0, 1}, {2, 1, 2}, "wall");
    addPolygon(scene, "lamp", {{1, 2.4, 1}, {2, 2.4, 1}, {2, 2.4, 2}, {1, 2.4, 2}}, "lamp");
    scene.solver.patchSize = 0.5;
    scene.solver.hemicube = 64;
    return scene;
}

// The closed room with adaptive subdivision on and 5 cm as the smallest
// edge: what the refinement splits before the first shot.
inline model::Scene closedRoomRefined()
{
    model::Scene scene = closedRoom();
    scene.solver.adaptive.enabled = true;
    scene.solver.adaptive.minEdge = 0.05;
    return scene;
}

} // namespace regio::test
