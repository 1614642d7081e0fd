#pragma once
// The interior angles of a triangle, the weights of angle-weighted vertex
// normals (an OBJ's smoothing groups).

#include <array>
#include <cmath>

#include "geometry/vec.h"

namespace raylab {

/// The interior angles of triangle (p0, p1, p2) at p0, p1 and p2: at corner a
/// of (a, b, c), atan2(|e1 × e2|, e1 · e2) with e1, e2 the unit edges from a
/// to b and to c. Each edge is normalised once and shared by its two corners:
/// negating a vector is exact in IEEE arithmetic (p − q = −(q − p),
/// normalize(−v) = −normalize(v), cross(a, −b) = −cross(a, b), dot(a, −b) =
/// −dot(a, b), all bit for bit), so every angle has the bits of the textbook
/// per-corner formula with half its square roots and divisions. Not for a
/// zero edge (p − p = +0 but −(p − p) = −0, and atan2(0, ±0) differ) nor an
/// edge that overflows: the OBJ loader passes neither (only triangles with
/// area, vertices within float range).
inline std::array<double, 3> cornerAngles(const Vec3& p0, const Vec3& p1, const Vec3& p2) {
    const Vec3 e01 = normalize(p1 - p0), e02 = normalize(p2 - p0), e12 = normalize(p2 - p1);
    // At p1 the edges are e12 and -e01: the cross product's sign vanishes in
    // length(), the dot product's is applied. At p2 they are -e02 and -e12:
    // both signs cancel.
    return {std::atan2(length(cross(e01, e02)), dot(e01, e02)),
            std::atan2(length(cross(e12, e01)), -dot(e12, e01)),
            std::atan2(length(cross(e02, e12)), dot(e02, e12))};
}

}  // namespace raylab
