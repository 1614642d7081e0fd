#pragma once
// A texture of a material: an image (a shared MIP pyramid) or a procedural
// checkerboard, placed in the surface's (u, v) by a scale and an offset:
// (s', t') = (su·u + ou, sv·v + ov). Images are stored top row first while
// (u, v) has v running up (OBJ's vt), so an image lookup uses
// (s, t) = (s', 1 - t'): the image's top row lands at v = 1.

#include <cstdint>
#include <memory>
#include <string>

#include "geometry/vec2.h"
#include "shading/color.h"
#include "shading/mipmap.h"

namespace raylab {

/// How texture lookups are filtered (--texture-filter).
enum class TextureFilter {
    Point,        ///< nearest texel of the full-resolution image
    Bilinear,     ///< bilinear on the full-resolution image
    Trilinear,    ///< bilinear on the two MIP levels around the footprint, blended
    Anisotropic,  ///< EWA over the footprint's ellipse
};

/// Whether a filter reads the hit's footprint (the others need only uv).
inline bool usesFootprint(TextureFilter f) {
    return f == TextureFilter::Trilinear || f == TextureFilter::Anisotropic;
}

/// Where a texture is looked up: the surface parameters and how they change
/// from one sample to the next across the image (zero when not known).
struct TextureCoords {
    Vec2 uv;
    Vec2 duvdx, duvdy;
};

/// What every lookup of one texture at one footprint shares (a bump map
/// reads its height at three uv with the hit's footprint): the footprint in
/// image coordinates and, for trilinear, its level of detail. Made by
/// Texture::footprint; for that texture only (it holds its scale and size).
struct LookupFootprint {
    Vec2 duvdx, duvdy;  ///< the footprint in (u, v), for the checker's box
    Vec2 dstdx, dstdy;  ///< the same in image (s, t)
    double lod = 0;     ///< trilinear: MipMap::trilinearLevel(dstdx, dstdy)
};

/// Which value of a texel a scalar map (bump height, exponent) reads: MTL's
/// -imfchan r|g|b|m|l|z.
enum class TextureChannel { Red, Green, Blue, Matte, Luminance };

class Texture {
public:
    enum class Kind { Image, Checker };

    /// An image texture over `image` (named `name` in messages and statistics).
    static Texture fromImage(std::shared_ptr<const MipMap> image, std::string name);
    /// A checkerboard with unit squares in (s', t'): square (i, j) has colour
    /// `even` when i + j is even, else `odd`.
    static Texture checker(const Color& even, const Color& odd);

    Kind kind() const { return m_kind; }
    const std::string& name() const { return m_name; }
    const MipMap* image() const { return m_image.get(); }

    Vec2 scale{1, 1};
    Vec2 offset{0, 0};
    WrapMode wrap = WrapMode::Repeat;
    TextureChannel channel = TextureChannel::Luminance;  ///< what scalar() reads

    /// RGB at `tc`: a one- or two-channel image gives grey (its first channel).
    Color color(const TextureCoords& tc, TextureFilter filter) const;
    /// One value at `tc`, the `channel` of the texel.
    double scalar(const TextureCoords& tc, TextureFilter filter) const;

    /// The footprint lookups of this texture at `tc` share. color(tc, f) is
    /// color(tc.uv, footprint(tc, f), f), bit for bit.
    LookupFootprint footprint(const TextureCoords& tc, TextureFilter filter) const;
    Color color(Vec2 uv, const LookupFootprint& fp, TextureFilter filter) const;
    double scalar(Vec2 uv, const LookupFootprint& fp, TextureFilter filter) const;

    /// Whether color() of this and `other` give the same value everywhere
    /// (same image or checker, placement and wrap): a material whose ka and
    /// kd name the same map looks it up once.
    bool sameColors(const Texture& other) const;

private:
    Texel lookup(Vec2 uv, const LookupFootprint& fp, TextureFilter filter) const;
    Color checkerColor(Vec2 uv, const LookupFootprint& fp, TextureFilter filter) const;

    Kind m_kind = Kind::Image;
    std::shared_ptr<const MipMap> m_image;
    std::string m_name;
    Color m_even, m_odd;
};

}  // namespace raylab
