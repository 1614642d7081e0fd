#include "tools/bench/primitive_bench.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iomanip>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "geometry/primitives.h"
#include "geometry/random.h"
#include "geometry/shape.h"

namespace raylab {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr int kRays = 1024;

/// The same ray sets on every platform and run.
using Rng = SplitMix64;

struct Case {
    std::string name;
    std::function<std::unique_ptr<Shape>()> make;
    bool polygonGrid = true;  ///< IntersectOptions::polygonGrid
};

/// Rays from a shell around the shape's box towards it. Hit-heavy rays aim at
/// points near the centre (spread over half the box), miss-heavy ones at points
/// 1.5 box sizes off to the side. Sidedness Both so back faces count too.
std::vector<Ray> makeRays(const Bounds3& b, bool hitHeavy, uint64_t seed) {
    Rng rng(seed);
    const Vec3 c = b.centre();
    const double size = std::max(length(b.extent()), 1e-3);
    std::vector<Ray> rays;
    rays.reserve(kRays);
    for (int i = 0; i < kRays; ++i) {
        const Vec3 o = c + rng.direction() * (size * rng.uniform(1.5, 3.0));
        Vec3 target =
            c + Vec3{rng.uniform(-0.25, 0.25), rng.uniform(-0.25, 0.25), rng.uniform(-0.25, 0.25)} *
                    size;
        if (!hitHeavy) {
            // Perpendicular offset from the line of sight: the ray passes beside the box.
            const Vec3 view = normalize(c - o);
            Vec3 side = cross(view, rng.direction());
            if (lengthSquared(side) == 0) side = cross(view, Vec3{1, 0, 0});
            target = target + normalize(side) * (1.5 * size);
        }
        rays.push_back({o, (target - o) * rng.uniform(0.5, 2.0)});
    }
    return rays;
}

struct Timing {
    double ns = 0;
    double hitFraction = 0;
};

Timing timeIntersect(const Shape& shape, const std::vector<Ray>& rays, int iterations,
                     Precision precision, bool polygonGrid) {
    IntersectOptions opt;
    opt.precision = precision;
    opt.polygonGrid = polygonGrid;
    Timing result;
    int hits = 0;
    for (const Ray& r : rays) hits += shape.intersect(0, r, 0, kInf, opt).has_value();  // warm-up
    result.hitFraction = static_cast<double>(hits) / static_cast<double>(rays.size());
    result.ns = std::numeric_limits<double>::infinity();
    for (int run = 0; run < 3; ++run) {
        int sink = 0;
        const auto start = std::chrono::steady_clock::now();
        for (int it = 0; it < iterations; ++it) {
            for (const Ray& r : rays) sink += shape.intersect(0, r, 0, kInf, opt).has_value();
        }
        const double ns =
            std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start)
                .count();
        // sink is used so the calls cannot be dropped.
        if (sink != hits * iterations) result.hitFraction = -1;
        result.ns = std::min(result.ns, ns / (static_cast<double>(iterations) * rays.size()));
    }
    return result;
}

std::unique_ptr<Shape> polygonShape(std::vector<Vec3> v, PolygonTest test) {
    PolygonParams p;
    p.vertices = std::move(v);
    p.test = test;
    return makePolygon(p);
}

std::vector<Vec3> gearFace() {
    // 144 vertices, 18 teeth: the shape of SPD gears' faces.
    std::vector<Vec3> v;
    for (int i = 0; i < 144; ++i) {
        const double a = 2 * kPi * i / 144;
        const double r = (i / 4) % 2 == 0 ? 1.0 : 0.8;
        v.push_back({r * std::cos(a), r * std::sin(a), 0.25});
    }
    return v;
}

std::vector<Case> cases() {
    const std::vector<Vec3> quad{{-1, -1, 0.3}, {1, -1, 0.3}, {1, 1, 0.3}, {-1, 1, 0.3}};
    std::vector<Case> c;
    c.push_back({"sphere", [] { return makeSphere({0.1, -0.2, 0.3}, 1.0); }});
    c.push_back({"plane", [] { return makePlane({0, 0, 0.2}, {0.1, 0.2, 1}, 2.0); }});
    c.push_back({"disk", [] { return makeDisk({0, 0, 0.2}, {0.1, 0.2, 1}, 1.0); }});
    c.push_back({"cylinder (open)", [] {
                     ConeParams p;
                     p.base = {0, 0, -1};
                     p.apex = {0.2, 0.1, 1};
                     p.baseRadius = p.apexRadius = 0.6;
                     return makeCone(p);
                 }});
    c.push_back({"cone (open)", [] {
                     ConeParams p;
                     p.base = {0, 0, -1};
                     p.apex = {0.2, 0.1, 1};
                     p.baseRadius = 0.8;
                     p.apexRadius = 0;
                     return makeCone(p);
                 }});
    c.push_back({"truncated cone (capped)", [] {
                     ConeParams p;
                     p.base = {0, 0, -1};
                     p.apex = {0.2, 0.1, 1};
                     p.baseRadius = 0.8;
                     p.apexRadius = 0.4;
                     p.capped = true;
                     return makeCone(p);
                 }});
    c.push_back({"quadric (ellipsoid)", [] {
                     QuadricParams p;
                     p.A = 1;
                     p.B = 0.5;
                     p.C = 2;
                     p.D = 0.3;
                     p.J = -1;
                     return makeQuadric(p);
                 }});
    c.push_back({"quadric (hyperboloid, clipped)", [] {
                     QuadricParams p;
                     p.A = 1;
                     p.B = 1;
                     p.C = -1;
                     p.J = -0.25;
                     p.clip = Bounds3({-1, -1, -1}, {1, 1, 1});
                     p.hasClip = true;
                     return makeQuadric(p);
                 }});
    c.push_back(
        {"quad, projected test", [quad] { return polygonShape(quad, PolygonTest::Projected); }});
    c.push_back(
        {"quad, watertight test", [quad] { return polygonShape(quad, PolygonTest::Watertight); }});
    c.push_back({"144-gon gear, projected test",
                 [] { return polygonShape(gearFace(), PolygonTest::Projected); }});
    c.push_back({"144-gon gear, watertight test",
                 [] { return polygonShape(gearFace(), PolygonTest::Watertight); }});
    c.push_back({"144-gon gear, watertight, no grid",
                 [] { return polygonShape(gearFace(), PolygonTest::Watertight); }, false});
    return c;
}

