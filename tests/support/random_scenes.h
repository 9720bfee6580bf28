#pragma once
// Test scenes for the preparation tests: a room split into authored regions,
// with random boxes standing in each region's cell.
#include "model/geometry/primitives.h"
#include "model/scene.h"

#include <random>
#include <string>

namespace regio::test {

// A room [0, size] with `cellsX` x `cellsZ` regions tiling it on the floor
// plan, and `boxesPerCell` random boxes inside each cell (kept clear of the
// cell walls, so no box crosses a separating plane). Region bspOrders list the
// cell's boxes' top faces first.
inline model::Scene roomWithRegions(unsigned seed, int cellsX, int cellsZ, int boxesPerCell,
                                    model::Vec3 size = {6.0, 3.0, 4.0}, double patchSize = 0.5)
{
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    model::Scene scene;
    scene.materials.push_back({"white", "", {0.7, 0.7, 0.7}, {0, 0, 0}});
    scene.materials.push_back({"lamp", "", {0.8, 0.8, 0.8}, {10, 10, 10}});
    scene.solver.patchSize = patchSize;
    scene.solver.elementsPerPatch = 4;

    model::Object room{"room", "", {*model::makeRoom("room.shell", {0, 0, 0}, size, "white")}};
    scene.objects.push_back(room);
    model::Object lamp{"lamp",
                       "",
                       {*model::makeBox("lamp.panel", {size.x * 0.4, size.y - 0.05, size.z * 0.4},
                                        {size.x * 0.6, size.y - 0.01, size.z * 0.6}, "lamp")}};
    scene.objects.push_back(lamp);

    const double cellX = size.x / cellsX, cellZ = size.z / cellsZ;
    int count = 0;
    for (int i = 0; i < cellsX; ++i)
        for (int k = 0; k < cellsZ; ++k) {
            model::Region region;
            region.id = "cell-" + std::to_string(i) + "-" + std::to_string(k);
            region.min = {i * cellX, 0.0, k * cellZ};
            region.max = {(i + 1) * cellX, size.y, (k + 1) * cellZ};
            for (int b = 0; b < boxesPerCell; ++b) {
                const double w = 0.2 + 0.3 * unit(random) * cellX, d = 0.2 + 0.3 * unit(random) * cellZ;
                const double h = 0.2 + 1.2 * unit(random);
                const double x = region.min.x + 0.05 + unit(random) * (cellX - w - 0.1);
                const double z = region.min.z + 0.05 + unit(random) * (cellZ - d - 0.1);
                const double y = unit(random) < 0.3 ? 0.6 + unit(random) : 0.0; // some float (tables, shelves)
                const std::string id = "box" + std::to_string(++count);
                model::Object object{
                    id, "", {*model::makeBox(id + ".body", {x, y, z}, {x + w, y + h, z + d}, "white")}};
                scene.objects.push_back(object);
                region.bspOrder.push_back(id + ".body.py");
            }
            scene.regions.push_back(region);
        }
    return scene;
}

} // namespace regio::test
