// The grid in front of the watertight inside test of large polygons
// (geometry/polygon_grid.h): its cells agree with the geometry, and a polygon
// gives exactly the same answer (hit or miss, t, u, v) with the grid as with
// the watertight test alone, for rays aimed anywhere (through vertices and
// edges exactly, grazing, from far away, at scenes far from the origin and
// tiny ones), under both fill rules. The zones about the centroid (a disc no
// edge comes near, everything past the farthest vertex) against distances
// computed by hand and point by point.

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "geometry/polygon.h"
#include "geometry/polygon_grid.h"
#include "geometry/primitives.h"
#include "geometry/random.h"

using namespace raylab;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;

/// SPD gears' face outline: 144 vertices, 18 teeth, in the plane z = 0.25.
std::vector<Vec3> gearFace(const Vec3& centre = {}, double scale = 1) {
    std::vector<Vec3> v;
    for (int i = 0; i < 144; ++i) {
        const double a = 2 * kPi * i / 144;
        const double r = (i / 4) % 2 == 0 ? 1.0 : 0.8;
        v.push_back(centre + Vec3{r * std::cos(a), r * std::sin(a), 0.25} * scale);
    }
    return v;
}

/// A {15/7} star: self-intersecting, so even-odd and nonzero differ inside.
std::vector<Vec3> star(const Vec3& normalTilt) {
    std::vector<Vec3> v;
    const Frame f = Frame::fromNormal(normalize(normalTilt));
    for (int i = 0; i < 15; ++i) {
        const double a = 2 * kPi * ((7 * i) % 15) / 15;
        v.push_back(f.t * std::cos(a) + f.b * std::sin(a));
    }
    return v;
}

/// A {n/m} star polygon on the unit circle: its centre has winding number m.
std::vector<Vec3> starPolygon(int n, int m, const Vec3& normalTilt) {
    std::vector<Vec3> v;
    const Frame f = Frame::fromNormal(normalize(normalTilt));
    for (int i = 0; i < n; ++i) {
        const double a = 2 * kPi * ((m * i) % n) / n;
        v.push_back(f.t * std::cos(a) + f.b * std::sin(a));
    }
    return v;
}

/// A ring of radii 1 and 0.4 (24 vertices each) cut open along a zero-width
/// slit: the outer circle counter-clockwise, the inner one clockwise. Its
/// centre, where the vertex mean lies, is a hole: outside under both rules.
std::vector<Vec3> keyhole(const Vec3& centre = {}) {
    std::vector<Vec3> v;
    for (int k = 0; k <= 24; ++k)
        v.push_back(centre + Vec3{std::cos(2 * kPi * k / 24), std::sin(2 * kPi * k / 24), 0});
    for (int k = 24; k >= 0; --k)
        v.push_back(centre + Vec3{0.4 * std::cos(2 * kPi * k / 24), 0.4 * std::sin(2 * kPi * k / 24), 0});
    return v;
}

std::vector<Vec2> flatten(const std::vector<Vec3>& v) {
    std::vector<Vec2> out;
    for (const Vec3& p : v) out.push_back({p.x, p.y});
    return out;
}

/// Distance from p to the nearest edge of the closed outline v.
double edgeDistance(const std::vector<Vec2>& v, const Vec2& p) {
    double best = kInf;
    for (size_t k = 0; k < v.size(); ++k) {
        const Vec2 a = v[k] - p, e = v[(k + 1) % v.size()] - v[k];
        const double ee = e.x * e.x + e.y * e.y;
        const double f = ee > 0 ? std::clamp(-(a.x * e.x + a.y * e.y) / ee, 0.0, 1.0) : 0.0;
        const Vec2 q = a + e * f;
        best = std::min(best, std::hypot(q.x, q.y));
    }
    return best;
}

/// Winding-rule answer for point c: the signed count of edges crossing c's
/// horizontal line to its right, half-open (an edge counts when exactly one
/// end lies at or below the line).
bool insideOutline(const std::vector<Vec2>& v, FillRule rule, const Vec2& c) {
    int winding = 0, count = 0;
    for (size_t k = 0; k < v.size(); ++k) {
        const Vec2& a = v[k];
        const Vec2& b = v[(k + 1) % v.size()];
        if ((a.y <= c.y) == (b.y <= c.y)) continue;
        const double x = a.x + (c.y - a.y) * (b.x - a.x) / (b.y - a.y);
        if (x > c.x) {
            winding += b.y > a.y ? 1 : -1;
            ++count;
        }
    }
    return rule == FillRule::EvenOdd ? (count & 1) != 0 : winding != 0;
}

