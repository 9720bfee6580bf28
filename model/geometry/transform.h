#pragma once
// Affine transforms of B-rep parts (move, rotate, scale, mirror). An affine map
// keeps planar faces planar and convex faces convex; a projective one would
// not, so only affine matrices are accepted. A mirroring map (negative
// determinant) turns every loop clockwise seen from outside, so the loops are
// reversed to keep the normals pointing out.
#include "model/diagnostic.h"
#include "model/result.h"
#include "model/scene.h"

#include <glm/mat4x4.hpp>

#include <optional>

namespace regio::model {

// nullopt when `m` is finite, affine (last row 0 0 0 1) and not singular.
Check checkAffineTransform(const glm::dmat4& m);
bool isMirroring(const glm::dmat4& m);
Vec3 transformPoint(const glm::dmat4& m, const Vec3& p);

// Transforms the vertices; reverses every loop (keeping its first vertex) when
// `m` mirrors. Precondition: checkAffineTransform(m) is nullopt.
void transformVertices(std::vector<Vec3>& vertices, std::vector<Face>& faces, const glm::dmat4& m);
Part transformedPart(Part part, const glm::dmat4& m);

} // namespace regio::model
