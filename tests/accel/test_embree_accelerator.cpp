// Embree-specific behaviour of the adaptor: the ray it hands to Embree (mask,
// flags, interval rounding, camera-relative origin), bounds Embree would drop
// (infinite, NaN), bad meshes, the device configuration, and queries made
// directly on rtcHandle(): bare rtcIntersect1 replay, 8-wide packets and
// streams (callbacks handle any N and valid[]), masks and the occlusion marker.

#include <doctest/doctest.h>
#include <embree3/rtcore.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "accel/accel_test_helpers.h"
#include "geometry/random.h"
#include "renderer/accel/embree_accelerator.h"
#include "renderer/accel/naive_accelerator.h"
#include "renderer/io/scene_loader.h"
#include "renderer/render_setup.h"

using namespace raylab;
using namespace raylab::accel_test;

namespace {

/// Objects: 0 = unit sphere at the origin, 1 = quad [2,4]×[-1,1] at z = 0.
Scene smallScene() {
    Scene scene;
    scene.materials.resize(1);
    scene.objects.push_back(shapeObject("ball", makeSphere({0, 0, 0}, 1)));
    scene.objects.push_back(meshObject("quad", quadMesh(2, -1, 4, 1, 0)));
    return scene;
}

RTCRayHit rayHit(const EmbreeAccelerator& accel, const Ray& ray, double tMin, double tMax) {
    RTCRayHit rh{};
    REQUIRE(accel.toEmbreeRay(ray, tMin, tMax, rh.ray));
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    return rh;
}

}  // namespace

TEST_CASE("embree: the Embree ray is relative to the origin, masked, and brackets the interval") {
    const Scene scene = smallScene();
    AccelOptions options;
    options.origin = {100, 0, 0};
    const EmbreeAccelerator accel(scene, options);
    CHECK(accel.origin() == Vec3{100, 0, 0});

    RTCRay r{};
    REQUIRE(accel.toEmbreeRay(Ray{{101, 2, 3}, {0, 0.5, -1}}, 0.1, kInf, r));
    CHECK(r.org_x == 1.0f);  // 101 - 100
    CHECK(r.org_y == 2.0f);
    CHECK(r.org_z == 3.0f);
    CHECK(r.dir_y == 0.5f);
    CHECK(r.mask == 0xFFFFFFFFu);  // an unset mask drops hits silently
    CHECK(r.flags == 0u);
    CHECK(r.time == 0.0f);
    // 0.1 is not a float: tnear is the largest float below it.
    CHECK(double(r.tnear) < 0.1);
    CHECK(double(std::nextafter(r.tnear, 1.0f)) > 0.1);
    CHECK(r.tfar == std::numeric_limits<float>::infinity());

    REQUIRE(accel.toEmbreeRay(Ray{{101, 2, 3}, {0, 0, 1}}, -5, 1e300, r));
    CHECK(r.tnear == 0.0f);                                   // Embree requires tnear >= 0
    CHECK(r.tfar == std::numeric_limits<float>::infinity());  // beyond float range
    REQUIRE(accel.toEmbreeRay(Ray{{101, 2, 3}, {0, 0, 1}}, 0, 2.5, r));
    CHECK(r.tfar == 2.5f);

    // Not traceable: non-finite, zero direction, empty interval, beyond float range.
    CHECK_FALSE(accel.toEmbreeRay(Ray{{101, 2, 3}, {0, 0, 0}}, 0, kInf, r));
    CHECK_FALSE(accel.toEmbreeRay(Ray{{101, 2, 3}, {0, 0, 1}}, 1, 1, r));
    CHECK_FALSE(accel.toEmbreeRay(Ray{{1e300, 2, 3}, {0, 0, 1}}, 0, kInf, r));
    CHECK_FALSE(accel.toEmbreeRay(Ray{{101, 2, 3}, {1e-60, 0, 0}}, 0, kInf, r));
}

namespace {

/// The conversion's rules stated one coordinate at a time (the scalar code
/// the SSE2 version replaced): the reference for the test below.
bool referenceEmbreeRay(const Vec3& origin, const Ray& ray, double tMin, double tMax, RTCRay& out) {
    constexpr double kFloatOverflow = 0x1.ffffffp127;
    const double ox = ray.o.x - origin.x, oy = ray.o.y - origin.y, oz = ray.o.z - origin.z;
    const bool inRange = std::abs(ox) < kFloatOverflow && std::abs(oy) < kFloatOverflow &&
                         std::abs(oz) < kFloatOverflow && std::abs(ray.d.x) < kFloatOverflow &&
                         std::abs(ray.d.y) < kFloatOverflow && std::abs(ray.d.z) < kFloatOverflow;
    if (!(inRange && tMin < tMax)) return false;
    out.org_x = static_cast<float>(ox);
    out.org_y = static_cast<float>(oy);
    out.org_z = static_cast<float>(oz);
    out.dir_x = static_cast<float>(ray.d.x);
    out.dir_y = static_cast<float>(ray.d.y);
    out.dir_z = static_cast<float>(ray.d.z);
    if (out.dir_x == 0.0f && out.dir_y == 0.0f && out.dir_z == 0.0f) return false;
    if (tMin > 0) {
        float f = static_cast<float>(std::min(tMin, double(FLT_MAX)));
        if (double(f) > tMin) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
        out.tnear = f;
    } else {
        out.tnear = 0.0f;
    }
    out.time = 0;
    const float inf = std::numeric_limits<float>::infinity();
    out.tfar = tMax > double(FLT_MAX) ? inf : (tMax < -double(FLT_MAX) ? -inf : float(tMax));
    out.mask = 0xFFFFFFFFu;
    out.id = 0;
    out.flags = 0;
    return true;
}

}  // namespace

