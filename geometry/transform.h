#pragma once
// An affine transform p -> L p + t of 3D space: points, vectors and normals,
// composition and inverse. Loaders apply it to mesh vertices (the JSON mesh
// "transform"); it carries what instancing will need (an inverse, normals).

#include <array>

#include "geometry/vec.h"

namespace raylab {

class Transform {
public:
    using Matrix3 = std::array<std::array<double, 3>, 3>;

    /// The identity.
    Transform() = default;
    Transform(const Matrix3& linear, const Vec3& translation)
        : m_linear(linear), m_translation(translation) {}

    static Transform translate(const Vec3& offset);
    static Transform scale(const Vec3& factors);
    /// Right-handed rotation by `degrees` about `axis` (any non-zero length):
    /// counter-clockwise when the axis points at the viewer (Rodrigues' formula).
    static Transform rotate(const Vec3& axis, double degrees);

    /// The composition "first this, then `next`" (next ∘ this).
    Transform then(const Transform& next) const;
    /// The inverse map. Throws std::invalid_argument when the linear part is
    /// singular (determinant 0 or not finite).
    Transform inverse() const;

    /// L p + t.
    Vec3 point(const Vec3& p) const;
    /// L v: directions and offsets ignore the translation.
    Vec3 vector(const Vec3& v) const;
    /// The unit normal of the transformed surface: the inverse transpose of L
    /// applied to n, pointing to the side the transformed winding calls outside
    /// (a mirroring transform reverses windings, and loaders swap them back).
    Vec3 normal(const Vec3& n) const;

    double determinant() const;
    /// Whether the transform mirrors (determinant < 0), reversing windings.
    bool flipsHandedness() const { return determinant() < 0; }
    bool isIdentity() const;

    const Matrix3& linear() const { return m_linear; }
    const Vec3& translation() const { return m_translation; }

private:
    Matrix3 m_linear{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    Vec3 m_translation{0, 0, 0};
};

}  // namespace raylab
