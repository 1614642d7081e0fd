// Texture lookups against hand-computed values: sRGB decoding, the exact
// bilinear weights on a 2x2 image, wrap modes, the v orientation, the MIP
// pyramid and its level of detail, the box-filtered checkerboard, bump and
// normal maps, and what lookups at one hit share (the level of detail, a map
// named twice).
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>

#include "shading/material_textures.h"
#include "shading/mipmap.h"
#include "shading/normal_mapping.h"
#include "shading/srgb.h"
#include "shading/texture.h"

using namespace raylab;

namespace {

/// A 2x2 single-channel image: a b (top row), c d (bottom row).
MipMap grey2x2(float a, float b, float c, float d) { return MipMap(2, 2, 1, {a, b, c, d}); }

/// A 2x2 RGB image whose top row is red and bottom row blue.
std::shared_ptr<const MipMap> redOverBlue() {
    return std::make_shared<const MipMap>(
        2, 2, 3, std::vector<float>{1, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 1});
}

}  // namespace

TEST_CASE("sRGB: known 8-bit codes decode to their linear values") {
    // ((c/255 + 0.055) / 1.055)^2.4 above 0.04045, c/255/12.92 below.
    const float* table = srgb8ToLinearTable();
    CHECK(table[0] == 0.0f);
    CHECK(table[255] == 1.0f);
    CHECK(table[10] == doctest::Approx(0.003035269835488375).epsilon(1e-6));
    CHECK(table[64] == doctest::Approx(0.05126945837404324).epsilon(1e-6));
    CHECK(table[128] == doctest::Approx(0.21586050011389926).epsilon(1e-6));
    CHECK(table[188] == doctest::Approx(0.5028864580325687).epsilon(1e-6));
    // The round trip is the identity.
    for (int i = 0; i < 256; i += 17)
        CHECK(linearToSrgb(srgbToLinear(i / 255.0)) == doctest::Approx(i / 255.0));
}

TEST_CASE("bilinear on a 2x2 image: exact weights between texel centres") {
    const MipMap m = grey2x2(0, 1, 2, 3);
    const WrapMode c = WrapMode::Clamp;
    // Texel centres at 0.25 and 0.75 return the texels themselves.
    CHECK(m.bilinear(0, {0.25, 0.25}, c)[0] == 0.0);
    CHECK(m.bilinear(0, {0.75, 0.25}, c)[0] == 1.0);
    CHECK(m.bilinear(0, {0.25, 0.75}, c)[0] == 2.0);
    CHECK(m.bilinear(0, {0.75, 0.75}, c)[0] == 3.0);
    // The image centre is the mean of all four; a quarter of the way from a
    // to b weighs them 3:1.
    CHECK(m.bilinear(0, {0.5, 0.5}, c)[0] == 1.5);
    CHECK(m.bilinear(0, {0.375, 0.25}, c)[0] == 0.25);
    // (0.625, 0.375): fx = 0.75, fy = 0.25: 0.75·0.25·... = 0.25·(0.25·0 + 0.75·1)
    // + ... worked out: top row 0.75, bottom row 2.75, blended 3:1 -> 1.25.
    CHECK(m.bilinear(0, {0.625, 0.375}, c)[0] == 1.25);
}

