// The texture path's speed-ups (tex5, tex6) against the formulas they
// replace, bit for bit (memcmp), over ordinary values and the ends of the
// range (zero, denormals, 1e±300, infinities, NaN): the x and y steps of a
// differential computed in lockstep (step_pair.h), the level of detail
// trilinear reads (no hypot or log2 where only one level is read), the one
// hypot of the spherical and polar parameters, the inlined hypot, bilinear
// lookups far out on a tiled plane, and LateValue.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <vector>

#include "geometry/hypot.h"
#include "geometry/surface_parameters.h"
#include "renderer/camera.h"
#include "renderer/late_value.h"
#include "shading/mipmap.h"
#include "shading/ray_differential.h"

using namespace raylab;

namespace {

/// The same bits; any two NaNs count as the same: the compiler may fold
/// (-a) * (-b) into a * b, which changes only a NaN's sign, and a NaN never
/// reaches a pixel (it is replaced before the film).
bool same(double a, double b) {
    return (std::isnan(a) && std::isnan(b)) || std::memcmp(&a, &b, sizeof a) == 0;
}
bool same(const Vec3& a, const Vec3& b) { return same(a.x, b.x) && same(a.y, b.y) && same(a.z, b.z); }
bool same(const Vec2& a, const Vec2& b) { return same(a.x, b.x) && same(a.y, b.y); }

/// Deterministic values: mostly ordinary magnitudes, some from the ends of
/// the double range and the special values.
struct Values {
    uint64_t state = 0x9E3779B97F4A7C15ull;

    uint64_t next() {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        return state;
    }
    double uniform() { return double(next() >> 11) / double(1ull << 53); }
    double any() {
        const uint64_t pick = next() % 64;
        constexpr double kInf = std::numeric_limits<double>::infinity();
        switch (pick) {
        case 0: return 0.0;
        case 1: return -0.0;
        case 2: return kInf;
        case 3: return -kInf;
        case 4: return std::nan("");
        case 5: return 4.9e-324;  // the smallest denormal
        case 6: return (uniform() - 0.5) * 1e300;
        case 7: return (uniform() - 0.5) * 1e-300;
        case 8: return (uniform() - 0.5) * 1e150;
        case 9: return (uniform() - 0.5) * 1e-150;
        default: return (uniform() - 0.5) * std::pow(10.0, double(int(next() % 9) - 4));
        }
    }
    double ordinary() { return (uniform() - 0.5) * std::pow(10.0, double(int(next() % 7) - 3)); }
    Vec3 vec(bool ordinaryOnly) {
        return ordinaryOnly ? Vec3{ordinary(), ordinary(), ordinary()} : Vec3{any(), any(), any()};
    }
};

// The scalar formulas as they were before the lockstep pairs (the reference).

Vec3 transferOneReference(const Vec3& dodx, const Vec3& dddx, const Vec3& d, double t, const Vec3& n,
                          double dn) {
    const Vec3 moved = dodx + dddx * t;
    const double dt = -dot(moved, n) / dn;
    return moved + d * dt;
}

void transferReference(const RayDifferential& rd, const Vec3& d, double t, const Vec3& n, Vec3& dpdx,
                       Vec3& dpdy) {
    const double dn = dot(d, n);
    if (!(std::abs(dn) > 0)) {
        dpdx = dpdy = Vec3{0, 0, 0};
        return;
    }
    dpdx = transferOneReference(rd.dodx, rd.dddx, d, t, n, dn);
    dpdy = transferOneReference(rd.dody, rd.dddy, d, t, n, dn);
}

Vec2 solveReference(const Vec3& dpdu, const Vec3& dpdv, const Vec3& dp) {
    const double a00 = dot(dpdu, dpdu), a01 = dot(dpdu, dpdv), a11 = dot(dpdv, dpdv);
    const double det = a00 * a11 - a01 * a01;
    if (!(std::abs(det) > 0 && std::isfinite(det))) return Vec2{0, 0};
    const double b0 = dot(dpdu, dp), b1 = dot(dpdv, dp);
    const auto clampFinite = [](double x) { return std::isfinite(x) ? std::clamp(x, -1e8, 1e8) : 0.0; };
    return Vec2{clampFinite((a11 * b0 - a01 * b1) / det), clampFinite((a00 * b1 - a01 * b0) / det)};
}

std::shared_ptr<const MipMap> image(int w, int h) {
    std::vector<float> v(size_t(w) * size_t(h) * 3);
    for (size_t i = 0; i < v.size(); ++i) v[i] = float((i * 7919) % 1000) / 1000.0f;
    return std::make_shared<const MipMap>(w, h, 3, std::move(v));
}

}  // namespace

