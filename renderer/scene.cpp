#include "renderer/scene.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/triangle.h"

namespace raylab {

namespace {

/// Barycentrics (u, v) of the point q in the plane of the triangle, clamped
/// to the triangle. Only used when the watertight test misses the triangle the
/// accelerator chose (float traversal can hit a hair outside an edge).
void clampedBarycentrics(const Vec3& q, const Vec3& p0, const Vec3& p1, const Vec3& p2, double& u,
                         double& v) {
    const Vec3 e1 = p1 - p0, e2 = p2 - p0, r = q - p0;
    const double d11 = dot(e1, e1), d12 = dot(e1, e2), d22 = dot(e2, e2);
    const double r1 = dot(r, e1), r2 = dot(r, e2);
    const double den = d11 * d22 - d12 * d12;
    u = 0;
    v = 0;
    if (!(den > 0)) return;  // degenerate triangle: report vertex p0
    u = (d22 * r1 - d12 * r2) / den;
    v = (d11 * r2 - d12 * r1) / den;
    if (!std::isfinite(u) || !std::isfinite(v)) {
        u = v = 0;
        return;
    }
    u = std::max(u, 0.0);
    v = std::max(v, 0.0);
    const double s = u + v;
    if (s > 1) {
        u /= s;
        v /= s;
    }
}

/// Surface data of a hit on triangle `prim` of `mesh`, recomputed in double
/// from the ray alone, so every accelerator that picks this triangle gets
/// bit-identical results. `fallbackT` is only used for a ray parallel to the
/// triangle's plane, which no accelerator should report.
SurfaceInteraction meshSurface(const Ray& ray, const TriangleMesh& mesh, uint32_t prim,
                               double fallbackT) {
    const auto& idx = mesh.triangles[prim];
    const Vec3& p0 = mesh.positions[idx[0]];
    const Vec3& p1 = mesh.positions[idx[1]];
    const Vec3& p2 = mesh.positions[idx[2]];
    const Vec3 n = triangleNormal(p0, p1, p2);

    SurfaceInteraction si;
    double u = 0, v = 0;
    constexpr double kInf = std::numeric_limits<double>::infinity();
    if (const auto h = intersectTriangle(ray, p0, p1, p2, -kInf, kInf)) {
        si.t = h->t;
        u = h->u;
        v = h->v;
    } else {
        // t from the plane, barycentrics from the plane point clamped inside.
        const double tPlane = dot(n, p0 - ray.o) / dot(n, ray.d);
        si.t = std::isfinite(tPlane) ? tPlane : fallbackT;
        clampedBarycentrics(ray.at(si.t), p0, p1, p2, u, v);
    }
    // The point from the barycentrics lies on the triangle up to rounding,
    // unlike o + t·d whose error grows with t.
    si.p = p0 * (1 - u - v) + p1 * u + p2 * v;
    si.span = std::max({maxComponent(abs(p0 - si.p)), maxComponent(abs(p1 - si.p)),
                        maxComponent(abs(p2 - si.p))});

    si.ng = normalize(n);
    if (si.ng == Vec3{0, 0, 0}) si.ng = -normalize(ray.d);  // zero-area: face the ray
    si.ns = si.ng;
    if (mesh.hasNormals()) {
        const Vec3 ns = normalize(mesh.normals[idx[0]] * (1 - u - v) + mesh.normals[idx[1]] * u +
                                  mesh.normals[idx[2]] * v);
        // Interpolated normals can cancel to zero or carry bad input; keep ng then.
        if (isFinite(ns) && ns != Vec3{0, 0, 0}) si.ns = ns;
    }
    si.frontFace = dot(ray.d, si.ng) < 0;
    return si;
}

}  // namespace

size_t Scene::primitiveCount() const {
    size_t n = 0;
    for (const Object& o : objects) n += o.primitiveCount();
    return n;
}

Bounds3 Scene::bounds() const {
    Bounds3 b;
    for (const Object& o : objects) {
        if (o.isMesh())
            b.expand(o.mesh->bounds());
        else if (o.shape)
            b.expand(o.shape->bounds());
    }
    return b;
}

SurfaceInteraction Scene::surfaceAt(const Ray& ray, const Hit& hit) const {
    const Object& object = objects[hit.object];
    SurfaceInteraction si;
    if (object.isMesh()) {
        si = meshSurface(ray, *object.mesh, hit.prim, hit.t);
    } else {
        const SurfaceGeometry g = object.shape->surfaceAt(ray, ShapeHit{hit.t, hit.u, hit.v});
        si.t = hit.t;
        si.p = g.p;
        si.ng = g.ng;
        si.ns = g.ns;
        si.frontFace = g.frontFace;
        // Float-precision shapes solve relative to a point of their own (centre,
        // base, plane point), which lies within their bounds.
        if (object.shape->precision() == Precision::Float)
            si.span = maxComponent(abs(si.p - object.shape->bounds().centre()));
    }
    si.object = hit.object;
    si.material = object.materialOf(hit.prim);
    return si;
}

}  // namespace raylab
