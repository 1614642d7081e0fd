// Planes, disks and polygons through the accelerators: rays parallel to the
// plane and in it, grazing rays, and rays through a vertex shared by a fan of
// polygons (NUMERICS.md §3.4 / §4 (10), (13), (14)). Each case also runs with
// the geometry 1e5 from the world origin (camera-relative Embree data).

#include <doctest/doctest.h>

#include <cmath>

#include "numerics/numerics_helpers.h"
#include "shape_queries.h"

using namespace raylab;
using namespace raylab::numerics_test;

namespace {

PolygonParams polygonParams(std::vector<Vec3> vertices, PolygonTest test) {
    PolygonParams p;
    p.vertices = std::move(vertices);
    p.test = test;
    return p;
}

/// Objects in the plane z = offset.z, all two-sided: 0 = clipped plane,
/// 1 = disk of radius 2, 2 = pentagon polygon (watertight test), 3 = the
/// same pentagon with the projected test, 4 = a two-triangle quad mesh.
Scene flatScene(const Vec3& offset) {
    Scene scene;
    scene.materials.resize(1);
    scene.objects.push_back(shapeObject("plane", makePlane(offset, {0, 0, 1}, 50)));
    scene.objects.push_back(shapeObject("disk", makeDisk(offset, {0, 0, 1}, 2)));
    std::vector<Vec3> pentagon;
    for (int k = 0; k < 5; ++k)
        pentagon.push_back(offset +
                           Vec3{2 * std::cos(2 * kPi * k / 5), 2 * std::sin(2 * kPi * k / 5), 0});
    scene.objects.push_back(
        shapeObject("pentagon", makePolygon(polygonParams(pentagon, PolygonTest::Watertight))));
    scene.objects.push_back(
        shapeObject("pentagon2d", makePolygon(polygonParams(pentagon, PolygonTest::Projected))));
    auto quad = accel_test::quadMesh(-2, -2, 2, 2, 0);
    for (Vec3& p : quad->positions) p += offset;
    scene.objects.push_back(meshObject("quad", quad));
    for (Object& o : scene.objects)
        if (o.shape) o.shape->setSidedness(Sidedness::Both);
    return scene;
}

/// The scene holding only object `i` of flatScene.
Scene only(const Vec3& offset, size_t i) {
    Scene all = flatScene(offset);
    Scene s;
    s.materials.resize(1);
    s.objects.push_back(std::move(all.objects[i]));
    return s;
}

}  // namespace

TEST_CASE("flat: rays parallel to the plane and rays lying in it miss, without NaN") {
    // n·d = 0: t = (d0 - n·o) / 0 is ±inf (parallel, off the plane) or NaN
    // (in the plane, 0/0). Both must be misses for intersect and occluded,
    // for every flat kind and back end, near the origin and 1e5 away.
    for (const Vec3 offset : {Vec3{0, 0, 0}, Vec3{1e5, -1e5, 1e5}}) {
        for (size_t i = 0; i < 5; ++i) {
            const Scene scene = only(offset, i);
            for (const Backend& b : allBackends()) {
                CAPTURE(b.label);
                CAPTURE(scene.objects[0].name);
                CAPTURE(offset.x);
                const auto accel = build(b, scene, offset + Vec3{0, 0, 3});
                Rng rng(909);
                int hits = 0;
                for (int k = 0; k < 200; ++k) {
                    const double phi = rng.uniform(0, 2 * kPi);
                    const Vec3 d{std::cos(phi), std::sin(phi), 0};
                    const Vec3 start{rng.uniform(-5, 5), rng.uniform(-5, 5), 0};
                    for (double h : {0.0, 1e-9, -1e-9, 0.5}) {
                        const Ray ray{offset + start + Vec3{0, 0, h}, d};
                        hits += accel->intersect(ray, 0, kInf).has_value();
                        hits += accel->occluded(ray, 0, kInf);
                    }
                }
                CHECK(hits == 0);
            }
        }
    }
}

