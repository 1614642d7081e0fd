#include "shading/mipmap.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "geometry/hypot.h"

namespace raylab {

namespace {

/// Integer texel coordinate of a continuous one, safe for any double (huge
/// repeats, NaN): beyond ±2^52 every double is an integer anyway.
long long floorIndex(double x) {
    constexpr double kLimit = 4503599627370496.0;  // 2^52
    if (!(x > -kLimit)) return -(1LL << 52);       // also NaN
    if (x > kLimit) return 1LL << 52;
    // floor without a call to std::floor (a library call per coordinate on
    // baseline x86-64, which has no SSE4.1 round): the conversion truncates
    // towards zero, one less below zero unless x was an integer. Exact here:
    // |x| <= 2^52, so x's integer part and double(i) are exact.
    const long long i = static_cast<long long>(x);
    return double(i) > x ? i - 1 : i;
}

/// Index into [0, n), or -1 for a texel outside the image under WrapMode::Black.
long long wrapIndex(long long i, int n, WrapMode wrap) {
    // Inside the image under every mode: the common case, without a division.
    if (i >= 0 && i < n) return i;
    switch (wrap) {
    case WrapMode::Repeat: {
        // A 32-bit division where the index fits (a tiled floor's lookups are
        // all outside [0, n)): the same remainder, at a fraction of the
        // latency of a 64-bit one on x86-64.
        const long long r = i >= INT32_MIN && i <= INT32_MAX ? int32_t(i) % n : i % n;
        return r < 0 ? r + n : r;
    }
    case WrapMode::Clamp:
        return std::clamp<long long>(i, 0, n - 1);
    case WrapMode::Black:
        break;
    }
    return i < 0 || i >= n ? -1 : i;
}

/// wrapIndex(i + 1, n, wrap), given a = wrapIndex(i, n, wrap): under Repeat
/// (i + 1) mod n is (a + 1) mod n, so the second texel of a bilinear
/// footprint costs no division.
long long wrapNextIndex(long long i, long long a, int n, WrapMode wrap) {
    if (wrap == WrapMode::Repeat) return a + 1 < n ? a + 1 : 0;
    return wrapIndex(i + 1, n, wrap);
}

Texel lerp(double f, const Texel& a, const Texel& b) {
    Texel r;
    for (int c = 0; c < 4; ++c) r[size_t(c)] = (1 - f) * a[size_t(c)] + f * b[size_t(c)];
    return r;
}

/// Bilinear blend of four texels' first C channels into out[0..C).
template <int C>
inline void blendChannels(const float* p00, const float* p10, const float* p01, const float* p11,
                          double fx, double fy, Texel& out) {
    for (int c = 0; c < C; ++c) {
        const double top = (1 - fx) * double(p00[c]) + fx * double(p10[c]);
        const double bottom = (1 - fx) * double(p01[c]) + fx * double(p11[c]);
        out[size_t(c)] = (1 - fy) * top + fy * bottom;
    }
}

/// Bilinear interpolation between the four texel centres around (s, t) on
/// one level (width × height × channels floats, row 0 at the top).
template <WrapMode W>
Texel bilinearTexels(const float* texels, int width, int height, int channels, Vec2 st) {
    // Texel centres sit at half-integers of the level's texel grid.
    const double x = st.x * width - 0.5, y = st.y * height - 0.5;
    const long long x0 = floorIndex(x), y0 = floorIndex(y);
    // Beyond 2^52 (or NaN) there is no fraction left; floorIndex clamped.
    const auto fraction = [](double c, long long i) {
        const double f = c - double(i);
        return f >= 0 && f < 1 ? f : 0.0;
    };
    const double fx = fraction(x, x0), fy = fraction(y, y0);
    // Each column and row wrapped once for the four texels.
    const long long xa = wrapIndex(x0, width, W), xb = wrapNextIndex(x0, xa, width, W);
    const long long ya = wrapIndex(y0, height, W), yb = wrapNextIndex(y0, ya, height, W);
    // The four texels' values in place (zeros outside the image under
    // WrapMode::Black), blended channel by channel: no Texel copies.
    static constexpr float kBlack[4] = {0, 0, 0, 0};
    const size_t row = size_t(width) * size_t(channels);
    const auto at = [&](long long xi, long long yi) -> const float* {
        if constexpr (W == WrapMode::Black)
            if (xi < 0 || yi < 0) return kBlack;
        return texels + size_t(yi) * row + size_t(xi) * size_t(channels);
    };
    const float *p00 = at(xa, ya), *p10 = at(xb, ya), *p01 = at(xa, yb), *p11 = at(xb, yb);
    Texel out{0, 0, 0, 0};
    // The channel count as a constant (RGB and grey are the common images):
    // the same blend per channel, unrolled.
    switch (channels) {
    case 3:
        blendChannels<3>(p00, p10, p01, p11, fx, fy, out);
        break;
    case 1:
        blendChannels<1>(p00, p10, p01, p11, fx, fy, out);
        break;
    case 4:
        blendChannels<4>(p00, p10, p01, p11, fx, fy, out);
        break;
    default:
        blendChannels<2>(p00, p10, p01, p11, fx, fy, out);
        break;
    }
    return out;
}

/// Gaussian falloff of the EWA filter, exp(-α r²) - exp(-α) with α = 2 as in
/// pbrt, tabulated over r² in [0, 1).
constexpr int kEwaTableSize = 128;
const double* ewaWeights() {
    static const struct Table {
        double w[kEwaTableSize];
        Table() {
            for (int i = 0; i < kEwaTableSize; ++i) {
                const double r2 = double(i) / (kEwaTableSize - 1);
                w[i] = std::exp(-2.0 * r2) - std::exp(-2.0);
            }
        }
    } table;
    return table.w;
}

}  // namespace

MipMap::MipMap(int width, int height, int channels, std::vector<float> texels)
    : m_channels(channels) {
    if (width < 1 || height < 1 || channels < 1 || channels > 4 ||
        texels.size() != size_t(width) * size_t(height) * size_t(channels))
        throw std::invalid_argument("texture: " + std::to_string(width) + "x" +
                                    std::to_string(height) + " image with " +
                                    std::to_string(channels) + " channels does not match its " +
                                    std::to_string(texels.size()) + " values");
    m_levels.push_back(Level{width, height, std::move(texels)});
    // Each level halves the previous one (rounding up) with a 2x2 box.
    while (m_levels.back().width > 1 || m_levels.back().height > 1) {
        const Level& src = m_levels.back();
        Level dst;
        dst.width = (src.width + 1) / 2;
        dst.height = (src.height + 1) / 2;
        dst.texels.resize(size_t(dst.width) * dst.height * channels);
        for (int y = 0; y < dst.height; ++y) {
            const int y0 = 2 * y, y1 = std::min(2 * y + 1, src.height - 1);
            for (int x = 0; x < dst.width; ++x) {
                const int x0 = 2 * x, x1 = std::min(2 * x + 1, src.width - 1);
                for (int c = 0; c < channels; ++c) {
                    const auto at = [&](int xx, int yy) {
                        return double(src.texels[(size_t(yy) * src.width + xx) * channels + c]);
                    };
                    dst.texels[(size_t(y) * dst.width + x) * channels + c] =
                        float(0.25 * (at(x0, y0) + at(x1, y0) + at(x0, y1) + at(x1, y1)));
                }
            }
        }
        m_levels.push_back(std::move(dst));
    }
}

size_t MipMap::bytes() const {
    size_t n = 0;
    for (const Level& l : m_levels) n += l.texels.size() * sizeof(float);
    return n;
}

Texel MipMap::texel(int level, long long x, long long y, WrapMode wrap) const {
    const Level& l = m_levels[size_t(level)];
    return fetch(l, wrapIndex(x, l.width, wrap), wrapIndex(y, l.height, wrap));
}

Texel MipMap::fetch(const Level& l, long long xi, long long yi) const {
    Texel out{0, 0, 0, 0};
    if (xi < 0 || yi < 0) return out;  // outside, under WrapMode::Black
    const float* p = &l.texels[(size_t(yi) * l.width + size_t(xi)) * m_channels];
    for (int c = 0; c < m_channels; ++c) out[size_t(c)] = p[c];
    return out;
}

Texel MipMap::point(Vec2 st, WrapMode wrap) const {
    return texel(0, floorIndex(st.x * width(0)), floorIndex(st.y * height(0)), wrap);
}

Texel MipMap::bilinear(int level, Vec2 st, WrapMode wrap) const {
    const Level& l = m_levels[size_t(level)];
    // One instance per wrap mode: the hot loop of every filtered lookup then
    // has no wrap-mode tests, and only Black tests for texels outside.
    switch (wrap) {
    case WrapMode::Repeat:
        return bilinearTexels<WrapMode::Repeat>(l.texels.data(), l.width, l.height, m_channels, st);
    case WrapMode::Clamp:
        return bilinearTexels<WrapMode::Clamp>(l.texels.data(), l.width, l.height, m_channels, st);
    case WrapMode::Black:
        break;
    }
    return bilinearTexels<WrapMode::Black>(l.texels.data(), l.width, l.height, m_channels, st);
}

MipMap::FootprintSides MipMap::sides(Vec2 dstdx, Vec2 dstdy) const {
    const double w = width(0), h = height(0);
    FootprintSides s;
    s.ax = dstdx.x * w;
    s.ay = dstdx.y * h;
    s.bx = dstdy.x * w;
    s.by = dstdy.y * h;
    s.a2 = s.ax * s.ax + s.ay * s.ay;
    s.b2 = s.bx * s.bx + s.by * s.by;
    return s;
}

double MipMap::levelOfDetail(Vec2 dstdx, Vec2 dstdy) const {
    return levelOfDetail(sides(dstdx, dstdy));
}

double MipMap::levelOfDetail(const FootprintSides& s) {
    // ρ = max(hypot(a), hypot(b)). hypot is the costly part of a trilinear
    // lookup; when the squared lengths differ by far more than their rounding
    // (and neither under- nor overflows) the longer side is known and only its
    // hypot is taken: the same ρ, bit for bit, as taking both.
    const double a2 = s.a2, b2 = s.b2;
    constexpr double kMargin = 1 + 1e-9, kTiny = 1e-290, kHuge = 1e290;
    double rho;
    if (a2 > kTiny && b2 > kTiny && a2 < kHuge && b2 < kHuge && (a2 > b2 * kMargin || b2 > a2 * kMargin))
        rho = a2 > b2 ? fastHypot(s.ax, s.ay) : fastHypot(s.bx, s.by);
    else
        rho = std::max(fastHypot(s.ax, s.ay), fastHypot(s.bx, s.by));
    return rho > 0 && std::isfinite(rho) ? std::log2(rho) : 0.0;
}

double MipMap::trilinearLevel(Vec2 dstdx, Vec2 dstdy) const {
    const FootprintSides s = sides(dstdx, dstdy);
    // The squares are rounded (relative error below 1e-15) and hypot and
    // log2 are within an ulp: a margin of 1e-9 keeps ρ on its side of 1 and
    // of 2^last, so log2(ρ) on its side of 0 and of last. NaN fails both tests.
    constexpr double kBelow = 1 - 1e-9, kAbove = 1 + 1e-9, kHuge = 1e290;
    // ρ <= 1, ρ = 0 included: trilinear reads level 0.
    if (s.a2 <= kBelow && s.b2 <= kBelow) return 0.0;
    // ρ >= 2^last and finite (both sides: hypot(inf, NaN) is inf, which
    // levelOfDetail maps to 0): trilinear reads the last level.
    const int last = levels() - 1;
    const double lastSide = double(1LL << last);
    if (std::max(s.a2, s.b2) >= lastSide * lastSide * kAbove && s.a2 < kHuge && s.b2 < kHuge)
        return double(last);
    return levelOfDetail(s);
}

Texel MipMap::trilinear(Vec2 st, Vec2 dstdx, Vec2 dstdy, WrapMode wrap) const {
    return trilinear(st, trilinearLevel(dstdx, dstdy), wrap);
}

Texel MipMap::trilinear(Vec2 st, double lod, WrapMode wrap) const {
    if (lod <= 0) return bilinear(0, st, wrap);
    const int last = levels() - 1;
    if (lod >= last) return bilinear(last, st, wrap);
    const int level = int(lod);
    return lerp(lod - level, bilinear(level, st, wrap), bilinear(level + 1, st, wrap));
}

Texel MipMap::ewa(Vec2 st, Vec2 dstdx, Vec2 dstdy, WrapMode wrap, double maxAnisotropy) const {
    // Axes in level-0 texels, so non-square images weigh both directions alike.
    const double w = width(0), h = height(0);
    Vec2 major{dstdx.x * w, dstdx.y * h}, minor{dstdy.x * w, dstdy.y * h};
    double majorLen = fastHypot(major.x, major.y), minorLen = fastHypot(minor.x, minor.y);
    if (minorLen > majorLen) {
        std::swap(major, minor);
        std::swap(majorLen, minorLen);
    }
    if (!(minorLen > 0) || !std::isfinite(majorLen)) return bilinear(0, st, wrap);
    // Clamp the eccentricity: a longer minor axis blurs a little more but
    // bounds the texels visited (pbrt's maxAnisotropy).
    if (minorLen * maxAnisotropy < majorLen) {
        const double scale = majorLen / (minorLen * maxAnisotropy);
        minor = minor * scale;
        minorLen *= scale;
    }
    const double lod = std::log2(minorLen);
    const int last = levels() - 1;
    if (lod >= last) return bilinear(last, st, wrap);
    const Vec2 a{major.x / w, major.y / h}, b{minor.x / w, minor.y / h};
    if (lod <= 0) return ewaLevel(0, st, a, b, wrap);
    const int level = int(lod);
    return lerp(lod - level, ewaLevel(level, st, a, b, wrap), ewaLevel(level + 1, st, a, b, wrap));
}

Texel MipMap::ewaLevel(int level, Vec2 st, Vec2 a, Vec2 b, WrapMode wrap) const {
    // pbrt-v4's MIPMap::EWA: the implicit ellipse A s² + B s t + C t² < 1
    // spanned by the axes in this level's texels, widened by one texel so it
    // always covers at least one texel centre.
    const double lw = width(level), lh = height(level);
    const double s = st.x * lw - 0.5, t = st.y * lh - 0.5;
    const Vec2 d0{a.x * lw, a.y * lh}, d1{b.x * lw, b.y * lh};
    double A = d0.y * d0.y + d1.y * d1.y + 1;
    double B = -2 * (d0.x * d0.y + d1.x * d1.y);
    double C = d0.x * d0.x + d1.x * d1.x + 1;
    const double invF = 1 / (A * C - B * B * 0.25);
    A *= invF;
    B *= invF;
    C *= invF;
    const double det = -B * B + 4 * A * C;
    const double invDet = 1 / det;
    const double uSqrt = std::sqrt(std::max(0.0, det * C)), vSqrt = std::sqrt(std::max(0.0, A * det));
    const long long s0 = -floorIndex(-(s - 2 * invDet * uSqrt)), s1 = floorIndex(s + 2 * invDet * uSqrt);
    const long long t0 = -floorIndex(-(t - 2 * invDet * vSqrt)), t1 = floorIndex(t + 2 * invDet * vSqrt);
    const double* weights = ewaWeights();
    Texel sum{0, 0, 0, 0};
    double sumWeights = 0;
    for (long long it = t0; it <= t1; ++it) {
        const double tt = double(it) - t;
        for (long long is = s0; is <= s1; ++is) {
            const double ss = double(is) - s;
            const double r2 = A * ss * ss + B * ss * tt + C * tt * tt;
            if (!(r2 < 1)) continue;
            const double wgt = weights[std::min(int(r2 * kEwaTableSize), kEwaTableSize - 1)];
            const Texel v = texel(level, is, it, wrap);
            for (int c = 0; c < 4; ++c) sum[size_t(c)] += wgt * v[size_t(c)];
            sumWeights += wgt;
        }
    }
    if (!(sumWeights > 0)) return bilinear(level, st, wrap);
    for (double& c : sum) c /= sumWeights;
    return sum;
}

}  // namespace raylab
