#include "model/geometry/primitives.h"

#include "model/edit/edit_support.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace regio::model {

namespace {

Check checkId(const std::string& id)
{
    if (id.empty())
        return makeError("a primitive needs a non-empty id");
    return success();
}

bool positiveFinite(double value) { return std::isfinite(value) && value > 0.0; }

Check checkBox(const std::string& id, const Vec3& min, const Vec3& max)
{
    if (Check check = checkId(id); !check)
        return check;
    if (!edit::isFinite(min) || !edit::isFinite(max))
        return makeError("the corners of \"" + id + "\" must be finite numbers");
    for (int a = 0; a < 3; ++a)
        if (!(max[a] - min[a] > 0.0))
            return makeError("\"" + id + "\" needs min < max on every axis");
    return success();
}

// Vertex k of a box: bit 0 selects max.x, bit 1 max.y, bit 2 max.z.
Part boxPart(const std::string& id, const Vec3& min, const Vec3& max, const std::string& material)
{
    Part part;
    part.id = id;
    part.material = material;
    for (int k = 0; k < 8; ++k)
        part.vertices.push_back({(k & 1) ? max.x : min.x, (k & 2) ? max.y : min.y, (k & 4) ? max.z : min.z});
    // Counter-clockwise seen from outside: e.g. nx runs 0 -> 4 (+z) -> 6 (+y),
    // and z cross y = -x.
    part.faces = {
        {id + ".nx", {0, 4, 6, 2}, {}}, {id + ".px", {1, 3, 7, 5}, {}}, {id + ".ny", {0, 1, 5, 4}, {}},
        {id + ".py", {2, 6, 7, 3}, {}}, {id + ".nz", {0, 2, 3, 1}, {}}, {id + ".pz", {4, 5, 7, 6}, {}},
    };
    return part;
}

} // namespace

Result<Part> makeBox(const std::string& id, const Vec3& min, const Vec3& max, const std::string& material)
{
    if (Check check = checkBox(id, min, max); !check)
        return check.error();
    return boxPart(id, min, max, material);
}

Result<Part> makeRoom(const std::string& id, const Vec3& min, const Vec3& max, const std::string& material)
{
    if (Check check = checkBox(id, min, max); !check)
        return check.error();
    Part part = boxPart(id, min, max, material);
    // Reversing a loop but keeping its first corner flips the normal and keeps
    // the faces' starting vertices, so box and room read alike.
    for (Face& face : part.faces)
        std::reverse(face.loop.begin() + 1, face.loop.end());
    return part;
}

Result<Part> makePrism(const std::string& id, int sides, double radius, double height, const Vec3& baseCenter,
                       const std::string& material)
{
    if (Check check = checkId(id); !check)
        return check.error();
    if (sides < 3 || sides > 1024)
        return makeError("a prism needs 3 to 1024 sides, not " + std::to_string(sides));
    if (!positiveFinite(radius) || !positiveFinite(height) || !edit::isFinite(baseCenter))
        return makeError("the radius and height of \"" + id + "\" must be positive numbers");
    Part part;
    part.id = id;
    part.material = material;
    // Corner i at angle 2 pi i / n from +x towards +z: vertices 0..n-1 form
    // the bottom ring, n..2n-1 the top ring above them. Walking the ring
    // towards +z turns clockwise seen from above (x cross z = -y).
    for (int ring = 0; ring < 2; ++ring)
        for (int i = 0; i < sides; ++i) {
            double angle = 2.0 * std::numbers::pi * i / sides;
            part.vertices.push_back(baseCenter +
                                    Vec3{radius * std::cos(angle), ring * height, radius * std::sin(angle)});
        }
    Face bottom{id + ".bottom", {}, {}};
    Face top{id + ".top", {}, {}};
    for (int i = 0; i < sides; ++i) {
        bottom.loop.push_back(i);
        top.loop.push_back(sides + (sides - i) % sides);
    }
    part.faces.push_back(bottom);
    part.faces.push_back(top);
    for (int i = 0; i < sides; ++i) {
        int j = (i + 1) % sides;
        // Up, then along the ring: y cross (tangent) points away from the axis.
        part.faces.push_back({id + ".side" + std::to_string(i + 1), {i, sides + i, sides + j, j}, {}});
    }
    return part;
}

Result<Part> makeWedge(const std::string& id, const Vec3& min, const Vec3& max, const std::string& material)
{
    if (Check check = checkBox(id, min, max); !check)
        return check.error();
    Part part;
    part.id = id;
    part.material = material;
    // 0..2 at z = min.z: the low front edge, the bottom and top of the back;
    // 3..5 the same at z = max.z.
    for (double z : {min.z, max.z}) {
        part.vertices.push_back({min.x, min.y, z});
        part.vertices.push_back({max.x, min.y, z});
        part.vertices.push_back({max.x, max.y, z});
    }
    part.faces = {
        {id + ".bottom", {0, 1, 4, 3}, {}}, {id + ".slope", {0, 3, 5, 2}, {}}, {id + ".px", {1, 2, 5, 4}, {}},
        {id + ".nz", {0, 2, 1}, {}},        {id + ".pz", {3, 4, 5}, {}},
    };
    return part;
}

// Why one box per step: the side of a single staircase solid is a stepped
// polygon, which is not convex. Cutting it into convex pieces puts corners in
// the middle of the neighbouring treads', risers' and bottom's edges
// (T-junctions) unless those faces carry extra collinear vertices; both break
// the clean winged-edge topology and the mesher's strips. Boxes are closed,
// manifold and convex-faced by construction, and as a whole-part object the
// flight still moves, groups and ungroups as one.
Result<Object> makeStairs(const std::string& id, int steps, double width, double depth, double height,
                          const Vec3& origin, const std::string& material)
{
    if (Check check = checkId(id); !check)
        return check.error();
    if (steps < 1 || steps > 1000)
        return makeError("stairs need 1 to 1000 steps, not " + std::to_string(steps));
    if (!positiveFinite(width) || !positiveFinite(depth) || !positiveFinite(height) || !edit::isFinite(origin))
        return makeError("the width, depth and height of \"" + id + "\" must be positive numbers");
    Object object;
    object.id = id;
    for (int i = 0; i < steps; ++i) {
        Vec3 min{origin.x, origin.y, origin.z + depth * i / steps};
        Vec3 max{origin.x + width, origin.y + height * (i + 1) / steps, origin.z + depth * (i + 1) / steps};
        object.parts.push_back(boxPart(id + ".step" + std::to_string(i + 1), min, max, material));
    }
    return object;
}

} // namespace regio::model