std::unique_ptr<Polygon> makeGridPolygon(std::vector<Vec3> v, FillRule rule) {
    PolygonParams p;
    p.vertices = std::move(v);
    p.rule = rule;
    auto shape = makePolygon(p);
    auto* poly = dynamic_cast<Polygon*>(shape.get());
    REQUIRE(poly != nullptr);
    shape.release();
    poly->setSidedness(Sidedness::Both);
    return std::unique_ptr<Polygon>(poly);
}

struct Agreement {
    long rays = 0, hits = 0, differ = 0;
};

/// Rays from random origins around the polygon towards: random points in and
/// around it, exact vertices, exact edge points (midpoints and random
/// fractions), and grazing directions.
Agreement compare(const Polygon& poly, uint64_t seed, int count) {
    SplitMix64 rng(seed);
    // The vertices' own box: bounds() is padded to at least 1e-30 across
    // (Embree's float boxes), far wider than a polygon of 1e-100.
    const std::vector<Vec3>& v = poly.vertices();
    Bounds3 b;
    for (const Vec3& p : v) b.expand(p);
    const Vec3 c = b.centre();
    const double size = length(b.extent());
    IntersectOptions withGrid, without;
    without.polygonGrid = false;
    Agreement a;
    for (int i = 0; i < count; ++i) {
        Vec3 target;
        switch (i % 4) {
            case 0: target = c + rng.point(-0.7, 0.7) * size; break;
            case 1: target = v[rng.next() % v.size()]; break;
            case 2: {
                const size_t k = rng.next() % v.size();
                const double f = i % 8 == 2 ? 0.5 : rng.uniform();
                target = v[k] + (v[(k + 1) % v.size()] - v[k]) * f;
                break;
            }
            default: target = c + rng.point(-0.5, 0.5) * size; break;
        }
        Vec3 dir = rng.direction();
        if (i % 16 == 3) {
            // Grazing: almost in the plane.
            dir = dir - poly.normal() * dot(dir, poly.normal()) + poly.normal() * rng.uniform(-1e-9, 1e-9);
        }
        const Vec3 o = target - dir * (size * rng.uniform(0.01, 50));
        const Ray ray{o, (target - o) * rng.uniform(0.3, 3)};
        const auto g = poly.intersect(0, ray, 0, kInf, withGrid);
        const auto w = poly.intersect(0, ray, 0, kInf, without);
        ++a.rays;
        a.hits += w.has_value();
        const bool same = g.has_value() == w.has_value() &&
                          (!g || (g->t == w->t && g->u == w->u && g->v == w->v));
        a.differ += !same;
    }
    return a;
}

}  // namespace

TEST_CASE("polygon grid: cells of a subdivided square agree with the square") {
    // A 2x2 square with 4 vertices per side (16 in all), clearance 1e-3.
    std::vector<Vec2> sq;
    for (int k = 0; k < 4; ++k) sq.push_back({-1 + 0.5 * k, -1});
    for (int k = 0; k < 4; ++k) sq.push_back({1, -1 + 0.5 * k});
    for (int k = 0; k < 4; ++k) sq.push_back({1 - 0.5 * k, 1});
    for (int k = 0; k < 4; ++k) sq.push_back({-1, 1 - 0.5 * k});
    const PolygonGrid grid(sq, FillRule::EvenOdd, 1e-3, 400);
    CHECK(grid.columns() == 20);
    CHECK(grid.rows() == 20);
    int inside = 0, edge = 0;
    for (double y = -1.2; y <= 1.2; y += 0.0173) {
        for (double x = -1.2; x <= 1.2; x += 0.0191) {
            const PolygonGrid::Cell c = grid.at(x, y);
            const double clear = std::min(std::abs(std::abs(x) - 1), std::abs(std::abs(y) - 1));
            const bool in = std::abs(x) < 1 && std::abs(y) < 1;
            if (c == PolygonGrid::Cell::Edge) {
                ++edge;
                continue;
            }
            // A non-Edge answer is right and keeps the clearance.
            CHECK((c == PolygonGrid::Cell::Inside) == in);
            CHECK((in ? clear : std::max(std::abs(x) - 1, std::abs(y) - 1)) >= 1e-3);
            inside += c == PolygonGrid::Cell::Inside;
        }
    }
    CHECK(inside > 0);
    CHECK(edge > 0);
    CHECK(grid.at(5, 0) == PolygonGrid::Cell::Outside);
    CHECK(grid.at(std::numeric_limits<double>::quiet_NaN(), 0) == PolygonGrid::Cell::Outside);
    CHECK(grid.edgeFraction() < 0.25);
}

