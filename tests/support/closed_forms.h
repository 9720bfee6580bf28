#pragma once
// Closed forms that tests check form factors against.
#include <cmath>
#include <numbers>

namespace regio::test {

// From a differential area to a parallel a x b rectangle at distance c, the
// area's normal passing through a corner of the rectangle (the classical
// closed form, e.g. Howell's catalogue of configuration factors).
inline double cornerFormFactor(double a, double b, double c)
{
    const double x = a / c, y = b / c;
    const double sx = std::sqrt(1.0 + x * x), sy = std::sqrt(1.0 + y * y);
    return (x / sx * std::atan(y / sx) + y / sy * std::atan(x / sy)) / (2.0 * std::numbers::pi);
}

} // namespace regio::test
