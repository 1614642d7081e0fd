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

private:
    Texel lookup(const TextureCoords& tc, TextureFilter filter) const;
    Color checkerColor(const TextureCoords& tc, TextureFilter filter) const;

    Kind m_kind = Kind::Image;
    std::shared_ptr<const MipMap> m_image;
    std::string m_name;
    Color m_even, m_odd;
};

}  // namespace raylab