TEST_CASE("polygon grid: every cell keeps its state in the two-bit packing, at any grid size") {
    // Cells are stored four to a byte: grids whose cell count is not a
    // multiple of four, and rows that start inside a byte, must read back
    // each cell's own state. An L-shaped hexagon under a fine point scan,
    // checked against the exact answer wherever the grid claims one.
    const std::vector<Vec2> ell{{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 2}, {0, 2}};
    const auto inside = [](double x, double y) {
        return x > 0 && y > 0 && ((x < 3 && y < 1) || (x < 1 && y < 2));
    };
    int unevenGrids = 0;  // cell counts that leave a partly filled last byte
    for (const int cells : {1, 2, 3, 5, 7, 13, 35, 51, 97, 1000}) {
        CAPTURE(cells);
        const PolygonGrid grid(ell, FillRule::NonZero, 1e-4, cells);
        unevenGrids += grid.columns() * grid.rows() % 4 != 0;
        int decided = 0, states[3] = {0, 0, 0};
        for (double y = -0.13; y < 2.2; y += 0.0137)
            for (double x = -0.11; x < 3.2; x += 0.0119) {
                const PolygonGrid::Cell c = grid.at(x, y);
                ++states[int(c)];
                if (c == PolygonGrid::Cell::Edge) continue;
                ++decided;
                CHECK((c == PolygonGrid::Cell::Inside) == inside(x, y));
            }
        CHECK(states[int(PolygonGrid::Cell::Edge)] > 0);
        if (cells >= 35) {
            // Fine enough for whole cells inside and outside the L.
            CHECK(states[int(PolygonGrid::Cell::Inside)] > 0);
            CHECK(states[int(PolygonGrid::Cell::Outside)] > 0);
            CHECK(decided > 0);
        }
    }
    CHECK(unevenGrids >= 3);
}

TEST_CASE("polygon grid: every non-Edge cell holds the winding of its centre, counted edge by edge") {
    // The grid classifies a row's cells in runs between crossings; this is
    // the definition it must reproduce, cell by cell: the signed count of
    // edges crossing the centre's horizontal line to its right (half-open:
    // an edge counts when exactly one end lies at or below the line):
    // insideOutline.
    const auto expected = insideOutline;
    std::vector<std::vector<Vec2>> shapes;
    std::vector<Vec2> gear, starOutline, square;
    for (const Vec3& p : gearFace()) gear.push_back({p.x, p.y});
    for (const Vec3& p : star({0, 0, 1})) starOutline.push_back({p.x, p.y});
    // The plainest outline: whole rows of inside cells between two edges.
    for (const Vec2& p : {Vec2{0, 0}, Vec2{4, 0}, Vec2{4, 4}, Vec2{0, 4}}) square.push_back(p);
    shapes = {gear, starOutline, square};
    SplitMix64 rng(20261205);
    // A comb: 150 teeth, 300 crossings in a row, each row's crossings found in
    // rising order (an insertion sort's worst case).
    std::vector<Vec2> comb;
    for (int k = 0; k < 150; ++k) {
        comb.push_back({double(k), 0});
        comb.push_back({k + 0.5, 10});
    }
    comb.push_back({150, -1});
    comb.push_back({0, -1});
    shapes.push_back(comb);
    for (int t = 0; t < 40; ++t) {  // scribbles: self-intersecting, repeated x and y
        std::vector<Vec2> s;
        const int n = 3 + int(rng.uniform() * 60);
        for (int k = 0; k < n; ++k)
            s.push_back({std::round(rng.uniform() * 16) / 4, std::round(rng.uniform() * 16) / 4});
        shapes.push_back(s);
    }
    long checked = 0, edges = 0;
    for (const std::vector<Vec2>& v : shapes) {
        for (const FillRule rule : {FillRule::EvenOdd, FillRule::NonZero}) {
            for (const int cells : {16, 99, 1000, 9216}) {
                const PolygonGrid grid(v, rule, 1e-4, cells);
                long gridEdges = 0;
                for (int j = 0; j < grid.rows(); ++j) {
                    for (int i = 0; i < grid.columns(); ++i) {
                        const PolygonGrid::Cell c = grid.cell(i, j);
                        CHECK(c == grid.at(grid.cellCentre(i, j).x, grid.cellCentre(i, j).y));
                        if (c == PolygonGrid::Cell::Edge) {
                            ++gridEdges;
                            continue;
                        }
                        ++checked;
                        CHECK((c == PolygonGrid::Cell::Inside) == expected(v, rule, grid.cellCentre(i, j)));
                    }
                }
                // The edge fraction is the count of Edge cells.
                CHECK(grid.edgeFraction() ==
                      double(gridEdges) / double(grid.rows() * grid.columns()));
                edges += gridEdges;
            }
        }
    }
    CHECK(checked > 100000);
    CHECK(edges > 0);
}