TEST_CASE("embree: the ray conversion gives the scalar rules' floats, bit for bit") {
    const Scene scene = smallScene();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double overflow = 0x1.ffffffp127;
    // Values where the rules change: around float overflow, around float
    // underflow to zero (2^-150), signed zeros, subnormal doubles, NaN, Inf.
    const std::vector<double> special = {0.0, -0.0, 1.0, -2.5, 0x1p-150, 0x1.000001p-150,
                                         -0x1p-150, 0x1p-149, 0x1p-1074, -0x1p-1060, 1e-300,
                                         double(FLT_MAX), -double(FLT_MAX), overflow, -overflow,
                                         std::nextafter(overflow, 0.0), -std::nextafter(overflow, 0.0),
                                         std::nextafter(overflow, kInf), 1e300, kInf, -kInf, nan};
    for (const Vec3& origin : {Vec3{0, 0, 0}, Vec3{101, -2, 3e5}, Vec3{-1e15, 1e-20, 7}}) {
        AccelOptions options;
        options.origin = origin;
        const EmbreeAccelerator accel(scene, options);
        SplitMix64 rng(42);
        const auto value = [&]() {
            switch (rng.next() % 4) {
                case 0: return special[rng.next() % special.size()];
                case 1: return rng.uniform(-1000, 1000);
                case 2: return std::ldexp(rng.uniform(-1, 1), int(rng.next() % 600) - 300);
                default: return std::ldexp(rng.uniform(-1, 1), int(rng.next() % 60) - 170);
            }
        };
        long accepted = 0, compared = 0;
        for (int i = 0; i < 300000; ++i) {
            const Ray ray{{value(), value(), value()}, {value(), value(), value()}};
            const double tMin = i % 3 == 0 ? value() : 1e-6 * (i % 7);
            const double tMax = i % 5 == 0 ? value() : kInf;
            RTCRay got, want;
            std::memset(&got, 0xAB, sizeof got);
            std::memset(&want, 0xAB, sizeof want);
            const bool g = accel.toEmbreeRay(ray, tMin, tMax, got);
            const bool w = referenceEmbreeRay(origin, ray, tMin, tMax, want);
            ++compared;
            REQUIRE(g == w);
            if (!g) continue;
            ++accepted;
            CHECK(std::memcmp(&got, &want, sizeof got) == 0);
        }
        CHECK(accepted > compared / 10);
    }
}

TEST_CASE("embree: the ray conversion's edge cases: float range, tnear rounding, NaN") {
    const Scene scene = smallScene();
    const EmbreeAccelerator accel(scene);
    RTCRay r{};
    // Origins and directions convert while they round to a finite float:
    // FLT_MAX and anything below the midpoint to 2^128 do, the midpoint does not.
    const double below = std::nextafter(0x1.ffffffp127, 0.0);
    CHECK(accel.toEmbreeRay(Ray{{double(FLT_MAX), 0, 0}, {0, 0, 1}}, 0, kInf, r));
    CHECK(r.org_x == FLT_MAX);
    CHECK(accel.toEmbreeRay(Ray{{0, -below, 0}, {0, 0, 1}}, 0, kInf, r));
    CHECK(r.org_y == -FLT_MAX);
    CHECK_FALSE(accel.toEmbreeRay(Ray{{0, 0, 0x1.ffffffp127}, {0, 0, 1}}, 0, kInf, r));
    CHECK(accel.toEmbreeRay(Ray{{0, 0, 0}, {0, below, 1}}, 0, kInf, r));
    CHECK_FALSE(accel.toEmbreeRay(Ray{{0, 0, 0}, {-0x1.ffffffp127, 0, 1}}, 0, kInf, r));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    CHECK_FALSE(accel.toEmbreeRay(Ray{{nan, 0, 0}, {0, 0, 1}}, 0, kInf, r));
    CHECK_FALSE(accel.toEmbreeRay(Ray{{0, 0, 0}, {0, nan, 1}}, 0, kInf, r));
    CHECK_FALSE(accel.toEmbreeRay(Ray{{0, 0, 0}, {0, 0, 1}}, nan, kInf, r));
    CHECK_FALSE(accel.toEmbreeRay(Ray{{0, 0, 0}, {0, 0, 1}}, 0, nan, r));
    CHECK_FALSE(accel.toEmbreeRay(Ray{{0, 0, kInf}, {0, 0, 1}}, 0, kInf, r));
    // A direction whose components all underflow float is zero.
    CHECK_FALSE(accel.toEmbreeRay(Ray{{0, 0, 0}, {1e-46, -1e-46, 1e-50}}, 0, kInf, r));
    CHECK(accel.toEmbreeRay(Ray{{0, 0, 0}, {1e-46, -1e-46, 1e-30}}, 0, kInf, r));
    // tnear: the largest float <= tMin, for values that are floats, that round
    // up, that round down, subnormal and beyond float range.
    for (double t : {0.1, 0.5, 1.0 / 3, 2.0 / 3, 1e-30, 1e-40, 1e-45, 3e38, 1e39, 1e300,
                     double(FLT_MAX), std::nextafter(1.0, 2.0), std::nextafter(1.0, 0.0)}) {
        CAPTURE(t);
        REQUIRE(accel.toEmbreeRay(Ray{{0, 0, 0}, {0, 0, 1}}, t, kInf, r));
        const double clamped = std::min(t, double(FLT_MAX));
        CHECK(double(r.tnear) <= clamped);
        CHECK(double(std::nextafter(r.tnear, std::numeric_limits<float>::infinity())) > clamped);
    }
}

