#include "renderer/first_look.h"

#include <algorithm>
#include <cmath>

#include "geometry/bounds.h"

namespace raylab {

namespace {

constexpr double kPi = 3.14159265358979323846;

/// A model's right, up and front axes for each up axis, right-handed
/// (right × up = front), so +y up gives the usual x right, z front and +z up
/// (CAD, terrains) looks from -y as a front view does.
struct ModelAxes {
    Vec3 right, up, front;
};

ModelAxes axesFor(const Vec3& up) {
    const int axis = dominantAxis(up);
    const double s = up[axis] < 0 ? -1.0 : 1.0;
    if (axis == 1) return {{1, 0, 0}, {0, s, 0}, {0, 0, s}};
    if (axis == 2) return {{1, 0, 0}, {0, 0, s}, {0, -s, 0}};
    return {{0, -s, 0}, {s, 0, 0}, {0, 0, 1}};
}

/// Projected extent of points in units of the image half-size.
struct Extent {
    double xmin = 0, xmax = 0, ymin = 0, ymax = 0;
};

}  // namespace

std::optional<Vec3> upAxisNamed(const std::string& name) {
    const double s = !name.empty() && name[0] == '-' ? -1.0 : 1.0;
    const std::string axis = s < 0 ? name.substr(1) : name;
    if (axis == "x") return Vec3(s, 0, 0);
    if (axis == "y") return Vec3(0, s, 0);
    if (axis == "z") return Vec3(0, 0, s);
    return std::nullopt;
}

Camera frameModel(const std::vector<Vec3>& points, const Vec3& up, double aspect,
                  double vfovDegrees, double fill) {
    const ModelAxes a = axesFor(up);
    const Vec3 w = normalize(a.right * 1.0 + a.up * 0.6 + a.front * 1.5);  // towards the eye
    const Vec3 u = normalize(cross(a.up, w)), v = cross(w, u);
    Bounds3 box;
    for (const Vec3& p : points) box.expand(p);
    const Vec3 centre = points.empty() ? Vec3{} : box.centre();

    // Points in the camera frame around the box centre.
    std::vector<Vec3> q;
    q.reserve(points.size());
    for (const Vec3& p : points) q.push_back({dot(p - centre, u), dot(p - centre, v), dot(p - centre, w)});
    const double ty = std::tan(0.5 * vfovDegrees * kPi / 180.0), tx = ty * aspect;

    // The distance at which every point projects within `fill` of the image
    // edge, for a look-at point offset by (au, av): x / (d - z) <= fill·tx.
    const auto distance = [&](double au, double av) {
        double d = 0, nearest = 0;
        for (const Vec3& p : q) {
            d = std::max({d, p.z + std::abs(p.x - au) / (fill * tx),
                          p.z + std::abs(p.y - av) / (fill * ty)});
            nearest = std::max(nearest, p.z);
        }
        // A model without extent (one point) still gets a camera in front of it.
        return d > nearest ? d : nearest + 1;
    };
    const auto extent = [&](double au, double av, double d) {
        Extent e{1e300, -1e300, 1e300, -1e300};
        for (const Vec3& p : q) {
            const double x = (p.x - au) / ((d - p.z) * tx), y = (p.y - av) / ((d - p.z) * ty);
            e.xmin = std::min(e.xmin, x);
            e.xmax = std::max(e.xmax, x);
            e.ymin = std::min(e.ymin, y);
            e.ymax = std::max(e.ymax, y);
        }
        return e;
    };
    // Perspective makes the silhouette lopsided about the box centre: shift
    // the look-at point until the projection is centred (a few steps converge).
    double au = 0, av = 0;
    for (int step = 0; step < 6 && !q.empty(); ++step) {
        const double d = distance(au, av);
        const Extent e = extent(au, av, d);
        au += 0.5 * (e.xmin + e.xmax) * d * tx;
        av += 0.5 * (e.ymin + e.ymax) * d * ty;
    }
    const double d = distance(au, av);
    const Vec3 lookAt = centre + u * au + v * av;
    return Camera::perspective(lookAt + w * d, lookAt, a.up, vfovDegrees);
}

std::vector<Light> studioLights(const Camera& camera) {
    const CameraFrame& f = camera.frame();
    const auto from = [&](double right, double up, double towardsViewer, const Color& c) {
        Light l;
        l.type = Light::Type::Directional;
        l.direction = -normalize(f.u * right + f.v * up + f.w * towardsViewer);
        l.intensity = c;
        return l;
    };
    return {from(-0.8, 0.8, 0.35, Color(1.0, 0.96, 0.9) * 0.85),  // key: upper left, warm
            from(0.8, 0.05, 0.6, Color(0.8, 0.87, 1.0) * 0.18),   // fill: right, cool, dim
            from(0.3, 0.6, -0.8, Color(0.45, 0.45, 0.45))};       // rim: behind, above
}

}  // namespace raylab