TEST_CASE("polygon grid: the gear face answers exactly as the watertight test") {
    const auto gear = makeGridPolygon(gearFace(), FillRule::EvenOdd);
    REQUIRE(gear->grid() != nullptr);
    CHECK(gear->grid()->edgeFraction() < 0.5);
    const Agreement a = compare(*gear, 1, 200000);
    CHECK(a.hits > a.rays / 4);
    CHECK(a.differ == 0);
}

TEST_CASE("polygon grid: far from the origin, tiny and huge polygons") {
    for (const auto& entry : {std::pair<Vec3, double>{{1e6, -2e6, 3e5}, 1.0},
                              {{0.5, 0.25, -1}, 1e-6},
                              {{1e3, 1e3, 1e3}, 1e5},
                              {{-7e7, 1e-3, 0}, 1e-2}}) {
        // No structured binding: CAPTURE's lambda may not capture one (clang, C++17).
        const auto& centre = entry.first;
        const auto& scale = entry.second;
        CAPTURE(centre.x);
        CAPTURE(scale);
        const auto gear = makeGridPolygon(gearFace(centre, scale), FillRule::EvenOdd);
        const Agreement a = compare(*gear, 7, 40000);
        CHECK(a.hits > 0);
        CHECK(a.differ == 0);
    }
}

TEST_CASE("polygon grid: extreme scales, where the watertight test's products underflow or overflow") {
    // The grid may answer only where its error bound holds: there it gives
    // the watertight test's answer, and beyond it (products of coordinates
    // of 1e-160 underflow, of 1e154 overflow) it is not built or not asked.
    // Before the scale limits, 1e-160 gave 5 differences in these 400,000 rays.
    for (const auto& entry : {std::pair<Vec3, double>{{0, 0, 0}, 1e-160},
                              {{3e-160, -1e-160, 2e-160}, 1e-160},
                              {{0, 0, 0}, 1e-100},
                              {{0, 0, 0}, 1e100},
                              {{0, 0, 0}, 1e154}}) {
        // No structured binding: CAPTURE's lambda may not capture one (clang, C++17).
        const auto& centre = entry.first;
        const auto& scale = entry.second;
        CAPTURE(centre.x);
        CAPTURE(scale);
        const auto gear = makeGridPolygon(gearFace(centre, scale), FillRule::EvenOdd);
        // Built from edges of 2^-350 to coordinates of 2^350.
        CHECK((gear->grid() != nullptr) == (scale > 1e-150 && scale < 1e150));
        const Agreement a = compare(*gear, 11, 400000);
        if (scale < 1e150) CHECK(a.hits > a.rays / 5);
        CHECK(a.differ == 0);
    }
}

