// Refraction through the full render path (camera -> accelerator ->
// Scene::surfaceAt -> Whitted integrator -> spawnRay -> film): total internal
// reflection at the critical angle and just past it (NUMERICS.md §4 (23)), an
// index of 1 that must leave every direction unchanged, and rays that enter a
// glass sphere and must leave it through its far side (§4 (3)), recorded
// query by query.

#include <doctest/doctest.h>

#include <cmath>

#include "numerics/numerics_helpers.h"
#include "renderer/image_compare.h"

using namespace raylab;
using namespace raylab::numerics_test;

namespace {

constexpr double kIor = 1.5;

/// A glass prism (ior 1.5, kt = 1, nothing else) seen by a 1x1 camera whose
/// one ray runs exactly along -z. Cross-section in x-z: (-1, 0), (1, 0),
/// (1, -2 tan θ), extruded over y in [-1, 1]. The ray enters the front face
/// z = 0 at normal incidence (undeviated) and meets the back face, whose
/// outward normal is (-sin θ, 0, -cos θ), at incidence θ.
Scene prism(double theta) {
    Scene s;
    s.camera = Camera::perspective({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 30);
    s.image.width = s.image.height = 1;
    s.image.maxDepth = 8;
    s.background = Color(0.2, 0.4, 0.6);
    s.materials.push_back(material(Color(0.0), Color(0.0), Color(0.0), Color(1.0), kIor));
    const double z = -2 * std::tan(theta);
    const std::vector<std::vector<Vec3>> faces = {
        {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}},  // front, +z
        {{-1, -1, 0}, {-1, 1, 0}, {1, 1, z}, {1, -1, z}},  // back, (-sin, 0, -cos)
        {{1, -1, 0}, {1, -1, z}, {1, 1, z}, {1, 1, 0}},    // right, +x
        {{-1, -1, 0}, {1, -1, z}, {1, -1, 0}},             // end, -y
        {{-1, 1, 0}, {1, 1, 0}, {1, 1, z}},                // end, +y
    };
    for (const auto& f : faces) {
        PolygonParams p;
        p.vertices = f;
        auto poly = makePolygon(p);
        poly->setSidedness(Sidedness::Both);
        s.objects.push_back(shapeObject("face", std::move(poly)));
    }
    return s;
}

uint64_t at(const RenderResult& r, RayType type, int depth) {
    return r.rays.byDepth[size_t(type)][size_t(depth)];
}

}  // namespace

TEST_CASE("refraction path: total internal reflection at the critical angle and just past it") {
    // sin θc = 1 / 1.5. At θc - 1e-7 the back face refracts (a refraction
    // ray at depth 3); at θc + 1e-7 it reflects totally (a reflection ray at
    // depth 3, carrying kt); exactly at θc (to rounding) either may happen,
    // but the cosine under the root is clamped, so never NaN. In every case
    // the pixel is finite and, since nothing absorbs (kt = 1 on every
    // interface, TIR passes kt on), it is the background once the ray escapes.
    const double critical = std::asin(1 / kIor);
    for (double delta : {-1e-7, 0.0, 1e-7}) {
        CAPTURE(delta);
        for (const Backend& b : allBackends()) {
            if (b.robust) continue;
            CAPTURE(b.label);
            Scene scene = prism(critical + delta);
            RenderOverrides o;
            o.accel = b.kind;
            const RenderResult r = renderWith(scene, o);
            CHECK(r.nonFiniteSamples == 0);
            CHECK(nonFiniteValues(r.film) == 0);
            CHECK(at(r, RayType::Camera, 1) == 1);
            CHECK(at(r, RayType::Refraction, 2) == 1);  // in through the front face
            const uint64_t refr = at(r, RayType::Refraction, 3);
            const uint64_t refl = at(r, RayType::Reflection, 3);
            MESSAGE("theta_c " << std::string(delta < 0   ? "- 1e-7"
                                              : delta > 0 ? "+ 1e-7"
                                                          : "exactly")
                               << ": depth-3 refraction " << refr << ", reflection (TIR) " << refl);
            CHECK(refr + refl == 1);
            if (delta < 0) CHECK(refr == 1);
            if (delta > 0) CHECK(refl == 1);
            if (delta != 0) {
                CHECK(r.film.rgba[0] == doctest::Approx(0.2).epsilon(1e-6));
                CHECK(r.film.rgba[2] == doctest::Approx(0.6).epsilon(1e-6));
            }
        }
    }
}