TEST_CASE("embree: camera-relative data keeps a tiny triangle far from the world origin") {
    // A triangle with 0.003-long legs at (1e5, 1e5, 1e5 - 10): a float ulp
    // there is 2^-7 = 0.0078, so in absolute float coordinates all three
    // vertices round to the same point (0.003 < half an ulp) and the triangle
    // vanishes. Relative to the eye
    // (1e5, 1e5, 1e5) it is exact.
    const Vec3 eye{1e5, 1e5, 1e5};
    Scene scene;
    scene.materials.resize(1);
    auto mesh = std::make_shared<TriangleMesh>();
    mesh->positions = {eye + Vec3{0, 0, -10}, eye + Vec3{0.003, 0, -10}, eye + Vec3{0, 0.003, -10}};
    mesh->triangles = {{0, 1, 2}};
    scene.objects.push_back(meshObject("tiny", mesh));
    // And a sphere of radius 0.002 beside it: analytic shapes are intersected
    // in double either way, only their (outward-rounded) boxes are float.
    scene.objects.push_back(shapeObject("speck", makeSphere(eye + Vec3{0.02, 0, -10}, 0.002)));

    AccelOptions relative;
    relative.origin = eye;
    const EmbreeAccelerator rel(scene, relative);
    const EmbreeAccelerator abs(scene, AccelOptions{});
    const NaiveAccelerator naive(scene);

    // Rays from the eye to the centroid and to points 10% inside each vertex.
    const Vec3 c = (mesh->positions[0] + mesh->positions[1] + mesh->positions[2]) / 3.0;
    for (int k = -1; k < 3; ++k) {
        const Vec3 target = k < 0 ? c : mesh->positions[k] + (c - mesh->positions[k]) * 0.1;
        const Ray ray{eye, target - eye};
        const auto n = naive.intersect(ray, 0, kInf);
        const auto r = rel.intersect(ray, 0, kInf);
        REQUIRE(n);
        REQUIRE(r);
        CHECK(r->object == 0);
        CHECK(r->prim == 0);
        CHECK(r->t == doctest::Approx(n->t).epsilon(1e-6));
        CHECK_FALSE(abs.intersect(ray, 0, kInf));  // collapsed in absolute float coordinates
    }
    const Ray toSpeck{eye, Vec3{0.02, 0.0005, -10}};
    const auto ns = naive.intersect(toSpeck, 0, kInf);
    REQUIRE(ns);
    for (const EmbreeAccelerator* accel : {&rel, &abs}) {
        const auto h = accel->intersect(toSpeck, 0, kInf);
        REQUIRE(h);
        CHECK(h->object == 1);
        CHECK(h->t == ns->t);  // bit-identical double
    }
}

TEST_CASE("embree: infinite bounds are clamped, not silently dropped") {
    // Embree ignores a user primitive whose box is not finite (NUMERICS.md §1);
    // the adaptor clamps it to ±1e18 around the origin, so it stays hittable.
    Scene scene;
    scene.materials.resize(1);
    scene.objects.push_back(shapeObject("unbounded", std::make_unique<UnboundedPlaneZ>(-2)));
    const EmbreeAccelerator accel(scene);
    const NaiveAccelerator naive(scene);
    for (const Vec3& o : {Vec3{0, 0, 0}, Vec3{1e6, -3e6, 0}, Vec3{-1e12, 1e12, 5}}) {
        const Ray ray{o, {0, 0, -1}};
        const auto h = accel.intersect(ray, 0, kInf);
        REQUIRE(h);
        CHECK(h->t == naive.intersect(ray, 0, kInf)->t);
        CHECK(accel.occluded(ray, 0, kInf));
    }
    RTCBounds b;
    rtcGetSceneBounds(accel.rtcHandle(), &b);
    CHECK(b.lower_x <= -1e17f);
    CHECK(b.upper_y >= 1e17f);
    CHECK(std::isfinite(b.lower_x));

    // The clipped plane of primitives.h reports finite bounds and is hit.
    auto plane = makePlane({0, 0, -1}, {0, 0, 1});
    CHECK(plane->bounds().finite());
    Scene planeScene;
    planeScene.objects.push_back(shapeObject("plane", std::move(plane)));
    const EmbreeAccelerator planeAccel(planeScene);
    const auto p = planeAccel.intersect(Ray{{5e4, 5e4, 3}, {0, 0, -1}}, 0, kInf);
    REQUIRE(p);
    CHECK(p->t == doctest::Approx(4.0).epsilon(1e-15));
}

TEST_CASE("embree: geometry Embree cannot represent is rejected at build time") {
    SUBCASE("NaN bounds") {
        Scene scene;
        scene.objects.push_back(shapeObject("broken", std::make_unique<NanBoundsShape>()));
        CHECK_THROWS_WITH_AS(EmbreeAccelerator{scene},
                             "embree: object 'broken' (nan-bounds): NaN bounds",
                             std::invalid_argument);
    }
    SUBCASE("the first broken object in scene order is named, whichever thread meets it") {
        // The user-geometry table is made from blocks of 512 objects in
        // parallel; the error is still the one a loop in object order meets
        // first. The first broken object ends its block and the second starts
        // one, so the later block's error is usually met first in time.
        Scene scene;
        for (int i = 0; i < 3000; ++i) {
            const bool broken = i == 1023 || i == 1536;
            scene.objects.push_back(
                broken ? shapeObject("broken" + std::to_string(i), std::make_unique<NanBoundsShape>())
                       : shapeObject("ball" + std::to_string(i), makeSphere({double(i), 0, 0}, 0.4)));
        }
        for (int repeat = 0; repeat < 20; ++repeat)
            CHECK_THROWS_WITH_AS(EmbreeAccelerator{scene},
                                 "embree: object 'broken1023' (nan-bounds): NaN bounds",
                                 std::invalid_argument);
    }
    SUBCASE("index out of range") {
        Scene scene;
        auto mesh = quadMesh(0, 0, 1, 1, 0);
        mesh->triangles[1][2] = 4;
        scene.objects.push_back(meshObject("bad", mesh));
        CHECK_THROWS_WITH_AS(EmbreeAccelerator{scene},
                             "embree: object 'bad' (triangle mesh): triangle 1 uses vertex 4 of 4",
                             std::invalid_argument);
        CHECK_THROWS_WITH_AS(NaiveAccelerator{scene},
                             "naive: object 'bad' (triangle mesh): triangle 1 uses vertex 4 of 4",
                             std::invalid_argument);
    }
    SUBCASE("non-finite vertex") {
        Scene scene;
        auto mesh = quadMesh(0, 0, 1, 1, 0);
        mesh->positions[2].y = std::numeric_limits<double>::quiet_NaN();
        scene.objects.push_back(meshObject("nan", mesh));
        CHECK_THROWS_WITH_AS(EmbreeAccelerator{scene},
                             "embree: object 'nan' (triangle mesh): vertex 2 is not finite or too far from the "
                             "origin",
                             std::invalid_argument);
    }
}

