#pragma once
// Solves the preview tests run for a while, shared by the tests of what the
// preview does and those of how fast it does it (the *_timing_test.cpp files).
#include "support/sample_scenes.h"

namespace regio::test {

// A solve that runs for a while: normal settings and no convergence stop.
// Adaptive subdivision as the sample has it: the mesh grows from 14k to 55k
// elements in 8 rounds of 0.13 to 0.25 s while the tests run (a round stops
// at its next slice when cancelled: Stop inside rounds has tests of its own,
// bigRoundsRoom()).
inline model::Scene longSample(bool adaptive = true)
{
    model::Scene scene = loadSample("two-lights-room");
    scene.solver.maxIterations = 100000;
    scene.solver.convergence = 1e-9;
    scene.solver.patchSize = 0.3;
    scene.solver.adaptive.enabled = adaptive;
    return scene;
}

// Big refinement rounds (0.1 to 0.3 s each, 21k elements growing to 83k over
// 8 rounds) and no end of its own.
inline model::Scene bigRoundsRoom()
{
    model::Scene scene = loadSample("two-lights-room");
    scene.solver.elementsPerPatch = 16;
    scene.solver.adaptive.enabled = true;
    scene.solver.adaptive.threshold = 0.01;
    scene.solver.adaptive.minEdge = 0.01;
    scene.solver.adaptive.anchoring = true;
    scene.solver.maxIterations = 100000;
    scene.solver.convergence = 1e-9;
    return scene;
}

} // namespace regio::test