TEST_CASE("refraction path: a glass sphere of index 1 is invisible") {
    // Ambient-only matte spheres (no lights, so no shadow rays that the glass
    // would block) behind a glass sphere with kt = 1, ior = 1, no other term:
    // every camera ray through the glass refracts twice without bending and
    // must see what it would see without the glass. refract() with equal
    // indices returns d up to rounding (~1e-16), and the spawned origins move
    // by the robust offset (~4e-6 |p|) along the normal, so only pixels whose
    // ray passes within ~1e-5 of a silhouette behind can change.
    for (const Vec3 offset : {Vec3{0, 0, 0}, Vec3{1e5, -1e5, 1e5}}) {
        const auto build = [&](bool glass) {
            Scene s;
            s.camera = Camera::perspective(offset + Vec3{0, 0, 6}, offset, {0, 1, 0}, 40);
            s.image.width = 64;
            s.image.height = 48;
            s.background = Color(0.05, 0.05, 0.1);
            s.ambient = Color(1.0);
            s.materials.push_back(material(Color(0.0), Color(0.0), Color(0.0), Color(1.0), 1.0));
            s.materials.push_back(material(Color(0.0), Color(0.9, 0.2, 0.1)));
            s.materials.push_back(material(Color(0.0), Color(0.1, 0.8, 0.3)));
            s.materials.push_back(material(Color(0.0), Color(0.2, 0.3, 0.9)));
            if (glass) {
                auto g = makeSphere(offset + Vec3{0, 0, 1}, 1.6);
                g->setSidedness(Sidedness::Both);
                s.objects.push_back(shapeObject("glass", std::move(g), 0));
            }
            s.objects.push_back(shapeObject("red", makeSphere(offset + Vec3{-1, 0.4, -3}, 1), 1));
            s.objects.push_back(
                shapeObject("green", makeSphere(offset + Vec3{0.8, -0.5, -2}, 0.7), 2));
            s.objects.push_back(shapeObject("blue", makeSphere(offset + Vec3{0.3, 1.0, -6}, 2), 3));
            return s;
        };
        Scene with = build(true), without = build(false);
        RenderOverrides o;
        const RenderResult a = renderWith(with, o);
        const RenderResult b = renderWith(without, o);
        CHECK(a.nonFiniteSamples == 0);
        CHECK(a.rays.total(RayType::Refraction) > 1000);  // the glass covers much of the image
        const ImageComparison c = compareImages(a.film, b.film, 1e-3);
        MESSAGE("ior 1 glass, offset " << offset.x << ": max error " << c.maxAbsError << ", "
                                       << c.pixelsOverThreshold << " pixels over 1e-3");
        CHECK(c.pixelsOverThreshold <= 2);
    }
}

TEST_CASE("refraction path: every ray entering a glass sphere leaves through the far side") {
    // A glass sphere (ior 1.5, kt = 1, two-sided) alone, rendered at 48x36
    // through a recording accelerator on one thread. A secondary ray that
    // starts on the sphere and heads inward must start inside (its near root
    // behind it) and hit the far side: the long-double far root, about the
    // chord -2 (p - c)·d̂ (never t ~ 0: that would be the entry point again);
    // a ray that heads outward must hit nothing (the sphere is convex and
    // alone). Double precision, robust offset, camera-relative
    // Embree data: 0 violations at every scale.
    for (const Vec3 offset : {Vec3{0, 0, 0}, Vec3{1e4, 2e4, -3e4}, Vec3{1e5, -1e5, 1e5}}) {
        const Vec3 c = offset;
        const double r = 1.0;
        Scene scene;
        scene.camera = Camera::perspective(offset + Vec3{0.5, 0.3, 4}, c, {0, 1, 0}, 35);
        scene.image.width = 48;
        scene.image.height = 36;
        scene.image.maxDepth = 6;
        scene.materials.push_back(material(Color(0.0), Color(0.0), Color(0.0), Color(1.0), kIor));
        auto g = makeSphere(c, r);
        g->setSidedness(Sidedness::Both);
        scene.objects.push_back(shapeObject("glass", std::move(g)));
        for (const Backend& b : allBackends()) {
            CAPTURE(b.label);
            CAPTURE(offset.x);
            RenderOverrides ov;
            ov.threads = 1;
            const RenderOptions options = resolveRenderOptions(scene, ov);
            const auto inner = build(b, scene, options.accelOptions.origin);
            const RecordingAccelerator rec(*inner);
            const RenderResult res = render(scene, rec, options, analyseEffects(scene, options));
            CHECK(res.nonFiniteSamples == 0);
            const Vec3 eye = scene.camera.frame().eye;
            int inward = 0, outward = 0, badInward = 0, badOutward = 0;
            double worst = 0;
            for (const Query& q : rec.queries()) {
                if (q.occlusion || q.ray.o == eye) continue;  // camera rays start at the eye
                const Vec3 d = normalize(q.ray.d);
                const Vec3 rel = q.ray.o - c;
                if (dot(rel, d) < 0) {
                    ++inward;
                    // From an origin just inside, the far root is the only one ahead.
                    const SphereRoots ref = sphereReference(q.ray, c, r);
                    if (!q.hit || !ref.hit) {
                        ++badInward;
                        continue;
                    }
                    const double err = std::abs(q.hit->t - double(ref.t1)) * length(q.ray.d);
                    worst = std::max(worst, err);
                    if (err > 1e-9 * r || !(ref.t0 < 0)) ++badInward;
                } else {
                    ++outward;
                    if (q.hit) ++badOutward;
                }
            }
            MESSAGE(b.label << ", offset " << offset.x << ": " << inward << " inward rays ("
                            << badInward << " bad, worst chord error " << worst << "), " << outward
                            << " outward rays (" << badOutward << " re-hits)");
            CHECK(inward > 300);
            CHECK(badInward == 0);
            CHECK(badOutward == 0);
        }
    }
}
