#pragma once
// The light that reaches a point straight from the lights' emission, exact:
// the part of each light that the point sees, cut out of the light's polygon
// by the outlines of whatever stands between, and Lambert's contour formula
// over what is left.
//
// Why the picture needs it: across a penumbra the direct light rises from
// nothing to full within a centimetre or two and bends sharply at the
// umbra's edge. Vertex radiosity averaged from the elements around a vertex
// (§6) rounds the bend off, and a straight line between two vertices an
// element apart cuts across it; the shooting's element values, summed from
// hemicube pixels (§5.6), also scatter where an element is a few pixels
// across. Point values of the direct light do neither, so a picture can take
// its direct part from here and only the reflected light, which varies
// slowly, from the elements (as Wallace, Elmquist and Haines 1989 take the
// lights' contribution at the vertices).
//
// Visibility from a point x to a light L: every face between x and L's plane
// is clipped to the slab between them and projected from x onto L's plane
// (a convex polygon stays convex: the projection is central, from one side),
// and the projections are cut out of L's polygon, which leaves a set of
// convex pieces. The emission of the light's front side only counts (a
// light emits forwards).
#include "solver/prepare/prepared_scene.h"

#include <span>
#include <vector>

namespace regio::solver {

class DirectLight {
public:
    explicit DirectLight(const PreparedScene& scene);

    // The scene has a light.
    bool any() const { return !m_lights.empty(); }

    // Sum over the lights of the emission times the form factor from the
    // point (on input face `face`, facing its normal) to the part of the
    // light it sees: times the face's reflectance, the radiosity that the
    // lights give the point directly.
    Rgb irradiance(int face, const Vec3& x) const;

    // The radiosity the lights give the point directly (the reflectance of
    // `face` times irradiance).
    Rgb radiosity(int face, const Vec3& x) const;

    // The form factor from the point to the part of light `light` (an input
    // face) that it sees; 0 for a face that emits nothing.
    double visibleFactor(int face, const Vec3& x, int light) const;

private:
    struct Light {
        int face = -1;
        Box3 box;
    };
    // A bounding-volume hierarchy over the faces' boxes: to find the faces
    // that may stand between a point and a light.
    struct Node {
        Box3 box;
        int first = 0;  // leaves: [first, first + count) of m_order; inner nodes: the left child
        int count = 0;  // 0: an inner node
        int second = 0; // inner nodes: the right child
    };
    // The faces that may stand between a point and a light reach into
    // this: the box of both, and in front of every plane.
    struct Pyramid {
        Box3 box;
        std::vector<Plane> planes;
    };
    int build(int first, int count);
    template <typename Visit>
    void overlapping(const Pyramid& pyramid, Visit&& visit) const;
    double factorOf(int face, const Vec3& x, const Vec3& n, const Light& light) const;

    const PreparedScene& m_scene;
    std::vector<Light> m_lights;
    std::vector<Box3> m_faceBox; // per input face (empty box: no polygon)
    std::vector<int> m_order;    // face indices, in the leaves' order
    std::vector<Node> m_nodes;   // root first
};

} // namespace regio::solver
