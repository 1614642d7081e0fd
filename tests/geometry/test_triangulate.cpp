// Ear-clipping triangulation: triangle counts, winding, area and coverage on
// convex, concave, collinear, tilted and gear-shaped polygons.

#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "geometry/geometry_test_helpers.h"
#include "geometry/polygon.h"
#include "geometry/primitives.h"
#include "shape_queries.h"

using namespace raylab;

namespace {
constexpr double kPi = 3.14159265358979323846;

/// Checks that the triangles are wound like the polygon (normals along its Newell
/// normal), that their areas add up to the polygon's area (so, all being inside the
/// polygon, they do not overlap), and that every triangle's centroid is inside it.
void checkTriangulation(const std::vector<Vec3>& v, size_t expectedTriangles) {
    const auto tris = triangulatePolygon(v);
    CHECK(tris.size() == expectedTriangles);
    const Vec3 n = newellNormal(v);
    const double polygonArea = length(n) / 2;
    const Vec3 unit = normalize(n);
    PolygonParams params;
    params.vertices = v;
    params.rule = FillRule::NonZero;
    auto poly = makePolygon(params);
    poly->setSidedness(Sidedness::Both);
    double sum = 0;
    for (const auto& t : tris) {
        const Vec3 tn = cross(v[t[1]] - v[t[0]], v[t[2]] - v[t[0]]);
        CHECK(dot(tn, unit) > 0);
        sum += length(tn) / 2;
        const Vec3 c = (v[t[0]] + v[t[1]] + v[t[2]]) / 3.0;
        CHECK(intersect1(*poly, Ray{c + unit, -unit}, 0, 10).has_value());
    }
    CHECK(sum == doctest::Approx(polygonArea).epsilon(1e-12));
}
}  // namespace

