#include "geometry/transform.h"

#include <cmath>

#include "geometry/validate.h"

namespace raylab {

namespace {
constexpr double kPi = 3.14159265358979323846;

Vec3 row(const Transform::Matrix3& m, int i) { return {m[i][0], m[i][1], m[i][2]}; }

/// Row i of the cofactor matrix is the cross product of the other two rows:
/// cofactor(L) = det(L) · L⁻ᵀ.
Transform::Matrix3 cofactors(const Transform::Matrix3& m) {
    const Vec3 r0 = row(m, 0), r1 = row(m, 1), r2 = row(m, 2);
    const Vec3 c0 = cross(r1, r2), c1 = cross(r2, r0), c2 = cross(r0, r1);
    return {{{c0.x, c0.y, c0.z}, {c1.x, c1.y, c1.z}, {c2.x, c2.y, c2.z}}};
}
}  // namespace

Transform Transform::translate(const Vec3& offset) {
    return Transform(Transform().m_linear, offset);
}

Transform Transform::scale(const Vec3& factors) {
    return Transform({{{factors.x, 0, 0}, {0, factors.y, 0}, {0, 0, factors.z}}}, {0, 0, 0});
}

Transform Transform::rotate(const Vec3& axis, double degrees) {
    // Rodrigues: R = cos θ I + sin θ [k]x + (1 - cos θ) k kᵀ, k the unit axis.
    const Vec3 k = normalize(axis);
    const double theta = degrees * kPi / 180.0;
    const double c = std::cos(theta), s = std::sin(theta), C = 1 - c;
    return Transform({{{c + k.x * k.x * C, k.x * k.y * C - k.z * s, k.x * k.z * C + k.y * s},
                       {k.y * k.x * C + k.z * s, c + k.y * k.y * C, k.y * k.z * C - k.x * s},
                       {k.z * k.x * C - k.y * s, k.z * k.y * C + k.x * s, c + k.z * k.z * C}}},
                     {0, 0, 0});
}

Transform Transform::then(const Transform& next) const {
    // next(this(p)) = N (L p + t) + n = (N L) p + (N t + n)
    Matrix3 nl{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            double sum = 0;
            for (int k = 0; k < 3; ++k) sum += next.m_linear[i][k] * m_linear[k][j];
            nl[i][j] = sum;
        }
    return Transform(nl, next.point(m_translation));
}

Transform Transform::inverse() const {
    const double det = determinant();
    if (!(det != 0) || !std::isfinite(det))
        throwInvalid("transform", "cannot invert: the linear part is singular (determinant " +
                                      formatValue(det) + ")");
    // L⁻¹ = cofactor(L)ᵀ / det; then p = L⁻¹ (q - t) = L⁻¹ q - L⁻¹ t.
    const Matrix3 c = cofactors(m_linear);
    Matrix3 inv{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) inv[i][j] = c[j][i] / det;
    const Transform linearInverse(inv, {0, 0, 0});
    return Transform(inv, -linearInverse.vector(m_translation));
}

Vec3 Transform::point(const Vec3& p) const { return vector(p) + m_translation; }

Vec3 Transform::vector(const Vec3& v) const {
    const auto& m = m_linear;
    return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z,
            m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
            m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
}

Vec3 Transform::normal(const Vec3& n) const {
    // cofactor(L) = det · L⁻ᵀ: the positive factor |det| drops out under
    // normalisation, but its sign must stay so that a mirroring transform
    // keeps normals on the side the winding says is outside.
    const Matrix3 c = cofactors(m_linear);
    const Vec3 out{dot(row(c, 0), n), dot(row(c, 1), n), dot(row(c, 2), n)};
    return normalize(determinant() < 0 ? -out : out);
}

double Transform::determinant() const {
    return dot(row(m_linear, 0), cross(row(m_linear, 1), row(m_linear, 2)));
}

bool Transform::isIdentity() const {
    const Transform id;
    return m_linear == id.m_linear && m_translation == id.m_translation;
}

}  // namespace raylab
