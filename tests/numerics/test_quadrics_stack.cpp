// Cylinders, cones and general quadrics through the accelerators: the cases
// where the quadratic's leading coefficient a vanishes (NUMERICS.md §3.5 /
// §4 (15)-(18)): a ray along a cylinder's axis (a = b = 0), a ray parallel to
// a cone's side (a = 0, one real root), a paraboloid hit along its axis
// (a = 0 in a general quadric), a ray through a cone's apex. Every case runs
// in double and float, near the world origin and 1e5 away, with and without
// FTZ/DAZ (the direction (1e-20, 1e-20, 1) makes a = 2e-40, a float
// subnormal that DAZ flushes to 0).

#include <doctest/doctest.h>

#include <cmath>

#include "numerics/numerics_helpers.h"
#include "shape_queries.h"

using namespace raylab;
using namespace raylab::numerics_test;

namespace {

Scene single(std::unique_ptr<Shape> shape) {
    shape->setSidedness(Sidedness::Both);
    Scene s;
    s.materials.resize(1);
    const std::string kind = shape->kind();
    s.objects.push_back(shapeObject(kind, std::move(shape)));
    return s;
}

std::unique_ptr<Shape> cone(const Vec3& base, double r0, const Vec3& apex, double r1, bool capped) {
    ConeParams p;
    p.base = base;
    p.baseRadius = r0;
    p.apex = apex;
    p.apexRadius = r1;
    p.capped = capped;
    return makeCone(p);
}

const char* precisionName(Precision p) { return p == Precision::Float ? "float" : "double"; }

/// Float answers are good to ~1e-6 relative of the coordinates involved;
/// double ones to a few ulps of them (ulp(1e5) = 1.5e-11).
double tolerance(Precision p, const Vec3& offset) {
    const double scale = maxComponent(abs(offset));
    return p == Precision::Float ? 1e-5 * (1 + scale) : 1e-12 + 1e-15 * scale;
}

}  // namespace

TEST_CASE("quadrics stack: ray along a cylinder's axis hits only the caps, no NaN") {
    // Cylinder r = 1 from z = 0 to z = 2 (relative to the offset). From
    // inside at z = 1 along +z: capped -> top cap from inside at t = 1;
    // open -> nothing. From outside at z = -1 along +z: capped -> base cap
    // at t = 1; open -> nothing (the ray runs down the tube's hollow).
    for (const Vec3 offset : {Vec3{0, 0, 0}, Vec3{1e5, -1e5, 1e5}}) {
        for (Precision precision : {Precision::Double, Precision::Float}) {
            for (bool capped : {false, true}) {
                const Scene scene =
                    single(cone(offset, 1, offset + Vec3{0, 0, 2}, 1, capped));
                for (const Backend& b : allBackends()) {
                    const auto accel = build(b, scene, offset + Vec3{0, 0, -1}, precision);
                    for (bool daz : {false, true}) {
                        const FlushDenormals mode(daz);
                        for (const Vec3 d : {Vec3{0, 0, 1}, Vec3{1e-20, 1e-20, 1}}) {
                            CAPTURE(b.label);
                            CAPTURE(std::string(precisionName(precision)));
                            CAPTURE(capped);
                            CAPTURE(daz);
                            CAPTURE(d.x);
                            CAPTURE(offset.x);
                            for (double z0 : {1.0, -1.0}) {
                                const Ray ray{offset + Vec3{0, 0, z0}, d};
                                const auto hit = accel->intersect(ray, 0, kInf);
                                CHECK(hit.has_value() == capped);
                                CHECK(accel->occluded(ray, 0, kInf) == capped);
                                if (!hit) continue;
                                CHECK(std::abs(hit->t - 1.0) <= tolerance(precision, offset));
                                const SurfaceInteraction si = scene.surfaceAt(ray, *hit, withPrecision(precision));
                                CHECK(isFinite(si.ng));
                                CHECK(std::abs(si.ng.z) == doctest::Approx(1.0));
                                CHECK(si.frontFace == (z0 < 0));
                            }
                        }
                    }
                }
            }
        }
    }
}

