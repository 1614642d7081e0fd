#pragma once
// The ray-plane step shared by the plane, disk and polygon intersectors.

#include <cmath>

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

}  // namespace raylab
