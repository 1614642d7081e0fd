#pragma once
// The x and y steps of a footprint computed in lockstep. A ray differential
// runs every formula twice, once for a step right (x) and once for a step down
// (y), and those formulas are chains of divisions. StepPair holds the two in
// one SSE2 register (GCC/Clang vector extension): lane 0 the x step, lane 1
// the y step. Every lane does the same IEEE operations in the same order as
// the scalar formula it replaces (no FMA: the build does not enable it), so
// each result is the scalar one bit for bit, with one packed division where
// the scalar code had two.

#include "geometry/vec.h"
#include "geometry/vec2.h"

namespace raylab {

using StepPair = double __attribute__((vector_size(16)));

/// Both lanes `s`.
inline StepPair both(double s) { return StepPair{s, s}; }

/// Two vectors, x step in lane 0, y step in lane 1, component by component.
struct Vec3Pair {
    StepPair x, y, z;

    Vec3Pair() = default;
    Vec3Pair(StepPair x_, StepPair y_, StepPair z_) : x(x_), y(y_), z(z_) {}
    Vec3Pair(const Vec3& a, const Vec3& b) : x{a.x, b.x}, y{a.y, b.y}, z{a.z, b.z} {}

    Vec3 first() const { return {x[0], y[0], z[0]}; }
    Vec3 second() const { return {x[1], y[1], z[1]}; }
};

inline Vec3Pair operator+(const Vec3Pair& a, const Vec3Pair& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3Pair operator-(const Vec3Pair& a, const Vec3Pair& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
/// a * s for each lane's vector a and that lane's scalar s.
inline Vec3Pair operator*(const Vec3Pair& a, StepPair s) { return {a.x * s, a.y * s, a.z * s}; }
/// The one vector v times each lane's scalar: (v * s0, v * s1).
inline Vec3Pair operator*(const Vec3& v, StepPair s) { return {both(v.x) * s, both(v.y) * s, both(v.z) * s}; }
inline Vec3Pair operator/(const Vec3Pair& a, StepPair s) { return {a.x / s, a.y / s, a.z / s}; }

/// dot(a_lane, v) per lane, summed x + y + z as raylab::dot does.
inline StepPair dot(const Vec3Pair& a, const Vec3& v) {
    return a.x * both(v.x) + a.y * both(v.y) + a.z * both(v.z);
}

}  // namespace raylab
