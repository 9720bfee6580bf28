#pragma once
// Patches that shoot out of a narrow gap (paper §5.6, §7: the hemicube sees
// the scene from one point of the shooter). A ceiling patch 0.5 m across
// over a lamp hung 2 cm below the ceiling sees the room only through the
// slit between the two. Almost all it sends goes to the lamp's top, which
// the near field takes from the contour formula (near_field.h); the rest
// leaves through the slit, and how much depends on the element: one at the
// lamp's rim sends a quarter of its light out, one over the middle a few
// thousandths. Each element's share is right (near_field.h gives every
// element of the shooter its own far share), but where it lands was the
// centre's view, and from the centre the slit is a thin row of pixels at
// the horizon that shows only the walls' top strip: the light of the rim's
// elements, which would light the walls far down, landed in a band along
// their top, 10 % to more than 50 % too bright over 15-20 cm.
//
// Such a patch renders its hemicube from several points instead: the
// centroids of the k x k equal triangles of its own triangle. Each element
// of the patch sends its far share through the view of the points inside
// it (or, when it is smaller than they are apart, of the nearest one), so
// the rim's light goes where the rim sees. The receivers and the near
// field come from the points' mean view; the books stay exact (each
// element sends what its points' hemicubes sum to). The rows are kept like
// any other (Shooting), so a patch renders its points again only when the
// mesh changes.
//
// A patch counts as in a gap when a face standing in front of it
// (InputFace::facing) is closer than a kGapShooterRatio-th of its longest
// edge. The lights' own patches are cut small (meshing.h) and many of them
// shoot from points spread over the lamp's top already: at 2 cm under the
// ceiling their 18 cm edges are under the ratio. Shooting them from 9
// points each as well (at the lights' finer hemicube) made the furnished
// room's solve 1.4 times as long, against 1.25 times for its ceiling's
// patches alone from 16 points, for a picture the eye cannot tell apart.
#include "solver/prepare/prepared_scene.h"
#include "solver/shooting/near_field.h"

#include <cstdint>
#include <span>
#include <vector>

namespace regio::solver {

// A patch whose facing face is closer than its longest edge over this
// shoots from several points (see the top of the file).
inline constexpr double kGapShooterRatio = 10.0;
// Such a patch shoots from the centroids of k x k equal triangles: with 4,
// its points fall one or four to an element of the patch's first meshes
// (4 or 16 elements), and a patch 0.5 m across over a lamp 2 cm below
// sends the walls' top 12.5 cm and the rest below within 2 % and 8 % of a
// ray-cast reference (3 points a side: +29 %, -16 %).
inline constexpr int kGapShooterSplits = 4;

// The points a shot of `patch` renders its hemicube from: its centroid, or
// for a patch in a gap (above) kGapShooterSplits^2 points, each standing
// for an equal part of its area.
std::vector<Vec3> shooterPoints(const PreparedScene& scene, int patch);

// Which of `points` speak for each element of `patch`: w[s * m + p] (m
// points, s the element's offset in the patch), the points inside the
// element with equal weights, or for an element too small to hold one, the
// point nearest its centroid. Each row of w sums to 1.
std::vector<double> pointWeights(const PreparedScene& scene, int patch, std::span<const Vec3> points);

// A patch shot from several points: perPoint[p] holds the delta form factor
// sums of point p's hemicube per item id (item_buffer.h), `rowElements` and
// `near` their mean row's receivers and its near terms (correctNearField).
// Fills pointFactors[k * m + p] with what point p's hemicube saw of
// receiver rowElements[k], 0 for the near receivers, and
// coefficients[s * m + p] with what element s's power is multiplied by for
// point p's factors: its weight (pointWeights) times the element's far
// share over what its points' factors sum to, so that element s sends its
// near factors plus its points' far factors, the total its points saw.
void splitFarShareByPoints(const PreparedScene& scene, int patch, std::span<const Vec3> points,
                           const std::vector<std::vector<double>>& perPoint,
                           const std::vector<std::uint32_t>& rowElements, const std::vector<NearTerm>& near,
                           std::vector<double>& pointFactors, std::vector<double>& coefficients);

} // namespace regio::solver
