#pragma once
// The ray-plane steps shared by the plane, disk and polygon intersectors.

#include <cmath>
#include <optional>

#include "geometry/frame.h"
#include "geometry/shape.h"
#include "geometry/vec.h"

namespace raylab {

/// Where the ray o + t·d meets the plane through p0 with normal n:
/// t = n·(p0 - o) / (n·d). Returns false (and no NaN) when the ray is parallel
/// to the plane, including a ray lying in it (n·d == 0) or a NaN direction.
/// `cosine` receives n·d, whose sign tells the facing (< 0: front face).
template <class T>
bool intersectPlane(const Vec3T<T>& n, const Vec3T<T>& p0, const Vec3T<T>& o, const Vec3T<T>& d,
                    T& t, T& cosine) {
    cosine = dot(n, d);
    if (cosine == T(0) || std::isnan(cosine)) return false;
    t = dot(n, p0 - o) / cosine;
    return true;
}

/// A hit on a framed plane: the ray parameter and the hit's in-plane
/// coordinates along the frame's tangents, relative to the plane's origin.
template <class T>
struct FramedPlaneHit {
    double t;
    T u, v;
};

/// The step the plane and the disk share: the ray against the plane through
/// `origin` with normal frame.n, honouring the sidedness and (tMin, tMax),
/// with (u, v) = the hit's offset from `origin` along frame.t and frame.b.
/// The caller tests (u, v) against its own outline. The ray origin is taken
/// relative to `origin` in double before rounding to T, so float stays exact
/// far from the world origin.
template <class T>
std::optional<FramedPlaneHit<T>> intersectFramedPlane(const Frame& frame, const Vec3& origin,
                                                      Sidedness sides, const Ray& ray, double tMin,
                                                      double tMax) {
    using V = Vec3T<T>;
    const V o(ray.o - origin);
    const V d(ray.d);
    T t, cosine;
    if (!intersectPlane(V(frame.n), V{}, o, d, t, cosine)) return std::nullopt;
    if (!acceptsFacing(sides, cosine < T(0))) return std::nullopt;
    const double td = static_cast<double>(t);
    if (!(tMin < td && td < tMax)) return std::nullopt;
    // The in-plane offset; its normal component is rounding noise.
    const V local = o + d * t;
    return FramedPlaneHit<T>{td, dot(local, V(frame.t)), dot(local, V(frame.b))};
}

}  // namespace raylab
