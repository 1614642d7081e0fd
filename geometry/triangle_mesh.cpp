#include "geometry/triangle_mesh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "geometry/frame.h"
#include "geometry/triangle.h"

namespace raylab {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

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

/// Derivatives of a quantity given at the three corners with respect to
/// (u, v): solves f_i - f_2 = (uv_i - uv_2)·[df/du df/dv] for i = 0, 1.
/// Returns false when the corners' uv span no area.
template <class F>
bool uvDerivatives(const Vec2 uv[3], const F& f0, const F& f1, const F& f2, F& dfdu, F& dfdv) {
    const Vec2 duv02 = uv[0] - uv[2], duv12 = uv[1] - uv[2];
    const F df02 = f0 - f2, df12 = f1 - f2;
    const double det = duv02.x * duv12.y - duv02.y * duv12.x;
    if (!(std::abs(det) > 1e-12 * (std::abs(duv02.x * duv12.y) + std::abs(duv02.y * duv12.x))))
        return false;
    dfdu = (df02 * duv12.y - df12 * duv02.y) / det;
    dfdv = (df12 * duv02.x - df02 * duv12.x) / det;
    return true;
}

}  // namespace

Bounds3 TriangleMesh::bounds() const {
    Bounds3 b;
    for (const Vec3& p : positions) b.expand(p);
    return b;
}

Bounds3 TriangleMesh::bounds(uint32_t prim) const {
    const auto& t = triangles[prim];
    Bounds3 b(positions[t[0]], positions[t[1]]);
    b.expand(positions[t[2]]);
    return b;
}

void TriangleMesh::validate() const {
    const auto sized = [&](size_t n, const char* what) {
        if (n != 0 && n != positions.size())
            throw std::invalid_argument(std::to_string(n) + " " + what + " for " +
                                        std::to_string(positions.size()) + " vertices");
    };
    sized(normals.size(), "normals");
    sized(uvs.size(), "texture coordinates");
    sized(colors.size(), "vertex colours");
    // An out-of-range index would read garbage in either accelerator.
    for (size_t t = 0; t < triangles.size(); ++t)
        for (const uint32_t index : triangles[t])
            if (index >= positions.size())
                throw std::invalid_argument("triangle " + std::to_string(t) +
                                            " uses vertex " + std::to_string(index) + " of " +
                                            std::to_string(positions.size()));
}

bool TriangleMesh::acceptsFacing(uint32_t prim, const Vec3& d) const {
    if (m_sides == Sidedness::Both) return true;
    const auto& t = triangles[prim];
    const Vec3 n = triangleNormal(positions[t[0]], positions[t[1]], positions[t[2]]);
    return raylab::acceptsFacing(m_sides, dot(d, n) < 0);
}

std::optional<ShapeHit> TriangleMesh::intersect(uint32_t prim, const Ray& ray, double tMin,
                                                double tMax, const IntersectOptions&) const {
    const auto& t = triangles[prim];
    const auto h = intersectTriangle(ray, positions[t[0]], positions[t[1]], positions[t[2]], tMin,
                                     tMax);
    if (!h || !acceptsFacing(prim, ray.d)) return std::nullopt;
    return ShapeHit{h->t, h->u, h->v};
}

std::optional<Shape::PrimitiveHit> TriangleMesh::intersectAny(const Ray& ray, double tMin,
                                                              double tMax,
                                                              const IntersectOptions&) const {
    const WatertightRay wray(ray);  // per-ray constants, computed once
    // Local copies of the arrays' addresses: the loop then keeps them in
    // registers instead of reloading them after every store to `best`.
    const Vec3* const p = positions.data();
    const std::array<uint32_t, 3>* const tri = triangles.data();
    const uint32_t n = uint32_t(triangles.size());
    std::optional<PrimitiveHit> best;
    // Each hit shrinks the interval, so later triangles only count if closer;
    // on an exact tie the lower index wins.
    for (uint32_t i = 0; i < n; ++i) {
        const auto h = intersectTriangle(wray, p[tri[i][0]], p[tri[i][1]], p[tri[i][2]], tMin, tMax);
        if (!h || !acceptsFacing(i, ray.d)) continue;
        tMax = h->t;
        best = PrimitiveHit{i, ShapeHit{h->t, h->u, h->v}};
    }
    return best;
}

