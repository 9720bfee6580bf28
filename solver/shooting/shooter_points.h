#pragma once
// Patches that shoot from several points (paper §5.6, §7: the hemicube sees
// the scene from one point of the shooter, so what a patch hides and shows
// is what its centre hides and shows). Two kinds of patch are wrong by that
// at the sample settings, and both are found by the faces that stand in
// front of them (InputFace::facing, solver/prepare/facing_faces.h).
//
// In a narrow gap. A ceiling patch 0.5 m across over a lamp hung 2 cm below
// the ceiling sees the room only through the slit between the two. Almost
// all it sends goes to the lamp's top, which the near field takes from the
// contour formula (near_field.h); the rest leaves through the slit, and how
// much depends on the element: one at the lamp's rim sends a quarter of its
// light out, one over the middle a few thousandths. Each element's share is
// right (near_field.h gives every element of the shooter its own far share),
// but where it lands was the centre's view, and from the centre the slit is
// a thin row of pixels at the horizon that shows only the walls' top strip:
// the light of the rim's elements, which would light the walls far down,
// landed in a band along their top, 10 % to more than 50 % too bright over
// 15-20 cm. Only a patch over the face across the gap is in it: one beside
// the face within the same distance (the ceiling just outside a lamp's
// outline, which the ceiling is cut along: solver/prepare/near_outlines.h)
// sees the room, not a slit, and shoots from its centroid.
//
// Behind a narrow face. A table's leg 6 cm wide, 0.33 m in front of a wall
// of 0.5 m patches, casts from the whole patch a shadow that is penumbra all
// the way (its umbra ends 4.5 cm behind it); from the patch's centre it casts
// a hard one. A second leg 0.6 m further back, in line with a patch's centre,
// took nothing of that patch though most of the patch sees it, and its
// neighbours' patches, whose centres see past the first leg, gave it their
// whole factor: the back leg's face read 6.8 % dark of what that wall sends
// it, the front leg's inner side 4.8 % dark. A face counts as narrow when it
// is less than a kNarrowFaceWidth-th of the patch's longest edge across,
// and as close when the gap is under that edge; a face that solids cover
// whole (a shelf board's end against its side) hides nothing.
//
// Such a patch renders its hemicube from several points instead: the
// centroids of the k x k equal triangles of its own triangle. Each element
// of the patch sends its far share through the view of the points inside
// it (or, when it is smaller than they are apart, of the nearest one), so
// the rim's light goes where the rim sees. The receivers come from the
// points' mean view; a near receiver (near_field.h) is sent each element's
// contour factor times the share of its points that see it, so that the
// points' views decide what is hidden near the shooter too (with the mean
// view alone, every near receiver some point saw took the whole factor: the
// front leg's inner side 16 % bright). The books stay exact (each element
// sends what its points' hemicubes sum to). The rows are kept like any other
// (Shooting), so a patch renders its points again only when the mesh
// changes.
//
// The lights' own patches are cut small (meshing.h) and many of them
// shoot from points spread over the lamp's top already: at 2 cm under the
// ceiling their 18 cm edges are under the gap ratio. Shooting them from 9
// points each as well (at the lights' finer hemicube) made the furnished
// room's solve 1.4 times as long, against 1.25 times for its ceiling's
// patches alone from 16 points, for a picture the eye cannot tell apart.
#include "solver/prepare/prepared_scene.h"
#include "solver/shooting/near_field.h"

#include <cstdint>
#include <span>
#include <vector>

