// The bare-OBJ first look: the camera frames a model's projected silhouette to
// 80% of the image's limiting dimension, centred, for any up axis and aspect;
// the studio lights sit where their names say; camera overrides replace one
// setting and keep the rest.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "renderer/camera.h"
#include "geometry/vec2.h"
#include "renderer/first_look.h"
#include "support/vec_checks.h"

using namespace raylab;
using raylab::test::checkVec;

namespace {

constexpr double kPi = 3.14159265358979323846;

/// Where `p` lands in the image, in units of the half-width and half-height
/// (the edges are ±1), computed from the camera's frame alone.
Vec2 project(const Camera& c, const Vec3& p, double aspect) {
    const CameraFrame& f = c.frame();
    const Vec3 q = p - f.eye;
    const double depth = -dot(q, f.w);
    const double ty = std::tan(0.5 * c.vfovDegrees() * kPi / 180);
    return {dot(q, f.u) / (depth * ty * aspect), dot(q, f.v) / (depth * ty)};
}

struct Extent {
    double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
};

Extent extentOf(const Camera& c, const std::vector<Vec3>& points, double aspect) {
    Extent e;
    for (const Vec3& p : points) {
        const Vec2 s = project(c, p, aspect);
        e.xmin = std::min(e.xmin, s.x);
        e.xmax = std::max(e.xmax, s.x);
        e.ymin = std::min(e.ymin, s.y);
        e.ymax = std::max(e.ymax, s.y);
    }
    return e;
}

std::vector<Vec3> boxCorners(const Vec3& lo, const Vec3& hi) {
    std::vector<Vec3> c;
    for (int i = 0; i < 8; ++i)
        c.push_back({i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z});
    return c;
}

}  // namespace

TEST_CASE("first look: the silhouette spans 80% of the limiting dimension, centred") {
    struct Case {
        const char* what;
        std::vector<Vec3> points;
        double aspect;
        bool tall;  ///< the height limits the framing
    };
    const Case cases[] = {
        // A tall thin figure in a 4:3 image: the height limits.
        {"tall figure", boxCorners({-0.1, 0, -0.1}, {0.1, 3, 0.1}), 4.0 / 3, true},
        // A wide flat slab in a tall 1:2 image: the width limits.
        {"slab", boxCorners({-2, 0, -1}, {2, 0.2, 1}), 0.5, false},
        // An off-centre point cloud (a tetrahedron far from the origin).
        {"tetrahedron", {{100, 5, 7}, {101, 5, 7}, {100, 6, 7}, {100, 5, 8}}, 4.0 / 3, true},
    };
    for (const Case& c : cases) {
        CAPTURE(std::string(c.what));
        const Camera cam = frameModel(c.points, {0, 1, 0}, c.aspect);
        const Extent e = extentOf(cam, c.points, c.aspect);
        const double lo = c.tall ? e.ymin : e.xmin, hi = c.tall ? e.ymax : e.xmax;
        // 80% of the limiting dimension, split evenly about the centre (within 0.5%).
        CHECK(hi - lo == doctest::Approx(1.6).epsilon(0.005));
        CHECK(std::abs(hi + lo) < 0.01);
        // The other dimension fits inside the frame, centred as well.
        const double olo = c.tall ? e.xmin : e.ymin, ohi = c.tall ? e.xmax : e.ymax;
        CHECK(ohi - olo < 1.6 + 1e-9);
        CHECK(std::abs(ohi + olo) < 0.01);
        CHECK(cam.vfovDegrees() == kFirstLookFovDegrees);
    }
}