TEST_CASE("polygon grid: crossing determinants that underflow at ordinary scales") {
    // Found by review: a 2x2 square with a notch whose bottom edge runs from
    // (0.3, 0) to (0.2, 2^-1074). A ray straight down the middle passes 0.2
    // from every edge, so it hits; but the crossing determinant of the notch
    // bottom is about 2^-1076, whose products underflow. crossSign used to
    // read their lost error terms as zero and sent the hit outside.
    const std::vector<Vec2> notch = {{-1, -1},   {-0.5, -1}, {0, -1},     {0.5, -1},   {1, -1},
                                     {1, -0.5},  {1, 0},     {1, 0.5},    {1, 1},      {0.7, 1},
                                     {0.35, 1},  {0.3, 0},   {0.2, 0x1p-1074}, {0.15, 1}, {-0.3, 1},
                                     {-1, 1},    {-1, 0.5},  {-1, 0},     {-1, -0.5}};
    IntersectOptions without;
    without.polygonGrid = false;
    for (FillRule rule : {FillRule::EvenOdd, FillRule::NonZero}) {
        CAPTURE(int(rule));
        std::vector<Vec3> flat;
        for (const Vec2& p : notch) flat.push_back({p.x, p.y, 0});
        const auto a = makeGridPolygon(flat, rule);
        const Ray down{{0, 0, 1}, {0, 0, -1}};
        CHECK(a->intersect(0, down, 0, kInf, without).has_value());
        CHECK(a->intersect(0, down, 0, kInf, {}).has_value());
        // The same outline with the notch bottom on y = 0, in the plane z = x,
        // and a direction whose y is subnormal (-2^-1070).
        std::vector<Vec3> tilted;
        for (const Vec2& p : notch) tilted.push_back({p.x, p.y == 0x1p-1074 ? 0 : p.y, p.x});
        const auto b = makeGridPolygon(tilted, rule);
        const Ray slant{{0, 0, 0.25}, {0, -0x1p-1070, -1}};
        CHECK(b->intersect(0, slant, 0, kInf, without).has_value());
        CHECK(b->intersect(0, slant, 0, kInf, {}).has_value());
    }
}

TEST_CASE("polygon grid: a self-intersecting star under both fill rules") {
    for (FillRule rule : {FillRule::EvenOdd, FillRule::NonZero}) {
        const auto s = makeGridPolygon(star({0.3, -0.2, 1}), rule);
        REQUIRE(s->grid() != nullptr);
        const Agreement a = compare(*s, 3, 100000);
        CHECK(a.hits > 0);
        CHECK(a.differ == 0);
    }
}

TEST_CASE("polygon grid: vertices off the plane (within the planarity tolerance)") {
    // SPD writes 6 significant digits: the vertices wander off the plane.
    std::vector<Vec3> v = gearFace({2, 1, 0}, 3);
    SplitMix64 rng(5);
    for (Vec3& p : v) p.z += rng.uniform(-2e-5, 2e-5);
    const auto gear = makeGridPolygon(v, FillRule::EvenOdd);
    REQUIRE(gear->grid() != nullptr);
    const Agreement a = compare(*gear, 11, 100000);
    CHECK(a.hits > 0);
    CHECK(a.differ == 0);
}

