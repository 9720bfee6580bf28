#pragma once
// The hemicube of one shooting patch as the shooter sees it (§5.6): the five
// faces of its item buffer, rendered with the same frame, projection and
// visibility (painter or z-buffer) that a shot of that patch uses, so that a
// tool can show what the form factors of that shot are made of. Nothing of
// the solver's state changes; the caller owns the scene for the duration.
#include "solver/prepare/prepared_scene.h"
#include "solver/visibility/hemicube.h"
#include "solver/visibility/hemicube_raster.h"
#include "solver/visibility/item_buffer.h"
#include "solver/visibility/visibility.h"

#include <optional>
#include <vector>

namespace regio::solver {

struct HemicubeView {
    int patch = -1;
    Hemicube hemicube{2};
    ShooterFrame frame;
    ItemBuffer buffer;
    // Form factor from the patch to every element (F_ij, summed delta form
    // factors of its pixels), and the fractions that hit nothing or back faces.
    std::vector<double> formFactors;
    double escaped = 0.0;
    double blocked = 0.0;
};

// Empty when `patch` is out of range. `resolution` as Hemicube (rounded up to even).
std::optional<HemicubeView> renderHemicubeView(const PreparedScene& scene, int patch, int resolution,
                                               model::Visibility mode);

} // namespace regio::solver
