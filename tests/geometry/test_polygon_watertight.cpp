// The watertight inside test of polygons (Polygon::insideWatertight) against a
// reference written here as the textbook loop: every edge sheared into ray
// space in the same precision, the exact sign of each crossing edge's 2D
// cross product from wider arithmetic, the same perturbation rule for zeros.
// From 16 vertices on, the library finds the crossing edges from bit masks of
// 64 vertices at a time (several per SIMD instruction), below that by the
// plain loop; these polygons have 3 to 257 vertices, so both paths run and
// blocks end everywhere relative to the crossings, and the rays
// go through vertices and edge points exactly, along the axes (exact zeros in
// the shear) and at random, for both precisions and both fill rules.

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "geometry/polygon.h"
#include "geometry/primitives.h"
#include "geometry/random.h"
#include "support/float_bits.h"

using namespace raylab;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;

/// Exact sign of ax·by − ay·bx: the products of two floats are exact in
/// double and those of two doubles in binary128 (113-bit significands), and a
/// rounded difference of two exact values is zero only when they are equal.
int exactCrossSign(float ax, float ay, float bx, float by) {
    const double d = double(ax) * double(by) - double(ay) * double(bx);
    return (d > 0) - (d < 0);
}
#if defined(__SIZEOF_FLOAT128__)
using Quad = __float128;
#else
using Quad = long double;  // binary128 where there is no __float128 (aarch64)
static_assert(std::numeric_limits<long double>::digits >= 106, "needs a 106-bit significand");
#endif
int exactCrossSign(double ax, double ay, double bx, double by) {
    const Quad d = Quad(ax) * Quad(by) - Quad(ay) * Quad(bx);
    return (d > 0) - (d < 0);
}

int dominant(const Vec3T<double>& v) {
    const double x = std::abs(v.x), y = std::abs(v.y), z = std::abs(v.z);
    return x >= y ? (x >= z ? 0 : 2) : (y >= z ? 1 : 2);
}

/// The textbook watertight test (Woop et al. 2013's shear, the origin
/// perturbed to (+ε, +ε)), edge by edge, in precision T.
template <class T>
bool referenceInside(const std::vector<Vec3>& vertices, const Ray& ray, FillRule rule) {
    const int kz = dominant(Vec3T<double>(Vec3T<T>(ray.d)));
    const int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
    const Vec3T<T> o(ray.o), d(ray.d);
    const T sx = d[kx] / d[kz], sy = d[ky] / d[kz];
    const auto shear = [&](const Vec3& v, T& x, T& y) {
        const T wz = T(v[kz]) - o[kz];
        x = (T(v[kx]) - o[kx]) - sx * wz;
        y = (T(v[ky]) - o[ky]) - sy * wz;
    };
    int winding = 0, crossings = 0;
    T ax, ay;
    shear(vertices.back(), ax, ay);
    for (const Vec3& v : vertices) {
        T bx, by;
        shear(v, bx, by);
        const bool aAbove = ay > 0, bAbove = by > 0;
        if (aAbove != bAbove) {
            const T lx = bAbove ? ax : bx, ly = bAbove ? ay : by;
            const T ux = bAbove ? bx : ax, uy = bAbove ? by : ay;
            int s = exactCrossSign(lx, ly, ux, uy);
            if (s == 0) s = ux > lx ? 1 : -1;
            if (s > 0) {
                winding += bAbove ? 1 : -1;
                ++crossings;
            }
        }
        ax = bx;
        ay = by;
    }
    return rule == FillRule::EvenOdd ? (crossings & 1) != 0 : winding != 0;
}

/// n vertices around a centre in a plane with normal `normal`: star-shaped
/// (sorted angles, random radii) or, with `tangled`, in random order (edges
/// cross each other, so the fill rules differ).
std::vector<Vec3> randomPolygon(SplitMix64& rng, size_t n, const Vec3& centre, const Vec3& normal,
                                bool tangled) {
    const Frame f = Frame::fromNormal(normalize(normal));
    std::vector<double> angles(n);
    for (double& a : angles) a = rng.uniform(0, 2 * kPi);
    if (!tangled) std::sort(angles.begin(), angles.end());
    std::vector<Vec3> v;
    for (double a : angles) {
        const double r = rng.uniform(0.3, 1.0);
        v.push_back(centre + (f.t * std::cos(a) + f.b * std::sin(a)) * r);
    }
    return v;
}

struct Tally {
    long rays = 0, inside = 0, differ = 0;
};

