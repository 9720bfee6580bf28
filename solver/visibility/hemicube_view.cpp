#include "solver/visibility/hemicube_view.h"

namespace regio::solver {

std::optional<HemicubeView> renderHemicubeView(const PreparedScene& scene, int patch, int resolution,
                                               model::Visibility mode)
{
    if (patch < 0 || static_cast<size_t>(patch) >= scene.patches.size())
        return std::nullopt;
    HemicubeView view;
    view.patch = patch;
    view.hemicube = Hemicube(resolution);
    view.frame = shooterFrameOfPatch(scene, patch);
    Visibility visibility(scene, view.hemicube, mode);
    view.buffer = visibility.makeBuffer();
    view.buffer.clear();
    visibility.render(view.frame, view.buffer);

    std::vector<double> perItem(scene.elements.size() + kFirstElementItem, 0.0);
    view.buffer.accumulate(view.hemicube, perItem);
    view.escaped = perItem[kEmptyItem];
    view.blocked = perItem[kBlockerItem];
    view.formFactors.assign(perItem.begin() + kFirstElementItem, perItem.end());
    return view;
}

} // namespace regio::solver