TEST_CASE("embree: device configuration") {
    const Scene scene = smallScene();
    // threads= would throttle the whole process through tbb::global_control.
    CHECK_THROWS_AS(EmbreeAccelerator(scene, {}, "threads=2"), std::invalid_argument);
    CHECK_THROWS_AS(EmbreeAccelerator(scene, {}, "verbose=0, threads = 1"), std::invalid_argument);
    // A malformed value makes rtcNewDevice fail; surfaced as an exception.
    // (Embree 3.13.5 silently ignores unknown keys such as "no_such_option=1".)
    CHECK_THROWS_WITH_AS(EmbreeAccelerator(scene, {}, "verbose=x"),
                         "embree: cannot create device (RTC_ERROR_UNKNOWN)", std::runtime_error);
    // Pinning the ISA (golden tests): analytic hits stay bit-identical.
    const EmbreeAccelerator sse2(scene, {}, "isa=sse2");
    const EmbreeAccelerator native(scene);
    const Ray ray{{0.3, 0.2, 5}, {0, 0, -1}};
    const auto a = sse2.intersect(ray, 0, kInf);
    const auto b = native.intersect(ray, 0, kInf);
    REQUIRE(a);
    REQUIRE(b);
    CHECK(a->t == b->t);
    CHECK(native.buildSeconds() >= 0);
    CHECK(native.buildSeconds() < 10);
    CHECK(native.rtcHandle() != nullptr);
}

TEST_CASE("embree: bare rtcIntersect1 replay, masks and the occlusion marker") {
    const Scene scene = smallScene();
    const EmbreeAccelerator accel(scene);
    REQUIRE(accel.userGeometryId() != RTC_INVALID_GEOMETRY_ID);
    const Ray toBall{{0.25, 0, 5}, {0, 0, -1}};  // sphere at t = 5 - sqrt(1 - 0.0625)
    const Ray toQuad{{3, 0.5, 5}, {0, 0, -1}};   // quad at t = 5

    // Without the double ray in the context the callbacks use Embree's float lane.
    for (const Ray& ray : {toBall, toQuad}) {
        RTCRayHit rh = rayHit(accel, ray, 0, kInf);
        EmbreeQueryContext ctx;
        ctx.init(nullptr, 0, kInf);
        rtcIntersect1(accel.rtcHandle(), &ctx.rtc, &rh);
        const auto bare = accel.decode(rh, ctx);
        const auto full = accel.intersect(ray, 0, kInf);
        REQUIRE(bare);
        REQUIRE(full);
        CHECK(bare->object == full->object);
        CHECK(bare->t == doctest::Approx(full->t).epsilon(1e-6));
        CHECK(rh.hit.instID[0] == RTC_INVALID_GEOMETRY_ID);
    }
    {
        // The analytic callback fills Embree's hit record per the contract.
        RTCRayHit rh = rayHit(accel, toBall, 0, kInf);
        EmbreeQueryContext ctx;
        ctx.init(&toBall, 0, kInf);
        rtcIntersect1(accel.rtcHandle(), &ctx.rtc, &rh);
        CHECK(rh.hit.geomID == accel.userGeometryId());
        CHECK(rh.hit.primID == 0);
        CHECK(rh.ray.tfar == static_cast<float>(ctx.bestT));
        CHECK(ctx.bestT == doctest::Approx(5 - std::sqrt(0.9375)).epsilon(1e-15));
        // Ng is written (the contract) but never read: Scene::surfaceAt
        // computes the exact normal of the winning hit, so the callback
        // writes the cheap stand-in -d, which faces the ray.
        CHECK(rh.hit.Ng_x == -rh.ray.dir_x);
        CHECK(rh.hit.Ng_y == -rh.ray.dir_y);
        CHECK(rh.hit.Ng_z == -rh.ray.dir_z);
    }
    for (const Ray& ray : {toBall, toQuad}) {
        // Mask 0 matches no geometry (default geometry mask is all ones).
        RTCRayHit rh = rayHit(accel, ray, 0, kInf);
        rh.ray.mask = 0;
        EmbreeQueryContext ctx;
        ctx.init(&ray, 0, kInf);
        rtcIntersect1(accel.rtcHandle(), &ctx.rtc, &rh);
        CHECK(rh.hit.geomID == RTC_INVALID_GEOMETRY_ID);

        // Occlusion writes -inf on a hit and leaves tfar alone on a miss.
        RTCRay r{};
        REQUIRE(accel.toEmbreeRay(ray, 0, kInf, r));
        rtcOccluded1(accel.rtcHandle(), &ctx.rtc, &r);
        CHECK(r.tfar == -std::numeric_limits<float>::infinity());
        REQUIRE(accel.toEmbreeRay(ray, 0, 3.0, r));  // both hits are beyond t = 3
        ctx.init(&ray, 0, 3.0);
        rtcOccluded1(accel.rtcHandle(), &ctx.rtc, &r);
        CHECK(r.tfar == 3.0f);
    }
}

