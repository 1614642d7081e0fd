// The affine Transform against hand-computed values: rotations, scale,
// translation, their composition, the inverse, and normals under non-uniform
// and mirroring maps.
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>

#include "geometry/transform.h"
#include "support/vec_checks.h"

using namespace raylab;
using raylab::test::checkVec;


TEST_CASE("transform: rotations follow the right-hand rule") {
    // 90° about +z (axis length 2 is normalised): x -> y, y -> -x.
    const Transform rz = Transform::rotate({0, 0, 2}, 90);
    checkVec(rz.point({1, 0, 0}), {0, 1, 0});
    checkVec(rz.point({0, 1, 0}), {-1, 0, 0});
    // 120° about (1, 1, 1) permutes the axes: x -> y -> z -> x.
    const Transform r3 = Transform::rotate({1, 1, 1}, 120);
    checkVec(r3.point({1, 0, 0}), {0, 1, 0});
    checkVec(r3.point({0, 1, 0}), {0, 0, 1});
    checkVec(r3.point({0, 0, 1}), {1, 0, 0});
    CHECK(r3.determinant() == doctest::Approx(1));
}

TEST_CASE("transform: composition applies the first transform first") {
    const Transform rz = Transform::rotate({0, 0, 1}, 90);
    const Transform rx = Transform::rotate({1, 0, 0}, 90);
    // (1,0,0) -rz-> (0,1,0) -rx-> (0,0,1); the other order: (1,0,0) -rx-> (1,0,0) -rz-> (0,1,0).
    checkVec(rz.then(rx).point({1, 0, 0}), {0, 0, 1});
    checkVec(rx.then(rz).point({1, 0, 0}), {0, 1, 0});
    // Scale, then translate: 2·(1,1,1) + (1,2,3) = (3,4,5); the other order 2·((1,1,1) + (1,2,3)).
    const Transform st = Transform::scale({2, 2, 2}).then(Transform::translate({1, 2, 3}));
    checkVec(st.point({1, 1, 1}), {3, 4, 5});
    checkVec(Transform::translate({1, 2, 3}).then(Transform::scale({2, 2, 2})).point({1, 1, 1}),
             {4, 6, 8});
    CHECK(st.determinant() == 8);
    CHECK(!st.isIdentity());
    CHECK(Transform().isIdentity());
    // Vectors ignore the translation.
    checkVec(st.vector({1, 1, 1}), {2, 2, 2});
}

TEST_CASE("transform: the inverse undoes the map") {
    // p -> diag(2, 4, 5) p + (1, 2, 3) has the inverse q -> diag(1/2, 1/4, 1/5) (q - (1, 2, 3)).
    const Transform a = Transform::scale({2, 4, 5}).then(Transform::translate({1, 2, 3}));
    const Transform inv = a.inverse();
    checkVec(inv.point({3, 6, 8}), {1, 1, 1});
    checkVec(inv.translation(), {-0.5, -0.5, -0.6});
    CHECK(inv.linear()[0][0] == 0.5);
    CHECK(inv.linear()[1][1] == 0.25);
    CHECK(inv.linear()[2][2] == doctest::Approx(0.2));
    // A general affine map: rotation, shear-free non-uniform scale, translation;
    // the inverse composed with it is the identity on any point.
    const Transform b = Transform::scale({1, 3, -2})
                            .then(Transform::rotate({1, 2, 3}, 37))
                            .then(Transform::translate({-4, 0.5, 7}));
    const Transform round = b.then(b.inverse());
    for (const Vec3& p : {Vec3(0, 0, 0), Vec3(1, -2, 3), Vec3(100, 5, -7)})
        checkVec(round.point(p), p, 1e-12);
    CHECK(b.inverse().determinant() == doctest::Approx(1 / b.determinant()));
    // Rotation about z by 90° is inverted by -90°: the inverse's matrix is the transpose.
    const Transform r = Transform::rotate({0, 0, 1}, 90).inverse();
    checkVec(r.point({0, 1, 0}), {1, 0, 0});
    CHECK_THROWS_AS(Transform::scale({1, 0, 1}).inverse(), std::invalid_argument);
}

TEST_CASE("transform: normals use the inverse transpose and keep the outside") {
    // Scaling x by 2 turns the plane x + y = 0 (normal (1,1,0)/√2) into
    // x/2 + y = 0, whose normal is ∝ (0.5, 1, 0), i.e. (1, 2, 0)/√5.
    const Transform sx = Transform::scale({2, 1, 1});
    checkVec(sx.normal(normalize(Vec3(1, 1, 0))), normalize(Vec3(1, 2, 0)));
    // Under a rotation, normals rotate like vectors.
    checkVec(Transform::rotate({0, 0, 1}, 90).normal({1, 0, 0}), {0, 1, 0});
    // A translation leaves normals alone.
    checkVec(Transform::translate({5, 6, 7}).normal({0, 0, 1}), {0, 0, 1});
    // A mirror reverses windings; the normal stays on the side the swapped
    // winding calls outside: x -> -x maps the outward +x normal of a face to -x.
    const Transform mirror = Transform::scale({-1, 1, 1});
    CHECK(mirror.determinant() == -1);
    CHECK(mirror.flipsHandedness());
    checkVec(mirror.normal({1, 0, 0}), {-1, 0, 0});
    checkVec(mirror.normal({0, 0, 1}), {0, 0, 1});
    // Normals come out unit length whatever the scale.
    CHECK(length(Transform::scale({10, 10, 10}).normal({0, 3, 4})) == doctest::Approx(1));
}
