#pragma once
// Basic value types of the scene model. Geometry is kept in double precision:
// planarity and convexity tests and the BSP splits downstream need it.
#include <glm/vec3.hpp>

namespace regio::model {

using Vec3 = glm::dvec3;
// Linear RGB triple (reflectance in [0,1] or emission in W/m^2 per channel).
using Rgb = glm::dvec3;

} // namespace regio::model