TEST_CASE("polygon grid: the zones about the origin, by hand and point by point") {
    // Inner radius: the nearest edge's distance from the origin less the
    // clearance; outer: the farthest vertex's plus it. A {n/m} star's edges
    // pass cos(pi m/n) from its centre; the gear's nearest are the chords
    // of its 0.8 roots, 0.8 cos(pi/144) away; the keyhole's the chords of
    // its 0.4 hole.
    const double clearance = 1e-3;
    struct Case {
        std::string name;
        std::vector<Vec2> outline;
        FillRule rule;
        double nearest;
        PolygonGrid::Cell origin;
    };
    const std::vector<Case> cases{
        {"gear", flatten(gearFace()), FillRule::EvenOdd, 0.8 * std::cos(kPi / 144),
         PolygonGrid::Cell::Inside},
        {"keyhole even-odd", flatten(keyhole()), FillRule::EvenOdd, 0.4 * std::cos(kPi / 24),
         PolygonGrid::Cell::Outside},
        {"keyhole nonzero", flatten(keyhole()), FillRule::NonZero, 0.4 * std::cos(kPi / 24),
         PolygonGrid::Cell::Outside},
        // Winding 2 at the centre: outside by even-odd, inside by nonzero.
        {"{15/2} even-odd", flatten(starPolygon(15, 2, {0, 0, 1})), FillRule::EvenOdd,
         std::cos(2 * kPi / 15), PolygonGrid::Cell::Outside},
        {"{15/2} nonzero", flatten(starPolygon(15, 2, {0, 0, 1})), FillRule::NonZero,
         std::cos(2 * kPi / 15), PolygonGrid::Cell::Inside},
        {"{15/7} even-odd", flatten(starPolygon(15, 7, {0, 0, 1})), FillRule::EvenOdd,
         std::cos(7 * kPi / 15), PolygonGrid::Cell::Inside},
    };
    SplitMix64 rng(20261206);
    for (const Case& c : cases) {
        CAPTURE(c.name);
        const PolygonGrid grid(c.outline, c.rule, clearance, 64 * int(c.outline.size()));
        CHECK(grid.originCell() == c.origin);
        CHECK(grid.innerRadius() == doctest::Approx(c.nearest - clearance).epsilon(1e-12));
        CHECK(grid.outerRadius() == doctest::Approx(1 + clearance).epsilon(1e-12));
        long innerPoints = 0, outerPoints = 0;
        for (int i = 0; i < 20000; ++i) {
            const Vec2 p{rng.uniform(-1.5, 1.5), rng.uniform(-1.5, 1.5)};
            const double r = std::hypot(p.x, p.y);
            if (r < grid.innerRadius()) {
                ++innerPoints;
                CHECK(insideOutline(c.outline, c.rule, p) == (c.origin == PolygonGrid::Cell::Inside));
                CHECK(edgeDistance(c.outline, p) >= clearance + grid.innerRadius() - r - 1e-12);
            } else if (r > grid.outerRadius()) {
                ++outerPoints;
                CHECK(!insideOutline(c.outline, c.rule, p));
                CHECK(edgeDistance(c.outline, p) >= clearance + r - grid.outerRadius() - 1e-12);
            }
        }
        // About 20,000 · pi r^2 / 9 points fall in the inner disc (75 for {15/7}).
        CHECK(innerPoints > 0.5 * 20000 * kPi * grid.innerRadius() * grid.innerRadius() / 9);
        CHECK(outerPoints > 1000);
    }
    // An origin on an edge: no inner zone.
    const std::vector<Vec2> onEdge{{0, -1}, {1, -1}, {2, -1}, {2, 0}, {2, 1}, {1, 1}, {0, 1}, {0, 0}};
    const PolygonGrid grid(onEdge, FillRule::EvenOdd, clearance, 512);
    CHECK(grid.innerRadius() == 0);
    CHECK(grid.outerRadius() == doctest::Approx(std::sqrt(5.0) + clearance).epsilon(1e-12));
}

TEST_CASE("polygon grid: zones around a hole and a winding of 2 answer as the watertight test") {
    // The inner zone answers from the origin's cell: a keyhole's centre is a
    // hole, a {15/2} star's has winding 2 (outside by even-odd, inside by
    // nonzero). Tilted and moved away from the origin, both fill rules.
    for (FillRule rule : {FillRule::EvenOdd, FillRule::NonZero}) {
        CAPTURE(int(rule));
        const auto hole = makeGridPolygon(keyhole({3, -2, 0.5}), rule);
        REQUIRE(hole->grid() != nullptr);
        CHECK(hole->grid()->originCell() == PolygonGrid::Cell::Outside);
        CHECK(hole->grid()->innerRadius() > 0.3);
        const Agreement a = compare(*hole, 13, 100000);
        CHECK(a.hits > 0);
        CHECK(a.differ == 0);

        const auto star2 = makeGridPolygon(starPolygon(15, 2, {0.2, 0.4, 1}), rule);
        REQUIRE(star2->grid() != nullptr);
        CHECK(star2->grid()->originCell() ==
              (rule == FillRule::EvenOdd ? PolygonGrid::Cell::Outside : PolygonGrid::Cell::Inside));
        const Agreement b = compare(*star2, 17, 100000);
        CHECK(b.hits > 0);
        CHECK(b.differ == 0);
    }
}