TEST_CASE("quadrics stack: ray parallel to a cone's side (a = 0) has its one real root") {
    // Cone x² + y² = (1 - z)², 0 <= z <= 1 (base r = 1 at z = 0, apex at z = 1),
    // open. A ray o + t (-1, 0, 1) is parallel to the generator x = 1 - z:
    // (ox - t)² = (1 - oz - t)² leaves the linear equation
    // 2t = ox + 1 - oz, a single root on the opposite side of the cone.
    //  o = (1.2, 0, -1): t = 1.6, point (-0.4, 0, 0.6) (enters through the
    //      open base, leaves through the side: a back-face hit);
    //  o = (1.5, 0, -0.3): t = 1.4, point (0.1, 0, 1.1) beyond the apex, on
    //      the mirror nappe: rejected, a miss;
    //  o = (2, 0, -1): t = 2, point (0, 0, 1): the apex itself; the normal
    //      there (the axis, cone.h) must be finite.
    for (const Vec3 offset : {Vec3{0, 0, 0}, Vec3{1e5, -1e5, 1e5}}) {
        for (Precision precision : {Precision::Double, Precision::Float}) {
            const Scene scene =
                single(cone(offset, 1, offset + Vec3{0, 0, 1}, 0, false));
            const Vec3 d{-1, 0, 1};
            for (const Backend& b : allBackends()) {
                CAPTURE(b.label);
                CAPTURE(std::string(precisionName(precision)));
                CAPTURE(offset.x);
                const auto accel = build(b, scene, offset + Vec3{1.2, 0, -1}, precision);
                const double tol = tolerance(precision, offset);

                const Ray side{offset + Vec3{1.2, 0, -1}, d};
                const auto hit = accel->intersect(side, 0, kInf);
                REQUIRE(hit);
                CHECK(std::abs(hit->t - 1.6) <= tol);
                const SurfaceInteraction si = scene.surfaceAt(side, *hit);
                CHECK_FALSE(si.frontFace);
                // Outward normal at (-0.4, 0, 0.6): (x, y, ρ) / |.| = (-1, 0, 1) / sqrt 2.
                CHECK(si.ng.x == doctest::Approx(-std::sqrt(0.5)).epsilon(1e-5));
                CHECK(si.ng.z == doctest::Approx(std::sqrt(0.5)).epsilon(1e-5));

                CHECK_FALSE(accel->intersect(Ray{offset + Vec3{1.5, 0, -0.3}, d}, 0, kInf));

                const Ray apex{offset + Vec3{2, 0, -1}, d};
                const auto ha = accel->intersect(apex, 0, kInf);
                if (ha) {  // touching the apex may round either way; never NaN
                    CHECK(std::abs(ha->t - 2.0) <= 10 * tol);
                    CHECK(isFinite(scene.surfaceAt(apex, *ha).ng));
                }
            }
        }
    }
}

TEST_CASE("quadrics stack: paraboloid hit along its axis (a = 0) and a quadric cone's apex") {
    // Q = x² + y² - z (NUMERICS §4 (17)), clipped to [-2,2]² x [-1,4] around
    // the offset. From (0.3, 0.4, 10) along -z: a = dᵀMd = 0, the linear root
    // t = 9.75 (z = 0.25 = 0.3² + 0.4²). Quadric cone x² + y² - z² = 0
    // clipped to z in [0, 1]: the ray through its apex along (0.6, 0, 0.8)
    // starting at (-0.6, 0, -0.8) meets the surface only at the apex (t = 1)
    // and on no other point in the clip box; the gradient vanishes there and
    // the normal must still be finite (quadric.h: it faces the ray).
    for (const Vec3 offset : {Vec3{0, 0, 0}, Vec3{1e5, -1e5, 1e5}}) {
        for (Precision precision : {Precision::Double, Precision::Float}) {
            QuadricParams para;
            // Expanded around the offset (x' = x - ox ...): x² + y² - z + linear terms.
            para.A = 1;
            para.B = 1;
            para.G = -2 * offset.x;
            para.H = -2 * offset.y;
            para.I = -1;
            para.J = offset.x * offset.x + offset.y * offset.y + offset.z;
            para.clip = Bounds3(offset + Vec3{-2, -2, -1}, offset + Vec3{2, 2, 4});
            para.hasClip = true;
            const Scene scene = single(makeQuadric(para));
            for (const Backend& b : allBackends()) {
                CAPTURE(b.label);
                CAPTURE(std::string(precisionName(precision)));
                CAPTURE(offset.x);
                const Ray ray{offset + Vec3{0.3, 0.4, 10}, {0, 0, -1}};
                const auto accel = build(b, scene, ray.o, precision);
                const auto hit = accel->intersect(ray, 0, kInf);
                REQUIRE(hit);
                // The expanded coefficients at 1e5 carry J ~ 2e10: the
                // double answer keeps ~1e-6 there, float keeps nothing useful
                // beyond "a finite hit near the surface".
                const double tol = offset.x == 0                    ? tolerance(precision, offset)
                                   : precision == Precision::Double ? 1e-4
                                                                    : 1.0;
                MESSAGE(b.label << " " << std::string(precisionName(precision)) << " offset "
                                << offset.x << ": paraboloid t = " << hit->t << " (exact 9.75)");
                CHECK(std::abs(hit->t - 9.75) <= tol);
                CHECK(isFinite(scene.surfaceAt(ray, *hit, withPrecision(precision)).ng));
            }

            QuadricParams coneQ;
            coneQ.A = 1;
            coneQ.B = 1;
            coneQ.C = -1;
            coneQ.G = -2 * offset.x;
            coneQ.H = -2 * offset.y;
            coneQ.I = 2 * offset.z;
            coneQ.J = offset.x * offset.x + offset.y * offset.y - offset.z * offset.z;
            coneQ.clip = Bounds3(offset + Vec3{-1, -1, 0}, offset + Vec3{1, 1, 1});
            coneQ.hasClip = true;
            const Scene coneScene = single(makeQuadric(coneQ));
            for (const Backend& b : allBackends()) {
                CAPTURE(b.label);
                const Ray ray{offset + Vec3{-0.6, 0, -0.8}, {0.6, 0, 0.8}};
                const auto accel = build(b, coneScene, ray.o, precision);
                const auto hit = accel->intersect(ray, 0, kInf);
                if (hit) CHECK(isFinite(coneScene.surfaceAt(ray, *hit, withPrecision(precision)).ng));
                if (hit && offset.x == 0) CHECK(std::abs(hit->t - 1.0) <= 1e-3);
            }
        }
    }
}
