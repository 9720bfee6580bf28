#pragma once
// Receivers close to the shooter (paper §5.6, §7): the hemicube sees the
// scene from the shooter's centre, so among the elements a hand's width from
// a patch (a block's foot next to a floor patch) it shares the light by how
// they look from that one point, and the patch's elements all send alike.
// For such receivers the sharing is taken from Lambert's contour formula
// instead: the form factor between the element and each element of the
// shooter, taken on the smaller of the two (a ceiling element 35 cm across
// over a lamp element 12 cm across, 2 cm below it, sees that element from
// its centroid anywhere from not at all to filling its view), so the
// shooter's elements send their own unshot radiosity where it lands.
//
// The near receivers keep the contour formula's factors: the hemicube's
// total for them carries its proximity error (a floor patch's centre sees a
// block's foot at another angle than most of the patch does). What each
// element of the shooter gives them more or less than the hemicube saw
// comes out of its share for the far receivers (farScale), so that every
// element of the shooter still sends the hemicube's total: a shot's books
// stay exact and a closed room stays closed. The hemicube still decides
// which elements are seen at all.
//
// A receiver counts as near when its centroid lies within the shooter's
// longest edge of the shooter's centroid. Farther out, the hemicube's
// proximity error still shows where two faces stand in front of each other
// across a gap of a few patches (InputFace::facing,
// solver/prepare/facing_faces.h: a block's side 8-13 cm from a wall of 10 cm
// patches). A receiver on a face facing the shooter's, within kFacingReach
// times that edge, is near too, with other factors: the contour formula
// does not know what stands between, which out there may be something, so
// the hemicube's factor is kept as the share of the receiver that the
// shooter's centre sees (over the contour factor from that centre), times
// the whole shooter's contour factor, split among the shooter's elements by
// the point-to-point kernel so that each sends its own unshot radiosity.
#include "solver/prepare/prepared_scene.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace regio::solver {

// How much farther the near field reaches between facing faces.
inline constexpr double kFacingReach = 3.0;

// The most corners of a polygon that pointToPolygonFormFactor takes (it
// works without allocating: a row's near receivers call it often).
inline constexpr size_t kMaxContourCorners = 16;

// Form factor from a point with unit normal n to a convex polygon of at most
// kMaxContourCorners corners (the part in front of the point's plane), by
// Lambert's contour formula.
double pointToPolygonFormFactor(const Vec3& x, const Vec3& n, const std::vector<Vec3>& polygon);

// A near receiver's factor from one element of the shooter: the shooter's
// elements carry their own unshot radiosity, and this close the gradient
// across the shooter matters (a floor patch darker by the block's foot).
struct NearTerm {
    std::uint32_t entry = 0; // index into the row's elements / factors; a receiver's terms are consecutive
    int shooterElement = 0;  // offset in the shooter's elements
    double factor = 0.0;     // F(shooter element -> receiver)
};

// For the near `elements` (above): sets their factor to 0 and appends their
// per-shooter-element factors to `near`; sets farScale[s] (one per shooter
// element) so that shooter element s sends its near factors plus farScale[s]
// times the other elements' factors, exactly the row's total. Leaves the row
// as it is (and farScale empty) when no receiver is near or the contour
// formula sees none of them; when every receiver is near, farScale stays
// empty and each shooter element's near factors are scaled to the total.
//
// The contour formula takes most of the time; `parallelFor`, when given,
// runs body(begin, end) over chunk indices [0, count), each index once,
// perhaps on several threads. The row is the same, bit for bit, with or
// without it.
using ParallelFor = std::function<void(size_t count, const std::function<void(size_t begin, size_t end)>& body)>;
// seenShare(entry, s), when given, is the share of shooter element s that
// sees the near receiver elements[entry] (a patch behind a narrow face,
// shot from several points: shooter_points.h), which its contour factors
// are weighed by; without it a near receiver that the hemicube saw at all
// is seen by every element of the shooter.
using SeenShare = std::function<double(std::uint32_t entry, int shooterElement)>;
void correctNearField(const PreparedScene& scene, int shooter, const std::vector<std::uint32_t>& elements,
                      std::vector<double>& factors, std::vector<NearTerm>& near, std::vector<double>& farScale,
                      const ParallelFor& parallelFor = {}, const SeenShare& seenShare = {});

} // namespace regio::solver
