#pragma once
// Orthonormal frame around a unit vector (Duff et al., "Building an
// Orthonormal Basis, Revisited", JCGT 2017). Axis-aligned normals give
// axis-aligned tangents, so the finite square of a plane z = const is the
// box it looks like.

#include <cmath>

#include "geometry/vec.h"

namespace raylab {

/// Right-handed orthonormal frame (t, b, n): t × b = n.
struct Frame {
    Vec3 t;  ///< first tangent
    Vec3 b;  ///< second tangent
    Vec3 n;  ///< the unit axis the frame was built around

    /// Frame whose third axis is the unit vector n.
    static Frame fromNormal(const Vec3& n) {
        const double sign = std::copysign(1.0, n.z);
        const double a = -1.0 / (sign + n.z);
        const double b = n.x * n.y * a;
        Frame f;
        f.t = Vec3{1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x};
        f.b = Vec3{b, sign + n.y * n.y * a, -n.y};
        f.n = n;
        return f;
    }

    /// World vector -> local coordinates (x along t, y along b, z along n).
    Vec3 toLocal(const Vec3& v) const { return {dot(v, t), dot(v, b), dot(v, n)}; }
    /// Local coordinates -> world vector.
    Vec3 toWorld(const Vec3& v) const { return t * v.x + b * v.y + n * v.z; }
};

/// Half-extents of the axis-aligned box of a disk of radius r around unit
/// axis a: r·sqrt(1 - a_i²) per axis (the disk's extent along axis i).
inline Vec3 diskHalfExtent(const Vec3& a, double r) {
    auto e = [r](double ai) { return r * std::sqrt(std::max(0.0, 1.0 - ai * ai)); };
    return {e(a.x), e(a.y), e(a.z)};
}

}  // namespace raylab