TEST_CASE("embree: 8-wide packets and streams match single rays (callbacks handle any N)") {
    const Scene scene = randomScene(11, 60);
    const EmbreeAccelerator accel(scene);
    Rng rng(21);
    constexpr int kRays = 8 * 64;
    std::vector<Ray> rays;
    for (int i = 0; i < kRays; ++i) rays.push_back(Ray{rng.point(-12, 12), rng.direction()});

    // Reference: single rays through the bare path (float lanes, like packets).
    std::vector<std::optional<Hit>> single(kRays);
    for (int i = 0; i < kRays; ++i) {
        RTCRayHit rh = rayHit(accel, rays[i], 0, kInf);
        EmbreeQueryContext ctx;
        ctx.init(nullptr, 0, kInf);
        rtcIntersect1(accel.rtcHandle(), &ctx.rtc, &rh);
        single[i] = accel.decode(rh, ctx);
    }

    int packetDiffer = 0, streamDiffer = 0, packetInvalidHit = 0, hits = 0;
    const auto differs = [&](const std::optional<Hit>& a, const std::optional<Hit>& b) {
        return a.has_value() != b.has_value() ||
               (a && (a->object != b->object || a->prim != b->prim ||
                      std::abs(a->t - b->t) > 1e-6 * std::max(1.0, a->t)));
    };
    for (int base = 0; base < kRays; base += 8) {
        alignas(32) RTCRayHit8 packet;
        alignas(32) int valid[8];
        for (int k = 0; k < 8; ++k) {
            const RTCRayHit rh = rayHit(accel, rays[base + k], 0, kInf);
            valid[k] = (k == 5) ? 0 : -1;  // lane 5 inactive: must stay untouched
            packet.ray.org_x[k] = rh.ray.org_x;
            packet.ray.org_y[k] = rh.ray.org_y;
            packet.ray.org_z[k] = rh.ray.org_z;
            packet.ray.dir_x[k] = rh.ray.dir_x;
            packet.ray.dir_y[k] = rh.ray.dir_y;
            packet.ray.dir_z[k] = rh.ray.dir_z;
            packet.ray.tnear[k] = rh.ray.tnear;
            packet.ray.tfar[k] = rh.ray.tfar;
            packet.ray.time[k] = 0;
            packet.ray.mask[k] = rh.ray.mask;
            packet.ray.id[k] = 0;
            packet.ray.flags[k] = 0;
            packet.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
            packet.hit.primID[k] = RTC_INVALID_GEOMETRY_ID;
            packet.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
        }
        // Even with a double ray in the context, 8-wide callbacks use the lanes.
        EmbreeQueryContext ctx;
        ctx.init(&rays[base], 0, kInf);
        rtcIntersect8(valid, accel.rtcHandle(), &ctx.rtc, &packet);
        for (int k = 0; k < 8; ++k) {
            RTCRayHit rh{};
            rh.ray.tfar = packet.ray.tfar[k];
            rh.hit.u = packet.hit.u[k];
            rh.hit.v = packet.hit.v[k];
            rh.hit.primID = packet.hit.primID[k];
            rh.hit.geomID = packet.hit.geomID[k];
            if (k == 5) {
                packetInvalidHit += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
                continue;
            }
            packetDiffer += differs(accel.decode(rh, ctx), single[base + k]);
        }
    }
    {
        std::vector<RTCRayHit> stream(kRays);
        for (int i = 0; i < kRays; ++i) stream[i] = rayHit(accel, rays[i], 0, kInf);
        EmbreeQueryContext ctx;
        ctx.init(nullptr, 0, kInf);
        rtcIntersect1M(accel.rtcHandle(), &ctx.rtc, stream.data(), kRays, sizeof(RTCRayHit));
        for (int i = 0; i < kRays; ++i) {
            const auto h = accel.decode(stream[i], ctx);
            hits += h.has_value();
            streamDiffer += differs(h, single[i]);
        }
    }
    MESSAGE("packets/streams: ", kRays, " rays, ", hits, " hits, packet differences ", packetDiffer,
            ", stream differences ", streamDiffer);
    CHECK(hits > kRays / 4);
    CHECK(packetInvalidHit == 0);
    CHECK(packetDiffer == 0);
    CHECK(streamDiffer == 0);
}

TEST_CASE("embree: occlusion with a shadow-cache hint gives occluded()'s answer, hint or not") {
    // 300 spheres (user geometry), a triangle sphere and terrain (native
    // triangles), a ground plane: shadow segments between random points.
    const Scene scene = randomScene(20, 300);
    EmbreeAccelerator embree(scene, {});
    NaiveAccelerator naive(scene, {});
    Rng rng(7);
    OcclusionHint carried;  // as the integrator carries it from one feeler to the next
    int blocked = 0, named = 0;
    for (int i = 0; i < 4000; ++i) {
        const Vec3 from = rng.point(-12, 12), to = rng.point(-12, 12);
        const Ray ray{from, to - from};
        const bool expected = embree.occluded(ray, 1e-9, 1.0);
        CHECK(naive.occluded(ray, 1e-9, 1.0) == expected);
        CHECK(embree.occluded(ray, 1e-9, 1.0, carried) == expected);
        blocked += expected;
        if (carried.primitive != OcclusionHint::kNone) {
            ++named;
            // A named occluder blocks this very segment.
            OcclusionHint again = carried;
            CHECK(embree.occluded(ray, 1e-9, 1.0, again));
        }
        if (!expected) CHECK(carried.primitive == OcclusionHint::kNone);
        // Any entries as the guesses, blocking or not: the same answer.
        OcclusionHint any{uint32_t(rng.next() % 300), uint32_t(rng.next() % 300)};
        CHECK(embree.occluded(ray, 1e-9, 1.0, any) == expected);
        CHECK((embree.transmittance(ray, 1e-9, 1.0, any).isBlack()) == expected);
    }
    CHECK(blocked > 1000);  // both answers well represented
    CHECK(blocked < 3900);
    CHECK(named > 100);     // and spheres named as occluders
}