/// Rays from both sides of the plane, at least half the polygon's size away
/// and never grazing (|cos| >= 0.2), so the plane hit is never in doubt and
/// a hit is the inside test's answer.
template <class T>
void compare(const Polygon& poly, Precision precision, SplitMix64& rng, int count, Tally& tally) {
    const std::vector<Vec3>& v = poly.vertices();
    const Vec3 n = poly.normal();
    const Vec3 c = poly.bounds().centre();
    IntersectOptions opt;
    opt.precision = precision;
    opt.polygonTest = PolygonTest::Watertight;
    opt.polygonGrid = false;
    for (int i = 0; i < count; ++i) {
        Vec3 target;
        switch (i % 4) {
            case 0: target = v[rng.next() % v.size()]; break;  // a vertex exactly
            case 1: {
                const size_t k = rng.next() % v.size();
                target = v[k] + (v[(k + 1) % v.size()] - v[k]) * (i % 8 == 1 ? 0.5 : rng.uniform());
                break;
            }
            default: {
                const Vec3 p = c + rng.point(-1.1, 1.1);
                target = p - n * dot(p - c, n);  // in the plane
                break;
            }
        }
        Vec3 dir;
        do {
            // Every other ray along a coordinate axis: exact zeros in the shear.
            if (i % 2 == 0) {
                const double sign = rng.next() % 2 ? 1.0 : -1.0;
                const int axis = int(rng.next() % 3);
                dir = {axis == 0 ? sign : 0.0, axis == 1 ? sign : 0.0, axis == 2 ? sign : 0.0};
            } else {
                dir = rng.direction();
            }
        } while (std::abs(dot(dir, n)) < 0.2);
        const Vec3 o = target - dir * rng.uniform(1.0, 4.0);
        const Ray ray{o, dir * rng.uniform(0.5, 2.0)};
        const bool expected = referenceInside<T>(v, ray, poly.fillRule());
        const bool hit = poly.intersect(0, ray, 0, kInf, opt).has_value();
        ++tally.rays;
        tally.inside += expected;
        tally.differ += hit != expected;
    }
}

}  // namespace

TEST_CASE("polygon watertight test: bit masks of 64 vertices give the textbook loop's answers") {
    SplitMix64 rng(2026);
    // Both sides of the 16-vertex threshold and of every 64-vertex block.
    const std::vector<size_t> sizes{3,  4,  5,  8,   15,  16,  17,  31,  63,
                                    64, 65, 66, 127, 128, 129, 144, 200, 257};
    // Tilted planes (every dominant axis) and the coordinate planes (exact
    // zeros), near the origin and far from it.
    const std::vector<Vec3> normals{{0, 0, 1}, {0, 1, 0}, {1, 0, 0}, {0.3, -0.5, 0.8},
                                    {-0.9, 0.2, 0.1}, {0.1, 0.95, -0.3}};
    for (const FillRule rule : {FillRule::EvenOdd, FillRule::NonZero}) {
        for (const bool tangled : {false, true}) {
            Tally doubles, floats;
            for (size_t n : sizes) {
                for (size_t k = 0; k < normals.size(); ++k) {
                    const Vec3 centre = k % 2 ? Vec3{0, 0, 0} : Vec3{1e3, -2e3, 5e2};
                    PolygonParams p;
                    p.vertices = randomPolygon(rng, n, centre, normals[k], tangled);
                    p.rule = rule;
                    p.test = PolygonTest::Watertight;
                    const std::unique_ptr<Polygon> poly = Polygon::create(p);
                    poly->setSidedness(Sidedness::Both);
                    compare<double>(*poly, Precision::Double, rng, 200, doubles);
                    compare<float>(*poly, Precision::Float, rng, 200, floats);
                }
            }
            CAPTURE(int(rule));
            CAPTURE(tangled);
            CHECK(doubles.differ == 0);
            CHECK(floats.differ == 0);
            // Both answers occur often: the comparison is not all misses.
            CHECK(doubles.inside > doubles.rays / 5);
            CHECK(floats.inside > floats.rays / 5);
            CHECK(doubles.inside < doubles.rays * 4 / 5);
        }
    }
}

namespace {

/// Whether two intersect() answers are the same bit for bit (hit or miss, t, u, v).
bool sameAnswer(const std::optional<ShapeHit>& a, const std::optional<ShapeHit>& b) {
    if (a.has_value() != b.has_value()) return false;
    if (!a) return true;
    using test::bitsOf;
    return bitsOf(a->t) == bitsOf(b->t) && bitsOf(a->u) == bitsOf(b->u) &&
           bitsOf(a->v) == bitsOf(b->v);
}

/// n vertices of a gear-like outline (teeth of 4 vertices), radius `scale`.
std::vector<Vec3> gearPolygon(size_t n, double scale, const Vec3& centre, const Frame& f) {
    std::vector<Vec3> v;
    for (size_t i = 0; i < n; ++i) {
        const double a = 2 * kPi * double(i) / double(n);
        const double r = scale * ((i / 2) % 2 ? 1.0 : 0.8);
        v.push_back(centre + (f.t * std::cos(a) + f.b * std::sin(a)) * r);
    }
    return v;
}

}  // namespace