TEST_CASE("first look: --up turns the view with the model's up axis") {
    const std::vector<Vec3> points = boxCorners({-1, -1, -1}, {1, 1, 1});
    struct Case {
        const char* name;
        Vec3 up, right, front;
    };
    // (right, up, front) are right-handed; z up looks at the front from -y (a CAD front view).
    const Case cases[] = {{"y", {0, 1, 0}, {1, 0, 0}, {0, 0, 1}},
                          {"-y", {0, -1, 0}, {1, 0, 0}, {0, 0, -1}},
                          {"z", {0, 0, 1}, {1, 0, 0}, {0, -1, 0}},
                          {"-z", {0, 0, -1}, {1, 0, 0}, {0, 1, 0}},
                          {"x", {1, 0, 0}, {0, -1, 0}, {0, 0, 1}},
                          {"-x", {-1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    for (const Case& c : cases) {
        CAPTURE(std::string(c.name));
        REQUIRE(upAxisNamed(c.name).has_value());
        CHECK(*upAxisNamed(c.name) == c.up);
        checkVec(cross(c.right, c.up), c.front);
        const Camera cam = frameModel(points, c.up, 4.0 / 3);
        CHECK(cam.up() == c.up);
        // The eye sits at (1, 0.6, 1.5) in the model's own axes.
        checkVec(cam.frame().w, normalize(c.right * 1 + c.up * 0.6 + c.front * 1.5));
        // Up in the model is up in the image.
        CHECK(dot(cam.frame().v, c.up) > 0.8);
    }
    CHECK(!upAxisNamed("w"));
    CHECK(!upAxisNamed(""));
    CHECK(!upAxisNamed("--y"));
}

TEST_CASE("first look: key from the upper left, fill from the right, rim from behind") {
    const Camera cam = Camera::perspective({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 40);
    const std::vector<Light> lights = studioLights(cam);
    REQUIRE(lights.size() == 3);
    // Direction the light travels: towards the light is its negation.
    const Vec3 key = -lights[0].direction, fill = -lights[1].direction, rim = -lights[2].direction;
    CHECK(key.x < 0);   // left
    CHECK(key.y > 0);   // above
    CHECK(key.z > 0);   // on the camera's side
    CHECK(fill.x > 0);  // right
    CHECK(rim.z < 0);   // behind the model
    CHECK(rim.y > 0);
    // The key is the brightest, the fill the dimmest.
    CHECK(lights[0].intensity.maxComponent() > lights[2].intensity.maxComponent());
    CHECK(lights[2].intensity.maxComponent() > lights[1].intensity.maxComponent());
}

TEST_CASE("camera overrides replace one setting and keep the others") {
    const Camera base = Camera::perspective({0, 0, 5}, {0, 1, 0}, {0, 1, 0}, 45);
    CHECK(base.lookAt() == Vec3(0, 1, 0));
    CHECK(base.up() == Vec3(0, 1, 0));
    CameraOverrides o;
    CHECK(!o.any());
    // A new eye keeps looking at the same point.
    o.eye = Vec3(5, 1, 0);
    Camera c = base.overridden(o);
    CHECK(c.frame().eye == Vec3(5, 1, 0));
    checkVec(c.frame().w, {1, 0, 0});
    CHECK(c.vfovDegrees() == 45);
    // A field of view alone keeps the eye and the look-at point.
    CameraOverrides fov;
    fov.vfovDegrees = 20;
    c = base.overridden(fov);
    CHECK(c.frame().eye == Vec3(0, 0, 5));
    CHECK(c.lookAt() == Vec3(0, 1, 0));
    CHECK(c.vfovDegrees() == 20);
    // Up: the image's up follows it. With w = (0, -1, 5)/√26, u = up × w ∝ (0, -5, -1)
    // and v = w × u = (1, 0, 0), the new up exactly.
    CameraOverrides up;
    up.up = Vec3(1, 0, 0);
    checkVec(base.overridden(up).frame().v, {1, 0, 0});
    // An orthographic camera keeps its width and refuses a field of view.
    const Camera ortho = Camera::orthographic({0, 10, 0}, {0, -1, 0}, {0, 0, -1}, 12);
    CameraOverrides look;
    look.lookAt = Vec3(3, 0, 0);
    c = ortho.overridden(look);
    CHECK(c.projection() == Camera::Projection::Orthographic);
    CHECK(c.viewWidth() == 12);
    checkVec(c.frame().w, normalize(Vec3(-3, 10, 0)));
    CHECK_THROWS_AS(ortho.overridden(fov), std::invalid_argument);
    // The factories' checks hold: the eye at the look-at point is refused.
    CameraOverrides same;
    same.eye = Vec3(0, 1, 0);
    CHECK_THROWS_AS(base.overridden(same), std::invalid_argument);
}