TEST_CASE("wrap modes: repeat tiles, clamp extends the edge, black is zero outside") {
    const MipMap m = grey2x2(0, 1, 2, 3);
    // Point lookups one image width to the right.
    CHECK(m.point({1.25, 0.25}, WrapMode::Repeat)[0] == 0.0);
    CHECK(m.point({1.25, 0.25}, WrapMode::Clamp)[0] == 1.0);
    CHECK(m.point({1.25, 0.25}, WrapMode::Black)[0] == 0.0);
    CHECK(m.point({-0.25, 0.75}, WrapMode::Repeat)[0] == 3.0);
    CHECK(m.point({-0.25, 0.75}, WrapMode::Clamp)[0] == 2.0);
    // At the left edge, between texel a (centre 0.25) and its neighbour to
    // the left: repeat blends a with b, clamp with itself, black with 0.
    CHECK(m.bilinear(0, {0.0, 0.25}, WrapMode::Repeat)[0] == 0.5);
    CHECK(m.bilinear(0, {0.0, 0.75}, WrapMode::Repeat)[0] == 2.5);
    CHECK(m.bilinear(0, {0.0, 0.75}, WrapMode::Clamp)[0] == 2.0);
    CHECK(m.bilinear(0, {0.0, 0.75}, WrapMode::Black)[0] == 1.0);
    // Huge and non-finite coordinates stay finite.
    CHECK(std::isfinite(m.bilinear(0, {1e300, -1e300}, WrapMode::Repeat)[0]));
    CHECK(std::isfinite(m.bilinear(0, {NAN, 0.5}, WrapMode::Repeat)[0]));
}

TEST_CASE("v orientation: the image's top row lands at v = 1") {
    const Texture t = Texture::fromImage(redOverBlue(), "red-over-blue");
    TextureCoords top, bottom;
    // The centres of the top-left and bottom-left texels.
    top.uv = {0.25, 0.75};
    bottom.uv = {0.25, 0.25};
    for (TextureFilter f : {TextureFilter::Point, TextureFilter::Bilinear}) {
        CHECK(t.color(top, f) == Color(1, 0, 0));
        CHECK(t.color(bottom, f) == Color(0, 0, 1));
    }
    // Scale and offset act in uv before the flip: (2u, 2v + 0.5) at v = 0.3 is 1.1,
    // i.e. 0.1 in the repeated image: blue.
    Texture scaled = t;
    scaled.scale = {2, 2};
    scaled.offset = {0, 0.5};
    TextureCoords p;
    p.uv = {0.1, 0.3};
    CHECK(scaled.color(p, TextureFilter::Point) == Color(0, 0, 1));
}

TEST_CASE("MIP pyramid: halved levels, box averages, odd sizes round up") {
    std::vector<float> v(16);
    for (int i = 0; i < 16; ++i) v[size_t(i)] = float(i);
    const MipMap m(4, 4, 1, v);
    REQUIRE(m.levels() == 3);
    CHECK(m.width(1) == 2);
    CHECK(m.width(2) == 1);
    // Level 1 texel (0, 0) averages 0, 1, 4, 5.
    CHECK(m.texel(1, 0, 0, WrapMode::Clamp)[0] == 2.5);
    CHECK(m.texel(1, 1, 1, WrapMode::Clamp)[0] == 12.5);
    CHECK(m.texel(2, 0, 0, WrapMode::Clamp)[0] == 7.5);
    CHECK(m.bytes() == (16 + 4 + 1) * sizeof(float));
    // 3x1: level 1 is 2x1, its second texel the last column averaged with itself.
    const MipMap odd(3, 1, 1, {0, 3, 6});
    REQUIRE(odd.levels() == 3);
    CHECK(odd.texel(1, 0, 0, WrapMode::Clamp)[0] == 1.5);
    CHECK(odd.texel(1, 1, 0, WrapMode::Clamp)[0] == 6.0);
    CHECK(odd.texel(2, 0, 0, WrapMode::Clamp)[0] == 3.75);
}

TEST_CASE("level of detail: log2 of texels per step, the longer axis") {
    const MipMap m(16, 16, 1, std::vector<float>(256, 1.0f));
    // A step of 1/4 of the image is 4 texels: level 2.
    CHECK(m.levelOfDetail({0.25, 0}, {0, 0.25}) == doctest::Approx(2.0));
    CHECK(m.levelOfDetail({0.25, 0}, {0, 0.0625}) == doctest::Approx(2.0));
    CHECK(m.levelOfDetail({0, 0.125}, {0.03125, 0}) == doctest::Approx(1.0));
    // A constant image is constant under every filter.
    const Vec2 st{0.3, 0.7};
    CHECK(m.trilinear(st, {0.1, 0}, {0, 0.1}, WrapMode::Repeat)[0] == doctest::Approx(1.0));
    CHECK(m.ewa(st, {0.3, 0.01}, {0.0, 0.02}, WrapMode::Repeat)[0] == doctest::Approx(1.0));
    CHECK(m.ewa(st, {5, 0}, {0, 5}, WrapMode::Repeat)[0] == doctest::Approx(1.0));
}