TEST_CASE("lockstep transfer: both steps equal the scalar transfer, bit for bit") {
    Values r;
    int compared = 0;
    for (int i = 0; i < 20000; ++i) {
        const bool ordinary = i % 4 != 0;
        RayDifferential rd{r.vec(ordinary), r.vec(ordinary), r.vec(ordinary), r.vec(ordinary)};
        const Vec3 d = i % 50 == 0 ? Vec3{1, 0, 0} : normalize(r.vec(true));
        const Vec3 n = i % 50 == 0 ? Vec3{0, 1, 0} : normalize(r.vec(true));  // some parallel to d
        const double t = ordinary ? std::abs(r.ordinary()) * 100 : r.any();
        Vec3 ex, ey;
        transferReference(rd, d, t, n, ex, ey);
        const Vec3Pair got = transferDifferentials(rd, d, t, n);
        Vec3 gx, gy;
        transferDifferential(rd, d, t, n, gx, gy);
        CHECK(same(got.first(), ex));
        CHECK(same(got.second(), ey));
        CHECK(same(gx, ex));
        CHECK(same(gy, ey));
        ++compared;
    }
    CHECK(compared == 20000);
    // A ray parallel to the plane: zero change, as before.
    const RayDifferential rd{{1, 2, 3}, {4, 5, 6}, {7, 8, 9}, {1, 1, 1}};
    const Vec3Pair zero = transferDifferentials(rd, {1, 0, 0}, 2.0, {0, 0, 1});
    CHECK(same(zero.first(), Vec3{0, 0, 0}));
    CHECK(same(zero.second(), Vec3{0, 0, 0}));
}

TEST_CASE("lockstep (du, dv): both steps equal the scalar normal equations, bit for bit") {
    Values r;
    for (int i = 0; i < 20000; ++i) {
        const bool ordinary = i % 4 != 0;
        const Vec3 dpdu = r.vec(ordinary);
        // Some tangents parallel (no area: zero) and some nearly so (clamped to ±1e8).
        const Vec3 dpdv = i % 40 == 0 ? dpdu * 3.0 : i % 40 == 1 ? dpdu + Vec3{1e-12, 0, 0} : r.vec(ordinary);
        const Vec3 dpdx = r.vec(ordinary), dpdy = r.vec(ordinary);
        Vec2 gx, gy;
        surfaceParameterChanges(dpdu, dpdv, dpdx, dpdy, gx, gy);
        CHECK(same(gx, solveReference(dpdu, dpdv, dpdx)));
        CHECK(same(gy, solveReference(dpdu, dpdv, dpdy)));
        double du, dv;
        surfaceParameterChange(dpdu, dpdv, dpdx, du, dv);
        CHECK(same(Vec2{du, dv}, solveReference(dpdu, dpdv, dpdx)));
    }
    // Hand-computed: dpdu = (2,0,0), dpdv = (0,4,0), dp = (1,1,5) -> (0.5, 0.25).
    Vec2 a, b;
    surfaceParameterChanges({2, 0, 0}, {0, 4, 0}, {1, 1, 5}, {-2, 8, 0}, a, b);
    CHECK(a == Vec2{0.5, 0.25});
    CHECK(b == Vec2{-1, 2});
}

