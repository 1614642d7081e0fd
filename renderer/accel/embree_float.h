#pragma once
// Double -> float conversions for Embree's single-precision world: directed
// rounding (so float intervals and boxes contain the double ones), range
// clamping (Embree drops boxes beyond ±FLT_LARGE, NUMERICS.md §1) and the
// padded box of a user-geometry primitive.

#include <embree3/rtcore.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "geometry/bounds.h"

namespace raylab {

constexpr float kInfF = std::numeric_limits<float>::infinity();

/// Embree silently drops boxes beyond ±FLT_LARGE (1.844e18, NUMERICS.md §1);
/// infinite extents are clamped to this, which is still "everywhere" for any
/// ray a float BVH can trace.
constexpr double kMaxEmbreeCoordinate = 1e18;

/// User-geometry boxes are traversed with the non-robust slab test even under
/// RTC_SCENE_FLAG_ROBUST: pad them by ~1e-6 of their largest coordinate.
constexpr double kEmbreeBoxPadding = 8.0 * FLT_EPSILON;

/// Largest float <= x (x finite and within float range).
inline float roundDown(double x) {
    float f = static_cast<float>(x);
    if (static_cast<double>(f) > x) f = std::nextafter(f, -kInfF);
    return f;
}

/// Smallest float >= x (x finite and within float range).
inline float roundUp(double x) {
    float f = static_cast<float>(x);
    if (static_cast<double>(f) < x) f = std::nextafter(f, kInfF);
    return f;
}

/// double -> float without the undefined behaviour of converting an
/// out-of-range value: beyond ±FLT_MAX the result is ±inf.
inline float toFloat(double x) {
    if (x > static_cast<double>(FLT_MAX)) return kInfF;
    if (x < -static_cast<double>(FLT_MAX)) return -kInfF;
    return static_cast<float>(x);
}

inline Vec3 clampToEmbreeRange(const Vec3& p) {
    const auto c = [](double x) { return std::clamp(x, -kMaxEmbreeCoordinate, kMaxEmbreeCoordinate); };
    return {c(p.x), c(p.y), c(p.z)};
}

/// \brief The Embree box of a primitive: relative to `origin`, clamped to the
///   range Embree accepts, padded, and rounded outward to float. An empty box
///   becomes one Embree ignores (lower > upper).
/// \throws std::invalid_argument "NaN bounds" (the caller names the object).
inline RTCBounds toEmbreeBounds(const Bounds3& world, const Vec3& origin) {
    RTCBounds out{};
    if (std::isnan(world.lo.x) || std::isnan(world.lo.y) || std::isnan(world.lo.z) ||
        std::isnan(world.hi.x) || std::isnan(world.hi.y) || std::isnan(world.hi.z))
        throw std::invalid_argument("NaN bounds");
    if (world.empty()) {
        out.lower_x = out.lower_y = out.lower_z = 1.0f;
        out.upper_x = out.upper_y = out.upper_z = -1.0f;
        return out;
    }
    Bounds3 rel;
    rel.lo = clampToEmbreeRange(world.lo - origin);
    rel.hi = clampToEmbreeRange(world.hi - origin);
    rel = rel.padded(kEmbreeBoxPadding);
    rel.lo = clampToEmbreeRange(rel.lo);
    rel.hi = clampToEmbreeRange(rel.hi);
    out.lower_x = roundDown(rel.lo.x);
    out.lower_y = roundDown(rel.lo.y);
    out.lower_z = roundDown(rel.lo.z);
    out.upper_x = roundUp(rel.hi.x);
    out.upper_y = roundUp(rel.hi.y);
    out.upper_z = roundUp(rel.hi.z);
    return out;
}

}  // namespace raylab
