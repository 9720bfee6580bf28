#pragma once
// A generated test scene: a room with `count` objects standing on its floor
// (boxes, prisms and tables of a desk and four legs, the paper's whole-part
// table) and two ceiling lamps, laid out deterministically from a seed. No
// footprints overlap (a clearance is kept between them), so the scene is
// valid, but the layout is irregular: nothing lines up on a grid.
//
// Random numbers come from std::mt19937's raw output (its sequence is fixed
// by the standard), not from the library's distributions (whose algorithms
// differ between standard libraries), so every platform builds the same scene.
#include "model/geometry/primitives.h"
#include "model/scene.h"

#include <algorithm>
#include <random>
#include <string>
#include <vector>

namespace regio::test {

struct FurnishedRoomCounts {
    int boxes = 0;
    int prisms = 0;
    int tables = 0;
};

inline model::Scene furnishedRoom(unsigned seed, int count = 100, model::Vec3 size = {16.0, 3.0, 12.0},
                                  FurnishedRoomCounts* counts = nullptr)
{
    std::mt19937 random(seed);
    auto unit = [&] { return (double(random()) + 0.5) / 4294967296.0; };
    auto between = [&](double a, double b) { return a + (b - a) * unit(); };

    model::Scene scene;
    scene.materials.push_back({"wall", "", {0.7, 0.7, 0.68}, {0, 0, 0}});
    scene.materials.push_back({"wood", "", {0.55, 0.4, 0.25}, {0, 0, 0}});
    scene.materials.push_back({"grey", "", {0.5, 0.5, 0.5}, {0, 0, 0}});
    scene.materials.push_back({"lamp", "", {0.8, 0.8, 0.8}, {12, 12, 11}});
    scene.solver.patchSize = 0.5;
    scene.solver.elementsPerPatch = 4;

    scene.objects.push_back({"room", "", {*model::makeRoom("room.shell", {0, 0, 0}, size, "wall")}});
    for (int i = 0; i < 2; ++i) {
        const double x = size.x * (i == 0 ? 0.3 : 0.7), z = size.z * 0.5;
        const std::string id = "lamp" + std::to_string(i + 1);
        scene.objects.push_back({id,
                                 "",
                                 {*model::makeBox(id + ".panel", {x - 0.5, size.y - 0.06, z - 0.5},
                                                  {x + 0.5, size.y - 0.02, z + 0.5}, "lamp")}});
    }

    struct Footprint {
        double x0, z0, x1, z1;
    };
    std::vector<Footprint> placed;
    const double clearance = 0.1, wall = 0.15;
    auto fits = [&](const Footprint& f) {
        if (f.x0 < wall || f.z0 < wall || f.x1 > size.x - wall || f.z1 > size.z - wall)
            return false;
        return std::none_of(placed.begin(), placed.end(), [&](const Footprint& o) {
            return f.x0 < o.x1 + clearance && o.x0 < f.x1 + clearance && f.z0 < o.z1 + clearance &&
                   o.z0 < f.z1 + clearance;
        });
    };

    FurnishedRoomCounts made;
    for (int n = 1; n <= count; ++n) {
        const double kind = unit();
        double scale = 1.0;
        for (int attempt = 0;; ++attempt) {
            if (attempt > 0 && attempt % 200 == 0)
                scale *= 0.8; // crowded: try smaller
            const std::string id = "object" + std::to_string(n);
            if (kind < 0.4) {
                const double w = between(0.3, 1.2) * scale, d = between(0.3, 1.2) * scale;
                const double h = between(0.3, 1.6);
                const double x = between(0.0, size.x - w), z = between(0.0, size.z - d);
                const Footprint f{x, z, x + w, z + d};
                if (!fits(f))
                    continue;
                placed.push_back(f);
                scene.objects.push_back(
                    {id, "", {*model::makeBox(id + ".body", {x, 0, z}, {x + w, h, z + d}, "grey")}});
                ++made.boxes;
            } else if (kind < 0.7) {
                const int sides = 3 + int(unit() * 6.0); // 3..8
                const double r = between(0.2, 0.6) * scale, h = between(0.3, 2.0);
                const double x = between(r, size.x - r), z = between(r, size.z - r);
                const Footprint f{x - r, z - r, x + r, z + r};
                if (!fits(f))
                    continue;
                placed.push_back(f);
                scene.objects.push_back({id, "", {*model::makePrism(id + ".body", sides, r, h, {x, 0, z}, "grey")}});
                ++made.prisms;
            } else {
                const double w = between(0.8, 1.8) * scale, d = between(0.6, 1.0) * scale;
                const double h = between(0.7, 0.8), top = 0.04, leg = 0.06;
                const double x = between(0.0, size.x - w), z = between(0.0, size.z - d);
                const Footprint f{x, z, x + w, z + d};
                if (!fits(f))
                    continue;
                placed.push_back(f);
                model::Object table{id, "", {}};
                table.parts.push_back(*model::makeBox(id + ".desk", {x, h - top, z}, {x + w, h, z + d}, "wood"));
                const double lx[2] = {x, x + w - leg}, lz[2] = {z, z + d - leg};
                for (int k = 0; k < 4; ++k)
                    table.parts.push_back(*model::makeBox(id + ".leg" + std::to_string(k + 1),
                                                          {lx[k & 1], 0, lz[k >> 1]},
                                                          {lx[k & 1] + leg, h - top, lz[k >> 1] + leg}, "wood"));
                scene.objects.push_back(std::move(table));
                ++made.tables;
            }
            break;
        }
    }
    if (counts)
        *counts = made;
    return scene;
}

} // namespace regio::test
