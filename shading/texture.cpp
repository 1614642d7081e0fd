#include "shading/texture.h"

#include <algorithm>
#include <cmath>

namespace raylab {

namespace {

/// Parity of the checker square containing (s, t), safe for any double.
bool evenSquare(double s, double t) {
    const auto cell = [](double x) {
        const double f = std::floor(x);
        return std::isfinite(f) ? std::fmod(f, 2.0) : 0.0;  // -1, 0 or 1
    };
    return std::fmod(std::abs(cell(s) + cell(t)), 2.0) == 0;
}

/// ∫_0^x of the 0/1 step function that is 1 on [2k+1, 2k+2): the integral
/// pbrt-v3 uses for its closed-form box-filtered checkerboard.
double oddIntegral(double x) {
    const double h = x / 2;
    return std::floor(h) + 2 * std::max(h - std::floor(h) - 0.5, 0.0);
}

}  // namespace

Texture Texture::fromImage(std::shared_ptr<const MipMap> image, std::string name) {
    Texture t;
    t.m_kind = Kind::Image;
    t.m_image = std::move(image);
    t.m_name = std::move(name);
    return t;
}

Texture Texture::checker(const Color& even, const Color& odd) {
    Texture t;
    t.m_kind = Kind::Checker;
    t.m_even = even;
    t.m_odd = odd;
    t.m_name = "checker";
    return t;
}

LookupFootprint Texture::footprint(const TextureCoords& tc, TextureFilter filter) const {
    LookupFootprint fp;
    fp.duvdx = tc.duvdx;
    fp.duvdy = tc.duvdy;
    if (m_kind != Kind::Image || !usesFootprint(filter)) return fp;
    // Rows run down: t changes against v.
    fp.dstdx = Vec2{scale.x * tc.duvdx.x, -scale.y * tc.duvdx.y};
    fp.dstdy = Vec2{scale.x * tc.duvdy.x, -scale.y * tc.duvdy.y};
    if (filter == TextureFilter::Trilinear) fp.lod = m_image->trilinearLevel(fp.dstdx, fp.dstdy);
    return fp;
}

Texel Texture::lookup(Vec2 uv, const LookupFootprint& fp, TextureFilter filter) const {
    // (u, v) -> image (s, t): scale, offset, then flip t (rows run down).
    const Vec2 st{scale.x * uv.x + offset.x, 1.0 - (scale.y * uv.y + offset.y)};
    switch (filter) {
    case TextureFilter::Point:
        return m_image->point(st, wrap);
    case TextureFilter::Bilinear:
        return m_image->bilinear(0, st, wrap);
    case TextureFilter::Trilinear:
        return m_image->trilinear(st, fp.lod, wrap);
    case TextureFilter::Anisotropic:
        break;
    }
    return m_image->ewa(st, fp.dstdx, fp.dstdy, wrap);
}

Color Texture::checkerColor(Vec2 uv, const LookupFootprint& fp, TextureFilter filter) const {
    const double s = scale.x * uv.x + offset.x, t = scale.y * uv.y + offset.y;
    if (usesFootprint(filter)) {
        // Box filter over the sample's footprint, ± half a step each way,
        // in closed form (pbrt-v3's Checkerboard2DTexture).
        const double ds = 0.5 * std::max(std::abs(scale.x * fp.duvdx.x), std::abs(scale.x * fp.duvdy.x));
        const double dt = 0.5 * std::max(std::abs(scale.y * fp.duvdx.y), std::abs(scale.y * fp.duvdy.y));
        const double s0 = s - ds, s1 = s + ds, t0 = t - dt, t1 = t + dt;
        if (std::isfinite(ds) && std::isfinite(dt) &&
            (std::floor(s0) != std::floor(s1) || std::floor(t0) != std::floor(t1))) {
            if (ds > 1 || dt > 1) return (m_even + m_odd) * 0.5;
            // Fractions of odd columns and odd rows under the box; a square is
            // odd where exactly one of them is.
            const double fs = ds > 0 ? (oddIntegral(s1) - oddIntegral(s0)) / (2 * ds)
                                     : double(!evenSquare(s, 0));
            const double ft = dt > 0 ? (oddIntegral(t1) - oddIntegral(t0)) / (2 * dt)
                                     : double(!evenSquare(0, t));
            const double odd = fs + ft - 2 * fs * ft;
            return m_even * (1 - odd) + m_odd * odd;
        }
    }
    return evenSquare(s, t) ? m_even : m_odd;
}

Color Texture::color(const TextureCoords& tc, TextureFilter filter) const {
    return color(tc.uv, footprint(tc, filter), filter);
}

double Texture::scalar(const TextureCoords& tc, TextureFilter filter) const {
    return scalar(tc.uv, footprint(tc, filter), filter);
}

Color Texture::color(Vec2 uv, const LookupFootprint& fp, TextureFilter filter) const {
    if (m_kind == Kind::Checker) return checkerColor(uv, fp, filter);
    const Texel v = lookup(uv, fp, filter);
    if (m_image->channels() < 3) return Color(v[0]);
    return Color(v[0], v[1], v[2]);
}

double Texture::scalar(Vec2 uv, const LookupFootprint& fp, TextureFilter filter) const {
    if (m_kind == Kind::Checker) {
        const Color c = checkerColor(uv, fp, filter);
        return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
    }
    const Texel v = lookup(uv, fp, filter);
    const int n = m_image->channels();
    const double luminance = n < 3 ? v[0] : 0.2126 * v[0] + 0.7152 * v[1] + 0.0722 * v[2];
    switch (channel) {
    case TextureChannel::Red:
        return v[0];
    case TextureChannel::Green:
        return n >= 3 ? v[1] : v[0];
    case TextureChannel::Blue:
        return n >= 3 ? v[2] : v[0];
    case TextureChannel::Matte:
        return n == 2 ? v[1] : n == 4 ? v[3] : luminance;
    case TextureChannel::Luminance:
        break;
    }
    return luminance;
}

bool Texture::sameColors(const Texture& other) const {
    if (m_kind != other.m_kind || !(scale == other.scale) || !(offset == other.offset)) return false;
    if (m_kind == Kind::Checker) return m_even == other.m_even && m_odd == other.m_odd;
    return m_image == other.m_image && wrap == other.wrap;
}

}  // namespace raylab
