#pragma once
// The limits of a scene that Regio enforces when it reads one, so that a
// mistake (a model in micrometres, a typo of exponent) gets a message
// instead of garbage geometry or exhausted memory. docs/reliability.md lists them.
namespace regio::model {

// Every coordinate (vertices, region corners, the camera) lies within
// ±1000 km of the origin: a city in metres fits, a coordinate of 1e300
// does not, and the geometry's tolerances (micrometres) stay meaningful.
inline constexpr double kMaxCoordinate = 1e6;

} // namespace regio::model
