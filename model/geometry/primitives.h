#pragma once
// Primitive solids for whole-part authoring. Each returns a closed part (or,
// for stairs, an object of closed parts) whose faces are planar convex
// polygons wound counter-clockwise seen from outside, so every normal points
// out of the solid (into the room for makeRoom). Face ids are the part id plus
// a readable suffix, so "box1.body" gets "box1.body.px", "box1.body.ny", ...
// Faces carry no material of their own: they inherit the part's.
//
// Coordinates are metres, y up. Sizes must be positive and finite; bad input
// is refused with a diagnostic rather than producing a degenerate part.
#include "model/result.h"
#include "model/scene.h"

#include <string>

namespace regio::model {

// Axis-aligned box. Face suffixes name the side the face lies on, which is
// also its outward normal: ".nx" (-x, at min.x), ".px" (+x), ".ny" (bottom),
// ".py" (top), ".nz", ".pz".
Result<Part> makeBox(const std::string& id, const Vec3& min, const Vec3& max, const std::string& material);

// The inside of a box: the same six faces and ids as makeBox, each wound the
// other way so its normal points into the room (walls, floor, ceiling).
Result<Part> makeRoom(const std::string& id, const Vec3& min, const Vec3& max, const std::string& material);

// Right prism about the y axis through `baseCenter`: a regular polygon of
// `sides` corners (3..1024) on a circle of `radius`, extruded up by `height`.
// Many sides make a cylinder. The first corner lies on +x from the centre.
// Faces: ".bottom", ".top", ".side1" ... ".sideN".
Result<Part> makePrism(const std::string& id, int sides, double radius, double height, const Vec3& baseCenter,
                       const std::string& material);

// A ramp filling the box [min, max]: a triangular prism whose slope rises from
// the bottom edge at min.x to the top edge at max.x, constant along z.
// Faces: ".bottom", ".slope", ".px" (the vertical back), ".nz", ".pz" (the
// triangular ends).
Result<Part> makeWedge(const std::string& id, const Vec3& min, const Vec3& max, const std::string& material);

// A straight flight of `steps` steps (1..1000) occupying
// [origin, origin + (width, height, depth)]: `width` along x, climbing along
// +z over the total run `depth` to the total rise `height`. The object `id`
// has one box part per step, "id.step1" (lowest) ... "id.stepN", each a
// column standing on the floor at origin.y.
Result<Object> makeStairs(const std::string& id, int steps, double width, double depth, double height,
                          const Vec3& origin, const std::string& material);

} // namespace regio::model