namespace {

/// Analytic shapes only (Embree traces their packets): spheres, two
/// coincident spheres and two coplanar quads (exact ties, settled by the lower
/// entry), a tiling of quads sharing edges, a cylinder and a ground plane.
Scene packetScene() {
    Rng rng(31);
    Scene scene;
    scene.materials.resize(2);
    for (int i = 0; i < 40; ++i)
        scene.objects.push_back(shapeObject("sphere" + std::to_string(i),
                                            makeSphere(rng.point(-6, 6), rng.uniform(0.2, 1.2))));
    for (int i = 0; i < 2; ++i)
        scene.objects.push_back(shapeObject("twin" + std::to_string(i), makeSphere({1, 2, 3}, 0.9)));
    const auto quadAt = [](double x, double y, double z) {
        PolygonParams p;
        p.vertices = {{x, y, z}, {x + 1, y, z}, {x + 1, y + 1, z}, {x, y + 1, z}};
        return makePolygon(p);
    };
    for (int i = 0; i < 2; ++i) scene.objects.push_back(shapeObject("coplanar", quadAt(-1, -1, 7)));
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            scene.objects.push_back(shapeObject("tile", quadAt(-2 + i, -2 + j, -7)));
    ConeParams c;
    c.base = {-4, -4, -5};
    c.apex = {-3, -4, 4};
    c.baseRadius = c.apexRadius = 0.7;
    scene.objects.push_back(shapeObject("cylinder", makeCone(c)));
    scene.objects.push_back(shapeObject("ground", makePlane({0, 0, -9}, {0, 0, 1}, 40), 1));
    return scene;
}

bool sameHit(const std::optional<Hit>& a, const std::optional<Hit>& b) {
    if (a.has_value() != b.has_value()) return false;
    return !a || (a->t == b->t && a->object == b->object && a->prim == b->prim && a->u == b->u &&
                  a->v == b->v);
}

}  // namespace

TEST_CASE("embree: a packet's hits are intersect()'s, lane by lane") {
    // Bundles of 1-16 rays: neighbours from one eye (as a row of camera rays),
    // rays aimed exactly at shared quad edges and corners and at the ties,
    // random unrelated rays, and lanes that cannot be traced (NaN, an empty
    // interval), in every position of the packet.
    // Every ISA: the default device on an AVX-512 CPU traces one 16-wide
    // packet, the others two 8-wide ones; an SSE device emulates
    // rtcIntersect8 and calls back ray by ray, so the callbacks find each
    // lane by its ray id, not its position.
    const Scene scene = packetScene();
    NaiveAccelerator naive(scene, {});
    CHECK_FALSE(naive.tracesPackets());
    for (const std::string isa : {"", "isa=sse2", "isa=sse4.2", "isa=avx2"}) {
        CAPTURE(isa);
        EmbreeAccelerator embree(scene, {}, isa);
        CHECK(embree.tracesPackets());
        Rng rng(5);
        int hits = 0, ties = 0;
        for (int n = 0; n < 3000; ++n) {
            const int count = 1 + n % Accelerator::kPacketRays;  // 16-wide, or two 8-wide
            Ray rays[Accelerator::kPacketRays];
            double tMin[Accelerator::kPacketRays], tMax[Accelerator::kPacketRays];
            const Vec3 eye = rng.point(-3, 3) + Vec3{0, 0, 14};
            for (int k = 0; k < count; ++k) {
                Vec3 target;
                switch ((n / 8 + k) % 4) {
                    case 0: target = rng.point(-6, 6); break;                                         // anywhere
                    case 1: target = {-2 + double(rng.next() % 5), -2 + rng.uniform(0, 4), -7}; break;  // a shared edge
                    case 2: target = {-1 + rng.uniform(0, 1), -1 + rng.uniform(0, 1), 7}; break;      // the coplanar tie
                    default: target = Vec3{1, 2, 3} + rng.direction() * 0.5; break;                   // the twins
                }
                rays[k] = Ray{n % 5 == 4 ? rng.point(-14, 14) : eye, target - eye};
                tMin[k] = 0;
                tMax[k] = std::numeric_limits<double>::infinity();
            }
            if (n % 7 == 3) rays[n % count].d.x = std::numeric_limits<double>::quiet_NaN();
            if (n % 11 == 5) tMax[n % count] = tMin[n % count];
            std::optional<Hit> packet[Accelerator::kPacketRays];
            embree.intersectPacket(rays, tMin, tMax, count, packet);
            for (int k = 0; k < count; ++k) {
                const std::optional<Hit> single = embree.intersect(rays[k], tMin[k], tMax[k]);
                CHECK(sameHit(packet[k], single));
                CHECK(sameHit(packet[k], naive.intersect(rays[k], tMin[k], tMax[k])));
                hits += single.has_value();
                ties += single && (scene.objects[single->object].name == "coplanar" ||
                                   scene.objects[single->object].name.rfind("twin", 0) == 0);
            }
        }
        CHECK(hits > 8000);
        CHECK(ties > 2000);
    }
}

namespace {

void intersectPacketOf(const int* valid, RTCScene scene, RTCIntersectContext* ctx, RTCRayHit8* p) {
    rtcIntersect8(valid, scene, ctx, p);
}
void intersectPacketOf(const int* valid, RTCScene scene, RTCIntersectContext* ctx, RTCRayHit16* p) {
    rtcIntersect16(valid, scene, ctx, p);
}

}  // namespace