/// Fan of four quads tiling a tilted square; rays exactly through the shared edges
/// and the shared centre vertex. Returns the fraction of rays that hit no quad.
std::array<double, 2> fanMissRates(PolygonTest test, Precision precision) {
    const Vec3 origin{3.7, -12.1, 5.3};
    const Vec3 n = normalize(Vec3{0.3, -0.5, 0.8});
    const Vec3 t = normalize(cross(n, Vec3{1, 0, 0}));
    const Vec3 b = cross(n, t);
    const auto at = [&](double x, double y) { return origin + t * x + b * y; };
    const Vec3 centre = at(0.013, -0.021);
    const std::array<Vec3, 4> corners{at(1, 1), at(-1, 1), at(-1, -1), at(1, -1)};
    const std::array<Vec3, 4> mids{at(0.07, 1), at(-1, 0.11), at(-0.05, -1), at(1, -0.13)};
    std::vector<std::unique_ptr<Shape>> quads;
    for (int k = 0; k < 4; ++k)
        quads.push_back(polygonShape({centre, mids[(k + 3) % 4], corners[k], mids[k]}, test));
    IntersectOptions opt;
    opt.precision = precision;
    Rng rng(99);
    std::array<double, 2> rates{};
    const int count = 4000;
    for (int kind = 0; kind < 2; ++kind) {
        int misses = 0;
        for (int i = 0; i < count; ++i) {
            Vec3 target = centre;
            if (kind == 0) target = centre + (mids[i % 4] - centre) * rng.uniform(0.001, 0.999);
            Vec3 dir = rng.direction();
            if (dot(dir, n) < 0.05) dir = dir + n * (0.05 + 2 * std::abs(dot(dir, n)));
            const Vec3 o = target + dir * rng.uniform(0.5, 20);
            bool hit = false;
            for (const auto& q : quads)
                hit = hit || q->intersect(0, Ray{o, target - o}, 0, kInf, opt);
            misses += !hit;
        }
        rates[kind] = 100.0 * misses / count;
    }
    return rates;
}

}  // namespace

void runPrimitiveBench(std::ostream& out, int iterations) {
    iterations = std::max(1, iterations);
    const auto flags = out.flags();
    const auto precision = out.precision();
    out << "primitive intersect() cost: ns per call, best of 3 runs of " << iterations << " x "
        << kRays << " rays, 1 thread, two-sided\n";
    out << std::left << std::setw(32) << "shape" << std::setw(6) << "rays" << std::right
        << std::setw(11) << "double ns" << std::setw(7) << "hit%" << std::setw(11) << "float ns"
        << std::setw(7) << "hit%"
        << "\n";
    out << std::fixed;
    for (const Case& c : cases()) {
        auto shape = c.make();
        shape->setSidedness(Sidedness::Both);
        for (bool hitHeavy : {true, false}) {
            const std::vector<Ray> rays = makeRays(shape->bounds(), hitHeavy, hitHeavy ? 1 : 2);
            const Timing d =
                timeIntersect(*shape, rays, iterations, Precision::Double, c.polygonGrid);
            const Timing f =
                timeIntersect(*shape, rays, iterations, Precision::Float, c.polygonGrid);
            out << std::left << std::setw(32) << c.name << std::setw(6)
                << (hitHeavy ? "hit" : "miss") << std::right << std::setprecision(1)
                << std::setw(11) << d.ns << std::setw(7) << 100 * d.hitFraction << std::setw(11)
                << f.ns << std::setw(7) << 100 * f.hitFraction << "\n";
        }
    }
    out << "\npolygon watertightness (fan of 4 quads, rays exactly through shared edges / the "
           "shared vertex): % of rays missing every quad\n";
    out << std::left << std::setw(32) << "test" << std::right << std::setw(12) << "edge dbl"
        << std::setw(12) << "vertex dbl" << std::setw(12) << "edge flt" << std::setw(12)
        << "vertex flt"
        << "\n";
    for (PolygonTest test : {PolygonTest::Projected, PolygonTest::Watertight}) {
        const auto d = fanMissRates(test, Precision::Double);
        const auto f = fanMissRates(test, Precision::Float);
        out << std::left << std::setw(32)
            << (test == PolygonTest::Projected ? "projected (lecture)" : "watertight (ray space)")
            << std::right << std::setprecision(2) << std::setw(12) << d[0] << std::setw(12) << d[1]
            << std::setw(12) << f[0] << std::setw(12) << f[1] << "\n";
    }
    out.flags(flags);
    out.precision(precision);
}

}  // namespace raylab