bool TriangleMesh::occludedAny(const Ray& ray, double tMin, double tMax,
                               const IntersectOptions&) const {
    const WatertightRay wray(ray);
    const Vec3* const p = positions.data();
    const std::array<uint32_t, 3>* const tri = triangles.data();
    const uint32_t n = uint32_t(triangles.size());
    for (uint32_t i = 0; i < n; ++i)
        if (acceptsFacing(i, ray.d) &&
            intersectTriangle(wray, p[tri[i][0]], p[tri[i][1]], p[tri[i][2]], tMin, tMax))
            return true;
    return false;
}

SurfaceGeometry TriangleMesh::surfaceAt(uint32_t prim, const Ray& ray, const ShapeHit& hit,
                                        const IntersectOptions&, SurfaceDetail detail) const {
    const auto& idx = triangles[prim];
    const Vec3& p0 = positions[idx[0]];
    const Vec3& p1 = positions[idx[1]];
    const Vec3& p2 = positions[idx[2]];
    const Vec3 n = triangleNormal(p0, p1, p2);

    SurfaceGeometry g;
    double u = 0, v = 0;
    if (const auto h = intersectTriangle(ray, p0, p1, p2, n, -kInf, kInf)) {
        g.t = h->t;
        u = h->u;
        v = h->v;
    } else {
        // t from the plane, barycentrics from the plane point clamped inside.
        const double tPlane = dot(n, p0 - ray.o) / dot(n, ray.d);
        g.t = std::isfinite(tPlane) ? tPlane : hit.t;
        clampedBarycentrics(ray.at(g.t), p0, p1, p2, u, v);
    }
    // The point from the barycentrics lies on the triangle up to rounding,
    // unlike o + t·d whose error grows with t.
    const double w = 1 - u - v;
    g.p = p0 * w + p1 * u + p2 * v;
    g.span = std::max({maxComponent(abs(p0 - g.p)), maxComponent(abs(p1 - g.p)),
                       maxComponent(abs(p2 - g.p))});

    g.ng = normalize(n);
    if (g.ng == Vec3{0, 0, 0}) g.ng = -normalize(ray.d);  // zero-area: face the ray
    g.ns = g.ng;
    Vec3 interpolated;  // the unnormalised interpolated vertex normal
    if (hasNormals()) {
        interpolated = normals[idx[0]] * w + normals[idx[1]] * u + normals[idx[2]] * v;
        const Vec3 ns = normalize(interpolated);
        // Interpolated normals can cancel to zero or carry bad input; keep ng then.
        if (isFinite(ns) && ns != Vec3{0, 0, 0}) g.ns = ns;
    }
    g.frontFace = dot(ray.d, g.ng) < 0;
    if (hasColors()) g.color = colors[idx[0]] * w + colors[idx[1]] * u + colors[idx[2]] * v;
    if (detail == SurfaceDetail::Normals) return g;

    const Vec2 uv[3] = {hasUvs() ? uvs[idx[0]] : Vec2{0, 0}, hasUvs() ? uvs[idx[1]] : Vec2{1, 0},
                        hasUvs() ? uvs[idx[2]] : Vec2{1, 1}};
    g.uv = uv[0] * w + uv[1] * u + uv[2] * v;
    if (!uvDerivatives(uv, p0, p1, p2, g.dpdu, g.dpdv) ||
        lengthSquared(cross(g.dpdu, g.dpdv)) == 0 || !isFinite(g.dpdu) || !isFinite(g.dpdv)) {
        // Texture coordinates without area: any tangent frame of the triangle.
        const Frame f = Frame::fromNormal(g.ng);
        g.dpdu = f.t;
        g.dpdv = f.b;
        return g;
    }
    if (hasNormals()) {
        Vec3 dNdu, dNdv;
        const double len = length(interpolated);
        if (len > 0 && uvDerivatives(uv, normals[idx[0]], normals[idx[1]], normals[idx[2]], dNdu,
                                     dNdv)) {
            // d(N/|N|) = (dN - ns (ns·dN)) / |N|.
            g.dndu = (dNdu - g.ns * dot(g.ns, dNdu)) / len;
            g.dndv = (dNdv - g.ns * dot(g.ns, dNdv)) / len;
            if (!isFinite(g.dndu) || !isFinite(g.dndv)) g.dndu = g.dndv = Vec3{};
        }
    }
    return g;
}

}  // namespace raylab
