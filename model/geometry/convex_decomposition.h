#pragma once
// Splits a simple polygon, possibly with holes, into convex polygons that use
// only its own vertices: the caps of a plane cut through a non-convex part
// must be convex faces whose edges match the side faces' edges exactly.
//
// Method: holes are joined to the outer loop by bridge edges (Eberly's
// "Triangulation by ear clipping": the rightmost hole vertex to a visible outer
// vertex), the result is ear-clipped into triangles, and triangles are merged
// back across diagonals while the union stays convex (Hertel and Mehlhorn
// 1983: at most four times the optimal piece count). Collinear vertices are set
// aside first and put back on the edge they lie on afterwards, so they never
// produce zero-area triangles and they stay on the pieces' boundaries.
#include "model/result.h"

#include <glm/vec2.hpp>

#include <vector>

namespace regio::model {

using Polygon2Loop = std::vector<int>; // indices into the point array

// `outer` runs counter-clockwise, each hole clockwise, none self-intersecting.
// Returns counter-clockwise convex polygons covering the polygon exactly.
// `eps` is the distance below which a vertex counts as on a line.
Result<std::vector<Polygon2Loop>> convexDecomposition(const std::vector<glm::dvec2>& points, const Polygon2Loop& outer,
                                                      const std::vector<Polygon2Loop>& holes, double eps);

// Twice the signed area (positive = counter-clockwise).
double signedArea2(const std::vector<glm::dvec2>& points, const Polygon2Loop& loop);

} // namespace regio::model