TEST_CASE("embree: the packet triangle test is the single-ray test, bit for bit") {
    // What lets triangle meshes into packets at all: for every ISA Embree
    // may pick, rtcIntersect8 and rtcIntersect16 (native with AVX-512, split
    // by Embree's stream path elsewhere) report the same triangle, t, u, v
    // and Ng as rtcIntersect1, also for rays through vertices and edges
    // (where a rounding difference would move a hit across the edge band),
    // robust scene flag or not.
    Rng meshRng(4);
    Scene scene;
    scene.materials.resize(1);
    scene.objects.push_back(meshObject("terrain", terrainMesh(meshRng, 14, -2, 40), 0));
    scene.objects.push_back(meshObject("ball", uvSphereMesh({2, -3, 3}, 3, 16, 32, false), 0));
    std::vector<Vec3> targets;  // edge midpoints and vertices
    for (const Object& o : scene.objects) {
        const TriangleMesh& mesh = *o.shape->nativeTriangles();
        for (const auto& t : mesh.triangles)
            for (int e = 0; e < 3; ++e)
                targets.push_back((mesh.positions[t[e]] + mesh.positions[t[(e + 1) % 3]]) * 0.5);
        for (const Vec3& p : mesh.positions) targets.push_back(p);  // vertices
    }
    const auto sameBits = [](float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; };
    // 40,000 rays a packet width: `Packet` is RTCRayHit8 or RTCRayHit16.
    const auto compare = [&](const EmbreeAccelerator& embree, auto packetType, int& hits,
                             int& differ) {
        using Packet = decltype(packetType);
        constexpr int K = sizeof(packetType.ray.tfar) / sizeof(float);
        Rng rng(10);
        for (int n = 0; n < 40000 / K; ++n) {
            alignas(64) Packet packet;
            alignas(64) int valid[K];
            RTCRayHit single[K];
            const Vec3 eye = rng.point(-14, 14) + Vec3{0, 0, 20};
            for (int k = 0; k < K; ++k) {
                const Vec3 target = n % 4 == 3 ? rng.point(-14, 14) : targets[rng.next() % targets.size()];
                RTCRay r{};
                REQUIRE(embree.toEmbreeRay(Ray{eye, target - eye}, 0, kInf, r));
                single[k] = RTCRayHit{};
                single[k].ray = r;
                single[k].hit.geomID = RTC_INVALID_GEOMETRY_ID;
                packet.ray.org_x[k] = r.org_x;
                packet.ray.org_y[k] = r.org_y;
                packet.ray.org_z[k] = r.org_z;
                packet.ray.dir_x[k] = r.dir_x;
                packet.ray.dir_y[k] = r.dir_y;
                packet.ray.dir_z[k] = r.dir_z;
                packet.ray.tnear[k] = r.tnear;
                packet.ray.tfar[k] = r.tfar;
                packet.ray.time[k] = 0;
                packet.ray.mask[k] = r.mask;
                packet.ray.id[k] = 0;
                packet.ray.flags[k] = 0;
                packet.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
                valid[k] = -1;
            }
            for (int k = 0; k < K; ++k) {
                RTCIntersectContext ctx;
                rtcInitIntersectContext(&ctx);
                rtcIntersect1(embree.rtcHandle(), &ctx, &single[k]);
            }
            RTCIntersectContext ctx;
            rtcInitIntersectContext(&ctx);
            intersectPacketOf(valid, embree.rtcHandle(), &ctx, &packet);
            for (int k = 0; k < K; ++k) {
                const RTCRayHit& s = single[k];
                const bool hit = s.hit.geomID != RTC_INVALID_GEOMETRY_ID;
                hits += hit;
                const bool same =
                    s.hit.geomID == packet.hit.geomID[k] &&
                    (!hit || (s.hit.primID == packet.hit.primID[k] &&
                              sameBits(s.ray.tfar, packet.ray.tfar[k]) &&
                              sameBits(s.hit.u, packet.hit.u[k]) &&
                              sameBits(s.hit.v, packet.hit.v[k]) &&
                              sameBits(s.hit.Ng_x, packet.hit.Ng_x[k]) &&
                              sameBits(s.hit.Ng_y, packet.hit.Ng_y[k]) &&
                              sameBits(s.hit.Ng_z, packet.hit.Ng_z[k])));
                differ += !same;
            }
        }
    };
    for (const std::string isa : {"", "isa=sse2", "isa=sse4.2", "isa=avx2"}) {
        for (bool robust : {false, true}) {
            CAPTURE(isa);
            CAPTURE(robust);
            AccelOptions options;
            options.robust = robust;
            EmbreeAccelerator embree(scene, options, isa);
            int hits8 = 0, differ8 = 0, hits16 = 0, differ16 = 0;
            compare(embree, RTCRayHit8{}, hits8, differ8);
            compare(embree, RTCRayHit16{}, hits16, differ16);
            CHECK(differ8 == 0);
            CHECK(differ16 == 0);
            CHECK(hits8 > 30000);
            CHECK(hits16 > 30000);
        }
    }
}

TEST_CASE("embree: packets with native triangles answer as intersect(), edges included") {
    // Embree's packet triangle test gives the single-ray test's t, u, v bit
    // for bit (measured on 1.6 M rays, SSE4.2/AVX2/AVX-512, robust or not,
    // docs/benchmarks.md), and a lane whose hit lies in the edge band is
    // resolved exactly as intersect() resolves it. Rays from one eye to the
    // meshes' vertices and edge midpoints (every one of them in the edge
    // band), to random points, and from random points; one-sided and
    // two-sided meshes among spheres and a plane.
    Scene scene = randomScene(21, 50);
    auto oneSided = uvSphereMesh({-4, 5, -2}, 2.5, 12, 24, false);
    oneSided->setSidedness(Sidedness::Outside);
    scene.objects.push_back(meshObject("one-sided", oneSided, 2));
    std::vector<Vec3> targets;  // vertices and edge midpoints of every mesh
    for (const Object& o : scene.objects)
        if (const TriangleMesh* mesh = o.shape->nativeTriangles())
            for (const auto& t : mesh->triangles)
                for (int e = 0; e < 3; ++e) {
                    const Vec3 a = mesh->positions[t[e]], b = mesh->positions[t[(e + 1) % 3]];
                    targets.push_back(a);
                    targets.push_back((a + b) * 0.5);
                }
    for (const std::string isa : {"", "isa=sse2", "isa=avx2"}) {
        CAPTURE(isa);
        EmbreeAccelerator embree(scene, {}, isa);
        CHECK(embree.tracesPackets());
        Rng rng(9);
        int triangleHits = 0;
        for (int n = 0; n < 4000; ++n) {
            const int count = 2 + n % (Accelerator::kPacketRays - 1);
            Ray rays[Accelerator::kPacketRays];
            double tMin[Accelerator::kPacketRays], tMax[Accelerator::kPacketRays];
            const Vec3 eye = rng.point(-14, 14) + Vec3{0, 0, 8};
            for (int k = 0; k < count; ++k) {
                const Vec3 target = n % 3 == 2 ? rng.point(-12, 12)
                                               : targets[rng.next() % targets.size()];
                const Vec3 from = n % 5 == 4 ? rng.point(-14, 14) : eye;
                rays[k] = Ray{from, target - from};
                tMin[k] = 1e-9;
                tMax[k] = std::numeric_limits<double>::infinity();
            }
            std::optional<Hit> packet[Accelerator::kPacketRays];
            embree.intersectPacket(rays, tMin, tMax, count, packet);
            for (int k = 0; k < count; ++k) {
                const std::optional<Hit> single = embree.intersect(rays[k], tMin[k], tMax[k]);
                CHECK(sameHit(packet[k], single));
                triangleHits += single && scene.objects[single->object].shape->nativeTriangles();
            }
        }
        CHECK(triangleHits > 10000);
    }
}

