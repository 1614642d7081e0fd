// Ray footprints against what they approximate (Igehy's checks): camera
// differentials against neighbouring pixels' rays; reflected and refracted
// differentials off a sphere against finite differences of the actual
// secondary rays and of their next hits; the MIP level on a fronto-parallel
// quad against the analytic texel-to-pixel ratio, for cones and differentials.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>

#include "geometry/primitives.h"
#include "renderer/accel/accelerator.h"
#include "renderer/texture_shading.h"
#include "shading/optics.h"
#include "texture_test_helpers.h"

using namespace raylab;
using namespace raylab::testing;

namespace {

constexpr int kW = 64, kH = 48;
constexpr double kStep = 1e-4;  // pixels, for central differences

void checkClose(const Vec3& a, const Vec3& b, double tol) {
    CAPTURE(a.x);
    CAPTURE(a.y);
    CAPTURE(a.z);
    CAPTURE(b.x);
    CAPTURE(b.y);
    CAPTURE(b.z);
    CHECK(length(a - b) <= tol * std::max(1.0, length(b)));
}

/// What a camera ray through (px, py) meets on `shape`: its unit direction,
/// hit distance and surface record.
struct Probe {
    Vec3 d;
    double t = 0;
    SurfaceGeometry sg;
};

Probe probe(const Camera& cam, const Shape& shape, const Ray& ray) {
    Probe p;
    p.d = normalize(ray.d);
    const Ray unit{ray.o, p.d};
    const auto hit = shape.intersect(0, unit, 0, 1e30, {});
    REQUIRE(hit);
    p.t = hit->t;
    p.sg = shape.surfaceAt(0, unit, *hit, {}, SurfaceDetail::Complete);
    (void)cam;
    return p;
}

}  // namespace

TEST_CASE("camera differentials: the change of neighbouring pixels' rays") {
    const Camera persp = Camera::perspective({1, 2, 3}, {0, 0, -1}, {0, 1, 0}, 50);
    const Camera ortho = Camera::orthographic({1, 2, 3}, {-1, -2, -4}, {0, 1, 0}, 6);
    for (const Camera* cam : {&persp, &ortho}) {
        for (const auto& [px, py] : {std::pair{3.5, 40.25}, std::pair{32.0, 24.0}, std::pair{60.5, 1.5}}) {
            const Ray r = cam->generateRay(px, py, kW, kH);
            for (double spacing : {1.0, 0.25}) {
                const RayDifferential rd = cam->differential(r, kW, kH, spacing);
                const double h = kStep * spacing;
                const Ray xp = cam->generateRay(px + h, py, kW, kH), xm = cam->generateRay(px - h, py, kW, kH);
                const Ray yp = cam->generateRay(px, py + h, kW, kH), ym = cam->generateRay(px, py - h, kW, kH);
                const double k = spacing / (2 * h);
                checkClose(rd.dddx, (xp.d - xm.d) * k, 1e-6);
                checkClose(rd.dddy, (yp.d - ym.d) * k, 1e-6);
                checkClose(rd.dodx, (xp.o - xm.o) * k, 1e-6);
                checkClose(rd.dody, (yp.o - ym.o) * k, 1e-6);
            }
        }
    }
}