TEST_CASE("trilinear blends the two levels around the footprint") {
    // 2x2 image 0 1 / 2 3: level 1 is its mean 1.5. A step of 1/√2 image
    // widths is √2 texels: λ = 0.5, halfway between level 0 and level 1.
    const MipMap m = grey2x2(0, 1, 2, 3);
    const double s = std::sqrt(2.0) / 2;  // in [0,1] units: √2 texels of 2
    const double v = m.trilinear({0.25, 0.25}, {s, 0}, {0, s}, WrapMode::Clamp)[0];
    CHECK(v == doctest::Approx(0.5 * 0.0 + 0.5 * 1.5));
}

TEST_CASE("EWA: an elongated footprint averages along its major axis only") {
    // Columns alternate 0/1; rows are all alike. A footprint long in t and
    // thin in s sees one column; long in s it sees the average.
    std::vector<float> v(64 * 64);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) v[size_t(y * 64 + x)] = float(x % 2);
    const MipMap m(64, 64, 1, v);
    const double texel = 1.0 / 64;
    const Vec2 centreOfColumn1{1.5 * texel, 0.5};
    const double alongT =
        m.ewa(centreOfColumn1, {0, 8 * texel}, {0.01 * texel, 0}, WrapMode::Repeat, 64)[0];
    CHECK(alongT > 0.99);
    // The default anisotropy limit of 8 widens the minor axis to one texel,
    // which lets in some of the neighbouring columns.
    const double clamped =
        m.ewa(centreOfColumn1, {0, 8 * texel}, {0.01 * texel, 0}, WrapMode::Repeat)[0];
    CHECK(clamped > 0.6);
    CHECK(clamped < alongT);
    const double alongS = m.ewa(centreOfColumn1, {8 * texel, 0}, {0, 1 * texel}, WrapMode::Repeat)[0];
    CHECK(alongS == doctest::Approx(0.5).epsilon(0.1));
}

TEST_CASE("checker: squares by parity, box-filtered to the mean under a wide footprint") {
    const Texture t = Texture::checker(Color(1), Color(0));
    TextureCoords tc;
    tc.uv = {0.5, 0.5};
    CHECK(t.color(tc, TextureFilter::Point) == Color(1));
    tc.uv = {1.5, 0.5};
    CHECK(t.color(tc, TextureFilter::Point) == Color(0));
    tc.uv = {-0.5, 0.5};
    CHECK(t.color(tc, TextureFilter::Point) == Color(0));
    tc.uv = {-0.5, -0.5};
    CHECK(t.color(tc, TextureFilter::Point) == Color(1));
    // A footprint of one square each way straddles the edge at u = 1: the box
    // [0.5, 1.5] x [0.25, 0.75] is half even, half odd.
    tc.uv = {1.0, 0.5};
    tc.duvdx = {1.0, 0};
    tc.duvdy = {0, 0.5};
    CHECK(t.color(tc, TextureFilter::Trilinear).r == doctest::Approx(0.5));
    // Point sampling ignores the footprint.
    CHECK(t.color(tc, TextureFilter::Point) == Color(0));
    // Beyond one square per half-step: the mean.
    tc.duvdx = {4.0, 0};
    CHECK(t.color(tc, TextureFilter::Anisotropic).r == doctest::Approx(0.5));
}

