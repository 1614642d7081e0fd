#include "geometry/plane.h"

#include <cmath>

#include "geometry/plane_hit.h"
#include "geometry/primitives.h"
#include "geometry/validate.h"

namespace raylab {

Plane::Plane(const Vec3& point, const Vec3& normal, double halfExtent)
    : m_point(point), m_frame(Frame::fromNormal(normal)), m_halfExtent(halfExtent) {}

Bounds3 Plane::bounds() const {
    const Vec3 du = m_frame.t * m_halfExtent;
    const Vec3 dv = m_frame.b * m_halfExtent;
    Bounds3 b(m_point - du - dv, m_point + du + dv);
    b.expand(m_point - du + dv);
    b.expand(m_point + du - dv);
    return b.padded();
}

template <class T>
std::optional<ShapeHit> Plane::intersectT(const Ray& ray, double tMin, double tMax,
                                          const IntersectOptions&) const {
    const auto h = intersectFramedPlane<T>(m_frame, m_point, m_sides, ray, tMin, tMax);
    if (!h) return std::nullopt;
    const T e = static_cast<T>(m_halfExtent);
    if (!(std::abs(h->u) <= e && std::abs(h->v) <= e)) return std::nullopt;
    return ShapeHit{h->t, static_cast<double>(h->u), static_cast<double>(h->v)};
}

template std::optional<ShapeHit> Plane::intersectT<float>(const Ray&, double, double,
                                                         const IntersectOptions&) const;
template std::optional<ShapeHit> Plane::intersectT<double>(const Ray&, double, double,
                                                          const IntersectOptions&) const;

SurfaceGeometry Plane::surface(const Ray& ray, const ShapeHit& hit, SurfaceDetail detail) const {
    SurfaceGeometry g;
    const Vec3 p = ray.at(hit.t);
    // Remove the off-plane error that o + t·d accumulates for grazing rays.
    g.p = p - m_frame.n * dot(m_frame.n, p - m_point);
    g.ng = g.ns = m_frame.n;
    g.frontFace = dot(ray.d, m_frame.n) < 0;
    if (detail != SurfaceDetail::Normals) {
        const Vec3 local = g.p - m_point;
        g.uv = {dot(local, m_frame.t), dot(local, m_frame.b)};
        g.dpdu = m_frame.t;
        g.dpdv = m_frame.b;
    }
    return g;
}

std::unique_ptr<Shape> makePlane(const Vec3& point, const Vec3& normal, double halfExtent) {
    requireFinite("plane", "point", point);
    const Vec3 n = requireDirection("plane", "normal", normal);
    requirePositive("plane", "halfExtent", halfExtent);
    // The corners must stay finite (and within Embree's float range, ~1.8e19).
    if (!(halfExtent <= 1e18)) {
        throwInvalid("plane", "halfExtent must be <= 1e18 (got " + formatValue(halfExtent) + ")");
    }
    return std::make_unique<Plane>(point, n, halfExtent);
}

}  // namespace raylab