TEST_CASE("flat: a ray at 1e-6 rad to the plane gives a finite t and an accurate hit point") {
    // From height h = 1e-3 at angle a = 1e-6 below the horizon: t = h / sin a
    // ≈ 1000 (|d| = 1), the hit point 1000 units away. The relative error of t
    // is ~ε / sin a for the plane formula in general, but here n·o and n·d are
    // exact, so t is good to a few ulps and the point to ~1e-12 relative. The quad mesh goes
    // through Embree's float triangle test (and is recomputed in double by Scene::surfaceAt).
    const double a = 1e-6, h = 1e-3;
    for (const Vec3 offset : {Vec3{0, 0, 0}, Vec3{1e5, -1e5, 1e5}}) {
        for (size_t i : {size_t(0), size_t(4)}) {
            // Large enough that the grazing ray lands on it 1000 units away.
            Scene scene;
            scene.materials.resize(1);
            if (i == 0) {
                scene.objects.push_back(shapeObject("plane", makePlane(offset, {0, 0, 1}, 5000)));
            } else {
                auto strip = accel_test::quadMesh(-1, -1, 2000, 1, 0);
                for (Vec3& p : strip->positions) p += offset;
                scene.objects.push_back(meshObject("strip", strip));
            }
            for (const Backend& b : allBackends()) {
                CAPTURE(b.label);
                CAPTURE(i);
                CAPTURE(offset.x);
                const Ray ray{offset + Vec3{0, 0, h}, {std::cos(a), 0, -std::sin(a)}};
                // Exact answer for the ray as stored (at 1e5 the height 1e-3 is
                // itself rounded to ulp(1e5) = 1.5e-11, which moves the hit by
                // ~4e-6 along x): long double, z - offset.z is exact (Sterbenz).
                using L = long double;
                const L tExact = L(ray.o.z - offset.z) / -L(ray.d.z);
                const Vec3 exact{double(L(ray.o.x) + tExact * L(ray.d.x)),
                                 double(L(ray.o.y) + tExact * L(ray.d.y)), offset.z};
                const auto accel = build(b, scene, ray.o);
                const auto hit = accel->intersect(ray, 0, kInf);
                REQUIRE(hit);
                CHECK(std::isfinite(hit->t));
                const SurfaceInteraction si = scene.surfaceAt(ray, *hit);
                const double dt = std::abs(hit->t - double(tExact)) / double(tExact);
                MESSAGE(b.label << " " << scene.objects[0].name << " offset " << offset.x
                                << ": |t - exact| / t = " << dt
                                << ", |p - exact| = " << length(si.p - exact));
                if (b.kind == AcceleratorKind::Naive || i == 0) CHECK(dt <= 1e-12);
                // Embree's float triangle t is only the search bound; surfaceAt redoes it.
                CHECK(length(si.p - exact) <= 1e-12 * double(tExact) + 1e-15 * length(offset));
                CHECK(isFinite(si.ng));
            }
        }
    }
}

TEST_CASE("flat: rays through the shared vertex of a polygon fan hit exactly one polygon") {
    // Seven coplanar polygons (alternately triangles and quads) around the
    // shared vertex c tile a disk; vertices are shared bit-exactly. Rays from
    // random points above, aimed exactly at c or at a shared edge's midpoint:
    // - with the watertight ray-space test exactly one polygon accepts each
    //   ray (polygon.h: symbolic perturbation breaks the ties consistently);
    // - through every back end the ray hits the fan at t = 1 (|d| = |c - o|),
    //   never misses;
    // - the lecture's projected test is reported (0 or 2 hits are possible).
    for (const Vec3 offset : {Vec3{0, 0, 0}, Vec3{1e5, -1e5, 1e5}}) {
        const Vec3 c = offset + Vec3{0.3, -0.2, 0};
        std::vector<Vec3> rim;
        for (int k = 0; k < 7; ++k) {
            const double phi = 2 * kPi * k / 7 + 0.1;
            rim.push_back(c + Vec3{std::cos(phi), std::sin(phi), 0} * (1.0 + 0.1 * k));
        }
        for (PolygonTest test : {PolygonTest::Watertight, PolygonTest::Projected}) {
            Scene scene;
            scene.materials.resize(1);
            for (int k = 0; k < 7; ++k) {
                const Vec3& a = rim[k];
                const Vec3& b = rim[(k + 1) % 7];
                std::vector<Vec3> v = {c, a, b};
                if (k % 2 == 1) v = {c, a, (a + b) * 0.5 + (a + b - c * 2) * 0.25, b};
                scene.objects.push_back(
                    shapeObject("fan" + std::to_string(k), makePolygon(polygonParams(v, test))));
            }
            const bool watertight = test == PolygonTest::Watertight;
            for (const Backend& b : allBackends()) {
                CAPTURE(b.label);
                CAPTURE(watertight);
                CAPTURE(offset.x);
                const auto accel = build(b, scene, c + Vec3{0, 0, 2});
                Rng rng(1001);
                int misses = 0, notOne = 0, rays = 0;
                double worstT = 0;
                for (int i = 0; i < 400; ++i) {
                    const Vec3 o =
                        c + Vec3{rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(0.1, 3)};
                    const Vec3 target = i % 2 == 0 ? c : (c + rim[i % 7]) * 0.5;
                    const Ray ray{o, target - o};
                    ++rays;
                    int accepting = 0;
                    for (const Object& obj : scene.objects)
                        accepting += intersect1(*obj.shape, ray, 0, kInf).has_value();
                    notOne += accepting != 1;
                    const auto hit = accel->intersect(ray, 0, kInf);
                    if (!hit) {
                        ++misses;
                        continue;
                    }
                    worstT = std::max(worstT, std::abs(hit->t - 1.0));
                }
                MESSAGE(std::string(watertight ? "watertight" : "projected")
                        << ", " << b.label << ", offset " << offset.x << ": " << misses << "/"
                        << rays << " misses, " << notOne
                        << " rays not accepted by exactly one polygon, worst |t - 1| " << worstT);
                if (watertight) {
                    CHECK(misses == 0);
                    CHECK(notOne == 0);
                    CHECK(worstT < 1e-12);
                }
            }
        }
    }
}
