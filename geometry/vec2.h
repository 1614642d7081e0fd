#pragma once
// Two-component vectors: surface parameters (u, v) and their differences.

namespace raylab {

template <class T>
struct Vec2T {
    T x{}, y{};

    constexpr Vec2T() = default;
    constexpr Vec2T(T x_, T y_) : x(x_), y(y_) {}

    constexpr Vec2T operator+(const Vec2T& o) const { return {x + o.x, y + o.y}; }
    constexpr Vec2T operator-(const Vec2T& o) const { return {x - o.x, y - o.y}; }
    constexpr Vec2T operator*(T s) const { return {x * s, y * s}; }
    constexpr bool operator==(const Vec2T& o) const { return x == o.x && y == o.y; }
    constexpr bool operator!=(const Vec2T& o) const { return !(*this == o); }
};

using Vec2 = Vec2T<double>;
using Vec2f = Vec2T<float>;

}  // namespace raylab