TEST_CASE("triangulate: convex polygons") {
    checkTriangulation({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}, 1);
    checkTriangulation({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, 2);
    std::vector<Vec3> hexagon;
    for (int i = 0; i < 6; ++i) {
        hexagon.push_back({std::cos(kPi * i / 3), std::sin(kPi * i / 3), 2});
    }
    checkTriangulation(hexagon, 4);
}

TEST_CASE("triangulate: concave polygons") {
    // L shape (area 3), a comb with three teeth, and a clockwise-seen-from-+z version
    // (normal -z) to exercise the projection flip.
    checkTriangulation({{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}}, 4);
    const std::vector<Vec3> comb{{0, 0, 0}, {5, 0, 0}, {5, 3, 0}, {4, 3, 0}, {4, 1, 0}, {3, 1, 0},
                                 {3, 3, 0}, {2, 3, 0}, {2, 1, 0}, {1, 1, 0}, {1, 3, 0}, {0, 3, 0}};
    checkTriangulation(comb, 10);
    std::vector<Vec3> reversed(comb.rbegin(), comb.rend());
    checkTriangulation(reversed, 10);
}

TEST_CASE("triangulate: collinear vertices produce no zero-area triangles") {
    // Square with an extra vertex in the middle of each of two sides: still 2 + 2 triangles
    // at most, and none degenerate.
    const std::vector<Vec3> v{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {0, 1, 0}};
    const auto tris = triangulatePolygon(v);
    for (const auto& t : tris) {
        CHECK(length(cross(v[t[1]] - v[t[0]], v[t[2]] - v[t[0]])) > 0);
    }
    checkTriangulation(v, tris.size());
    CHECK(tris.size() <= 4);
}

TEST_CASE("triangulate: tilted concave polygon and a 144-vertex gear face") {
    // A star-shaped (simple) 10-gon in a tilted plane.
    const Vec3 n = normalize(Vec3{0.2, -0.7, 0.4});
    const Vec3 t = test::perpendicular(n), b = cross(n, t);
    std::vector<Vec3> star;
    for (int i = 0; i < 10; ++i) {
        const double r = i % 2 == 0 ? 1.0 : 0.4;
        const double a = 2 * kPi * i / 10;
        star.push_back(Vec3{3, -1, 2} + t * (r * std::cos(a)) + b * (r * std::sin(a)));
    }
    checkTriangulation(star, 8);
    std::vector<Vec3> gear;
    for (int i = 0; i < 144; ++i) {
        const double a = 2 * kPi * i / 144;
        const double r = (i / 4) % 2 == 0 ? 1.0 : 0.8;
        gear.push_back({r * std::cos(a), r * std::sin(a), 0.5});
    }
    checkTriangulation(gear, 142);
}

TEST_CASE("triangulate: invalid input") {
    CHECK_THROWS_AS(triangulatePolygon({{0, 0, 0}, {1, 0, 0}}), std::invalid_argument);
    CHECK_THROWS_AS(triangulatePolygon({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}), std::invalid_argument);
    CHECK_THROWS_AS(triangulatePolygon({{0, 0, 0}, {1, 0, 0}, {1, 0, 0}}), std::invalid_argument);
    CHECK_THROWS_AS(triangulatePolygon({{0, 0, 0}, {1, std::nan(""), 0}, {0, 1, 0}}),
                    std::invalid_argument);
}

TEST_CASE("triangulateFace: triangles as given, convex quads along the shorter diagonal") {
    using Tris = std::vector<std::array<uint32_t, 3>>;
    CHECK(triangulateFace({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}) == Tris{{0, 1, 2}});
    // Diagonal 0-2 (length² 1 + 0.25) shorter than 1-3 (length² 4 + 1): split along it.
    CHECK(triangulateFace({{0, 0, 0}, {1, 0, 0}, {1, 0.5, 0}, {-1, 1, 0}}) ==
          Tris{{0, 1, 2}, {0, 2, 3}});
    // The other way round (a kite: 0-2 has length² 9, 1-3 only 4), and a
    // square (a tie) along 1-3, as tinyobjloader did.
    CHECK(triangulateFace({{0, 0, 0}, {1, -1, 0}, {3, 0, 0}, {1, 1, 0}}) ==
          Tris{{0, 1, 3}, {1, 2, 3}});
    CHECK(triangulateFace({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}) ==
          Tris{{0, 1, 3}, {1, 2, 3}});
    // A concave quad (a dart, reflex at corner 2): only the diagonal 0-2 lies
    // inside, although 1-3 is shorter; a fan from corner 1 would cover the notch.
    const std::vector<Vec3> dart = {{0, 0, 0}, {2, 1, 0}, {0, 0.5, 0}, {-2, 1, 0}};
    checkTriangulation(dart, 2);
    for (const auto& t : triangulateFace(dart)) {
        const bool usesDiagonal02 = (t[0] == 0 || t[1] == 0 || t[2] == 0) &&
                                    (t[0] == 2 || t[1] == 2 || t[2] == 2);
        CHECK(usesDiagonal02);
    }
    // A collinear corner on an axis-aligned L is removed exactly: 6 corners, 4 triangles.
    const std::vector<Vec3> l = {{3, 0, 0}, {3, 1, 0}, {1, 1, 0}, {1, 3, 0}, {0, 3, 0}, {0, 0, 0}, {1.5, 0, 0}};
    CHECK(triangulateFace(l).size() == 4);
    checkTriangulation(l, 4);
    CHECK_THROWS_AS(triangulateFace({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}}), std::invalid_argument);
}

TEST_CASE("triangulatePolygon: a warped face is clipped on its Newell plane") {
    // A concave hexagon whose corners alternate 0.4 above and below z = 0,
    // seen from +z it is an L. Dropping the dominant axis projects it like
    // its Newell plane does; the triangles must still cover the L's area
    // once (measured in the xy plane) and face +z.
    const std::vector<Vec3> warped = {{3, 0, 0.4}, {3, 1, -0.4}, {1, 1, 0.4},
                                      {1, 3, -0.4}, {0, 3, 0.4}, {0, 0, -0.4}};
    const auto tris = triangulatePolygon(warped);
    REQUIRE(tris.size() == 4);
    double area = 0;
    for (const auto& t : tris) {
        const Vec3 n = cross(warped[t[1]] - warped[t[0]], warped[t[2]] - warped[t[0]]);
        CHECK(n.z > 0);
        area += n.z / 2;
    }
    CHECK(area == doctest::Approx(5));  // the L: 3 + 2
}
