#include "renderer/accel/naive_accelerator.h"

#include <stdexcept>
#include <string>

namespace raylab {

namespace {

/// Both back ends treat a ray they cannot trace (non-finite, zero direction,
/// empty or NaN interval) as a miss, so they agree on it too.
bool traceable(const Ray& ray, double tMin, double tMax) {
    return isFinite(ray.o) && isFinite(ray.d) && ray.d != Vec3{0, 0, 0} && tMin < tMax;
}

}  // namespace

Surface Surface::analytic(const Shape& shape, uint32_t object) {
    Surface s;
    s.m_shape = &shape;
    s.m_object = object;
    return s;
}

Surface Surface::triangle(const TriangleMesh& mesh, uint32_t object, uint32_t prim,
                          Sidedness sides) {
    Surface s;
    s.m_sides = sides;
    const auto& idx = mesh.triangles[prim];
    s.m_vertices = {mesh.positions[idx[0]], mesh.positions[idx[1]], mesh.positions[idx[2]]};
    s.m_object = object;
    s.m_prim = prim;
    return s;
}

bool Surface::acceptsTriangleFacing(const Vec3& d) const {
    if (m_sides == Sidedness::Both) return true;
    const Vec3 n = triangleNormal(m_vertices[0], m_vertices[1], m_vertices[2]);
    return acceptsFacing(m_sides, dot(d, n) < 0);
}

std::optional<Hit> Surface::hit(const Ray& ray, const WatertightRay& wray, double tMin,
                                double tMax) const {
    if (m_shape) {
        const auto h = m_shape->intersect(ray, tMin, tMax);
        if (!h) return std::nullopt;
        return Hit{h->t, m_object, m_prim, h->u, h->v};
    }
    const auto h = intersectTriangle(wray, m_vertices[0], m_vertices[1], m_vertices[2], tMin, tMax);
    if (!h || !acceptsTriangleFacing(ray.d)) return std::nullopt;
    return Hit{h->t, m_object, m_prim, h->u, h->v};
}

bool Surface::occluded(const Ray& ray, const WatertightRay& wray, double tMin, double tMax) const {
    if (m_shape) return m_shape->occluded(ray, tMin, tMax);
    return acceptsTriangleFacing(ray.d) &&
           intersectTriangle(wray, m_vertices[0], m_vertices[1], m_vertices[2], tMin, tMax)
               .has_value();
}

Bounds3 Surface::bounds() const {
    if (m_shape) return m_shape->bounds();
    Bounds3 b(m_vertices[0], m_vertices[1]);
    b.expand(m_vertices[2]);
    return b;
}

NaiveAccelerator::NaiveAccelerator(const Scene& scene) {
    m_surfaces.reserve(scene.primitiveCount());
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const Object& o = scene.objects[i];
        const auto object = static_cast<uint32_t>(i);
        if (o.isMesh()) {
            // Same check as the Embree back end: a bad index would read garbage.
            for (size_t t = 0; t < o.mesh->triangleCount(); ++t)
                for (const uint32_t index : o.mesh->triangles[t])
                    if (index >= o.mesh->positions.size())
                        throw std::invalid_argument("naive: mesh '" + o.name + "': triangle " +
                                                    std::to_string(t) + " uses vertex " +
                                                    std::to_string(index) + " of " +
                                                    std::to_string(o.mesh->positions.size()));
            for (size_t t = 0; t < o.mesh->triangleCount(); ++t)
                m_surfaces.push_back(
                    Surface::triangle(*o.mesh, object, static_cast<uint32_t>(t), o.meshSides));
        } else if (o.shape) {
            m_surfaces.push_back(Surface::analytic(*o.shape, object));
        }
    }
}

std::optional<Hit> NaiveAccelerator::intersect(const Ray& ray, double tMin, double tMax) const {
    if (!traceable(ray, tMin, tMax)) return std::nullopt;
    const WatertightRay wray(ray);  // per-ray constants, computed once
    std::optional<Hit> best;
    // Each hit shrinks the interval, so later surfaces only count if closer;
    // on an exact tie the earlier surface in scene order wins.
    for (const Surface& s : m_surfaces) {
        if (auto h = s.hit(ray, wray, tMin, tMax)) {
            tMax = h->t;
            best = h;
        }
    }
    return best;
}

bool NaiveAccelerator::occluded(const Ray& ray, double tMin, double tMax) const {
    if (!traceable(ray, tMin, tMax)) return false;
    const WatertightRay wray(ray);
    for (const Surface& s : m_surfaces)
        if (s.occluded(ray, wray, tMin, tMax)) return true;
    return false;
}

}  // namespace raylab
