#pragma once
// The hemicube of Cohen and Greenberg (1985) as the paper uses it (§5.6): a
// top face of N x N pixels and four side faces of N x N/2 pixels around a
// unit half cube over the shooter's centre. Delta form factors are
// precomputed for one quarter of the top face and one half of a side face;
// the rest follows by symmetry. The table is normalised so that the whole
// hemicube sums to exactly 1 (the midpoint rule alone is off by ~1/N^2).
//
// Pixel layout, in the shooter's local frame (x, y in the patch plane, z
// along its normal): the top face lies in z = 1 with x, y in [-1, 1]; a side
// face lies in the plane "forward axis = 1" with its horizontal coordinate in
// [-1, 1] and height z in [0, 1]. Column i covers [-1 + 2i/N, -1 + 2(i+1)/N],
// top row j covers the same range in y, side row j covers z in [2j/N, 2(j+1)/N].
#include <array>
#include <cstdint>
#include <vector>

namespace regio::solver {

enum class HemicubeFace : std::uint8_t { Top = 0, PosX = 1, NegX = 2, PosY = 3, NegY = 4 };
inline constexpr int kHemicubeFaceCount = 5;
// Largest top-face resolution: 4096^2 x 3 ids is already 200 MB, and the
// rasteriser's exact 64-bit edge arithmetic is proven up to this size.
inline constexpr int kMaxHemicubeResolution = 4096;

class Hemicube {
public:
    // `resolution` is the top face's N; odd values are rounded up so that the
    // side faces have an integral N/2 rows. Clamped to [2, kMaxHemicubeResolution].
    explicit Hemicube(int resolution);

    int resolution() const { return m_n; }
    int half() const { return m_n / 2; }
    int width(HemicubeFace) const { return m_n; }
    int height(HemicubeFace face) const { return face == HemicubeFace::Top ? m_n : m_n / 2; }
    // Pixels of one face and of the whole hemicube (N^2 + 4 N^2/2 = 3 N^2).
    int pixelCount(HemicubeFace face) const { return width(face) * height(face); }
    int totalPixelCount() const { return 3 * m_n * m_n; }
    // Offset of a face's first pixel in a buffer holding all five faces, row-major.
    int faceOffset(HemicubeFace face) const { return m_faceOffset[static_cast<int>(face)]; }

    // Normalised delta form factor of one pixel (column x, row y) of a face.
    float delta(HemicubeFace face, int x, int y) const;

    // The stored symmetric tables: quarter top ((N/2)^2, index qy * N/2 + qx,
    // qx/qy counted outwards from the centre lines) and half side (N/2 rows
    // by N/2 columns, qx outwards from the centre line, row = height).
    const std::vector<float>& topQuarter() const { return m_topQuarter; }
    const std::vector<float>& sideHalf() const { return m_sideHalf; }
    // Symmetry index of a column (or top row): distance from the centre line in pixels.
    int mirrored(int i) const { return i >= m_n / 2 ? i - m_n / 2 : m_n / 2 - 1 - i; }

    // Sum of the table over the full hemicube after normalisation (1 within
    // float rounding) and the normalisation factor that was applied (the
    // midpoint-rule sum before it was 1 / factor).
    double totalSum() const;
    double normalisation() const { return m_normalisation; }

private:
    int m_n = 0;
    std::array<int, kHemicubeFaceCount> m_faceOffset{};
    std::vector<float> m_topQuarter;
    std::vector<float> m_sideHalf;
    double m_normalisation = 1.0;
};

} // namespace regio::solver
