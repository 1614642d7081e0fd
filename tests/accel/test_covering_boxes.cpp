// Long slanted cylinders and cones go into Embree as several boxes each
// (Shape::appendCoveringBoxes), every box standing for the whole primitive.
// A ray that enters several boxes tests the primitive several times; the
// answers must still be the naive loop's, bit for bit: the closest hit (t, u,
// v, object), occlusion with and without the shadow cache's hint, and the
// transmittance of filtered feelers, which must count each crossing of a
// glass cylinder once however many of its boxes the feeler enters.

#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include "geometry/cone.h"
#include "geometry/frame.h"
#include "geometry/primitives.h"
#include "geometry/random.h"
#include "renderer/accel/embree_accelerator.h"
#include "renderer/accel/naive_accelerator.h"
#include "renderer/render_setup.h"

using namespace raylab;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct Rod {
    Vec3 base, apex;
    double r0, r1;
};

/// Random long rods (length 4 to 12, radius 0.05 to 0.4) in every
/// orientation around the origin: cylinders, cones and truncated cones,
/// half of them capped; every third one glass (kt 0.6, seen from both
/// sides), the rest matte. A ground plane below.
Scene rodScene(std::vector<Rod>& rods) {
    SplitMix64 rng(88);
    Scene s;
    Material matte;
    matte.kd = Color(0.6);
    Material glass;
    glass.kd = Color(0.0);
    glass.kt = Color(0.6);
    glass.ior = 1.5;
    s.materials = {matte, glass};
    for (int i = 0; i < 60; ++i) {
        ConeParams p;
        p.base = rng.point(-6, 6);
        p.apex = p.base + rng.direction() * rng.uniform(4, 12);
        p.baseRadius = rng.uniform(0.05, 0.4);
        p.apexRadius = i % 3 == 0 ? p.baseRadius * 0.5 : i % 3 == 1 ? p.baseRadius : 0.0;
        p.capped = i % 2 == 0;
        Object o;
        o.name = "rod " + std::to_string(i);
        o.shape = makeCone(p);
        const bool clear = i % 3 == 2;
        o.shape->setSidedness(clear ? Sidedness::Both : Sidedness::Outside);
        o.material = clear ? 1 : 0;
        s.objects.push_back(std::move(o));
        rods.push_back({p.base, p.apex, p.baseRadius, p.apexRadius});
    }
    Object ground;
    ground.name = "ground";
    ground.shape = makePlane({0, -14, 0}, {0, 1, 0}, 40);
    s.objects.push_back(std::move(ground));
    s.lights.push_back(Light{});
    return s;
}

/// A point on a rod's side at fraction f of its length and angle phi, and
/// the unit tangent of the side there around the axis.
Vec3 sidePoint(const Rod& r, double f, double phi, Vec3& around) {
    const Vec3 axis = r.apex - r.base;
    const Frame fr = Frame::fromNormal(normalize(axis));
    const double rho = r.r0 + (r.r1 - r.r0) * f;
    around = fr.b * std::cos(phi) - fr.t * std::sin(phi);
    return r.base + axis * f + (fr.t * std::cos(phi) + fr.b * std::sin(phi)) * rho;
}

}  // namespace

TEST_CASE("covering boxes: slanted rods give the naive loop's hits, occlusion and shadows") {
    std::vector<Rod> rods;
    const Scene s = rodScene(rods);
    size_t boxes = 0;
    for (const Object& o : s.objects) {
        std::vector<Bounds3> b;
        o.shape->appendCoveringBoxes(0, IntersectOptions{}, b);
        boxes += b.size();
    }
    MESSAGE("objects ", s.objects.size(), ", Embree boxes ", boxes);
    CHECK(boxes > 2 * s.objects.size());  // most rods are split

    RenderOverrides overrides;
    const RenderOptions options = resolveRenderOptions(s, overrides);
    const EmbreeAccelerator embree(s, options.accelOptions);
    const NaiveAccelerator naive(s, options.accelOptions);

    SplitMix64 rng(5);
    int hits = 0, grazingHits = 0, blocked = 0, dimmed = 0;
    for (int k = 0; k < 30000; ++k) {
        // A third random rays, a third aimed at a random side point, a third
        // grazing: along the side's tangent through such a point.
        Ray ray;
        const int kind = k % 3;
        if (kind == 0) {
            ray = Ray{rng.point(-16, 16), rng.direction()};
        } else {
            const Rod& r = rods[rng.next() % rods.size()];
            Vec3 around;
            const Vec3 p = sidePoint(r, rng.uniform(0, 1), rng.uniform(0, 6.283185307179586),
                                     around);
            const Vec3 d = kind == 1 ? p - rng.point(-16, 16)
                                     : around * std::cos(rng.uniform(-1.5, 1.5)) +
                                           normalize(r.apex - r.base) * rng.uniform(-1, 1);
            ray = Ray{p - d * rng.uniform(1, 3), d};
        }
        const double tMin = k % 4 == 0 ? rng.uniform(0, 2) : 1e-9;
        CAPTURE(k);
        const auto e = embree.intersect(ray, tMin, kInf);
        const auto n = naive.intersect(ray, tMin, kInf);
        REQUIRE(e.has_value() == n.has_value());
        if (n) {
            ++hits;
            grazingHits += kind == 2;
            CHECK(e->object == n->object);
            CHECK(e->prim == n->prim);
            CHECK(e->t == n->t);
            CHECK(e->u == n->u);
            CHECK(e->v == n->v);
        }
        // Feelers over a finite stretch, as towards a light.
        const double tMax = rng.uniform(2, 30);
        const bool occluded = naive.occluded(ray, tMin, tMax);
        CHECK(embree.occluded(ray, tMin, tMax) == occluded);
        OcclusionHint hint;
        CHECK(embree.occluded(ray, tMin, tMax, hint) == occluded);
        OcclusionHint again = hint;  // a hint that names one of several boxes
        CHECK(embree.occluded(ray, tMin, tMax, again) == occluded);
        const Color through = naive.transmittance(ray, tMin, tMax);
        CHECK(embree.transmittance(ray, tMin, tMax) == through);
        if (through.isBlack()) ++blocked;
        else if (through.r < 1.0) ++dimmed;
    }
    MESSAGE("hits ", hits, " (grazing ", grazingHits, "), feelers blocked ", blocked,
            ", dimmed by glass ", dimmed);
    CHECK(hits > 12000);
    CHECK(grazingHits > 3000);
    CHECK(blocked > 3000);
    CHECK(dimmed > 1000);
}

