// cornerAngles: the interior angles of a triangle, each edge normalised once.
// Checked against hand-computed angles and, bit for bit, against the
// textbook per-corner formula (which the OBJ loader's smoothing normals used
// before) on random, skinny, collinear, grid and extreme-scale triangles.

#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "geometry/corner_angles.h"
#include "geometry/random.h"

using namespace raylab;

namespace {

constexpr double kPi = 3.14159265358979323846;

/// The textbook angle at a of triangle (a, b, c): both edges normalised here.
double textbookAngle(const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 e1 = normalize(b - a), e2 = normalize(c - a);
    return std::atan2(length(cross(e1, e2)), dot(e1, e2));
}

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

/// Number of corners whose angle differs in any bit from the textbook one.
int differingCorners(const Vec3& p0, const Vec3& p1, const Vec3& p2) {
    const auto got = cornerAngles(p0, p1, p2);
    return !sameBits(got[0], textbookAngle(p0, p1, p2)) +
           !sameBits(got[1], textbookAngle(p1, p2, p0)) +
           !sameBits(got[2], textbookAngle(p2, p0, p1));
}

}  // namespace

TEST_CASE("cornerAngles: hand-computed triangles") {
    // Right isosceles: 90, 45, 45 degrees.
    auto a = cornerAngles({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
    CHECK(a[0] == kPi / 2);  // atan2(1, 0), exactly
    CHECK(a[1] == doctest::Approx(kPi / 4).epsilon(1e-15));
    CHECK(a[2] == doctest::Approx(kPi / 4).epsilon(1e-15));
    // 3-4-5 right triangle: at (0,0,0) 90 degrees, at (4,0,0) atan(3/4), at (0,3,0) atan(4/3).
    a = cornerAngles({0, 0, 0}, {4, 0, 0}, {0, 3, 0});
    CHECK(a[0] == kPi / 2);
    CHECK(a[1] == doctest::Approx(std::atan(0.75)).epsilon(1e-15));
    CHECK(a[2] == doctest::Approx(std::atan(4.0 / 3.0)).epsilon(1e-15));
    // Equilateral, tilted out of every axis plane: 60 degrees each.
    const Vec3 p0{1, 0, 0}, p1{0, 1, 0}, p2{0, 0, 1};
    for (double x : cornerAngles(p0, p1, p2)) CHECK(x == doctest::Approx(kPi / 3).epsilon(1e-15));
    // 60 degrees at the apex of an equilateral triangle in the xy plane.
    a = cornerAngles({0, 0, 0}, {std::sqrt(3.0), -1, 0}, {std::sqrt(3.0), 1, 0});
    CHECK(a[0] == doctest::Approx(kPi / 3).epsilon(1e-15));
    // An obtuse corner: 120 degrees at the apex of an isosceles triangle.
    a = cornerAngles({0, 1, 0}, {-std::sqrt(3.0), 0, 0}, {std::sqrt(3.0), 0, 0});
    CHECK(a[0] == doctest::Approx(2 * kPi / 3).epsilon(1e-15));
    CHECK(a[1] == doctest::Approx(kPi / 6).epsilon(1e-15));
}

TEST_CASE("cornerAngles: the textbook formula's bits on random triangles") {
    SplitMix64 rng(20261203);
    int differ = 0, tested = 0;
    for (int i = 0; i < 20000; ++i) {
        const Vec3 p0 = rng.point(-10, 10), p1 = rng.point(-10, 10), p2 = rng.point(-10, 10);
        differ += differingCorners(p0, p1, p2);
        ++tested;
        // Skinny: p2 almost on the edge p0 p1 (angles near 0 and pi).
        const double s = rng.uniform();
        const Vec3 onEdge = p0 + (p1 - p0) * s + rng.direction() * (1e-9 * rng.uniform());
        differ += differingCorners(p0, p1, onEdge);
        ++tested;
        // Far from the origin, and at the ends of the double range (where
        // normalize() and length() scale before squaring).
        for (const double scale : {1e-310, 1e-200, 1e-30, 1e30, 1e200, 1e300}) {
            differ += differingCorners(p0 * scale, p1 * scale, p2 * scale);
            ++tested;
        }
        const Vec3 far{1e8, -3e7, 2e9};
        differ += differingCorners(far + p0 * 1e-3, far + p1 * 1e-3, far + p2 * 1e-3);
        ++tested;
    }
    CHECK(tested == 180000);
    CHECK(differ == 0);
}

TEST_CASE("cornerAngles: the textbook formula's bits on a grid (shared coordinates, signed zeros)") {
    // Terrains and axis-aligned meshes share coordinates between corners:
    // edges with zero components, where -(p - q) and q - p differ in the sign
    // of a zero. Every triangle with area on the {-1, 0, 1}^3 grid.
    std::vector<Vec3> grid;
    for (int x = -1; x <= 1; ++x)
        for (int y = -1; y <= 1; ++y)
            for (int z = -1; z <= 1; ++z) grid.push_back(Vec3(x, y, z));
    int tested = 0, differ = 0;
    for (const Vec3& p0 : grid)
        for (const Vec3& p1 : grid)
            for (const Vec3& p2 : grid) {
                if (lengthSquared(cross(p1 - p0, p2 - p0)) == 0) continue;
                differ += differingCorners(p0, p1, p2);
                ++tested;
            }
    CHECK(tested > 15000);
    CHECK(differ == 0);
}

TEST_CASE("cornerAngles: degenerate triangles") {
    // Collinear corners, all distinct: the identities hold, the bits agree
    // (angles 0, 0 and pi).
    const Vec3 a{1, 2, 3}, b{4, 5, 6}, c{7, 8, 9};
    CHECK(differingCorners(a, b, c) == 0);
    CHECK(differingCorners(a, c, b) == 0);
    const auto straight = cornerAngles(a, c, b);
    CHECK(straight[2] == doctest::Approx(kPi));
    // Repeated corners: a zero edge, where p - p = +0 but -(p - p) = -0, so
    // atan2(0, +-0) may differ from the textbook's. The loader weights only
    // triangles with area (whose three edges are non-zero); here the
    // angles need only be finite.
    for (const auto& t : {std::array<Vec3, 3>{a, a, b}, std::array<Vec3, 3>{a, b, b},
                          std::array<Vec3, 3>{a, b, a}, std::array<Vec3, 3>{a, a, a}})
        for (double x : cornerAngles(t[0], t[1], t[2])) CHECK(std::isfinite(x));
}