TEST_CASE("differentials off a sphere: transfer, reflection and refraction vs the actual rays") {
    const Camera cam = Camera::perspective({0.3, 0.2, 5}, {0, 0, 0}, {0, 1, 0}, 40);
    const std::shared_ptr<Shape> sphere = makeSphere({0, 0, 0}, 1);
    sphere->setSidedness(Sidedness::Both);  // the refracted rays leave from inside
    const double eta = 1.0 / 1.5;
    // Pixels whose rays hit the sphere at various angles of incidence.
    for (const auto& entry : {std::pair{32.0, 24.0}, std::pair{40.3, 20.7}, std::pair{25.5, 31.25}}) {
        // No structured binding: CAPTURE's lambda may not capture one (clang, C++17).
        const auto& px = entry.first;
        const auto& py = entry.second;
        CAPTURE(px);
        CAPTURE(py);
        const auto at = [&](double x, double y) { return probe(cam, *sphere, cam.generateRay(x, y, kW, kH)); };
        const Probe c = at(px, py);
        const RayDifferential rd = cam.differential(cam.generateRay(px, py, kW, kH), kW, kH, 1.0);
        Vec3 dpdx, dpdy;
        transferDifferential(rd, c.d, c.t, c.sg.ng, dpdx, dpdy);
        const Probe xp = at(px + kStep, py), xm = at(px - kStep, py);
        const Probe yp = at(px, py + kStep), ym = at(px, py - kStep);
        const double k = 1 / (2 * kStep);
        checkClose(dpdx, (xp.sg.p - xm.sg.p) * k, 1e-4);
        checkClose(dpdy, (yp.sg.p - ym.sg.p) * k, 1e-4);

        // dn/dx from the surface's dn/du, dn/dv and the uv change.
        double dudx, dvdx, dudy, dvdy;
        surfaceParameterChange(c.sg.dpdu, c.sg.dpdv, dpdx, dudx, dvdx);
        surfaceParameterChange(c.sg.dpdu, c.sg.dpdv, dpdy, dudy, dvdy);
        CHECK(dudx == doctest::Approx((xp.sg.uv.x - xm.sg.uv.x) * k).epsilon(1e-3));
        CHECK(dvdy == doctest::Approx((yp.sg.uv.y - ym.sg.uv.y) * k).epsilon(1e-3));
        const Vec3 dndx = c.sg.dndu * dudx + c.sg.dndv * dvdx;
        const Vec3 dndy = c.sg.dndu * dudy + c.sg.dndv * dvdy;
        checkClose(dndx, (xp.sg.ns - xm.sg.ns) * k, 1e-4);

        // Mirror rays.
        const RayDifferential refl = reflectDifferential(rd, c.d, c.sg.ns, dpdx, dpdy, dndx, dndy);
        checkClose(refl.dddx, (reflect(xp.d, xp.sg.ns) - reflect(xm.d, xm.sg.ns)) * k, 1e-4);
        checkClose(refl.dddy, (reflect(yp.d, yp.sg.ns) - reflect(ym.d, ym.sg.ns)) * k, 1e-4);

        // Refracted rays, and where they leave the sphere again.
        const auto refr = [&](const Probe& p) { return *refract(p.d, p.sg.ns, 1.0, 1.5); };
        const Vec3 tc = refr(c);
        const RayDifferential trd =
            refractDifferential(rd, c.d, c.sg.ns, tc, eta, dpdx, dpdy, dndx, dndy);
        checkClose(trd.dddx, (refr(xp) - refr(xm)) * k, 1e-4);
        checkClose(trd.dddy, (refr(yp) - refr(ym)) * k, 1e-4);
        const auto exitPoint = [&](const Probe& p) {
            const Ray inside{p.sg.p, refr(p)};
            const auto h = sphere->intersect(0, inside, 1e-6, 1e30, {});
            REQUIRE(h);
            return std::pair{inside.at(h->t), h->t};
        };
        const auto [pc, tcHit] = exitPoint(c);
        const SurfaceGeometry exitSg = sphere->surfaceAt(0, Ray{c.sg.p, tc}, ShapeHit{tcHit, 0, 0}, {}, SurfaceDetail::Complete);
        Vec3 dpdx2, dpdy2;
        transferDifferential(trd, tc, tcHit, exitSg.ng, dpdx2, dpdy2);
        checkClose(dpdx2, (exitPoint(xp).first - exitPoint(xm).first) * k, 1e-4);
        checkClose(dpdy2, (exitPoint(yp).first - exitPoint(ym).first) * k, 1e-4);
        (void)pc;
    }
}

TEST_CASE("camera footprint from the integrator's unit direction: the ray's own, bit for bit") {
    // The integrator computes a camera ray's footprint at its hit from the
    // normalize(ray.d) it has there; that must be what the ray alone gives.
    for (const bool ortho : {false, true}) {
        Scene s;
        s.camera = ortho ? Camera::orthographic({0, 1, 5}, {0.1, -0.2, -1}, {0, 1, 0}, 3.0)
                         : Camera::perspective({0, 1, 5}, {0.3, 0, 0}, {0, 1, 0}, 35);
        addTexturedMaterial(s, Texture::fromImage(patternImage(8, 8), "p"));
        for (TextureFootprint fp : {TextureFootprint::Cones, TextureFootprint::Differentials}) {
            for (const int spp : {1, 9}) {
                const RenderOptions opt = textureOptions(s, kW, kH, TextureFilter::Trilinear, fp, spp);
                const TextureShading shading(s, opt);
                const double spacing = spp > 1 ? 1.0 / std::sqrt(double(spp)) : 1.0;
                const Camera::DifferentialSteps steps = s.camera.differentialSteps(kW, kH, spacing);
                for (double py = 0.25; py < kH; py += 7.5) {
                    for (double px = 0.5; px < kW; px += 9.25) {
                        const Ray r = s.camera.generateRay(px, py, kW, kH);
                        const RayFootprint a = shading.cameraFootprint(r);
                        const RayFootprint b = shading.cameraFootprint(r, normalize(r.d));
                        CHECK(std::memcmp(&a, &b, sizeof a) == 0);
                        const RayDifferential da = s.camera.differential(r, steps);
                        const RayDifferential db = s.camera.differential(r, normalize(r.d), steps);
                        CHECK(std::memcmp(&da, &db, sizeof da) == 0);
                        if (fp == TextureFootprint::Cones) {
                            const RayCone c = s.camera.cone(kW, kH, spacing);
                            CHECK(std::memcmp(&b.cone, &c, sizeof c) == 0);
                        } else {
                            CHECK(std::memcmp(&b.differential, &da, sizeof da) == 0);
                        }
                    }
                }
            }
        }
    }
}

