#pragma once
// An image texture as a MIP pyramid of linear float texels, and its four
// lookups: point and bilinear on the full-resolution level, trilinear between
// the two levels around the footprint's size, and EWA (elliptically weighted
// averaging, Heckbert 1989, as in pbrt-v4's MIPMap) for anisotropic
// footprints. Coordinates (s, t) are image coordinates in [0, 1]²: s runs
// right, t runs down from the top row (OpenImageIO's convention); texel
// (x, y) covers [x, x+1) / width × [y, y+1) / height, so its centre is at
// ((x + 0.5) / width, (y + 0.5) / height).
//
// Level 0 is the image as read; level k+1 halves level k (rounding up) with a
// 2×2 box, the last row or column of an odd size averaged with itself. The
// pyramid is built once when the file is read and shared by every texture
// that names the file.

#include <array>
#include <cstddef>
#include <vector>

#include "geometry/vec2.h"

namespace raylab {

/// What a lookup outside [0, 1]² sees.
enum class WrapMode {
    Repeat,  ///< the image tiles the plane
    Clamp,   ///< the edge texels extend outwards
    Black,   ///< zero outside the image
};

/// Up to four channels of one filtered lookup (unused channels are 0).
using Texel = std::array<double, 4>;

class MipMap {
public:
    /// `texels`: width × height × channels linear floats, row 0 at the top.
    /// Throws std::invalid_argument on sizes that do not match.
    MipMap(int width, int height, int channels, std::vector<float> texels);

    int channels() const { return m_channels; }
    int levels() const { return int(m_levels.size()); }
    int width(int level = 0) const { return m_levels[size_t(level)].width; }
    int height(int level = 0) const { return m_levels[size_t(level)].height; }
    /// Bytes of every level's texels (what the memory guard counts).
    size_t bytes() const;

    /// Texel (x, y) of `level`, any integer coordinates, through `wrap`.
    Texel texel(int level, long long x, long long y, WrapMode wrap) const;

    /// The texel that contains (s, t) on level 0.
    Texel point(Vec2 st, WrapMode wrap) const;
    /// Bilinear interpolation between the four texel centres around (s, t).
    Texel bilinear(int level, Vec2 st, WrapMode wrap) const;
    /// The level of detail of a footprint: log2 of its longer side in level-0
    /// texels (OpenGL's λ = log2 ρ). dstdx, dstdy: change of (s, t) per step.
    double levelOfDetail(Vec2 dstdx, Vec2 dstdy) const;
    /// The level of detail as trilinear() reads it: levelOfDetail where it
    /// falls between level 0 and the last level; 0 where the footprint is at
    /// most one texel and levels() - 1 where it covers the last level (there
    /// trilinear reads one level whatever the exact value, so the hypot and
    /// log2 are skipped). trilinear(st, trilinearLevel(a, b), wrap) is
    /// trilinear(st, levelOfDetail(a, b), wrap), bit for bit.
    double trilinearLevel(Vec2 dstdx, Vec2 dstdy) const;
    /// Bilinear lookups on the two levels around levelOfDetail, blended.
    Texel trilinear(Vec2 st, Vec2 dstdx, Vec2 dstdy, WrapMode wrap) const;
    /// The same at a level of detail computed before: lookups that share a
    /// footprint (a bump map's three) compute it once.
    Texel trilinear(Vec2 st, double lod, WrapMode wrap) const;
    /// EWA over the ellipse with axes dstdx, dstdy (its minor axis stretched
    /// to at most `maxAnisotropy` times shorter than the major), on the two
    /// levels around the minor axis's level, blended.
    Texel ewa(Vec2 st, Vec2 dstdx, Vec2 dstdy, WrapMode wrap, double maxAnisotropy = 8) const;

private:
    struct Level {
        int width = 0, height = 0;
        std::vector<float> texels;
    };
    /// ρ² of the footprint's two sides, (ax, ay) and (bx, by), in level-0 texels.
    struct FootprintSides {
        double ax, ay, bx, by;
        double a2, b2;  ///< the squared lengths, rounded
    };
    FootprintSides sides(Vec2 dstdx, Vec2 dstdy) const;
    static double levelOfDetail(const FootprintSides& s);
    Texel ewaLevel(int level, Vec2 st, Vec2 a, Vec2 b, WrapMode wrap) const;
    /// Texel (xi, yi) of `l`, already wrapped (-1: black).
    Texel fetch(const Level& l, long long xi, long long yi) const;

    int m_channels = 0;
    std::vector<Level> m_levels;
};

}  // namespace raylab