TEST_CASE("textured optics: a colour map multiplies its constant") {
    std::vector<Texture> textures{Texture::fromImage(redOverBlue(), "rb")};
    Material m;
    m.kd = Color(0.5, 0.5, 0.5);
    m.maps.kd = 0;
    TextureCoords tc;
    tc.uv = {0.5, 0.9};
    const SurfaceOptics o = evaluateOptics(m, textures, tc, TextureFilter::Point);
    CHECK(o.kd == Color(0.5, 0, 0));
    CHECK(o.ks == m.ks);
}

TEST_CASE("normal map: (0.5, 0.5, 1) keeps the normal, red and green tilt towards +u and +v") {
    SurfaceGeometry sg;
    sg.ns = {0, 0, 1};
    sg.dpdu = {2, 0, 0.5};  // not orthogonal to ns: orthogonalised to +x
    sg.dpdv = {0, -3, 0};   // v runs along -y: green tilts towards -y
    const auto flat = [](float r, float g, float b) {
        return Texture::fromImage(std::make_shared<const MipMap>(1, 1, 3, std::vector<float>{r, g, b}), "n");
    };
    TextureCoords tc;
    tc.uv = {0.5, 0.5};
    const Vec3 same = normalMappedNormal(sg, flat(0.5f, 0.5f, 1.0f), tc, TextureFilter::Point);
    CHECK(same.z == doctest::Approx(1.0));
    // rgb (1, 0.5, 0.5) is the tangent-space vector (1, 0, 0): +u = +x.
    const Vec3 u = normalMappedNormal(sg, flat(1.0f, 0.5f, 0.5f), tc, TextureFilter::Point);
    CHECK(u.x == doctest::Approx(1.0));
    // rgb (0.5, 1, 0.5): (0, 1, 0), towards +v = -y.
    const Vec3 v = normalMappedNormal(sg, flat(0.5f, 1.0f, 0.5f), tc, TextureFilter::Point);
    CHECK(v.y == doctest::Approx(-1.0));
    // rgb (0.75, 0.5, 0.75): (0.5, 0, 0.5) normalised: 45° towards +x.
    const Vec3 d = normalMappedNormal(sg, flat(0.75f, 0.5f, 0.75f), tc, TextureFilter::Point);
    CHECK(d.x == doctest::Approx(std::sqrt(0.5)));
    CHECK(d.z == doctest::Approx(std::sqrt(0.5)));
}

TEST_CASE("bump map: a height ramp in u tilts the normal against the slope") {
    // Heights 0 and 1 in a 2x1 image, clamped: bilinear between the texel
    // centres u = 0.25 and 0.75 is h = 2 (u - 0.25), slope 2 per unit u.
    // Scale 0.5 makes the slope dh/du = 1 on a plane with dp/du = x, dp/dv = y:
    // dp'/du = (1, 0, 1), dp'/dv = (0, 1, 0), n = (-1, 0, 1)/√2.
    Texture h = Texture::fromImage(std::make_shared<const MipMap>(2, 1, 1, std::vector<float>{0, 1}), "h");
    h.wrap = WrapMode::Clamp;
    SurfaceGeometry sg;
    sg.ns = {0, 0, 1};
    sg.dpdu = {1, 0, 0};
    sg.dpdv = {0, 1, 0};
    TextureCoords tc;
    tc.uv = {0.5, 0.5};
    const Vec3 n = bumpedNormal(sg, h, 0.5, tc, TextureFilter::Bilinear);
    CHECK(n.x == doctest::Approx(-std::sqrt(0.5)));
    CHECK(n.y == doctest::Approx(0.0));
    CHECK(n.z == doctest::Approx(std::sqrt(0.5)));
    // A flat height field leaves the normal alone.
    Texture flat = Texture::fromImage(std::make_shared<const MipMap>(1, 1, 1, std::vector<float>{0.7f}), "f");
    const Vec3 same = bumpedNormal(sg, flat, 3.0, tc, TextureFilter::Point);
    CHECK(same.z == doctest::Approx(1.0));
}