TEST_CASE("reflected and refracted footprints: the normal's change computed at the spawn equals the eager one") {
    // The normal's change (differentials) and the curvature (cones) are
    // computed only when a mirror or refracted ray leaves the hit; they must
    // be what computing them at every hit (as atHit did before) gives, bit for bit.
    Scene s;
    s.camera = Camera::perspective({0.3, 0.4, 4}, {0, 0, 0}, {0, 1, 0}, 40);
    const uint32_t mat = addTexturedMaterial(s, Texture::fromImage(patternImage(8, 8), "p"));
    addObject(s, makeSphere({0, 0, 0}, 1), mat, "ball");
    for (TextureFootprint fp : {TextureFootprint::Cones, TextureFootprint::Differentials}) {
        const RenderOptions opt = textureOptions(s, kW, kH, TextureFilter::Trilinear, fp);
        auto accel = makeAccelerator("naive", s, opt.accelOptions);
        const TextureShading shading(s, opt);
        int hits = 0;
        for (double py = 0.5; py < kH; py += 5.5) {
            for (double px = 0.5; px < kW; px += 6.5) {
                const Ray r = s.camera.generateRay(px, py, kW, kH);
                const auto hit = accel->intersect(r, 0, 1e30);
                if (!hit) continue;
                ++hits;
                const SurfaceInteraction si = s.surfaceAt(r, *hit, {}, SurfaceDetail::Complete);
                const Vec3 d = normalize(r.d);
                const RayFootprint in = shading.cameraFootprint(r);
                const HitFootprint hf = shading.atHit(in, r, d, hit->t, si);
                for (const bool entering : {true, false}) {
                    const Vec3 n = entering ? si.ns : -si.ns;
                    const double sign = entering ? 1.0 : -1.0;
                    const Vec2 dx = hf.coords.duvdx, dy = hf.coords.duvdy;
                    const Vec3 dndx = (si.dndu * dx.x + si.dndv * dx.y) * sign;
                    const Vec3 dndy = (si.dndu * dy.x + si.dndv * dy.y) * sign;
                    const double k = meanCurvature(si.dpdu, si.dpdv, si.dndu, si.dndv);
                    const double kappa = entering ? k : -k;
                    const RayFootprint refl = shading.reflected(in, hf, si, entering, d, n);
                    const auto t = refract(d, n, entering ? 1.0 : 1.5, entering ? 1.5 : 1.0);
                    if (fp == TextureFootprint::Differentials) {
                        const RayDifferential e =
                            reflectDifferential(in.differential, d, n, hf.dpdx, hf.dpdy, dndx, dndy);
                        CHECK(std::memcmp(&refl.differential, &e, sizeof e) == 0);
                    } else {
                        const RayCone e = reflectCone(in.cone, hf.coneWidth, kappa);
                        CHECK(std::memcmp(&refl.cone, &e, sizeof e) == 0);
                    }
                    if (!t) continue;
                    const double eta = entering ? 1.0 / 1.5 : 1.5;
                    const RayFootprint refr = shading.refracted(in, hf, si, entering, d, n, *t, eta);
                    if (fp == TextureFootprint::Differentials) {
                        const RayDifferential e = refractDifferential(in.differential, d, n, *t, eta,
                                                                      hf.dpdx, hf.dpdy, dndx, dndy);
                        CHECK(std::memcmp(&refr.differential, &e, sizeof e) == 0);
                    } else {
                        const RayCone e = refractCone(in.cone, hf.coneWidth, kappa, eta);
                        CHECK(std::memcmp(&refr.cone, &e, sizeof e) == 0);
                    }
                }
            }
        }
        CHECK(hits > 20);
    }
}

