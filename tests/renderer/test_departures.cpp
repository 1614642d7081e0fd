// Departures (renderer/accel/accelerator.h): a ray spawned from a shape that
// it cannot meet again (Shape::revisit) names that object, and the
// accelerator leaves the object's test out. Checked: both accelerators skip
// the named object and nothing else, in every kind of query; whole renders
// are byte-identical with departures on and off, through both accelerators,
// for a scene of every analytic kind with mirrors, glass (rays that enter a
// ball must not skip it), inside-visible and two-sided shapes, filtered and
// opaque shadows and the general kernel; and a shape that wrongly claims to
// be planar changes the picture, which shows the comparison can fail.

#include <doctest/doctest.h>

#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "accel/accel_test_helpers.h"
#include "geometry/primitives.h"
#include "renderer/accel/embree_accelerator.h"
#include "renderer/accel/naive_accelerator.h"
#include "renderer/effects.h"
#include "renderer/render.h"
#include "renderer/render_setup.h"
#include "support/forwarding_shape.h"

using namespace raylab;
using accel_test::shapeObject;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

Material glass(double kt) {
    Material m;
    m.kd = Color(0.05);
    m.ks = Color(0.5);
    m.shininess = 60;
    m.km = Color(0.1);
    m.kt = Color(kt);
    m.ior = 1.5;
    return m;
}

Material surface(const Color& kd, double km) {
    Material m;
    m.kd = kd;
    m.ka = kd;
    m.ks = Color(0.3);
    m.shininess = 20;
    m.km = Color(km);
    return m;
}

/// Two unit balls on the z axis, at z = 0 (object 0) and z = -3 (object 1).
Scene twoBalls(const Material& a, const Material& b) {
    Scene s;
    s.materials = {a, b};
    s.objects.push_back(shapeObject("near", makeSphere({0, 0, 0}, 1), 0));
    s.objects.push_back(shapeObject("far", makeSphere({0, 0, -3}, 1), 1));
    return s;
}

std::vector<std::unique_ptr<Accelerator>> both(const Scene& s, const AccelOptions& o = {}) {
    std::vector<std::unique_ptr<Accelerator>> v;
    v.push_back(std::make_unique<NaiveAccelerator>(s, o));
    v.push_back(std::make_unique<EmbreeAccelerator>(s, o));
    return v;
}

/// A shape that answers as `inner` but claims, wrongly for a ball, that no
/// ray leaving it can meet it again.
class ClaimsPlanar final : public test::ForwardingShape {
public:
    /// `inner` answers for both sides, as the glass ball does (the sidedness
    /// everyKind() sets is the wrapper's, which no query reads).
    explicit ClaimsPlanar(std::unique_ptr<Shape> inner) : ForwardingShape(std::move(inner)) {
        this->inner().setSidedness(Sidedness::Both);
    }
    const char* kind() const override { return "ball claiming to be flat"; }
    Revisit revisit() const override { return Revisit::None; }
};

