#include "geometry/sphere.h"

#include <cmath>

#include "geometry/primitives.h"
#include "geometry/quadratic.h"
#include "geometry/surface_parameters.h"
#include "geometry/validate.h"

namespace raylab {

namespace {
/// Below this |c| / r² the origin is within ~6% of the radius from the surface
/// and |o - centre|² - r² loses more than four bits to cancellation.
constexpr double kIllConditionedC = 0.125;

/// u, v = x and y of the unit outward normal at the hit (cheap; spherical angles
/// would cost an atan2 and an acos, ~50 ns, on every accepted candidate).
ShapeHit sphereHit(double t, const Vec3& local, double radius) {
    return {t, local.x / radius, local.y / radius};
}
}  // namespace

Sphere::Sphere(const Vec3& centre, double radius, const Vec3& pole)
    : m_centre(centre), m_radius(radius), m_frame(Frame::fromNormal(pole)) {}

Bounds3 Sphere::bounds() const {
    const Vec3 r{m_radius, m_radius, m_radius};
    return Bounds3(m_centre - r, m_centre + r).padded();
}

template <class T>
std::optional<ShapeHit> Sphere::intersectT(const Ray& ray, double tMin, double tMax,
                                           const IntersectOptions&) const {
    using V = Vec3T<T>;
    const T r = static_cast<T>(m_radius);
    const V d(ray.d);
    // Work relative to the centre, subtracting in double before any rounding
    // to T: a float path that rounded origin and centre separately would lose
    // everything below ulp(|origin|) (acne far from the world origin).
    const Vec3 ocd = ray.o - m_centre;
    const V oc(ocd);
    const T a = dot(d, d);
    if (!(a > T(0))) return std::nullopt;  // zero or NaN direction
    const T h = dot(oc, d);                // half of the textbook b

    T c = dot(oc, oc) - r * r;
    T disc;
    if (std::abs(c) < T(kIllConditionedC) * r * r) {
        // Origin close to the surface: redo c in doubled precision, from the
        // exact double difference o - centre (hi + lo), split into T, so the
        // result does not depend on where the centre is.
        double ex, ey, ez;
        const double dx = twoSum(ray.o.x, -m_centre.x, ex);
        const double dy = twoSum(ray.o.y, -m_centre.y, ey);
        const double dz = twoSum(ray.o.z, -m_centre.z, ez);
        const T hx = T(dx), hy = T(dy), hz = T(dz);
        const T lx = T((dx - double(hx)) + ex), ly = T((dy - double(hy)) + ey),
                lz = T((dz - double(hz)) + ez);
        c = sumSquaresMinusSquare(hx, hy, hz, lx, ly, lz, r);
        // With an accurate small c, h² - a·c does not cancel (unless the ray grazes),
        // while r - |f| does for shallow rays: it is the better discriminant here.
        disc = h * h - a * c;
    } else {
        // f: centre -> closest point of the line. r² - |f|² = (r - |f|)(r + |f|) keeps
        // the digits that the naive h² - a·c loses when the sphere is small and far away.
        const V f = oc - d * (h / a);
        const T lf = length(f);
        disc = a * ((r - lf) * (r + lf));
    }
    if (!(disc >= T(0))) return std::nullopt;

    const QuadraticRoots<T> roots = solveQuadraticHalfB(a, h, c, disc);
    if (roots.count == 0) return std::nullopt;

    // The near root enters (front face) unless the ray only touches the sphere.
    const bool nearFront = disc > T(0);
    const double t0 = static_cast<double>(roots.t0);
    if (acceptsFacing(m_sides, nearFront) && tMin < t0 && t0 < tMax) {
        return sphereHit(t0, ray.o - m_centre + ray.d * t0, m_radius);
    }
    const double t1 = static_cast<double>(roots.t1);
    if (acceptsFacing(m_sides, false) && tMin < t1 && t1 < tMax) {
        return sphereHit(t1, ray.o - m_centre + ray.d * t1, m_radius);
    }
    return std::nullopt;
}

template std::optional<ShapeHit> Sphere::intersectT<float>(const Ray&, double, double,
                                                          const IntersectOptions&) const;
template std::optional<ShapeHit> Sphere::intersectT<double>(const Ray&, double, double,
                                                           const IntersectOptions&) const;

SurfaceGeometry Sphere::surface(const Ray& ray, const ShapeHit& hit, SurfaceDetail detail) const {
    SurfaceGeometry g;
    const Vec3 local = ray.o - m_centre + ray.d * hit.t;
    Vec3 n = normalize(local);
    if (n == Vec3{}) n = -normalize(ray.d);  // unreachable for a real hit; never a zero normal
    g.ng = g.ns = n;
    // Reproject onto the surface: removes the error o + t·d accumulates along t.
    g.p = m_centre + n * m_radius;
    g.frontFace = dot(ray.d, n) < 0;
    if (detail != SurfaceDetail::Normals) {
        // uv (an atan2 and an acos) only for Complete: the footprint of a
        // mirror or glass ball needs the derivatives alone.
        const LocalParameters l =
            sphericalParameters(m_frame.toLocal(n), detail == SurfaceDetail::Complete);
        g.uv = l.uv;
        // n = ω(u, v) and p = centre + r ω: the normal's derivatives are ω's.
        g.dndu = m_frame.toWorld(l.dpdu);
        g.dndv = m_frame.toWorld(l.dpdv);
        g.dpdu = g.dndu * m_radius;
        g.dpdv = g.dndv * m_radius;
    }
    return g;
}

std::unique_ptr<Shape> makeSphere(const Vec3& centre, double radius, const Vec3& pole) {
    requireFinite("sphere", "centre", centre);
    requirePositive("sphere", "radius", radius);
    const Vec3 n = requireDirection("sphere", "pole", pole);
    return std::make_unique<Sphere>(centre, radius, n);
}

}  // namespace raylab
