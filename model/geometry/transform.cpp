#include "model/geometry/transform.h"

#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>

namespace regio::model {

Check checkAffineTransform(const glm::dmat4& m)
{
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r]))
                return makeError("the transform contains a number that is not finite");
    // glm is column-major: m[c][3] is the bottom row.
    if (m[0][3] != 0.0 || m[1][3] != 0.0 || m[2][3] != 0.0 || m[3][3] != 1.0)
        return makeError(
            "only affine transforms (move, rotate, scale, shear, mirror) keep faces "
            "planar; this one is projective");
    // Relative test: a scale of 1e-3 on every axis (mm from m) must pass, a
    // flattening of one axis must not.
    glm::dmat3 linear(m);
    double scale = 0.0;
    for (int c = 0; c < 3; ++c)
        scale = std::max(scale, std::abs(linear[c][0]) + std::abs(linear[c][1]) + std::abs(linear[c][2]));
    if (scale == 0.0 || std::abs(glm::determinant(linear)) < 1e-12 * scale * scale * scale)
        return makeError("the transform flattens the part (its determinant is zero)");
    return success();
}

bool isMirroring(const glm::dmat4& m) { return glm::determinant(glm::dmat3(m)) < 0.0; }

Vec3 transformPoint(const glm::dmat4& m, const Vec3& p) { return Vec3(m * glm::dvec4(p, 1.0)); }

void transformVertices(std::vector<Vec3>& vertices, std::vector<Face>& faces, const glm::dmat4& m)
{
    for (Vec3& v : vertices)
        v = transformPoint(m, v);
    if (isMirroring(m))
        for (Face& face : faces)
            if (face.loop.size() > 1)
                std::reverse(face.loop.begin() + 1, face.loop.end());
}

Part transformedPart(Part part, const glm::dmat4& m)
{
    transformVertices(part.vertices, part.faces, m);
    return part;
}

} // namespace regio::model