namespace {

/// A 37x23 RGB image of unrelated values (a fixed linear congruential
/// sequence), so every texel, level and filter weight shows in a lookup.
std::shared_ptr<const MipMap> noisyImage() {
    std::vector<float> v(37 * 23 * 3);
    uint32_t x = 12345;
    for (float& f : v) {
        x = x * 1664525u + 1013904223u;
        f = float(x >> 8) / float(1 << 24);
    }
    return std::make_shared<const MipMap>(37, 23, 3, std::move(v));
}

/// The level of detail as issue 18's first version took it, both sides'
/// hypot always: the reference for the one-hypot shortcut.
double levelOfDetailBothSides(const MipMap& m, Vec2 dstdx, Vec2 dstdy) {
    const double w = m.width(0), h = m.height(0);
    const double rho =
        std::max(std::hypot(dstdx.x * w, dstdx.y * h), std::hypot(dstdy.x * w, dstdy.y * h));
    return rho > 0 && std::isfinite(rho) ? std::log2(rho) : 0.0;
}

}  // namespace

TEST_CASE("level of detail: the one-hypot shortcut gives both sides' value, bit for bit") {
    const std::shared_ptr<const MipMap> m = noisyImage();
    const double tiny = 1e-160, huge = 1e160, nan = std::nan("");
    const Vec2 steps[] = {{0, 0},        {0.01, 0},      {0, 0.01},     {0.01, 0.01},
                          {-0.3, 0.002}, {1e-9, -2e-9},  {0.05, 0.05},  {0.05, -0.05},
                          {tiny, tiny},  {huge, 1},      {1e-300, 0},   {nan, 0.1},
                          {0.1, nan},    {3e7, 3e7},     {0.0123, 0.0456}};
    for (const Vec2& a : steps)
        for (const Vec2& b : steps) {
            const double ref = levelOfDetailBothSides(*m, a, b);
            const double got = m->levelOfDetail(a, b);
            CHECK(std::memcmp(&ref, &got, sizeof ref) == 0);
        }
    // Sides whose squares differ by less than the shortcut's margin: the
    // same length up to rounding, in both orders.
    const Vec2 a{0.1, 0.2};
    const Vec2 b{0.1 * (1 + 1e-15), 0.2};
    CHECK(m->levelOfDetail(a, b) == levelOfDetailBothSides(*m, a, b));
    CHECK(m->levelOfDetail(b, a) == levelOfDetailBothSides(*m, b, a));
}

TEST_CASE("shared footprint: lookups at one prepared footprint equal lookups that each take it") {
    // A bump map reads three uv with one footprint (and one level of detail);
    // every filter and wrap must give what separate lookups give, bit for bit.
    Texture t = Texture::fromImage(noisyImage(), "noise");
    t.scale = {2.5, 0.75};
    t.offset = {0.1, -0.3};
    const Texture checker = Texture::checker(Color(0.9, 0.2, 0.1), Color(0.1, 0.3, 0.8));
    const TextureFilter filters[] = {TextureFilter::Point, TextureFilter::Bilinear,
                                     TextureFilter::Trilinear, TextureFilter::Anisotropic};
    const Vec2 footprints[][2] = {{{0, 0}, {0, 0}},           {{0.001, 0}, {0, 0.002}},
                                  {{0.03, 0.01}, {-0.02, 0.05}}, {{0.4, 0}, {0, 0.01}},
                                  {{2, 3}, {-3, 2}}};
    int compared = 0;
    for (WrapMode wrap : {WrapMode::Repeat, WrapMode::Clamp, WrapMode::Black}) {
        t.wrap = wrap;
        for (TextureFilter f : filters)
            for (const auto& d : footprints) {
                TextureCoords tc;
                tc.uv = {0.37, 0.81};
                tc.duvdx = d[0];
                tc.duvdy = d[1];
                const LookupFootprint fp = t.footprint(tc, f);
                const LookupFootprint cfp = checker.footprint(tc, f);
                for (const Vec2 uv : {Vec2{0.37, 0.81}, Vec2{0.3705, 0.81}, Vec2{0.37, 0.8105},
                                      Vec2{-1.2, 1.7}}) {
                    TextureCoords own = tc;
                    own.uv = uv;
                    CHECK(t.color(uv, fp, f) == t.color(own, f));
                    CHECK(t.scalar(uv, fp, f) == t.scalar(own, f));
                    CHECK(checker.color(uv, cfp, f) == checker.color(own, f));
                    ++compared;
                }
            }
    }
    CHECK(compared == 3 * 4 * 5 * 4);
}

