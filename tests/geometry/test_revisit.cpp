// Shape::revisit: which rays leaving a shape could meet it again. The
// integrator lets the accelerators skip a shape's test for a ray that cannot
// (renderer Departure), so the claim must hold for every ray the robust
// offset spawns (geometry/spawn.h) and the exact double test sees: checked
// here on hits all over each kind of shape, near the origin and 1e5 from it,
// at unit size and at 1e-3, hit from outside and from inside, for directions
// anywhere and within 1e-9 of the tangent plane (cones of both slopes, pointed
// at either end). The other half is checked too: a ray leaving a closed
// convex shape inwards does meet it again, so Revisit::Inward is no more
// generous than it must be.

#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "geometry/primitives.h"
#include "geometry/random.h"
#include "geometry/spawn.h"
#include "geometry/triangle_mesh.h"

using namespace raylab;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct Kind {
    std::string name;
    std::unique_ptr<Shape> shape;
    Revisit expected;
    bool closed;  ///< a closed surface: every inward ray meets it again
};

/// One shape of every analytic kind around c, of size about `size`.
std::vector<Kind> kinds(const Vec3& c, double size) {
    std::vector<Kind> v;
    v.push_back({"sphere", makeSphere(c, size), Revisit::Inward, true});
    ConeParams cylinder;
    cylinder.base = c + Vec3{0.1, -1, 0.2} * size;
    cylinder.apex = c + Vec3{-0.2, 1, 0.1} * size;
    cylinder.baseRadius = cylinder.apexRadius = 0.7 * size;
    cylinder.capped = true;
    v.push_back({"capped cylinder", makeCone(cylinder), Revisit::Inward, true});
    ConeParams open = cylinder;
    open.capped = false;
    v.push_back({"open cylinder", makeCone(open), Revisit::Inward, false});
    ConeParams cone = cylinder;
    cone.apexRadius = 0;
    v.push_back({"capped cone", makeCone(cone), Revisit::Inward, true});
    ConeParams frustum = cylinder;
    frustum.apexRadius = 0.3 * size;
    frustum.capped = false;
    v.push_back({"open truncated cone", makeCone(frustum), Revisit::Inward, false});
    ConeParams widening = cylinder;  // the wide end at the apex
    widening.baseRadius = 0.2 * size;
    widening.apexRadius = 0.9 * size;
    v.push_back({"capped cone widening to its apex", makeCone(widening), Revisit::Inward, true});
    ConeParams pointedBase = cylinder;  // the point at the base
    pointedBase.baseRadius = 0;
    v.push_back({"capped cone pointed at its base", makeCone(pointedBase), Revisit::Inward, true});
    v.push_back({"disk", makeDisk(c, normalize(Vec3{-0.1, 0.3, 1}), size), Revisit::None, false});
    v.push_back({"plane", makePlane(c, normalize(Vec3{0.2, 1, 0.1}), 10 * size), Revisit::None,
                 false});
    PolygonParams quad;
    quad.vertices = {c + Vec3{-1, -1, 0} * size, c + Vec3{1, -1, 0.2} * size,
                     c + Vec3{1, 1, 0.4} * size, c + Vec3{-1, 1, 0.2} * size};
    v.push_back({"quad", makePolygon(quad), Revisit::None, false});
    PolygonParams notch;  // concave, in the plane x + y + z = const
    for (const auto& [a, b] : std::vector<std::pair<double, double>>{
             {-1, -1}, {1, -1}, {1, 1}, {0, 0}, {-1, 1}})
        notch.vertices.push_back(c + Vec3{a, b, -a - b} * size);
    v.push_back({"concave polygon", makePolygon(notch), Revisit::None, false});
    QuadricParams saddle;  // z = x² - y² (hyperbolic paraboloid), clipped
    saddle.A = 1;
    saddle.B = -1;
    saddle.I = -1;
    saddle.clip = Bounds3{{-1, -1, -1}, {1, 1, 1}};
    saddle.hasClip = true;
    v.push_back({"saddle quadric", makeQuadric(saddle), Revisit::Any, false});
    for (Kind& k : v) k.shape->setSidedness(Sidedness::Both);
    return v;
}

struct Count {
    long away = 0, awayHits = 0;      ///< rays that cannot meet the shape again, and those that did
    long inward = 0, inwardHits = 0;  ///< Inward kinds: rays leaving inwards, and those that met it
};

Count leaveFromHits(const Shape& shape, const Vec3& c, double size, uint64_t seed) {
    SplitMix64 rng(seed);
    const IntersectOptions opt;  // double precision
    const Vec3 eye = c + Vec3{0.3, 2.1, 4.7} * size;
    SpawnSettings spawn;
    spawn.reference = eye;
    Count n;
    for (int i = 0; i < 1500; ++i) {
        // From outside (the eye, anywhere around) and from inside (a ray that
        // entered a closed shape meets its far side from within).
        const Vec3 from = i % 3 == 0   ? eye
                          : i % 3 == 1 ? c + rng.direction() * (5 * size)
                                       : c + rng.point(-0.2, 0.2) * size;
        const Ray ray{from, c + rng.point(-1.2, 1.2) * size - from};
        const auto h = shape.intersect(0, ray, 0, kInf, opt);
        if (!h) continue;
        const SurfaceGeometry g = shape.surfaceAt(0, ray, *h, opt, SurfaceDetail::Normals);
        for (int j = 0; j < 6; ++j) {
            Vec3 d = rng.direction();
            if (j >= 4) {
                // Within 1e-9 of the tangent plane, on either side.
                d = normalize(d - g.ng * dot(d, g.ng) + g.ng * rng.uniform(-1e-9, 1e-9));
            }
            const double side = dot(d, g.ng);
            const SpawnedRay s = spawnRay(g.p, g.ng, g.span, d, spawn);
            const bool met = shape.intersect(0, s.ray, s.tMin, kInf, opt).has_value();
            CHECK(met == shape.occluded(0, s.ray, s.tMin, kInf, opt));
            const Revisit r = shape.revisit();
            if (r == Revisit::None || (r == Revisit::Inward && side > 0)) {
                ++n.away;
                n.awayHits += met;
            } else if (r == Revisit::Inward && side < -0.01) {
                ++n.inward;
                n.inwardHits += met;
            }
        }
    }
    return n;
}

}  // namespace

TEST_CASE("revisit: a ray the robust offset spawns never meets a shape that says it cannot") {
    for (const Vec3 c : {Vec3{0, 0, 0}, Vec3{1e5, -5e4, 2.5e4}}) {
        for (double size : {1.0, 1e-3}) {
            uint64_t seed = 1;
            for (const Kind& k : kinds(c, size)) {
                CAPTURE(k.name);
                CAPTURE(c.x);
                CAPTURE(size);
                CHECK(k.shape->revisit() == k.expected);
                const Count n = leaveFromHits(*k.shape, c, size, seed++);
                if (k.expected == Revisit::Any) continue;
                CHECK(n.away > 1000);
                CHECK(n.awayHits == 0);
                if (k.expected == Revisit::Inward && k.closed) {
                    // Leaving a closed convex surface inwards, a ray has to cross it again.
                    CHECK(n.inward > 500);
                    CHECK(n.inwardHits == n.inward);
                }
            }
        }
    }
}

TEST_CASE("revisit: meshes and shapes of several primitives are never skipped") {
    // The accelerators skip whole objects, and Embree tests a mesh's
    // triangles natively: a mesh answers Any even where it is flat.
    TriangleMesh flat;
    flat.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}};
    flat.triangles = {{0, 1, 2}};
    CHECK(flat.revisit() == Revisit::Any);
}
