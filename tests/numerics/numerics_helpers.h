#pragma once
// Helpers shared by the numerical hard cases: the accelerator back ends every
// case runs through, a long-double sphere reference, a recording accelerator
// that exposes what the integrator asked and got, and a one-call render.

#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "accel/accel_test_helpers.h"
#include "geometry/geometry_test_helpers.h"
#include "geometry/primitives.h"
#include "shape_queries.h"
#include "renderer/accel/accelerator.h"
#include "renderer/accelerator_kind.h"
#include "renderer/effects.h"
#include "renderer/render.h"
#include "renderer/render_setup.h"
#include "renderer/scene.h"

namespace raylab::numerics_test {

using accel_test::kInf;
using accel_test::kPi;
using accel_test::meshObject;
using accel_test::Rng;
using test::FlushDenormals;
using test::perpendicular;
using test::ulpDistance;
using accel_test::shapeObject;

/// One accelerator configuration the hard cases run through.
struct Backend {
    std::string label;
    AcceleratorKind kind;
    bool robust = false;
};

/// Embree with its fast traversal (--no-robust), Embree with RTC_SCENE_FLAG_ROBUST
/// (the default), and the naive loop.
inline std::vector<Backend> allBackends() {
    return {
        {"embree", AcceleratorKind::Embree, false},
            {"embree robust", AcceleratorKind::Embree, true},
            {"naive", AcceleratorKind::Naive, false}};
}

/// Builds `b` over `scene` with geometry relative to `origin` (the eye) and
/// the analytic intersectors in `precision`.
inline std::unique_ptr<Accelerator> build(const Backend& b, const Scene& scene,
                                          const Vec3& origin = {0, 0, 0},
                                          Precision precision = Precision::Double) {
    AccelOptions o;
    o.robust = b.robust;
    o.origin = origin;
    o.intersect.precision = precision;
    return makeAccelerator(b.kind, scene, o);
}

/// \brief Ray-sphere roots in long double (64-bit significand), for rays
///   whose inputs are exact doubles.
/// \details |o + t d - c|² = r² with oc = o - c: a t² + 2 h t + cc = 0,
///   a = d·d, h = oc·d, cc = |oc|² - r². The discriminant is taken as
///   a (r - |f|)(r + |f|), f = oc - d h / a the closest point of the line
///   (no cancellation for small far spheres), and the roots in the stable
///   form q = -(h + sign(h)·sqrt(disc)), t = q / a and cc / q. Every step
///   carries 11 more bits than double, so the reference is good to well
///   under one double ulp of t for the cases used here.
struct SphereRoots {
    bool hit = false;
    long double t0 = 0, t1 = 0;
};
inline SphereRoots sphereReference(const Ray& ray, const Vec3& centre, double radius) {
    using L = long double;
    const L ox = L(ray.o.x) - L(centre.x), oy = L(ray.o.y) - L(centre.y),
            oz = L(ray.o.z) - L(centre.z);
    const L dx = ray.d.x, dy = ray.d.y, dz = ray.d.z, r = radius;
    const L a = dx * dx + dy * dy + dz * dz;
    const L h = ox * dx + oy * dy + oz * dz;
    const L fx = ox - dx * (h / a), fy = oy - dy * (h / a), fz = oz - dz * (h / a);
    const L lf = std::sqrt(fx * fx + fy * fy + fz * fz);
    const L disc = a * ((r - lf) * (r + lf));
    SphereRoots out;
    if (disc < 0) return out;
    const L cc = (ox * ox + oy * oy + oz * oz) - r * r;
    const L s = std::sqrt(disc);
    const L q = -(h + (h < 0 ? -s : s));
    L t0 = q / a, t1 = cc / q;
    if (t0 > t1) std::swap(t0, t1);
    out.hit = true;
    out.t0 = t0;
    out.t1 = t1;
    return out;
}

/// One query the integrator made and the answer it got.
struct Query {
    Ray ray;
    double tMin = 0, tMax = 0;
    bool occlusion = false;
    std::optional<Hit> hit;  ///< intersect() answers
    bool occluded = false;   ///< occluded() answers
};

/// A decorator that forwards every query and records it (thread-safe; use
/// one render thread when the order matters). It asks the inner accelerator
/// without the Departure the integrator names: the tests that record check
/// that a ray does not meet its own surface again, which a query leaving that
/// surface's test out could not show.
class RecordingAccelerator final : public Accelerator {
public:
    explicit RecordingAccelerator(const Accelerator& inner) : m_inner(inner) {}
    using Accelerator::intersect;
    using Accelerator::occluded;
    using Accelerator::transmittance;
    std::optional<Hit> intersect(const Ray& ray, double tMin, double tMax,
                                 Departure) const override {
        Query q{ray, tMin, tMax, false, m_inner.intersect(ray, tMin, tMax), false};
        std::lock_guard<std::mutex> lock(m_mutex);
        m_queries.push_back(q);
        return q.hit;
    }
    bool occluded(const Ray& ray, double tMin, double tMax, Departure) const override {
        Query q{ray, tMin, tMax, true, std::nullopt, m_inner.occluded(ray, tMin, tMax)};
        std::lock_guard<std::mutex> lock(m_mutex);
        m_queries.push_back(q);
        return q.occluded;
    }
    Color transmittance(const Ray& ray, double tMin, double tMax, Departure) const override {
        const Color c = m_inner.transmittance(ray, tMin, tMax);
        Query q{ray, tMin, tMax, true, std::nullopt, c.isBlack()};
        std::lock_guard<std::mutex> lock(m_mutex);
        m_queries.push_back(q);
        return c;
    }
    std::string name() const override { return m_inner.name(); }
    double buildSeconds() const override { return m_inner.buildSeconds(); }
    FilterCounts filterCounts() const override { return m_inner.filterCounts(); }
    const std::vector<Query>& queries() const { return m_queries; }

private:
    const Accelerator& m_inner;
    mutable std::mutex m_mutex;
    mutable std::vector<Query> m_queries;
};

/// Renders `scene` with `overrides` (accelerator built as `raylab render`
/// builds it: geometry relative to the eye).
/// `departures` off: every spawned ray is tested against its own surface too
/// (RenderOptions::departures), as the self-intersection tests need.
inline RenderResult renderWith(Scene& scene, RenderOverrides overrides, bool departures = true) {
    RenderOptions options = resolveRenderOptions(scene, overrides);
    options.departures = departures;
    const auto accel = makeAccelerator(options.accel, scene, options.accelOptions);
    return render(scene, *accel, options, analyseEffects(scene, options));
}

/// NaN/Inf values among the RGBA floats of a film.
inline uint64_t nonFiniteValues(const Film& f) {
    uint64_t n = 0;
    for (float v : f.rgba) n += !std::isfinite(v);
    return n;
}

/// Material with only the given terms (everything else black).
inline Material material(Color kd, Color ka = Color(0.0), Color km = Color(0.0),
                         Color kt = Color(0.0), double ior = 1.0) {
    Material m;
    m.kd = kd;
    m.ka = ka;
    m.km = km;
    m.kt = kt;
    m.ior = ior;
    return m;
}

}  // namespace raylab::numerics_test
