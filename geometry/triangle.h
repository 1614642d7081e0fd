#pragma once
// Ray–triangle intersection in double precision: the watertight test of
// Woop, Benthin & Wald (JCGT 2013) used by the naive accelerator and by
// Scene::surfaceAt, and the lecture's Möller–Trumbore test for comparison.
//
// Both are two-sided and use Embree's barycentric convention
// p = (1-u-v)·p0 + u·p1 + v·p2, so a hit from either test (or from Embree)
// describes the same point of the same triangle.

#include <optional>

#include "geometry/ray.h"
#include "geometry/vec.h"

namespace raylab {

/// A ray–triangle hit: ray parameter t (units of |d|) and Embree barycentrics.
struct TriangleHit {
    double t = 0;
    double u = 0;  ///< weight of p1
    double v = 0;  ///< weight of p2
};

/// \brief Watertight ray–triangle test (Woop, Benthin & Wald 2013), two-sided.
/// \details Translates the triangle to the ray origin, permutes the axes so the
///   dominant direction component is z (swapping x and y to keep the winding
///   when d_z < 0), shears the ray onto +z and evaluates 2D edge functions.
///   Edge functions that come out exactly zero are recomputed in long double,
///   so a ray through a shared edge or vertex hits at least one of the
///   triangles sharing it, never none. Zero-area triangles, zero or non-finite
///   directions never hit and never produce NaN.
/// \return the hit with tMin < t < tMax (strict, NaN-safe), or nothing.
std::optional<TriangleHit> intersectTriangle(const Ray& ray, const Vec3& p0, const Vec3& p1,
                                             const Vec3& p2, double tMin, double tMax);

/// The per-ray constants of the watertight test (axis permutation and shear),
/// computed once per ray as in the paper, so a loop over many triangles does
/// not redo the three divisions for each.
struct WatertightRay {
    /// Precomputes the constants; a non-finite or zero direction, or a
    /// non-finite origin, gives an invalid ray that never hits.
    explicit WatertightRay(const Ray& ray);

    Vec3 o;                         ///< ray origin
    int kx = 0, ky = 1, kz = 2;     ///< permuted axes: kz is the dominant |d| component
    double sx = 0, sy = 0, sz = 0;  ///< shear: x' = x - sx·z, y' = y - sy·z, z' = sz·z
    bool valid = false;
    /// The permuted axes as member pointers (&Vec3::x, ...): selecting a
    /// component through them is a fixed offset, not a branch per access.
    double Vec3::*mx = &Vec3::x;
    double Vec3::*my = &Vec3::y;
    double Vec3::*mz = &Vec3::z;
};

/// \brief intersectTriangle with the per-ray constants precomputed; gives
///   bit-identical results to the Ray overload.
std::optional<TriangleHit> intersectTriangle(const WatertightRay& ray, const Vec3& p0,
                                             const Vec3& p1, const Vec3& p2, double tMin,
                                             double tMax);

/// \brief The lecture's Möller–Trumbore test (two-sided, same conventions).
/// \details Not watertight: a ray through a shared edge can miss both
///   triangles. Kept for the accuracy study; the renderer uses intersectTriangle.
/// \return the hit with tMin < t < tMax (strict, NaN-safe), or nothing.
std::optional<TriangleHit> intersectTriangleMollerTrumbore(const Ray& ray, const Vec3& p0,
                                                           const Vec3& p1, const Vec3& p2,
                                                           double tMin, double tMax);

/// \brief Unnormalised normal (p1-p0)×(p2-p0): points to the side from which
///   p0, p1, p2 appear counter-clockwise; its length is twice the area.
inline Vec3 triangleNormal(const Vec3& p0, const Vec3& p1, const Vec3& p2) {
    return cross(p1 - p0, p2 - p0);
}

/// \brief intersectTriangle for a caller that already holds the triangle's
///   `normal` (triangleNormal(p0, p1, p2)): the test's zero-area check reads it
///   instead of computing it again. Bit-identical to the other overloads.
std::optional<TriangleHit> intersectTriangle(const Ray& ray, const Vec3& p0, const Vec3& p1,
                                             const Vec3& p2, const Vec3& normal, double tMin,
                                             double tMax);

}  // namespace raylab
