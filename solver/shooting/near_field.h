#pragma once
// Receivers close to the shooter (paper §5.6, §7): the hemicube sees the
// scene from the shooter's centre, so among the elements a hand's width from
// a patch (a block's foot next to a floor patch) it shares the light by how
// they look from that one point, and the patch's elements all send alike.
// For such receivers the sharing is taken from Lambert's contour formula
// instead: the mean form factor from three points of the element to each
// element of the shooter (clipped to the front of the receiver's plane), so
// the shooter's elements send their own unshot radiosity where it lands.
//
// What the hemicube gave the near receivers in total is kept: each element
// of the shooter hands on exactly that share. A shot's factors still sum to
// the hemicube's, the energy books stay exact and a closed room closed; the
// hemicube also still decides which elements are seen at all.
#include "solver/prepare/prepared_scene.h"

#include <cstdint>
#include <vector>

namespace regio::solver {

// Form factor from a point with unit normal n to a convex polygon (the part
// in front of the point's plane), by Lambert's contour formula.
double pointToPolygonFormFactor(const Vec3& x, const Vec3& n, const std::vector<Vec3>& polygon);

// A near receiver's factor from one element of the shooter: the shooter's
// elements carry their own unshot radiosity, and this close the gradient
// across the shooter matters (a floor patch darker by the block's foot).
struct NearTerm {
    std::uint32_t entry = 0; // index into the row's elements / factors
    int shooterElement = 0;  // offset in the shooter's elements
    double factor = 0.0;     // F(shooter element -> receiver)
};

// For the `elements` whose centroid is closer to the shooter's centroid than
// the shooter's longest edge: sets their factor to 0 and appends their
// per-shooter-element factors to `near`, scaled so that every shooter
// element's near factors sum to the near elements' hemicube factors. Leaves
// the row as it is where the contour formula sees nothing from some element
// of the shooter.
void correctNearField(const PreparedScene& scene, int shooter, const std::vector<std::uint32_t>& elements,
                      std::vector<double>& factors, std::vector<NearTerm>& near);

} // namespace regio::solver