TEST_CASE("textured optics: equal maps on ka and kd are looked up once, with the same values") {
    const std::shared_ptr<const MipMap> image = noisyImage();
    Texture a = Texture::fromImage(image, "noise");
    a.scale = {3, 2};
    Texture same = a;           // another entry with the same image and placement
    Texture moved = a;          // the same image placed elsewhere
    moved.offset = {0.5, 0};
    Texture clamped = a;        // wrapped differently
    clamped.wrap = WrapMode::Clamp;
    CHECK(a.sameColors(same));
    CHECK_FALSE(a.sameColors(moved));
    CHECK_FALSE(a.sameColors(clamped));
    CHECK_FALSE(a.sameColors(Texture::fromImage(noisyImage(), "noise")));  // another file
    CHECK(Texture::checker(Color(1), Color(0)).sameColors(Texture::checker(Color(1), Color(0))));
    CHECK_FALSE(Texture::checker(Color(1), Color(0)).sameColors(Texture::checker(Color(1), Color(0.5))));

    // The values: each map's own lookup times its constant.
    const std::vector<Texture> textures{a, same, moved};
    Material m;
    m.ka = Color(0.2, 0.3, 0.4);
    m.kd = Color(0.5, 0.6, 0.7);
    m.ks = Color(0.9, 0.8, 0.1);
    m.maps.ka = 0;
    m.maps.kd = 1;
    m.maps.ks = 2;
    TextureCoords tc;
    tc.uv = {0.3, 0.6};
    tc.duvdx = {0.01, 0.002};
    tc.duvdy = {-0.003, 0.02};
    for (TextureFilter f : {TextureFilter::Bilinear, TextureFilter::Trilinear, TextureFilter::Anisotropic}) {
        const SurfaceOptics o = evaluateOptics(m, textures, tc, f);
        CHECK(o.ka == m.ka * a.color(tc, f));
        CHECK(o.kd == m.kd * same.color(tc, f));
        CHECK(o.ks == m.ks * moved.color(tc, f));
        CHECK_FALSE(a.color(tc, f) == moved.color(tc, f));
    }

    // One plan per material: kd and km share a map (another index, the same
    // colours), kt has its own, ka and ks none; each textured colour is its
    // constant times its own map's value, the others stay as they are.
    Material p;
    p.ka = Color(0.1, 0.2, 0.3);
    p.kd = Color(0.5, 0.6, 0.7);
    p.km = Color(0.25, 0.5, 0.75);
    p.kt = Color(0.9, 0.9, 0.9);
    p.maps.kd = 0;
    p.maps.km = 1;
    p.maps.kt = 2;
    const MaterialLookups plan(p, textures);
    for (TextureFilter f : {TextureFilter::Point, TextureFilter::Trilinear, TextureFilter::Anisotropic}) {
        const SurfaceOptics o = plan.evaluate(p, textures, tc, f);
        CHECK(o.ka == p.ka);
        CHECK(o.ks == p.ks);
        CHECK(o.kd == p.kd * a.color(tc, f));
        CHECK(o.km == p.km * same.color(tc, f));
        CHECK(o.kt == p.kt * moved.color(tc, f));
    }
}
