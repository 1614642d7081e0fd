#include "geometry/triangle.h"

#include <utility>

namespace raylab {

namespace {

/// Exactly zero-area triangles (repeated vertices, exactly collinear
/// coordinates). They are rejected: the edge functions of a collinear
/// triangle can round to a tiny non-zero determinant.
bool isDegenerate(const Vec3& p0, const Vec3& p1, const Vec3& p2) {
    return triangleNormal(p0, p1, p2) == Vec3{0, 0, 0};
}

/// 2D edge function a.x·b.y − a.y·b.x in extended precision.
double edgeFunctionExtended(double ax, double ay, double bx, double by) {
    using L = long double;
    return static_cast<double>(L(ax) * L(by) - L(ay) * L(bx));
}

}  // namespace

WatertightRay::WatertightRay(const Ray& ray) : o(ray.o) {
    const Vec3& d = ray.d;
    if (!isFinite(ray.o) || !isFinite(d)) return;

    // Permute the axes so that z is the dominant direction component; swap x
    // and y when d_z < 0 so the permutation keeps the winding (paper §3).
    kz = dominantAxis(d);
    if (d[kz] == 0) return;  // zero direction
    kx = (kz + 1) % 3;
    ky = (kx + 1) % 3;
    if (d[kz] < 0) std::swap(kx, ky);

    // Shear constants that map the ray direction onto +z with unit length.
    sx = d[kx] / d[kz];
    sy = d[ky] / d[kz];
    sz = 1.0 / d[kz];
    constexpr double Vec3::*axes[3] = {&Vec3::x, &Vec3::y, &Vec3::z};
    mx = axes[kx];
    my = axes[ky];
    mz = axes[kz];
    valid = true;
}

namespace {

/// The watertight test; `normal`, when a caller has it, is the triangle's
/// triangleNormal, read by the zero-area check instead of computed again.
inline std::optional<TriangleHit> watertightTest(const WatertightRay& ray, const Vec3& p0,
                                                 const Vec3& p1, const Vec3& p2, double tMin,
                                                 double tMax, const Vec3* normal) {
    if (!ray.valid) return std::nullopt;
    const auto mx = ray.mx, my = ray.my, mz = ray.mz;
    const double sx = ray.sx, sy = ray.sy, sz = ray.sz;

    // Vertices relative to the ray origin. A shared vertex is transformed by
    // exactly the same operations in every triangle, which is what makes the
    // test watertight.
    const Vec3 a = p0 - ray.o;
    const Vec3 b = p1 - ray.o;
    const Vec3 c = p2 - ray.o;
    const double ax = a.*mx - sx * a.*mz, ay = a.*my - sy * a.*mz;
    const double bx = b.*mx - sx * b.*mz, by = b.*my - sy * b.*mz;
    const double cx = c.*mx - sx * c.*mz, cy = c.*my - sy * c.*mz;

    // Edge functions: U is the (scaled) weight of p0, V of p1, W of p2. The
    // neighbour across an edge computes exactly the negated value (no FMA
    // contraction: the build uses -ffp-contract=off).
    double U = cx * by - cy * bx;
    double V = ax * cy - ay * cx;
    double W = bx * ay - by * ax;

    // An exact zero may be a rounding artefact; redo all three in higher
    // precision so the sign decision is made consistently on both sides.
    if (U == 0 || V == 0 || W == 0) {
        U = edgeFunctionExtended(cx, cy, bx, by);
        V = edgeFunctionExtended(ax, ay, cx, cy);
        W = edgeFunctionExtended(bx, by, ax, ay);
    }

    // Two-sided: inside means all three have the same sign (zeros allowed).
    if ((U < 0 || V < 0 || W < 0) && (U > 0 || V > 0 || W > 0)) return std::nullopt;
    const double det = U + V + W;
    if (det == 0) return std::nullopt;  // ray parallel to the triangle's plane
    // Checked only for candidate hits, off the hot path of a loop over many
    // triangles: a collinear triangle can pass the sign test by rounding.
    if (normal ? *normal == Vec3{0, 0, 0} : isDegenerate(p0, p1, p2)) return std::nullopt;

    // Depth: the scaled z coordinates interpolated with the edge weights. As
    // U, V, W share the sign of det, t is a convex combination of the vertex
    // depths and u, v lie in [0, 1].
    const double az = sz * a.*mz, bz = sz * b.*mz, cz = sz * c.*mz;
    const double T = U * az + V * bz + W * cz;
    const double invDet = 1.0 / det;
    const double t = T * invDet;
    if (!(t > tMin && t < tMax)) return std::nullopt;  // also rejects NaN
    return TriangleHit{t, V * invDet, W * invDet};
}

}  // namespace

std::optional<TriangleHit> intersectTriangle(const Ray& ray, const Vec3& p0, const Vec3& p1,
                                             const Vec3& p2, double tMin, double tMax) {
    return watertightTest(WatertightRay(ray), p0, p1, p2, tMin, tMax, nullptr);
}

std::optional<TriangleHit> intersectTriangle(const Ray& ray, const Vec3& p0, const Vec3& p1,
                                             const Vec3& p2, const Vec3& normal, double tMin,
                                             double tMax) {
    return watertightTest(WatertightRay(ray), p0, p1, p2, tMin, tMax, &normal);
}

std::optional<TriangleHit> intersectTriangle(const WatertightRay& ray, const Vec3& p0,
                                             const Vec3& p1, const Vec3& p2, double tMin,
                                             double tMax) {
    return watertightTest(ray, p0, p1, p2, tMin, tMax, nullptr);
}

std::optional<TriangleHit> intersectTriangleMollerTrumbore(const Ray& ray, const Vec3& p0,
                                                           const Vec3& p1, const Vec3& p2,
                                                           double tMin, double tMax) {
    if (isDegenerate(p0, p1, p2)) return std::nullopt;
    // Möller & Trumbore 1997: solve o + t·d = p0 + u·e1 + v·e2 by Cramer's rule.
    const Vec3 e1 = p1 - p0;
    const Vec3 e2 = p2 - p0;
    const Vec3 pvec = cross(ray.d, e2);
    const double det = dot(e1, pvec);
    // Two-sided: only an exactly zero (or NaN) determinant is rejected.
    if (!(det != 0)) return std::nullopt;
    const double invDet = 1.0 / det;

    const Vec3 tvec = ray.o - p0;
    const double u = dot(tvec, pvec) * invDet;
    if (!(u >= 0 && u <= 1)) return std::nullopt;

    const Vec3 qvec = cross(tvec, e1);
    const double v = dot(ray.d, qvec) * invDet;
    if (!(v >= 0 && u + v <= 1)) return std::nullopt;

    const double t = dot(e2, qvec) * invDet;
    if (!(t > tMin && t < tMax)) return std::nullopt;
    return TriangleHit{t, u, v};
}

}  // namespace raylab