// The chunk boxes only skip computing vertices whose side of the x axis their
// box already decides; every answer must stay the vertex-by-vertex one bit for
// bit, also where the watertight test's own arithmetic underflows or
// overflows (tiny and huge polygons, subnormal direction components: a review
// found an earlier version that also skipped crossing edges changing answers
// there).
TEST_CASE("polygon watertight test: chunk boxes give the vertex-by-vertex answers at every scale") {
    SplitMix64 rng(99);
    const std::vector<size_t> sizes{16, 17, 24, 63, 64, 65, 144, 200};
    // From polygons whose area is barely a normal double to ones whose area
    // barely fits (Polygon::create needs it for the normal); float chunk boxes
    // stop at 2^100 (about 1.27e30).
    const std::vector<double> scales{1e-140, 1e-40, 1e-25, 1e-3, 1, 1e15, 1e20, 1e25, 1e30, 1e31, 1e150};
    const std::vector<Vec3> normals{{0, 0, 1}, {0, 1, 0}, {0.3, -0.5, 0.8}, {-0.9, 0.2, 0.1}};
    long rays = 0, differ = 0, hits = 0;
    for (const FillRule rule : {FillRule::EvenOdd, FillRule::NonZero}) {
        for (size_t n : sizes) {
            for (double scale : scales) {
                for (size_t k = 0; k < normals.size(); ++k) {
                    const Frame f = Frame::fromNormal(normalize(normals[k]));
                    const Vec3 centre = k % 2 ? Vec3{} : Vec3{3 * scale, -scale, 0.5 * scale};
                    PolygonParams p;
                    if ((n + k) % 3 == 0) {  // unit-sized around the origin, then scaled
                        p.vertices = randomPolygon(rng, n, Vec3{}, normals[k], (n + k) % 2 == 0);
                        for (Vec3& v : p.vertices) v = centre + v * scale;
                    } else {
                        p.vertices = gearPolygon(n, scale, centre, f);
                    }
                    p.rule = rule;
                    p.test = PolygonTest::Watertight;
                    const std::unique_ptr<Polygon> poly = Polygon::create(p);
                    poly->setSidedness(Sidedness::Both);
                    const std::vector<Vec3>& v = poly->vertices();
                    for (int i = 0; i < 60; ++i) {
                        Vec3 target;
                        switch (i % 5) {
                            case 0: target = v[rng.next() % v.size()]; break;
                            case 1: {
                                const size_t j = rng.next() % v.size();
                                target = v[j] + (v[(j + 1) % v.size()] - v[j]) * rng.uniform();
                                break;
                            }
                            case 2: target = centre; break;
                            case 3: {  // just beside a vertex
                                const Vec3 w = v[rng.next() % v.size()];
                                target = w + (w - centre) * std::ldexp(1.0, -int(rng.next() % 46));
                                break;
                            }
                            default: target = centre + (f.t * rng.uniform(-1.2, 1.2) +
                                                        f.b * rng.uniform(-1.2, 1.2)) * scale;
                        }
                        Vec3 dir = i % 3 == 0 ? -f.n : normalize(rng.direction() - f.n * 2.0);
                        if (i % 4 == 1) dir.x = (rng.next() % 2 ? 1 : -1) * 0x1p-1074;  // subnormal
                        if (i % 4 == 2) dir.y = -0.0;
                        const Ray ray{target - dir * scale * rng.uniform(0.5, 3), dir};
                        for (const Precision precision : {Precision::Double, Precision::Float}) {
                            IntersectOptions with, without;
                            with.precision = without.precision = precision;
                            with.polygonGrid = without.polygonGrid = false;
                            without.polygonChunkBoxes = false;
                            const auto a = poly->intersect(0, ray, 0, kInf, with);
                            const auto b = poly->intersect(0, ray, 0, kInf, without);
                            ++rays;
                            hits += b.has_value();
                            differ += !sameAnswer(a, b);
                        }
                    }
                }
            }
        }
    }
    CAPTURE(rays);
    CHECK(differ == 0);
    CHECK(hits > rays / 5);  // not all misses
    // The review's first case: a 16-vertex unit square and a direction with a
    // subnormal component, through the wrap-around edge's corner.
    PolygonParams square;
    for (int side = 0; side < 4; ++side)
        for (int j = 0; j < 4; ++j) {
            const double s = j / 4.0;
            const double xy[4][2] = {{s, 0}, {1, s}, {1 - s, 1}, {0, 1 - s}};
            square.vertices.push_back({xy[side][0], xy[side][1], 0});
        }
    square.test = PolygonTest::Watertight;
    const std::unique_ptr<Polygon> poly = Polygon::create(square);
    poly->setSidedness(Sidedness::Both);
    for (const Precision precision : {Precision::Double, Precision::Float}) {
        const double tiny = precision == Precision::Double ? 0x1p-1074 : 0x1p-149;
        IntersectOptions with, without;
        with.precision = without.precision = precision;
        without.polygonChunkBoxes = false;
        const Ray ray{{0, 0, 1}, {-tiny, 0, -1}};
        CHECK(sameAnswer(poly->intersect(0, ray, 0, kInf, with), poly->intersect(0, ray, 0, kInf, without)));
    }
}