/// Every analytic kind under two point lights and a directional one: a glass
/// ball (refraction in and out, total internal reflection) in front of a
/// mirror ball, capped and open cylinders, a cone, a disk, a quad and a
/// concave polygon, a floor plane, and an inside-visible sky sphere around
/// it all. `glassBall` is the glass ball's shape (a test swaps in a liar).
Scene everyKind(std::unique_ptr<Shape> glassBall) {
    Scene s;
    s.camera = Camera::perspective({0.4, 2.2, 7.5}, {0, 0.6, 0}, {0, 1, 0}, 45);
    s.image.width = 96;
    s.image.height = 72;
    s.image.maxDepth = 6;
    s.ambient = Color(0.1);
    s.background = Color(0.2, 0.3, 0.5);
    for (const Vec3 p : {Vec3{-4, 6, 5}, Vec3{5, 4, 3}}) {
        Light l;
        l.position = p;
        l.intensity = Color(0.6);
        s.lights.push_back(l);
    }
    Light sun;
    sun.type = Light::Type::Directional;
    sun.direction = normalize(Vec3{0.3, -1, -0.2});
    sun.intensity = Color(0.3);
    s.lights.push_back(sun);
    s.materials = {surface(Color(0.7, 0.6, 0.5), 0.0), surface(Color(0.1), 0.85), glass(0.9),
                   surface(Color(0.3, 0.6, 0.4), 0.2), surface(Color(0.4, 0.4, 0.9), 0.0)};
    const auto add = [&](const char* name, std::unique_ptr<Shape> shape, uint32_t material,
                         Sidedness sides) {
        shape->setSidedness(sides);
        s.objects.push_back(shapeObject(name, std::move(shape), material));
    };
    add("floor", makePlane({0, 0, 0}, {0, 1, 0}, 40), 0, Sidedness::Outside);
    add("glass ball", std::move(glassBall), 2, Sidedness::Both);
    add("mirror ball", makeSphere({-1.6, 1.0, -1.5}, 1.0), 1, Sidedness::Outside);
    ConeParams cyl;
    cyl.base = {1.9, 0, -1.2};
    cyl.apex = {1.9, 1.8, -1.2};
    cyl.baseRadius = cyl.apexRadius = 0.45;
    cyl.capped = true;
    add("capped cylinder", makeCone(cyl), 3, Sidedness::Outside);
    ConeParams pipe = cyl;
    pipe.base = {-2.8, 0.3, 0.8};
    pipe.apex = {-1.4, 0.9, 1.6};
    pipe.capped = false;
    add("open cylinder", makeCone(pipe), 2, Sidedness::Both);
    ConeParams cone = cyl;
    cone.base = {0.9, 0, 1.6};
    cone.apex = {0.9, 1.2, 1.6};
    cone.baseRadius = 0.4;
    cone.apexRadius = 0;
    add("cone", makeCone(cone), 4, Sidedness::Outside);
    add("disk", makeDisk({-0.4, 0.01, 2.2}, {0, 1, 0.2}, 0.5), 1, Sidedness::Outside);
    PolygonParams quad;
    quad.vertices = {{2.6, 0, -3}, {4.2, 0, -2}, {4.2, 2.2, -2}, {2.6, 2.2, -3}};
    add("mirror quad", makePolygon(quad), 1, Sidedness::Both);
    PolygonParams notch;
    notch.vertices = {{-3.5, 0, -3.5}, {-1.5, 0, -4}, {-1.5, 2, -4}, {-2.5, 1, -3.75},
                      {-3.5, 2, -3.5}};
    add("glass notch", makePolygon(notch), 2, Sidedness::Both);
    add("sky", makeSphere({0, 0, 0}, 30), 4, Sidedness::Inside);
    return s;
}

struct Frame {
    FilmPlane rgba;
    RayCounters rays;
};

Frame renderWith(Scene& s, AcceleratorKind kind, bool departures, const RenderOverrides& base) {
    RenderOverrides o = base;
    o.accel = kind;
    o.threads = 2;
    RenderOptions options = resolveRenderOptions(s, o);
    options.departures = departures;
    const auto accel = makeAccelerator(options.accel, s, options.accelOptions);
    RenderResult r = render(s, *accel, options, analyseEffects(s, options));
    return {std::move(r.film.rgba), r.rays};
}

bool sameBytes(const FilmPlane& a, const FilmPlane& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

}  // namespace