TEST_CASE("lockstep camera differential: equals (dd' - d (d·dd')) / |d'| per step, bit for bit") {
    const Camera cams[] = {Camera::perspective({1, 2, 3}, {0, 0, -1}, {0, 1, 0}, 50),
                           Camera::perspective({0, 0, 0}, {3, -1, 0.5}, {0, 0, 1}, 170),
                           Camera::perspective({-4, 1, 9}, {-4.1, 1, -20}, {0, 1, 0}, 0.5)};
    for (const Camera& cam : cams) {
        for (const double spacing : {1.0, 1.0 / std::sqrt(6.0), 1e-3}) {
            const Camera::DifferentialSteps steps = cam.differentialSteps(640, 400, spacing);
            for (double py = 0.1; py < 400; py += 13.7) {
                for (double px = 0.3; px < 640; px += 21.1) {
                    const Ray ray = cam.generateRay(px, py, 640, 400);
                    const Vec3 d = normalize(ray.d);
                    const RayDifferential got = cam.differential(ray, d, steps);
                    const double along = -dot(d, cam.frame().w);
                    const double len = 1.0 / along;
                    CHECK(same(got.dddx, (steps.dx - d * dot(d, steps.dx)) / len));
                    CHECK(same(got.dddy, (steps.dy - d * dot(d, steps.dy)) / len));
                    CHECK(same(got.dodx, Vec3{0, 0, 0}));
                    CHECK(same(got.dody, Vec3{0, 0, 0}));
                }
            }
        }
    }
    // Orthographic: the origin moves by the steps, the direction not at all.
    const Camera ortho = Camera::orthographic({1, 2, 3}, {-1, -2, -4}, {0, 1, 0}, 6);
    const Camera::DifferentialSteps steps = ortho.differentialSteps(64, 48, 0.5);
    const Ray ray = ortho.generateRay(10.5, 7.25, 64, 48);
    const RayDifferential o = ortho.differential(ray, normalize(ray.d), steps);
    CHECK(same(o.dodx, steps.dx));
    CHECK(same(o.dody, steps.dy));
    CHECK(same(o.dddx, Vec3{0, 0, 0}));
    CHECK(same(o.dddy, Vec3{0, 0, 0}));
}

TEST_CASE("trilinear level: the same lookups as the exact level of detail, bit for bit") {
    // Footprints around the shortcuts' edges (one texel, the last level),
    // far from them, degenerate and non-finite, on images with 1 to 10 levels.
    Values r;
    const double inf = std::numeric_limits<double>::infinity(), nan = std::nan("");
    for (const auto& m : {image(1, 1), image(37, 23), image(256, 1), image(512, 512)}) {
        const double w = m->width(0), h = m->height(0);
        const int last = m->levels() - 1;
        std::vector<Vec2> steps;
        // Texel lengths in level-0 texels: 1 and 2^last, each side of them.
        for (const double texels : {1.0, std::ldexp(1.0, last)})
            for (const double f : {1.0, 1 - 1e-16, 1 + 1e-16, 1 - 1e-10, 1 + 1e-10, 1 - 1e-9, 1 + 1e-9,
                                   1 - 1e-8, 1 + 1e-8, 0.5, 2.0}) {
                steps.push_back({texels * f / w, 0});
                steps.push_back({0, -texels * f / h});
                steps.push_back({texels * f / w * std::sqrt(0.5), texels * f / h * std::sqrt(0.5)});
            }
        for (const Vec2 s : {Vec2{0, 0}, Vec2{1e-300, 0}, Vec2{4.9e-324, 4.9e-324}, Vec2{1e200, 1},
                             Vec2{inf, 0}, Vec2{inf, nan}, Vec2{nan, 0}, Vec2{0, nan}, Vec2{1e150, 1e150},
                             Vec2{-0.0, -0.0}, Vec2{1e-3, 2e-3}, Vec2{0.3, -0.1}})
            steps.push_back(s);
        for (int i = 0; i < 60; ++i) steps.push_back({r.any(), r.any()});
        int compared = 0;
        for (const Vec2& a : steps)
            for (const Vec2& b : steps) {
                const double exact = m->levelOfDetail(a, b), fast = m->trilinearLevel(a, b);
                // Where trilinear reads two levels the level is the exact one.
                if (exact > 0 && exact < last) CHECK(same(fast, exact));
                for (const WrapMode wrap : {WrapMode::Repeat, WrapMode::Clamp}) {
                    const Vec2 st{0.3721, 0.6183};
                    const Texel x = m->trilinear(st, exact, wrap), y = m->trilinear(st, fast, wrap);
                    CHECK(std::memcmp(&x, &y, sizeof x) == 0);
                    const Texel z = m->trilinear(st, a, b, wrap);
                    CHECK(std::memcmp(&x, &z, sizeof x) == 0);
                }
                ++compared;
            }
        CHECK(compared == int(steps.size() * steps.size()));
    }
    // Hand-computed: a 16x16 image, sides of 4 and 1 texels -> level 2; of
    // half a texel -> level 0 (magnified); of 64 texels -> the last level, 4.
    const auto m = image(16, 16);
    CHECK(m->trilinearLevel({0.25, 0}, {0, 1.0 / 16}) == 2.0);
    CHECK(m->trilinearLevel({1.0 / 32, 0}, {0, 1.0 / 32}) == 0.0);
    CHECK(m->trilinearLevel({4, 0}, {0, 4}) == 4.0);
}

