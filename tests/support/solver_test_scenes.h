#pragma once
// Small scenes for the solver tests, built directly as model values: quads,
// boxes and rooms with chosen materials. Independent of the file format.
#include "model/scene.h"

#include <algorithm>
#include <array>
#include <random>
#include <string>
#include <vector>

namespace regio::test {

using model::Rgb;
using model::Scene;
using model::Vec3;

inline void addMaterial(Scene& scene, const std::string& id, Rgb reflectance, Rgb emission = Rgb{0.0})
{
    model::Material m;
    m.id = id;
    m.reflectance = reflectance;
    m.emission = emission;
    scene.materials.push_back(m);
}

// One object with one part holding one convex face; corners counter-clockwise
// seen from the side the face shall face. Ids: id, id + ".part", id + ".face".
inline void addPolygon(Scene& scene, const std::string& id, const std::vector<Vec3>& corners,
                       const std::string& material)
{
    model::Part part;
    part.id = id + ".part";
    part.material = material;
    part.vertices = corners;
    model::Face face;
    face.id = id + ".face";
    for (int i = 0; i < static_cast<int>(corners.size()); ++i)
        face.loop.push_back(i);
    part.faces.push_back(face);
    model::Object object;
    object.id = id;
    object.parts.push_back(part);
    scene.objects.push_back(object);
}

// An axis-aligned box part with the six faces ".nx", ".px", ".ny", ".py",
// ".nz", ".pz"; normals point out of the box, or into it when `inward`
// (a room). `skip` leaves out faces by suffix (an open box).
inline model::Part boxPart(const std::string& id, Vec3 lo, Vec3 hi, const std::string& material, bool inward,
                           const std::vector<std::string>& skip = {})
{
    model::Part part;
    part.id = id;
    part.material = material;
    for (int i = 0; i < 8; ++i)
        part.vertices.push_back({(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z});
    // Outward-wound loops of the six faces.
    const std::array<std::pair<const char*, std::array<int, 4>>, 6> faces{{
        {"nx", {0, 4, 6, 2}},
        {"px", {1, 3, 7, 5}},
        {"ny", {0, 1, 5, 4}},
        {"py", {2, 6, 7, 3}},
        {"nz", {0, 2, 3, 1}},
        {"pz", {4, 5, 7, 6}},
    }};
    for (const auto& [suffix, loop] : faces) {
        if (std::find(skip.begin(), skip.end(), suffix) != skip.end())
            continue;
        model::Face f;
        f.id = id + "." + suffix;
        f.loop.assign(loop.begin(), loop.end());
        if (inward)
            std::reverse(f.loop.begin(), f.loop.end());
        part.faces.push_back(f);
    }
    return part;
}

inline void addBox(Scene& scene, const std::string& id, Vec3 lo, Vec3 hi, const std::string& material,
                   bool inward = false, const std::vector<std::string>& skip = {})
{
    model::Object object;
    object.id = id;
    object.parts.push_back(boxPart(id + ".body", lo, hi, material, inward, skip));
    scene.objects.push_back(object);
}

inline void addRegion(Scene& scene, const std::string& id, Vec3 lo, Vec3 hi, std::vector<std::string> bspOrder = {})
{
    model::Region r;
    r.id = id;
    r.min = lo;
    r.max = hi;
    r.bspOrder = std::move(bspOrder);
    scene.regions.push_back(r);
}

// A room [0, 3 cols] x [0, 2.5] x [0, 3 rows] split into cols x rows regions,
// each holding a random box (random size and position inside its cell), a
// ceiling lamp in the first cell and random materials.
inline Scene randomRegionScene(unsigned seed, int cols = 2, int rows = 2)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Scene scene;
    addMaterial(scene, "wall", {0.7, 0.6, 0.5});
    addMaterial(scene, "lamp", {0.5, 0.5, 0.5}, {20.0, 18.0, 15.0});
    addMaterial(scene, "a", {0.2 + 0.6 * u(rng), 0.2 + 0.6 * u(rng), 0.2 + 0.6 * u(rng)});
    addMaterial(scene, "b", {0.2 + 0.6 * u(rng), 0.2 + 0.6 * u(rng), 0.2 + 0.6 * u(rng)});
    const double cell = 3.0, height = 2.5;
    addBox(scene, "room", {0, 0, 0}, {cell * cols, height, cell * rows}, "wall", true);
    for (int c = 0; c < cols; ++c)
        for (int r = 0; r < rows; ++r) {
            const std::string id = "box" + std::to_string(c) + std::to_string(r);
            const double sx = 0.4 + 1.2 * u(rng), sz = 0.4 + 1.2 * u(rng), sy = 0.3 + 1.5 * u(rng);
            const double x = c * cell + 0.2 + (cell - 0.4 - sx) * u(rng);
            const double z = r * cell + 0.2 + (cell - 0.4 - sz) * u(rng);
            const double y = u(rng) < 0.5 ? 0.0 : 0.3 * u(rng); // standing or floating
            addBox(scene, id, {x, y, z}, {x + sx, y + sy, z + sz}, (c + r) % 2 ? "a" : "b");
            addRegion(scene, "cell" + std::to_string(c) + std::to_string(r), {c * cell, -0.01, r * cell},
                      {(c + 1) * cell, height + 0.01, (r + 1) * cell}, {id + ".body.py"});
        }
    // A square lamp just below the ceiling of the first cell, facing down.
    const double ly = height - 0.05;
    addPolygon(scene, "lamp", {{1.0, ly, 1.0}, {2.0, ly, 1.0}, {2.0, ly, 2.0}, {1.0, ly, 2.0}}, "lamp");
    scene.solver.patchSize = 0.5;
    scene.solver.elementsPerPatch = 4;
    return scene;
}

// A room of 2 x 2 cells of 3 m, authored as one region per cell: the floor,
// ceiling and outer walls are cut at the cell borders, and one box of 1 m
// height stands in each cell, placed so that no box's planes cut another
// box (their x and z ranges are disjoint). The BSP orders list the room's
// faces, then the lamp; the boxes follow unlisted. So one BSP tree over
// everything and four regional trees split no face differently: the meshes
// are the same in both modes.
inline Scene conformingRegionScene()
{
    Scene scene;
    addMaterial(scene, "wall", {0.7, 0.65, 0.6});
    addMaterial(scene, "red", {0.6, 0.2, 0.15});
    addMaterial(scene, "blue", {0.15, 0.25, 0.6});
    addMaterial(scene, "lamp", {0.5, 0.5, 0.5}, {30.0, 28.0, 24.0});
    const double h = 2.5;
    // Boxes (x0, x1, z0, z1), pairwise disjoint in x and in z.
    const double boxes[4][4] = {{0.8, 1.8, 0.8, 1.8}, {2.0, 2.6, 3.3, 3.8}, {5.3, 5.8, 2.0, 2.6}, {3.9, 5.1, 4.0, 5.0}};
    for (int c = 0; c < 2; ++c)
        for (int r = 0; r < 2; ++r) {
            const std::string cell = std::to_string(c) + std::to_string(r);
            const double x0 = 3.0 * c, x1 = x0 + 3.0, z0 = 3.0 * r, z1 = z0 + 3.0;
            std::vector<std::string> order;
            auto quad = [&](const std::string& id, std::vector<Vec3> corners) {
                addPolygon(scene, id, corners, "wall");
                order.push_back(id + ".face");
            };
            quad("floor" + cell, {{x0, 0, z0}, {x0, 0, z1}, {x1, 0, z1}, {x1, 0, z0}});
            quad("ceiling" + cell, {{x0, h, z0}, {x1, h, z0}, {x1, h, z1}, {x0, h, z1}});
            if (c == 0)
                quad("west" + cell, {{0, 0, z0}, {0, h, z0}, {0, h, z1}, {0, 0, z1}});
            else
                quad("east" + cell, {{6, 0, z0}, {6, 0, z1}, {6, h, z1}, {6, h, z0}});
            if (r == 0)
                quad("south" + cell, {{x0, 0, 0}, {x1, 0, 0}, {x1, h, 0}, {x0, h, 0}});
            else
                quad("north" + cell, {{x0, 0, 6}, {x0, h, 6}, {x1, h, 6}, {x1, 0, 6}});
            if (c == 1 && r == 1) {
                // Listed after every room face of every cell (this is the last
                // region), so that its plane cuts no wall in the single tree either.
                const double ly = h - 0.05;
                addPolygon(scene, "lamp", {{4.0, ly, 4.0}, {5.0, ly, 4.0}, {5.0, ly, 5.0}, {4.0, ly, 5.0}}, "lamp");
                order.push_back("lamp.face");
            }
            const double* b = boxes[2 * c + r];
            const std::string box = "box" + cell;
            addBox(scene, box, {b[0], 0.0, b[2]}, {b[1], 1.0, b[3]}, (c + r) % 2 ? "red" : "blue");
            addRegion(scene, "cell" + cell, {x0, -0.01, z0}, {x1, h + 0.01, z1}, order);
        }
    scene.solver.patchSize = 0.5;
    scene.solver.elementsPerPatch = 4;
    return scene;
}

} // namespace regio::test
