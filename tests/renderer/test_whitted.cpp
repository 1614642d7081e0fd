// A tiny scene rendered at single pixels whose exact values are derived by
// hand, plus determinism across thread counts. Each case runs on both
// accelerators.
#include <doctest/doctest.h>

#include <cstring>

#include "geometry/primitives.h"
#include "renderer/accel/accelerator.h"
#include "renderer/accelerator_kind.h"
#include "renderer/effects.h"
#include "renderer/render.h"
#include "renderer/render_setup.h"

using namespace raylab;

namespace {

/// Eye at the origin looking down -z; a 1x1 image whose single ray (through
/// the pixel centre) is exactly (0, 0, -1).
Scene baseScene() {
    Scene s;
    s.camera = Camera::perspective({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 30);
    s.image.width = s.image.height = 1;
    return s;
}

uint32_t addMaterial(Scene& s, const Material& m) {
    s.materials.push_back(m);
    return uint32_t(s.materials.size() - 1);
}

void addObject(Scene& s, std::unique_ptr<Shape> shape, uint32_t material,
               Sidedness sides = Sidedness::Outside) {
    Object o;
    shape->setSidedness(sides);
    o.shape = std::move(shape);
    o.material = material;
    s.objects.push_back(std::move(o));
}

Color renderCentre(const Scene& s, AcceleratorKind kind, RayCounters* rays = nullptr) {
    RenderOverrides o;
    o.accel = kind;
    const RenderOptions opt = resolveRenderOptions(s, o);
    auto accel = makeAccelerator(kind, s, opt.accelOptions);
    const RenderResult r = render(s, *accel, opt, analyseEffects(s, opt));
    if (rays) *rays = r.rays;
    CHECK(r.nonFiniteSamples == 0);
    return {r.film.rgba[0], r.film.rgba[1], r.film.rgba[2]};
}

Material matte(double kd, double ka) {
    Material m;
    m.kd = Color(kd);
    m.ka = Color(ka);
    return m;
}

}  // namespace

TEST_CASE("whitted: a lit pixel is ambient + Lambert") {
    for (const AcceleratorKind accel : {AcceleratorKind::Embree, AcceleratorKind::Naive}) {
        CAPTURE(acceleratorName(accel));
        Scene s = baseScene();
        s.ambient = Color(1.0);
        // Light at the eye: at the hit (0, 0, -4) on the sphere's front,
        // N = L = (0, 0, 1), so N.L = 1: pixel = ka·Ia + kd·I = 0.1 + 0.5·0.8.
        s.lights.push_back({Light::Type::Point, {0, 0, 0}, {}, Color(0.8)});
        addObject(s, makeSphere({0, 0, -5}, 1), addMaterial(s, matte(0.5, 0.1)));
        RayCounters rays;
        const Color c = renderCentre(s, accel, &rays);
        CHECK(c.r == doctest::Approx(0.5).epsilon(1e-6));
        CHECK(c.g == doctest::Approx(0.5).epsilon(1e-6));
        CHECK(rays.total(RayType::Camera) == 1);
        CHECK(rays.cameraHits == 1);
        CHECK(rays.total(RayType::Shadow) == 1);
        CHECK(rays.total(RayType::Reflection) == 0);
        CHECK(rays.total(RayType::Refraction) == 0);
    }
}

TEST_CASE("whitted: a shadowed pixel equals ambient alone") {
    for (const AcceleratorKind accel : {AcceleratorKind::Embree, AcceleratorKind::Naive}) {
        CAPTURE(acceleratorName(accel));
        Scene s = baseScene();
        s.ambient = Color(0.5);
        // Light at (0, 10, 6), 45° above the hit point (0, 0, -4) whose normal
        // is +z (so N.L > 0); a small sphere at (0, 5, 1), the midpoint of the
        // segment, blocks the shadow feeler but not the camera ray.
        s.lights.push_back({Light::Type::Point, {0, 10, 6}, {}, Color(1.0)});
        const uint32_t m = addMaterial(s, matte(0.5, 0.2));
        addObject(s, makeSphere({0, 0, -5}, 1), m);
        addObject(s, makeSphere({0, 5, 1}, 0.5), m);
        const Color c = renderCentre(s, accel);
        CHECK(c.r == doctest::Approx(0.1).epsilon(1e-6));  // ka·Ia = 0.2·0.5
    }
}

TEST_CASE("whitted: a light behind the surface adds nothing and traces no shadow ray") {
    Scene s = baseScene();
    s.ambient = Color(1.0);
    s.lights.push_back({Light::Type::Point, {0, 0, -20}, {}, Color(1.0)});
    addObject(s, makeSphere({0, 0, -5}, 1), addMaterial(s, matte(0.5, 0.25)));
    RayCounters rays;
    const Color c = renderCentre(s, AcceleratorKind::Embree, &rays);
    CHECK(c.r == doctest::Approx(0.25).epsilon(1e-6));
    CHECK(rays.total(RayType::Shadow) == 0);
}

TEST_CASE("whitted: a mirror reflects a known colour") {
    for (const AcceleratorKind accel : {AcceleratorKind::Embree, AcceleratorKind::Naive}) {
        CAPTURE(acceleratorName(accel));
        Scene s = baseScene();
        s.ambient = Color(1.0);
        // The camera ray hits the mirror sphere head-on at (0, 0, -4) and
        // reflects straight back (+z) past the eye onto a wall at z = 5 that
        // faces the scene; the wall shows ka·Ia = (0.3, 0.5, 0.7). km = 0.5.
        Material mirror;
        mirror.kd = Color(0);
        mirror.km = Color(0.5);
        addObject(s, makeSphere({0, 0, -5}, 1), addMaterial(s, mirror));
        Material wall = matte(0, 0);
        wall.ka = Color(0.3, 0.5, 0.7);
        addObject(s, makePlane({0, 0, 5}, {0, 0, -1}), addMaterial(s, wall));
        RayCounters rays;
        const Color c = renderCentre(s, accel, &rays);
        CHECK(c.r == doctest::Approx(0.15).epsilon(1e-6));
        CHECK(c.g == doctest::Approx(0.25).epsilon(1e-6));
        CHECK(c.b == doctest::Approx(0.35).epsilon(1e-6));
        CHECK(rays.total(RayType::Reflection) == 1);
    }
}

TEST_CASE("whitted: an ior 1.0 glass sphere lets the background through") {
    for (const AcceleratorKind accel : {AcceleratorKind::Embree, AcceleratorKind::Naive}) {
        CAPTURE(acceleratorName(accel));
        Scene s = baseScene();
        s.background = Color(0.2, 0.4, 0.6);
        Material glass;
        glass.kd = Color(0);
        glass.kt = Color(1);
        glass.ior = 1.0;
        addObject(s, makeSphere({0, 0, -5}, 1), addMaterial(s, glass), Sidedness::Both);
        RayCounters rays;
        const Color c = renderCentre(s, accel, &rays);
        // kt · kt · background = 1 · 1 · b exactly, then stored as float.
        CHECK(c.r == double(0.2f));
        CHECK(c.g == double(0.4f));
        CHECK(c.b == double(0.6f));
        // In at the front (depth 2), out at the back (depth 3), then the background.
        CHECK(rays.total(RayType::Refraction) == 2);
        CHECK(rays.byDepth[size_t(RayType::Refraction)][2] == 1);
        CHECK(rays.byDepth[size_t(RayType::Refraction)][3] == 1);
    }
}

TEST_CASE("whitted: the image is bit-identical for any thread count") {
    Scene s;
    s.camera = Camera::perspective({0, 2, 6}, {0, 0, 0}, {0, 1, 0}, 50);
    s.image.width = 96;
    s.image.height = 64;
    s.ambient = Color(0.1);
    s.background = Color(0.1, 0.2, 0.3);
    s.lights.push_back({Light::Type::Point, {3, 5, 4}, {}, Color(0.9)});
    s.lights.push_back({Light::Type::Directional, {}, normalize(Vec3{-1, -2, -1}), Color(0.3)});
    Material floor = matte(0.6, 0.6);
    Material mirror = matte(0.1, 0.1);
    mirror.km = Color(0.8);
    mirror.ks = Color(0.5);
    Material glass = matte(0, 0);
    glass.kt = Color(0.9);
    glass.ior = 1.5;
    addObject(s, makePlane({0, -1, 0}, {0, 1, 0}), addMaterial(s, floor));
    addObject(s, makeSphere({-1.2, 0, 0}, 1), addMaterial(s, mirror));
    addObject(s, makeSphere({1.2, 0, 0.5}, 1), addMaterial(s, glass), Sidedness::Both);
    for (int spp : {1, 4}) {
        CAPTURE(spp);
        RenderOverrides o;
        o.spp = spp;
        o.threads = 1;
        RenderOptions one = resolveRenderOptions(s, o);
        o.threads = 2;
        RenderOptions two = resolveRenderOptions(s, o);
        auto accel = makeAccelerator("embree", s, one.accelOptions);
        const EffectSet e = analyseEffects(s, one);
        const RenderResult a = render(s, *accel, one, e);
        const RenderResult b = render(s, *accel, two, e);
        const RenderResult c = render(s, *accel, two, e);
        REQUIRE(a.film.rgba.size() == b.film.rgba.size());
        CHECK(std::memcmp(a.film.rgba.data(), b.film.rgba.data(), a.film.rgba.size() * 4) == 0);
        CHECK(std::memcmp(b.film.rgba.data(), c.film.rgba.data(), b.film.rgba.size() * 4) == 0);
        CHECK(std::memcmp(a.film.z.data(), b.film.z.data(), a.film.z.size() * 4) == 0);
        CHECK(std::memcmp(a.film.distance.data(), b.film.distance.data(), a.film.distance.size() * 4) == 0);
        CHECK(std::memcmp(a.film.mattes.data(), b.film.mattes.data(), a.film.mattes.size() * sizeof(MatteEntry)) == 0);
        CHECK(a.rays.total() == b.rays.total());
        CHECK(a.nonFiniteSamples == 0);
        CHECK(a.rays.total(RayType::Reflection) > 0);
        CHECK(a.rays.total(RayType::Refraction) > 0);
    }
}

TEST_CASE("adaptive supersampling: corners are shared, and edges are refined") {
    // 32x16 pixels = two 16x16 tiles. Where no square is split, each tile
    // traces its (16+1)² corner grid once: 2 · 289 = 578 camera rays, about
    // one per pixel, and a constant background stays exactly the background.
    Scene s;
    s.camera = Camera::perspective({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 40);
    s.background = Color(0.25, 0.5, 0.75);
    s.image.width = 32;
    s.image.height = 16;
    RenderOverrides o;
    o.adaptiveThreshold = 1e-9;
    o.adaptiveMaxLevel = 3;
    RenderOptions opt = resolveRenderOptions(s, o);
    auto empty = makeAccelerator("embree", s, opt.accelOptions);
    RenderResult r = render(s, *empty, opt, analyseEffects(s, opt));
    CHECK(r.rays.total(RayType::Camera) == 578);
    CHECK(r.film.rgba[0] == 0.25f);
    CHECK(r.film.rgba[4 * 17 + 2] == 0.75f);

    // A sphere in view: squares across its silhouette split down to level 3,
    // so more rays are traced, but far fewer than 8x8 supersampling would.
    Material m;
    m.ka = Color(1);
    m.kd = Color(0);
    s.ambient = Color(1);
    s.materials.push_back(m);
    Object ob;
    ob.shape = makeSphere({0, 0, 0}, 1);
    s.objects.push_back(std::move(ob));
    opt = resolveRenderOptions(s, o);
    auto accel = makeAccelerator("embree", s, opt.accelOptions);
    r = render(s, *accel, opt, analyseEffects(s, opt));
    const uint64_t rays = r.rays.total(RayType::Camera);
    CHECK(rays > 578);
    CHECK(rays < 32u * 16u * 64u / 4u);
    CHECK(r.nonFiniteSamples == 0);
    // Coverage is fractional only on the silhouette; the sphere's centre pixel is fully covered.
    CHECK(r.film.rgba[4 * r.film.index(16, 8) + 3] == 1.0f);
}
