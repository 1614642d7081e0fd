// Shape::occluded's contract: the same answer as intersect(...).has_value(),
// for every analytic primitive (AnalyticShape answers it with its own inlined
// copy of intersectT, not through intersect). Rays aim at the shape, graze
// it, start on it (shadow feelers) and stop short of it, in both precisions,
// for both polygon inside tests and every sidedness.

#include <doctest/doctest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "geometry/primitives.h"
#include "geometry_test_helpers.h"

namespace raylab {
namespace {

struct NamedShape {
    std::string name;
    std::unique_ptr<Shape> shape;
};

/// A star of `points` spikes (concave; 2·points vertices) in the plane z = 0.5x + 1.
std::vector<Vec3> star(int points, double inner, double outer) {
    std::vector<Vec3> v;
    constexpr double kPi = 3.14159265358979323846;
    for (int i = 0; i < 2 * points; ++i) {
        const double a = kPi * i / points;
        const double r = i % 2 == 0 ? outer : inner;
        const double x = r * std::cos(a), y = r * std::sin(a);
        v.push_back({x, y, 0.5 * x + 1});
    }
    return v;
}

std::vector<NamedShape> everyAnalyticShape() {
    std::vector<NamedShape> s;
    s.push_back({"sphere", makeSphere({0.2, -0.1, 0.3}, 0.9)});
    s.push_back({"plane", makePlane({0, 0.1, 0}, {0.1, 1, 0.2}, 3)});
    s.push_back({"disk", makeDisk({0, 0, 0.2}, {0.3, 0.2, 1}, 1.1)});
    s.push_back({"cylinder", makeCone({{0, -1, 0}, 0.6, {0.1, 1, 0.2}, 0.6, false})});
    s.push_back({"capped cone", makeCone({{0, -1, 0}, 0.8, {0, 1, 0.1}, 0.3, true})});
    QuadricParams q;
    q.A = 1, q.B = 2, q.C = 0.5, q.J = -1;  // an ellipsoid
    s.push_back({"quadric", makeQuadric(q)});
    for (const PolygonTest test : {PolygonTest::Watertight, PolygonTest::Projected}) {
        const std::string suffix = test == PolygonTest::Watertight ? " (watertight)" : " (projected)";
        PolygonParams quad;
        quad.vertices = {{-1, -1, 0.1}, {1, -1, 0}, {1, 1, -0.1}, {-1, 1, 0}};
        quad.test = test;
        s.push_back({"quad" + suffix, makePolygon(quad)});
        PolygonParams gear;  // 48 vertices: the mask path and the grid
        gear.vertices = star(24, 0.6, 1.2);
        gear.test = test;
        s.push_back({"star" + suffix, makePolygon(gear)});
    }
    return s;
}

TEST_CASE("every analytic shape: occluded() answers exactly intersect().has_value()") {
    test::Rng rng(20261204);
    const double kInfinity = std::numeric_limits<double>::infinity();
    int hits = 0, misses = 0;
    for (NamedShape& named : everyAnalyticShape()) {
        for (const Sidedness sides : {Sidedness::Outside, Sidedness::Inside, Sidedness::Both}) {
            named.shape->setSidedness(sides);
            for (const Precision precision : {Precision::Double, Precision::Float}) {
                const IntersectOptions opt = withPrecision(precision);
                int differ = 0;
                for (int i = 0; i < 4000; ++i) {
                    Ray ray;
                    double tMin = 0, tMax = kInfinity;
                    switch (i % 4) {
                        case 0:  // from outside towards the shape's middle
                            ray.o = rng.direction() * rng.uniform(2, 6);
                            ray.d = rng.point(-0.8, 0.8) - ray.o;
                            break;
                        case 1:  // a feeler from a point the shape itself reports
                        {
                            const Ray aim{rng.direction() * 4, {}};
                            const Ray probe{aim.o, rng.point(-0.5, 0.5) - aim.o};
                            const auto h = intersect1(*named.shape, probe, 0, kInfinity, opt);
                            ray.o = h ? probe.at(h->t) : probe.o;
                            ray.d = rng.direction();
                            tMin = 1e-9;
                            break;
                        }
                        case 2:  // an interval that may end before the shape (t = 1 at the light)
                            ray.o = rng.direction() * 3;
                            ray.d = (rng.point(-0.5, 0.5) - ray.o) * rng.uniform(0.2, 1.5);
                            tMax = 1;
                            break;
                        default:  // from inside the bounds, any direction
                            ray.o = rng.point(-0.7, 0.7);
                            ray.d = rng.direction();
                            break;
                    }
                    const bool expected =
                        intersect1(*named.shape, ray, tMin, tMax, opt).has_value();
                    expected ? ++hits : ++misses;
                    if (occluded1(*named.shape, ray, tMin, tMax, opt) != expected) ++differ;
                }
                INFO(named.name << ", sides " << int(sides) << ", "
                                << (precision == Precision::Double ? "double" : "float"));
                CHECK(differ == 0);
            }
        }
    }
    // Both answers occur often, so agreement is not agreement on "no".
    CHECK(hits > 20000);
    CHECK(misses > 20000);
}

}  // namespace
}  // namespace raylab