TEST_CASE("spherical and polar parameters: one hypot gives what two gave, bit for bit") {
    Values r;
    for (int i = 0; i < 20000; ++i) {
        const Vec3 w = i % 3 == 0 ? r.vec(false) : normalize(r.vec(true));
        const LocalParameters s = sphericalParameters(w);
        const double rho = std::hypot(w.x, w.y);
        const double cosTheta = std::clamp(w.z, -1.0, 1.0);
        CHECK(same(s.uv.y, 1.0 - std::acos(cosTheta) / kPi));
        const Azimuth a(w.x, w.y);
        CHECK(same(a.rho, rho));
        CHECK(same(s.dpdv, Vec3{cosTheta * a.cosPhi, cosTheta * a.sinPhi, -rho} * -kPi));
        const double radius = 0.5 + r.uniform();
        const LocalParameters p = polarParameters(w.x, w.y, radius);
        CHECK(same(p.uv.y, rho / radius));
    }
    // Hand-computed: the equator point (0, 1, 0) is u = 1/4, v = 1/2.
    const LocalParameters e = sphericalParameters({0, 1, 0});
    CHECK(e.uv.x == doctest::Approx(0.25));
    CHECK(e.uv.y == doctest::Approx(0.5));
}

TEST_CASE("LateValue: nothing built until emplace, then the value given") {
    struct Big {
        double v[20] = {};
    };
    LateValue<Big> late;
    Big b;
    b.v[7] = 3.5;
    const Big& got = late.emplace(b);
    CHECK(got.v[7] == 3.5);
    CHECK(got.v[0] == 0.0);
    LateValue<double> x;
    CHECK(x.emplace(2.25) == 2.25);
    // emplaceFrom builds the value where it lives: the address the maker's
    // result is constructed at is the storage itself (no temporary).
    struct Where {
        const void* self;
        Where() : self(this) {}
        Where(const Where&) : self(nullptr) {}  // a copy would forget where it was built
    };
    LateValue<Where> w;
    const Where& built = w.emplaceFrom([] { return Where(); });
    CHECK(built.self == &built);
}

TEST_CASE("texel indices without std::floor: point lookups pick the texel floor(s w), floor(t h)") {
    // A 7x5 one-channel image whose texel (x, y) holds 10 y + x: the value
    // read names the texel. Coordinates on texel edges, just off them, below
    // zero (Repeat and Clamp wrap them), beyond 2^52 and NaN.
    std::vector<float> v;
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 7; ++x) v.push_back(float(10 * y + x));
    const MipMap m(7, 5, 1, std::move(v));
    const auto expected = [&](double s, double t, WrapMode wrap) {
        const auto index = [](double c) {
            if (!(c > -4503599627370496.0)) return -(1LL << 52);
            if (c > 4503599627370496.0) return 1LL << 52;
            return static_cast<long long>(std::floor(c));
        };
        return m.texel(0, index(s * 7), index(t * 5), wrap)[0];
    };
    Values r;
    std::vector<double> coords{0.0, -0.0, 1.0, -1.0, 3.0 / 7, -3.0 / 7, 2.0 / 5, -2.0 / 5, 1e-17, -1e-17,
                               std::nextafter(3.0 / 7, 0.0), std::nextafter(-3.0 / 7, -1.0), 1e16, -1e16,
                               4503599627370495.5 / 7, -4503599627370495.5 / 7, 1e300, -1e300,
                               std::nan(""), std::numeric_limits<double>::infinity()};
    for (int i = 0; i < 200; ++i) coords.push_back((r.uniform() - 0.5) * 40);
    for (int i = 0; i < 50; ++i) coords.push_back(std::round((r.uniform() - 0.5) * 80) / 7);  // texel edges
    int compared = 0;
    for (const double s : coords)
        for (const double t : coords)
            for (const WrapMode wrap : {WrapMode::Repeat, WrapMode::Clamp, WrapMode::Black}) {
                const double got = m.point({s, t}, wrap)[0];
                const double want = expected(s, t, wrap);
                CHECK(same(got, want));
                ++compared;
            }
    CHECK(compared == int(coords.size() * coords.size() * 3));
    // Hand-computed: s = -0.1 is texel x = floor(-0.7) = -1, which Repeat wraps to 6.
    CHECK(m.point({-0.1, 0.1}, WrapMode::Repeat)[0] == 6.0f);
    CHECK(m.point({-0.1, 0.1}, WrapMode::Clamp)[0] == 0.0f);
}

