#include "solver/visibility/hemicube.h"

#include <algorithm>
#include <numbers>

namespace regio::solver {

Hemicube::Hemicube(int resolution)
    : m_n(std::clamp(resolution + (resolution & 1), 2, kMaxHemicubeResolution))
{
    const int h = m_n / 2;
    m_faceOffset[0] = 0;
    for (int f = 1; f < kHemicubeFaceCount; ++f)
        m_faceOffset[static_cast<size_t>(f)] = m_n * m_n + (f - 1) * m_n * h;

    // Delta form factor of a pixel of area dA centred at c (Cohen & Greenberg):
    // top face (x, y, 1): dA / (pi (x^2 + y^2 + 1)^2); side face (1, y, z):
    // z dA / (pi (y^2 + z^2 + 1)^2). Computed in double, stored in float: the
    // table is read once per pixel per shooter and float halves its bandwidth
    // (docs/performance.md); sums are accumulated in double.
    const double step = 2.0 / m_n;
    const double dA = step * step;
    std::vector<double> top(static_cast<size_t>(h) * static_cast<size_t>(h));
    std::vector<double> side(static_cast<size_t>(h) * static_cast<size_t>(h));
    double sum = 0.0;
    for (int qy = 0; qy < h; ++qy) {
        const double y = (qy + 0.5) * step;
        for (int qx = 0; qx < h; ++qx) {
            const double x = (qx + 0.5) * step;
            const double r = x * x + y * y + 1.0;
            const auto i = static_cast<size_t>(qy * h + qx);
            top[i] = dA / (std::numbers::pi * r * r);
            sum += 4.0 * top[i]; // four quarters of the top face
        }
    }
    for (int row = 0; row < h; ++row) {
        const double z = (row + 0.5) * step;
        for (int qx = 0; qx < h; ++qx) {
            const double y = (qx + 0.5) * step;
            const double r = y * y + z * z + 1.0;
            const auto i = static_cast<size_t>(row * h + qx);
            side[i] = z * dA / (std::numbers::pi * r * r);
            sum += 8.0 * side[i]; // two halves of four side faces
        }
    }
    m_normalisation = 1.0 / sum;
    m_topQuarter.resize(top.size());
    m_sideHalf.resize(side.size());
    for (size_t i = 0; i < top.size(); ++i)
        m_topQuarter[i] = static_cast<float>(top[i] * m_normalisation);
    for (size_t i = 0; i < side.size(); ++i)
        m_sideHalf[i] = static_cast<float>(side[i] * m_normalisation);
}

float Hemicube::delta(HemicubeFace face, int x, int y) const
{
    const int h = m_n / 2;
    if (face == HemicubeFace::Top)
        return m_topQuarter[static_cast<size_t>(mirrored(y) * h + mirrored(x))];
    return m_sideHalf[static_cast<size_t>(y * h + mirrored(x))];
}

double Hemicube::totalSum() const
{
    double quarter = 0.0, half = 0.0;
    for (float d : m_topQuarter)
        quarter += d;
    for (float d : m_sideHalf)
        half += d;
    return 4.0 * quarter + 8.0 * half;
}

} // namespace regio::solver
