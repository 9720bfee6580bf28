#pragma once
// The angle an edge subtends at a point, from the sine and cosine of the
// angle between the unit vectors to its ends: the gamma of Lambert's contour
// formula (§5.6's near receivers take every form factor from it). It is the
// innermost operation of the near field (tens of millions a solve), and
// std::atan2 spends most of its time on the generality it does not need
// here (signs, infinities, correct rounding), so this is Cephes' arctangent
// (S. Moshier): a rational approximation good to about 2e-16 on [0, 0.66],
// the argument brought there by atan(x) = pi/4 + atan((x-1)/(x+1)) and
// atan(x) = pi/2 - atan(1/x).
#include <numbers>

namespace regio::solver {

// atan(x) for x >= 0.
inline double arctangentOfNonNegative(double x)
{
    constexpr double kMoreBits = 6.123233995736765886130e-17; // pi/2 - double(pi/2)
    constexpr double kTan3PiOver8 = 2.41421356237309504880;
    double base = 0.0, extra = 0.0;
    if (x > kTan3PiOver8) {
        base = std::numbers::pi / 2.0;
        extra = kMoreBits;
        x = -1.0 / x;
    } else if (x > 0.66) {
        base = std::numbers::pi / 4.0;
        extra = 0.5 * kMoreBits;
        x = (x - 1.0) / (x + 1.0);
    }
    const double z = x * x;
    const double p =
        (((-8.750608600031904122785e-1 * z - 1.615753718733365076637e1) * z - 7.500855792314704667340e1) * z -
         1.228866684490136173410e2) *
            z -
        6.485021904942025371773e1;
    const double q =
        ((((z + 2.485846490142306297962e1) * z + 1.650270098316988542046e2) * z + 4.328810604912902668951e2) * z +
         4.853903996359136964868e2) *
            z +
        1.945506571482613964425e2;
    return base + (x * (z * p / q) + x + extra);
}

// atan2(sine, cosine) for sine >= 0: an angle in [0, pi].
inline double edgeAngle(double sine, double cosine)
{
    if (cosine > 0.0)
        return arctangentOfNonNegative(sine / cosine);
    if (cosine < 0.0)
        return std::numbers::pi - arctangentOfNonNegative(sine / -cosine);
    return std::numbers::pi / 2.0;
}

} // namespace regio::solver