TEST_CASE("bilinear blend unrolled per channel count: the per-channel formula, bit for bit, 1 to 4 channels") {
    Values r;
    for (int channels = 1; channels <= 4; ++channels) {
        const int w = 5, h = 3;
        std::vector<float> v(size_t(w * h * channels));
        for (float& f : v) f = float(r.uniform() * 4 - 1);
        const MipMap m(w, h, channels, v);
        for (int i = 0; i < 4000; ++i) {
            // Near the image, and far out on a tiled plane: texel indices
            // beyond 32 bits take the 64-bit remainder, the others the 32-bit one.
            const double span = i % 4 == 3 ? 1e12 : i % 4 == 2 ? 1e6 : 1.0;
            const Vec2 st{(r.uniform() - 0.25) * 2 * span, (r.uniform() - 0.25) * 2 * span};
            const WrapMode wrap = i % 3 == 0 ? WrapMode::Repeat : i % 3 == 1 ? WrapMode::Clamp : WrapMode::Black;
            const double x = st.x * w - 0.5, y = st.y * h - 0.5;
            const long long x0 = static_cast<long long>(std::floor(x)), y0 = static_cast<long long>(std::floor(y));
            const double fx = x - double(x0), fy = y - double(y0);
            const Texel a = m.texel(0, x0, y0, wrap), b = m.texel(0, x0 + 1, y0, wrap);
            const Texel c = m.texel(0, x0, y0 + 1, wrap), d = m.texel(0, x0 + 1, y0 + 1, wrap);
            const Texel got = m.bilinear(0, st, wrap);
            for (int k = 0; k < 4; ++k) {
                const double top = (1 - fx) * a[size_t(k)] + fx * b[size_t(k)];
                const double bottom = (1 - fx) * c[size_t(k)] + fx * d[size_t(k)];
                const double want = k < channels ? (1 - fy) * top + fy * bottom : 0.0;
                CHECK(same(got[size_t(k)], want));
            }
        }
    }
}

TEST_CASE("fastHypot: std::hypot's bits, for every kind of double") {
    Values r;
    long long checked = 0, different = 0;
    const auto check = [&](double x, double y) {
        ++checked;
        if (!same(fastHypot(x, y), std::hypot(x, y))) ++different;
    };
    for (int i = 0; i < 200000; ++i) {
        // Any bit pattern (every exponent, denormals, Inf, NaN), the ends of
        // the range, ordinary values, and pairs of nearly equal size (where
        // the correction step decides the last bit).
        uint64_t bx = r.next(), by = r.next();
        double x, y;
        std::memcpy(&x, &bx, sizeof x);
        std::memcpy(&y, &by, sizeof y);
        check(x, y);
        check(r.any(), r.any());
        const double a = r.ordinary();
        check(a, a * (1 + (r.uniform() - 0.5) * 1e-3));
        check(a, r.ordinary());
        check(a * 1e200, a * 1e-200);
    }
    CHECK(checked == 1000000);
    CHECK(different == 0);
    // Hand-computed: 3-4-5, and the scaling paths at the ends of the range.
    CHECK(fastHypot(3, -4) == 5);
    CHECK(fastHypot(3e300, 4e300) == std::hypot(3e300, 4e300));
    CHECK(fastHypot(3e-320, 4e-320) == std::hypot(3e-320, 4e-320));
    CHECK(std::isinf(fastHypot(std::nan(""), -std::numeric_limits<double>::infinity())));
}
