#include "geometry/disk.h"

#include "geometry/plane_hit.h"
#include "geometry/primitives.h"
#include "geometry/surface_parameters.h"
#include "geometry/validate.h"

namespace raylab {

Disk::Disk(const Vec3& centre, const Vec3& normal, double radius)
    : m_centre(centre), m_frame(Frame::fromNormal(normal)), m_radius(radius) {}

Bounds3 Disk::bounds() const {
    const Vec3 e = diskHalfExtent(m_frame.n, m_radius);
    return Bounds3(m_centre - e, m_centre + e).padded();
}

template <class T>
std::optional<ShapeHit> Disk::intersectT(const Ray& ray, double tMin, double tMax,
                                         const IntersectOptions&) const {
    const auto h = intersectFramedPlane<T>(m_frame, m_centre, m_sides, ray, tMin, tMax);
    if (!h) return std::nullopt;
    const T r = static_cast<T>(m_radius);
    if (!(h->u * h->u + h->v * h->v <= r * r)) return std::nullopt;
    return ShapeHit{h->t, static_cast<double>(h->u / r), static_cast<double>(h->v / r)};
}

template std::optional<ShapeHit> Disk::intersectT<float>(const Ray&, double, double,
                                                        const IntersectOptions&) const;
template std::optional<ShapeHit> Disk::intersectT<double>(const Ray&, double, double,
                                                         const IntersectOptions&) const;

SurfaceGeometry Disk::surface(const Ray& ray, const ShapeHit& hit, SurfaceDetail detail) const {
    SurfaceGeometry g;
    const Vec3 p = ray.at(hit.t);
    g.p = p - m_frame.n * dot(m_frame.n, p - m_centre);
    g.ng = g.ns = m_frame.n;
    g.frontFace = dot(ray.d, m_frame.n) < 0;
    if (detail != SurfaceDetail::Normals) {
        const Vec3 local = m_frame.toLocal(g.p - m_centre);
        const LocalParameters l = polarParameters(local.x, local.y, m_radius);
        g.uv = l.uv;
        g.dpdu = m_frame.toWorld(l.dpdu);
        g.dpdv = m_frame.toWorld(l.dpdv);
    }
    return g;
}

std::unique_ptr<Shape> makeDisk(const Vec3& centre, const Vec3& normal, double radius) {
    requireFinite("disk", "centre", centre);
    const Vec3 n = requireDirection("disk", "normal", normal);
    requirePositive("disk", "radius", radius);
    return std::make_unique<Disk>(centre, n, radius);
}

}  // namespace raylab