TEST_CASE("embree: a packet of shadow feelers answers as one feeler at a time") {
    // Feelers from points over the shipped scenes' surfaces to their lights
    // and in random directions: through glass spheres, a glass polygon pane,
    // glass and gold mesh faces, cut-out leaves; with and without a
    // departure; filtered (transmittance, each lane with its own crossings)
    // and opaque; untraceable ones; with the shadow cache's hints (any
    // entries) and without. Every ISA: 16-wide with AVX-512, 8-wide or
    // emulated below.
    const std::string dir = std::string(RAYLAB_SOURCE_DIR) + "/scenes/";
    for (const char* name : {"glass_shadows.json", "demo.json", "cutouts.json"}) {
        CAPTURE(name);
        const Scene scene = loadScene(dir + name);
        const RenderOptions options = resolveRenderOptions(scene, {});
        const Bounds3 box = scene.bounds();
        for (const std::string isa : {"", "isa=avx2", "isa=sse2"}) {
            CAPTURE(isa);
            const EmbreeAccelerator packets(scene, options.accelOptions, isa);
            const EmbreeAccelerator single(scene, options.accelOptions, isa);
            Rng rng(17);
            int blocked = 0, dimmed = 0, lit = 0;
            for (int n = 0; n < 1500; ++n) {
                constexpr int K = Accelerator::kPacketRays;
                const int count = 1 + n % K;
                const bool filtered = n % 3 != 0;
                Ray rays[K];
                double tMin[K], tMax[K];
                Departure from[K];
                for (int k = 0; k < count; ++k) {
                    // Near the objects (the floors reach far beyond them).
                    const Vec3 p{rng.uniform(std::max(box.lo.x, -4.0), std::min(box.hi.x, 4.0)),
                                 rng.uniform(0, 1.5),
                                 rng.uniform(std::max(box.lo.z, -4.0), std::min(box.hi.z, 4.0))};
                    const bool toLight = rng.next() % 4 != 0;
                    const Light& light = scene.lights[rng.next() % scene.lights.size()];
                    rays[k] = toLight ? Ray{p, light.position - p} : Ray{p, rng.direction()};
                    tMin[k] = 1e-9;
                    tMax[k] = toLight ? 1.0 : std::numeric_limits<double>::infinity();
                    from[k] = rng.next() % 5 == 0
                                  ? Departure{uint32_t(rng.next() % scene.objects.size())}
                                  : Departure{};
                    if (n % 29 == 7 && k == count / 2) rays[k].d.y = std::numeric_limits<double>::quiet_NaN();
                    if (n % 31 == 5 && k == 0) tMax[k] = tMin[k];  // an empty interval
                }
                // Every other packet with the shadow cache's hints: any
                // entries (blocking or not) and none, as the cache may hold.
                const bool hinted = n % 2 == 0;
                OcclusionHint hints[K];
                for (int k = 0; k < count; ++k)
                    if (rng.next() % 3 != 0)
                        hints[k] = {uint32_t(rng.next() % 40), uint32_t(rng.next() % 40)};
                Color out[K];
                packets.shadowPacket(rays, tMin, tMax, from, count, filtered, out,
                                     hinted ? hints : nullptr);
                for (int k = 0; k < count; ++k) {
                    const Color expected =
                        filtered ? single.transmittance(rays[k], tMin[k], tMax[k], from[k])
                        : single.occluded(rays[k], tMin[k], tMax[k], from[k]) ? Color{}
                                                                              : Color(1.0);
                    CHECK(std::memcmp(&out[k], &expected, sizeof expected) == 0);
                    if (hinted && !filtered) {
                        // The hint comes back naming an occluder of this very
                        // feeler, or none where it got through. (Filtered
                        // feelers through a surface filter use no hint, as
                        // transmittance() uses none: usesOcclusionHints.)
                        if (!expected.isBlack()) CHECK(hints[k].primitive == OcclusionHint::kNone);
                        if (hints[k].primitive != OcclusionHint::kNone) {
                            OcclusionHint named{hints[k].primitive, hints[k].primitive};
                            CHECK(single.occluded(rays[k], tMin[k], tMax[k], from[k], named));
                        }
                    }
                    blocked += expected.isBlack();
                    lit += expected.r == 1 && expected.g == 1 && expected.b == 1;
                    dimmed += !expected.isBlack() && expected.r < 1;
                }
            }
            CHECK(packets.filterCounts().attenuated == single.filterCounts().attenuated);
            CHECK(blocked > 500);
            CHECK(lit > 500);
            if (std::string(name) != "cutouts.json") CHECK(dimmed > 50);
        }
    }
}