namespace regio::solver {

// A patch whose facing face is closer than its longest edge over this, and
// some of whose points lie over that face, is in a gap and shoots from
// several points (see the top of the file).
inline constexpr double kGapShooterRatio = 10.0;
// A facing face narrower than the patch's longest edge over this, closer
// than that edge, makes the patch shoot from several points too.
inline constexpr double kNarrowFaceWidth = 4.0;
// Such patches shoot from the centroids of k x k equal triangles: with 4,
// the points fall one or four to an element of the patch's first meshes
// (4 or 16 elements). A patch 0.5 m across over a lamp 2 cm below sends the
// walls' top 12.5 cm and the rest below within 2 % and 8 % of a ray-cast
// reference (3 points a side: +29 %, -16 %); a wall of 0.5 m patches sends
// the back leg above within 0.1 % of rays (3 points a side: +1.3 %).
inline constexpr int kShooterSplits = 4;
// In a dark gap (neither face emits: the ceiling over a panel that glows
// from its underside) the patch holds a few hundredths of what the ceiling
// around it holds, and 2 x 2 points do: against a reference cut 3 cm fine
// around such a panel the picture moved by less than 0.02 % anywhere, and
// the two-light room's 44 such patches render 176 times instead of 704.
inline constexpr int kDarkGapShooterSplits = 2;

// Where a patch shoots from (see the top of the file): its centroid, or
// kShooterSplits^2 points in a gap or behind a narrow face
// (kDarkGapShooterSplits^2 in a dark gap).
enum class ShooterKind { Centre, InGap, BehindNarrowFace };
ShooterKind shooterKind(const PreparedScene& scene, int patch);
// The face across the gap from a patch in a gap (the lamp's top under a
// ceiling patch), -1 for a patch in none. From the patch's points it hides
// most of the scene (solver/visibility/shadow_volume.h).
int gapFace(const PreparedScene& scene, int patch);
// Both at once: what a shot of the patch needs (Shooting::rowOf).
struct ShooterSite {
    ShooterKind kind = ShooterKind::Centre;
    int gapFace = -1;
};
ShooterSite shooterSite(const PreparedScene& scene, int patch);

// The smallest width of a convex polygon: the least, over its edges, of
// the farthest corner's distance from the edge's line.
double polygonWidth(std::span<const Vec3> polygon);

// The points a shot of `patch` renders its hemicube from: its centroid, or
// for a patch in a gap or behind a narrow face (above) kShooterSplits^2
// points (kDarkGapShooterSplits^2 in a dark gap), each standing for an
// equal part of its area.
std::vector<Vec3> shooterPoints(const PreparedScene& scene, int patch);
std::vector<Vec3> shooterPoints(const PreparedScene& scene, int patch, const ShooterSite& site);

// Which of `points` speak for each element of `patch`: w[s * m + p] (m
// points, s the element's offset in the patch), the points inside the
// element with equal weights, or for an element too small to hold one, the
// point nearest its centroid. Each row of w sums to 1.
std::vector<double> pointWeights(const PreparedScene& scene, int patch, std::span<const Vec3> points);

// Behind a narrow face, the share of shooter element `shooterElement` that
// sees receiver `element`: of its points (`weights`, as pointWeights gives
// them) in front of the receiver's plane, the weight of those whose
// hemicube (perPoint, as below) saw it; 0 when none is in front (1 there,
// for an element that reaches over the plane with its points behind it,
// made the furnished room's front leg's inner side 5.2 % too bright). The
// near field's contour factor already leaves out the part of the shooter
// behind the receiver's plane. In a gap the near receivers are not weighed so:
// there nothing stands between the patch and the lamp under it, and a lamp
// element a few pixels high at the horizon of a point that misses it is
// still seen; the far share is what is left of the hemicube's total after
// the near factors, a few thousandths, and the walls' top took 61 % more
// when the near factors lost such pixel misses.
double seenShare(const PreparedScene& scene, std::uint32_t element, std::span<const Vec3> points,
                 std::span<const double> weights, int shooterElement, const std::vector<std::vector<double>>& perPoint);

// A patch shot from several points: perPoint[p] holds the delta form factor
// sums of point p's hemicube per item id (item_buffer.h), `rowElements` and
// `near` their mean row's receivers and its near terms (correctNearField).
// Fills pointFactors[k * m + p] with what point p's hemicube saw of
// receiver rowElements[k], 0 for the near receivers, and
// coefficients[s * m + p] with what element s's power is multiplied by for
// point p's factors: its weight (`weights`, as pointWeights gives them)
// times the element's far share over what its points' factors sum to, so
// that element s sends its near factors plus its points' far factors, the
// total its points saw.
void splitFarShareByPoints(const PreparedScene& scene, int patch, std::span<const double> weights,
                           const std::vector<std::vector<double>>& perPoint,
                           const std::vector<std::uint32_t>& rowElements, const std::vector<NearTerm>& near,
                           std::vector<double>& pointFactors, std::vector<double>& coefficients);

} // namespace regio::solver