TEST_CASE("departures: both accelerators leave out the object named, and only it") {
    const Ray down{{0, 0, 5}, {0, 0, -1}};
    Scene balls = twoBalls(surface(Color(0.5), 0), surface(Color(0.5), 0));
    for (const auto& a : both(balls)) {
        CAPTURE(a->name());
        const auto first = a->intersect(down, 0, kInf);
        const auto skipNear = a->intersect(down, 0, kInf, Departure{0});
        const auto skipFar = a->intersect(down, 0, kInf, Departure{1});
        REQUIRE(first);
        REQUIRE(skipNear);
        REQUIRE(skipFar);
        CHECK(first->object == 0);
        CHECK(skipNear->object == 1);
        CHECK(skipFar->object == 0);
        CHECK(a->occluded(down, 0, kInf, Departure{0}));
        OcclusionHint hint;
        CHECK(a->occluded(down, 0, kInf, hint));  // the hint now names ball 0 (Embree)
        CHECK(a->occluded(down, 0, kInf, Departure{0}, hint));
    }
    Scene one;
    one.materials = {surface(Color(0.5), 0)};
    one.objects.push_back(shapeObject("ball", makeSphere({0, 0, 0}, 1)));
    for (const auto& a : both(one)) {
        CAPTURE(a->name());
        CHECK(a->occluded(down, 0, kInf));
        CHECK_FALSE(a->intersect(down, 0, kInf, Departure{0}));
        CHECK_FALSE(a->occluded(down, 0, kInf, Departure{0}));
        OcclusionHint hint;
        REQUIRE(a->occluded(down, 0, kInf, hint));
        CHECK_FALSE(a->occluded(down, 0, kInf, Departure{0}, hint));  // not even through the hint
        CHECK(a->transmittance(down, 0, kInf, Departure{0}) == Color(1.0));
    }
    // Filtered shadows: the named transmitter contributes no crossing.
    Scene panes = twoBalls(glass(0.5), glass(0.8));
    AccelOptions filtered;
    for (const auto& a : both(panes, filtered)) {
        CAPTURE(a->name());
        const Color all = a->transmittance(down, 0, kInf);
        const Color lastOnly = a->transmittance(down, 0, kInf, Departure{0});
        CHECK(all.r < lastOnly.r);
        Scene farOnly;
        farOnly.materials = {glass(0.8)};
        farOnly.objects.push_back(shapeObject("far", makeSphere({0, 0, -3}, 1)));
        const std::unique_ptr<Accelerator> alone = makeAccelerator(a->name(), farOnly, filtered);
        CHECK(lastOnly == alone->transmittance(down, 0, kInf));
        OcclusionHint hint;
        CHECK(a->transmittance(down, 0, kInf, Departure{0}, hint) == lastOnly);
    }
}

TEST_CASE("departures: every picture is the same with them and without, both accelerators") {
    struct Variant {
        const char* name;
        RenderOverrides o;
    };
    std::vector<Variant> variants(4);
    variants[0].name = "default (filtered shadows)";
    variants[1].name = "opaque shadows";
    variants[1].o.shadows = ShadowMode::Opaque;
    variants[2].name = "general kernel (feelers traced into surfaces facing away)";
    variants[2].o.effects = EffectsMode::All;
    variants[3].name = "2 samples per pixel, depth 9";
    variants[3].o.spp = 2;
    variants[3].o.maxDepth = 9;
    for (const Variant& v : variants) {
        Scene s = everyKind(makeSphere({0.3, 1.0, 0.9}, 0.9));
        for (AcceleratorKind kind : {AcceleratorKind::Naive, AcceleratorKind::Embree}) {
            CAPTURE(v.name);
            CAPTURE(int(kind));
            const Frame off = renderWith(s, kind, false, v.o);
            const Frame on = renderWith(s, kind, true, v.o);
            CHECK(sameBytes(on.rgba, off.rgba));
            CHECK(on.rays.byDepth == off.rays.byDepth);
            CHECK(on.rays.total() > 30000);
        }
    }
}

TEST_CASE("departures: a ball that claims to be flat changes the picture (the check can fail)") {
    // Refraction rays that enter the glass ball would skip it and never
    // leave through its back: the glass turns into a window.
    Scene s = everyKind(std::make_unique<ClaimsPlanar>(makeSphere({0.3, 1.0, 0.9}, 0.9)));
    for (AcceleratorKind kind : {AcceleratorKind::Naive, AcceleratorKind::Embree}) {
        CAPTURE(int(kind));
        const Frame off = renderWith(s, kind, false, {});
        const Frame on = renderWith(s, kind, true, {});
        CHECK_FALSE(sameBytes(on.rgba, off.rgba));
    }
}
