#pragma once
// Small fixed-size vector types. Templated on the scalar so the intersection
// code can run the same formula in float or double (the precision study).

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace raylab {

template <class T>
struct Vec3T {
    T x{}, y{}, z{};

    constexpr Vec3T() = default;
    constexpr Vec3T(T x_, T y_, T z_) : x(x_), y(y_), z(z_) {}
    template <class U>
    constexpr explicit Vec3T(const Vec3T<U>& o)
        : x(static_cast<T>(o.x)), y(static_cast<T>(o.y)), z(static_cast<T>(o.z)) {}

    constexpr T operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
    T& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }

    constexpr Vec3T operator+(const Vec3T& o) const { return {x + o.x, y + o.y, z + o.z}; }
    constexpr Vec3T operator-(const Vec3T& o) const { return {x - o.x, y - o.y, z - o.z}; }
    constexpr Vec3T operator-() const { return {-x, -y, -z}; }
    constexpr Vec3T operator*(T s) const { return {x * s, y * s, z * s}; }
    constexpr Vec3T operator/(T s) const { return {x / s, y / s, z / s}; }
    Vec3T& operator+=(const Vec3T& o) { x += o.x; y += o.y; z += o.z; return *this; }
    Vec3T& operator-=(const Vec3T& o) { x -= o.x; y -= o.y; z -= o.z; return *this; }
    Vec3T& operator*=(T s) { x *= s; y *= s; z *= s; return *this; }
    constexpr bool operator==(const Vec3T& o) const { return x == o.x && y == o.y && z == o.z; }
    constexpr bool operator!=(const Vec3T& o) const { return !(*this == o); }
};

template <class T>
constexpr Vec3T<T> operator*(T s, const Vec3T<T>& v) { return v * s; }

template <class T>
constexpr T dot(const Vec3T<T>& a, const Vec3T<T>& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

template <class T>
constexpr Vec3T<T> cross(const Vec3T<T>& a, const Vec3T<T>& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

template <class T>
constexpr T lengthSquared(const Vec3T<T>& v) { return dot(v, v); }

template <class T>
Vec3T<T> abs(const Vec3T<T>& v) { return {std::abs(v.x), std::abs(v.y), std::abs(v.z)}; }

template <class T>
T maxComponent(const Vec3T<T>& v) { return std::max(v.x, std::max(v.y, v.z)); }


/// Whether dot(v, v) is a normal number: squaring neither overflowed nor
/// underflowed, so sqrt of it is |v| to rounding (the common case).
template <class T>
bool squaredLengthIsSafe(T l2) {
    return l2 >= std::numeric_limits<T>::min() && l2 <= std::numeric_limits<T>::max();
}

/// length() where squaring overflowed or underflowed (components near the
/// ends of the range, 1e±300 in double): the vector is scaled by its largest
/// component before squaring.
template <class T>
[[gnu::noinline]] T lengthScaled(const Vec3T<T>& v, T l2) {
    const T m = maxComponent(abs(v));
    if (!(m > T(0) && m <= std::numeric_limits<T>::max())) return std::sqrt(l2);  // 0, Inf, NaN
    const Vec3T<T> s = v / m;
    return m * std::sqrt(dot(s, s));
}

/// |v|, also for components near the ends of the range.
template <class T>
inline T length(const Vec3T<T>& v) {
    const T l2 = dot(v, v);
    if (squaredLengthIsSafe(l2)) return std::sqrt(l2);
    return lengthScaled(v, l2);  // rare: kept out of line so the common case inlines
}

/// normalize() where squaring overflowed or underflowed.
template <class T>
[[gnu::noinline]] Vec3T<T> normalizeScaled(const Vec3T<T>& v) {
    const T m = maxComponent(abs(v));
    if (!(m > T(0) && m <= std::numeric_limits<T>::max())) return Vec3T<T>{};
    const Vec3T<T> s = v / m;
    return s / std::sqrt(dot(s, s));
}

/// Unit vector along v; the zero vector stays zero (never NaN). Scaled like
/// length() where squaring would overflow or underflow.
template <class T>
inline Vec3T<T> normalize(const Vec3T<T>& v) {
    const T l2 = dot(v, v);
    if (squaredLengthIsSafe(l2)) return v / std::sqrt(l2);
    return normalizeScaled(v);  // rare: kept out of line so the common case inlines
}

template <class T>
Vec3T<T> min(const Vec3T<T>& a, const Vec3T<T>& b) {
    return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
}

template <class T>
Vec3T<T> max(const Vec3T<T>& a, const Vec3T<T>& b) {
    return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
}

/// Index (0, 1, 2) of the component with the largest magnitude.
template <class T>
int dominantAxis(const Vec3T<T>& v) {
    const Vec3T<T> a = abs(v);
    return a.x >= a.y ? (a.x >= a.z ? 0 : 2) : (a.y >= a.z ? 1 : 2);
}

template <class T>
bool isFinite(const Vec3T<T>& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

using Vec3 = Vec3T<double>;
using Vec3f = Vec3T<float>;

}  // namespace raylab
