// A ray through an edge that two triangles share is given to the same
// triangle by Embree as by the naive loop (renderer/accel/embree_edge_hits.h):
// on a checkerboard whose neighbouring tiles differ in material, a different
// choice is a different colour. The rays are aimed at points exactly on the
// tiles' edges and diagonals, where Embree's float test and the double
// watertight test disagree most often.
#include <doctest/doctest.h>

#include "accel/accel_test_helpers.h"
#include "geometry/checkerboard.h"
#include "renderer/accel/accelerator.h"
#include "renderer/accel/embree_edge_hits.h"

using namespace raylab;
using namespace raylab::accel_test;

namespace {

struct EdgeAgreement {
    int rays = 0;
    int bothHit = 0;
    int sameTriangle = 0;
    int embreeMisses = 0;  ///< cracks: the float test rejected both neighbours
};

/// Rays from `eye` through points on every interior edge of an n x n
/// checkerboard in z = 0 (grid lines and square diagonals), at fractions along
/// the edge drawn from `rng`.
EdgeAgreement aimAtEdges(const Accelerator& embree, const Accelerator& naive, const Vec3& eye,
                         int n, Rng& rng) {
    EdgeAgreement a;
    const auto aim = [&](const Vec3& target) {
        const Ray ray{eye, target - eye};
        const auto e = embree.intersect(ray, 0, kInf);
        const auto v = naive.intersect(ray, 0, kInf);
        ++a.rays;
        REQUIRE(v);  // the double watertight test has no cracks
        if (!e) {
            ++a.embreeMisses;
            return;
        }
        ++a.bothHit;
        a.sameTriangle += e->object == v->object && e->prim == v->prim;
    };
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < 4; ++k) {
                const double f = rng.uniform(0, 1);
                if (i > 0) aim(Vec3{double(i), j + f, 0});          // edge between columns
                if (j > 0) aim(Vec3{i + f, double(j), 0});          // edge between rows
                aim(Vec3{i + f, j + f, 0});                         // the square's diagonal
            }
    return a;
}

}  // namespace

TEST_CASE("edge hits: Embree gives a shared-edge hit to the naive loop's triangle") {
    Scene scene;
    const int n = 12;
    scene.objects.push_back(meshObject(
        "floor", std::make_shared<TriangleMesh>(makeCheckerboard({0, 0, 0}, {n, 0, 0}, {0, n, 0}, n, n))));
    const auto naive = makeAccelerator("naive", scene);
    AccelOptions robustOptions;  // the default
    REQUIRE(robustOptions.robust);
    const auto robust = makeAccelerator("embree", scene, robustOptions);
    AccelOptions fastOptions;
    fastOptions.robust = false;
    const auto fast = makeAccelerator("embree", scene, fastOptions);

    Rng rng(7);
    for (const Vec3 eye : {Vec3{-3.1, -2.7, 4.3}, Vec3{5.9, 6.3, 0.7}, Vec3{17.3, -4.1, 2.2}}) {
        CAPTURE(eye.x);
        // Robust traversal is watertight on edges (NUMERICS.md §3.3): every
        // ray hits, and every hit is the naive loop's triangle.
        const EdgeAgreement r = aimAtEdges(*robust, *naive, eye, n, rng);
        CHECK(r.rays == 12 * 12 * 4 * 3 - 2 * 12 * 4);
        CHECK(r.embreeMisses == 0);
        CHECK(r.sameTriangle == r.bothHit);
        // The fast traversal (--no-robust) may miss a ray at an edge (a crack
        // of its float Möller-Trumbore test), but every ray it hits is agreed on.
        const EdgeAgreement f = aimAtEdges(*fast, *naive, eye, n, rng);
        MESSAGE("fast traversal: ", f.embreeMisses, " of ", f.rays, " edge rays missed");
        CHECK(f.sameTriangle == f.bothHit);
    }
}

TEST_CASE("edge hits: the band that sends a hit to resolution") {
    // Interior points are left alone; within 1e-3 of any edge they are resolved.
    CHECK_FALSE(nearTriangleEdge(0.3f, 0.3f));
    CHECK_FALSE(nearTriangleEdge(0.0011f, 0.5f));
    CHECK(nearTriangleEdge(0.0009f, 0.5f));
    CHECK(nearTriangleEdge(0.5f, 0.0f));
    CHECK(nearTriangleEdge(0.6f, 0.3995f));  // 1 - u - v = 0.0005
    CHECK_FALSE(nearTriangleEdge(0.6f, 0.398f));
}
