#pragma once
// How many equal pieces cut a length so that none is longer than a size
// (the patch size of §5.4, along a strip or across a face).
//
// A face exactly a whole number of patches long must not take one patch
// more by a rounding hair: scenes read from model files carry coordinates
// rounded to 32-bit floats (a relative error of 6e-8, so 6e-7 m in a room
// 10 m across), and a 1.0 m shelf at 0.5 m patches would be cut in three
// instead of two, its light and its neighbours' meshes changing with it. A
// length up to kDivisionSlack of a piece longer than a whole number of
// pieces takes that number (its pieces are at most 0.1 % longer than the
// size asked for, which nothing downstream can tell).
#include <algorithm>
#include <cmath>

namespace regio::solver {

inline constexpr double kDivisionSlack = 1e-3;

// At least 1; `size` must be positive.
inline int divisionsOf(double length, double size)
{
    return std::max(1, int(std::ceil(length / size - kDivisionSlack)));
}

} // namespace regio::solver
