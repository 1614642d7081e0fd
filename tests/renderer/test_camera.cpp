// Camera rays at pixel centres and corners, checked against hand-derived values.
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>

#include "renderer/camera.h"
#include "support/vec_checks.h"

using namespace raylab;
using raylab::test::checkVec;


TEST_CASE("perspective camera: eye frame follows the lecture's u, v, w") {
    // Eye at the origin looking down -z with +y up: w = +z, u = +x, v = +y.
    const Camera c = Camera::perspective({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 90);
    checkVec(c.frame().u, {1, 0, 0});
    checkVec(c.frame().v, {0, 1, 0});
    checkVec(c.frame().w, {0, 0, 1});
}

TEST_CASE("perspective camera: rays through pixel centres and corners") {
    // 90° vertical fov on a 2x2 image: the view plane at distance 1 spans [-1, 1]².
    const Camera c = Camera::perspective({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 90);
    // Centre of pixel (0, 0), the top-left one: screen (-0.5, +0.5).
    Ray r = c.generateRay(0.5, 0.5, 2, 2);
    checkVec(r.o, {0, 0, 0});
    checkVec(r.d, normalize(Vec3{-0.5, 0.5, -1}));
    // Centre of pixel (1, 1), bottom-right: (+0.5, -0.5).
    checkVec(c.generateRay(1.5, 1.5, 2, 2).d, normalize(Vec3{0.5, -0.5, -1}));
    // The image corner (0, 0) is the top-left corner of the view plane.
    checkVec(c.generateRay(0, 0, 2, 2).d, normalize(Vec3{-1, 1, -1}));
    // The image centre looks at the look-at point.
    checkVec(c.generateRay(1, 1, 2, 2).d, {0, 0, -1});
    // Aspect 2:1 widens the horizontal extent: corner (0, 0) of a 4x2 image is (-2, 1, -1).
    checkVec(c.generateRay(0, 0, 4, 2).d, normalize(Vec3{-2, 1, -1}));
}

TEST_CASE("orthographic camera: parallel rays from the view plane") {
    // View width 4 on a 4x2 image: the plane spans x in [-2, 2], y in [-1, 1].
    const Camera c = Camera::orthographic({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 4);
    Ray r = c.generateRay(0.5, 0.5, 4, 2);  // pixel (0,0) centre: x = -1.5, y = +0.5
    checkVec(r.o, {-1.5, 0.5, 0});
    checkVec(r.d, {0, 0, -1});
    r = c.generateRay(3.5, 1.5, 4, 2);  // pixel (3,1) centre: x = +1.5, y = -0.5
    checkVec(r.o, {1.5, -0.5, 0});
}

TEST_CASE("camera: degenerate frames are rejected") {
    CHECK_THROWS_AS(Camera::perspective({1, 2, 3}, {1, 2, 3}, {0, 1, 0}, 45), std::invalid_argument);
    CHECK_THROWS_AS(Camera::perspective({0, 0, 0}, {0, 0, -1}, {0, 0, 0}, 45), std::invalid_argument);
    CHECK_THROWS_AS(Camera::perspective({0, 0, 0}, {0, 0, -1}, {0, 0, 2}, 45), std::invalid_argument);
    CHECK_THROWS_AS(Camera::perspective({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 180), std::invalid_argument);
    CHECK_THROWS_AS(Camera::orthographic({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 0), std::invalid_argument);
}