TEST_CASE("covering boxes: a feeler along a glass cylinder's axis counts each wall once") {
    // A glass cylinder (kt 0.6) from (0,0,0) to (8,8,0), radius 0.2, covered
    // by four boxes; feelers cross it at right angles to the axis at every
    // height, through the box slices' shared ends too. Each crosses the side
    // twice: 0.6² = 0.36, however many boxes it enters.
    Scene s;
    Material glass;
    glass.kd = Color(0.0);
    glass.kt = Color(0.6);
    glass.ior = 1.5;
    s.materials = {glass};
    ConeParams p;
    p.base = {0, 0, 0};
    p.apex = {8, 8, 0};
    p.baseRadius = p.apexRadius = 0.2;
    Object o;
    o.name = "glass rod";
    o.shape = makeCone(p);
    o.shape->setSidedness(Sidedness::Both);
    std::vector<Bounds3> boxes;
    o.shape->appendCoveringBoxes(0, IntersectOptions{}, boxes);
    REQUIRE(boxes.size() == 4);
    s.objects.push_back(std::move(o));
    s.lights.push_back(Light{});
    RenderOverrides overrides;
    const RenderOptions options = resolveRenderOptions(s, overrides);
    const EmbreeAccelerator embree(s, options.accelOptions);
    const NaiveAccelerator naive(s, options.accelOptions);
    for (int i = 1; i < 400; ++i) {
        const double a = 8.0 * i / 400;  // the slices meet at a = 2, 4, 6
        for (const Vec3& d : {Vec3{1, -1, 0}, Vec3{1, -1, 1}, Vec3{0, 0, 1}}) {
            const Ray ray{Vec3{a, a, 0} - d * 5, d};
            CAPTURE(a);
            const Color expected = naive.transmittance(ray, 0, 10);
            CHECK(expected.r == doctest::Approx(0.36));
            CHECK(embree.transmittance(ray, 0, 10) == expected);
        }
    }
}

TEST_CASE("covering boxes: rays grazing the corners where slices meet, in both precisions") {
    // The cylinder (0,0,0) -> (4,4,0), radius 0.1, is cut into four slices
    // whose boxes meet the surface at the shared end disks, e.g. at
    // (1 + e, 1 - e, 0), e = 0.1/sqrt(2). Near-vertical rays from 300 away
    // graze the side there (just inside and just outside its radius), on
    // both sides, between parallel rods that make
    // the BVH keep the slices apart. Double precision: the slices' margin
    // covers the test's rounding, so Embree finds the naive loop's hits. Float
    // precision: hits may stray by about FLT_EPSILON x 300 from the surface,
    // so the cylinder keeps its one loose box, and agrees too.
    Scene s;
    Material matte;
    matte.kd = Color(0.5);
    s.materials = {matte};
    const auto addRod = [&](Vec3 base) {
        ConeParams p;
        p.base = base;
        p.apex = base + Vec3{4, 4, 0};
        p.baseRadius = p.apexRadius = 0.1;
        Object o;
        o.name = "rod";
        o.shape = makeCone(p);
        s.objects.push_back(std::move(o));
    };
    addRod({0, 0, 0});
    for (int k = 1; k <= 40; ++k)
        for (int j = -2; j <= 2; ++j)
            addRod(Vec3{1, -1, 0} * (0.5 * k / std::sqrt(2.0)) + Vec3{5.0 * j, 5.0 * j, 0});
    s.lights.push_back(Light{});
    const Vec3 across = Vec3{1, -1, 0} / std::sqrt(2.0), along = Vec3{1, 1, 0} / std::sqrt(2.0);
    for (const Precision precision : {Precision::Double, Precision::Float}) {
        AccelOptions options;
        options.intersect.precision = precision;
        const EmbreeAccelerator embree(s, options);
        const NaiveAccelerator naive(s, options);
        SplitMix64 rng(7);
        int hits = 0;
        for (int k = 0; k < 40000; ++k) {
            const int slice = 1 + int(rng.next() % 3);
            const double side = (rng.next() & 1) ? 1 : -1;
            const Vec3 corner = Vec3{double(slice), double(slice), 0} + across * (side * 0.1);
            const double a = rng.uniform(-1, 1) * 4e-6;
            const Vec3 d = Vec3{0, 0, std::cos(a)} + along * std::sin(a);
            const Vec3 q = corner + across * (side * rng.uniform(-6e-5, 6e-5));
            const Ray ray{q - d * 300.0, d};
            const auto n = naive.intersect(ray, 0, kInf);
            const auto e = embree.intersect(ray, 0, kInf);
            CAPTURE(k);
            REQUIRE(e.has_value() == n.has_value());
            if (n) {
                ++hits;
                CHECK(e->t == n->t);
                CHECK(e->u == n->u);
                CHECK(e->v == n->v);
            }
            CHECK(embree.occluded(ray, 0, 600) == naive.occluded(ray, 0, 600));
        }
        CHECK(hits > 4000);
    }
}