TEST_CASE("MIP level on a fronto-parallel quad: log2 of texels per pixel, cones and differentials") {
    // A square of side S at distance D facing the camera, uv over [0,1]², an
    // image of T texels a side: one pixel spans 2 D tan(fov/2) / H world units,
    // i.e. T · 2 D tan(fov/2) / (H S) texels.
    const double S = 2, D = 10, fov = 30;
    const int T = 1024;
    for (const double distance : {D, 4 * D}) {
        Scene s;
        s.camera = Camera::perspective({0, 0, distance}, {0, 0, 0}, {0, 1, 0}, fov);
        const uint32_t mat = addTexturedMaterial(s, Texture::fromImage(patternImage(T, T), "p"));
        PolygonParams quad;
        quad.vertices = {{-S / 2, -S / 2, 0}, {S / 2, -S / 2, 0}, {S / 2, S / 2, 0}, {-S / 2, S / 2, 0}};
        addObject(s, makePolygon(quad), mat, "quad");
        const double pixel = 2 * distance * std::tan(fov / 2 * M_PI / 180) / kH;
        const double expected = std::log2(T * pixel / S);
        for (TextureFootprint fp : {TextureFootprint::Cones, TextureFootprint::Differentials}) {
            const std::string footprintName = textureFootprintName(fp);
            CAPTURE(footprintName);
            const RenderOptions opt = textureOptions(s, kW, kH, TextureFilter::Trilinear, fp);
            auto accel = makeAccelerator("naive", s, opt.accelOptions);
            const TextureShading shading(s, opt);
            const Ray r = s.camera.generateRay(kW / 2.0, kH / 2.0, kW, kH);
            const auto hit = accel->intersect(r, 0, 1e30);
            REQUIRE(hit);
            const SurfaceInteraction si = s.surfaceAt(r, *hit, {}, SurfaceDetail::Complete);
            const HitFootprint hf = shading.atHit(shading.cameraFootprint(r), r, normalize(r.d), hit->t, si);
            const Vec2 dstdx{hf.coords.duvdx.x, -hf.coords.duvdx.y};
            const Vec2 dstdy{hf.coords.duvdy.x, -hf.coords.duvdy.y};
            const double lod = s.textures[0].image()->levelOfDetail(dstdx, dstdy);
            CAPTURE(expected);
            CHECK(lod == doctest::Approx(expected).epsilon(1e-3));
        }
    }
}

TEST_CASE("ray cones: spread grows by 2κw off a convex mirror, focuses through glass") {
    const RayCone in{0.0, 0.01};
    const double w = in.widthAt(10);
    CHECK(w == doctest::Approx(0.1));
    // A sphere of radius 2 seen from outside: κ = 1/2.
    const auto sphere = makeSphere({0, 0, 0}, 2);
    const Ray r{{0.3, 0.1, 10}, normalize(Vec3{0, 0, -1})};
    const auto h = sphere->intersect(0, r, 0, 1e30, {});
    REQUIRE(h);
    const SurfaceGeometry sg = sphere->surfaceAt(0, r, *h, {}, SurfaceDetail::Complete);
    const double k = meanCurvature(sg.dpdu, sg.dpdv, sg.dndu, sg.dndv);
    CHECK(k == doctest::Approx(0.5));
    CHECK(reflectCone(in, w, k).spread == doctest::Approx(0.01 + 2 * 0.5 * 0.1));
    // Entering glass (η = 1/1.5) a parallel beam converges: (η - 1) κ w < 0.
    const RayCone parallel{0.1, 0.0};
    CHECK(refractCone(parallel, 0.1, k, 1 / 1.5).spread == doctest::Approx((1 / 1.5 - 1) * 0.5 * 0.1));
    // The footprint of a head-on cone is a circle; at 60° it stretches by 2.
    Vec3 ax, ay;
    coneFootprint(0.1, Vec3{0, 0, -1}, Vec3{0, 0, 1}, Vec3{1, 0, 0}, ax, ay);
    CHECK(length(ax) == doctest::Approx(0.1));
    CHECK(length(ay) == doctest::Approx(0.1));
    coneFootprint(0.1, normalize(Vec3{std::sqrt(3.0), 0, -1}), Vec3{0, 0, 1}, Vec3{1, 0, 0}, ax, ay);
    CHECK(length(ax) == doctest::Approx(0.1));
    CHECK(length(ay) == doctest::Approx(0.2));
    CHECK(std::abs(dot(ay, Vec3{1, 0, 0})) == doctest::Approx(0.2));
}
