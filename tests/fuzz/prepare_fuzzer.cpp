// libFuzzer harness: scenes built from the input bytes, aimed at the
// solver's geometry (paper §5.2-§5.6): boxes, wedges and thin slabs on a
// coarse grid so that they touch, stack coplanar and overlap; a box stands
// on another's top; slivers; huge and tiny scales; a lamp; regions whose
// planes lie on faces; BSP orders of any faces. Every scene the validator
// accepts is prepared (regional tree, BSP trees, strips, pieces) and shot a
// few times; the energy books must balance.
#include "model/geometry/primitives.h"
#include "model/scene.h"
#include "model/validation/validation.h"
#include "solver/solver.h"

#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

namespace {

using namespace regio;

model::Vec3 gridPoint(FuzzedDataProvider& in, double cell)
{
    return {cell * in.ConsumeIntegralInRange<int>(-6, 6), cell * in.ConsumeIntegralInRange<int>(0, 6),
            cell * in.ConsumeIntegralInRange<int>(-6, 6)};
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    FuzzedDataProvider in(data, size);
    // One scale for the whole scene: millimetres to kilometres.
    static const double kScales[] = {1e-3, 0.05, 0.25, 1.0, 1.0, 1.0, 40.0, 1000.0};
    const double cell = kScales[in.ConsumeIntegralInRange<int>(0, 7)];

    model::Scene scene;
    scene.materials = {{"white", "", {0.7, 0.7, 0.7}, {0, 0, 0}}, {"lamp", "", {0, 0, 0}, {10, 10, 10}}};
    scene.solver.hemicube = 2 * in.ConsumeIntegralInRange<int>(2, 24);
    scene.solver.patchSize = cell * in.ConsumeIntegralInRange<int>(1, 8) / 2.0;
    scene.solver.elementsPerPatch = in.ConsumeIntegralInRange<int>(1, 9);
    scene.solver.adaptive.enabled = in.ConsumeBool();
    scene.solver.adaptive.minEdge = cell / 8.0;
    scene.solver.maxIterations = 6;

    const int solids = in.ConsumeIntegralInRange<int>(1, 6);
    for (int i = 0; i < solids && in.remaining_bytes() > 0; ++i) {
        const std::string id = "o" + std::to_string(i);
        model::Vec3 lo = gridPoint(in, cell);
        model::Vec3 hi =
            lo + model::Vec3(cell * in.ConsumeIntegralInRange<int>(1, 4), cell * in.ConsumeIntegralInRange<int>(1, 4),
                             cell * in.ConsumeIntegralInRange<int>(1, 4));
        switch (in.ConsumeIntegralInRange<int>(0, 4)) {
        case 0: hi.y = lo.y + cell * 1e-4; break; // a sliver slab
        case 1: lo.y = 0.0; break;                // standing on the floor plane
        case 2:
            if (!scene.objects.empty())
                lo.y = hi.y - cell;
            break; // stacked
        default: break;
        }
        const bool lamp = i == 0 || in.ConsumeIntegralInRange<int>(0, 5) == 0;
        const std::string material = lamp ? "lamp" : "white";
        model::Result<model::Part> part = in.ConsumeBool() ? model::makeWedge(id + ".p", lo, hi, material)
                                                           : model::makeBox(id + ".p", lo, hi, material);
        if (!part)
            continue;
        scene.objects.push_back({id, "", {std::move(*part)}});
    }
    if (in.ConsumeBool()) {
        // A room around it all, its walls facing in.
        model::Result<model::Part> room = model::makeRoom("room.p", model::Vec3(-7 * cell, -cell, -7 * cell),
                                                          model::Vec3(7 * cell, 8 * cell, 7 * cell), "white");
        if (room)
            scene.objects.push_back({"room", "", {std::move(*room)}});
    }
    const int regions = in.ConsumeIntegralInRange<int>(0, 3);
    for (int r = 0; r < regions; ++r) {
        // Regions split along grid planes, which is where faces lie.
        model::Region region;
        region.id = "r" + std::to_string(r);
        const int split = in.ConsumeIntegralInRange<int>(-6, 6);
        const int axis = in.ConsumeIntegralInRange<int>(0, 2);
        region.min = model::Vec3(-8 * cell, -2 * cell, -8 * cell);
        region.max = model::Vec3(8 * cell, 9 * cell, 8 * cell);
        (r % 2 == 0 ? region.max : region.min)[axis] = split * cell;
        std::vector<std::string> faces;
        for (const model::Object& o : scene.objects)
            for (const model::Face& f : o.parts[0].faces)
                faces.push_back(f.id);
        for (int k = in.ConsumeIntegralInRange<int>(0, 4); k > 0 && !faces.empty(); --k)
            region.bspOrder.push_back(faces[in.ConsumeIntegralInRange<std::size_t>(0, faces.size() - 1)]);
        scene.regions.push_back(std::move(region));
    }

    if (model::hasErrors(model::validateScene(scene)))
        return 0;
    solver::SolverOptions options;
    options.threads = 1;
    options.formFactorCacheBytes = 1 << 20;
    model::Result<std::unique_ptr<solver::Solver>> built = solver::Solver::create(scene, options);
    if (!built)
        return 0;
    (*built)->step(3);
    const solver::SolverStats stats = (*built)->stats();
    // Energy books (progressive shooting): emitted = absorbed + unshot + escaped.
    for (int c = 0; c < 3; ++c) {
        const double emitted = stats.energy.emitted[c];
        const double books = stats.energy.absorbed[c] + stats.energy.unshot[c] + stats.energy.escaped[c];
        if (!(std::abs(emitted - books) <= 1e-6 * std::max(1.0, std::abs(emitted))))
            std::abort();
    }
    return 0;
}
