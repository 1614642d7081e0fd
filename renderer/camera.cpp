#include "renderer/camera.h"

#include <cmath>
#include <stdexcept>

namespace raylab {

namespace {

constexpr double kPi = 3.14159265358979323846;

/// Builds the (u, v, w) frame with w = -viewDirection. Rejects a zero view
/// direction and an up vector that is zero or parallel to the view.
CameraFrame makeFrame(const Vec3& eye, const Vec3& viewDirection, const Vec3& up) {
    if (!isFinite(eye) || !isFinite(viewDirection) || !isFinite(up))
        throw std::invalid_argument("camera: eye, direction and up must be finite");
    const double viewLen = length(viewDirection);
    if (!(viewLen > 0)) throw std::invalid_argument("camera: eye and look-at point coincide");
    const Vec3 w = -viewDirection / viewLen;
    const double upLen = length(up);
    if (!(upLen > 0)) throw std::invalid_argument("camera: up vector has zero length");
    const Vec3 side = cross(up / upLen, w);
    // sin of the angle between up and the view direction; below ~1e-9 the frame is undefined.
    if (!(length(side) > 1e-9))
        throw std::invalid_argument("camera: up vector is parallel to the view direction");
    CameraFrame f;
    f.eye = eye;
    f.w = w;
    f.u = normalize(side);
    f.v = cross(f.w, f.u);
    return f;
}

}  // namespace

Camera Camera::perspective(const Vec3& eye, const Vec3& lookAt, const Vec3& up,
                           double vfovDegrees) {
    if (!(vfovDegrees > 0 && vfovDegrees < 180))
        throw std::invalid_argument("camera: field of view must be in (0, 180) degrees (got " +
                                    std::to_string(vfovDegrees) + ")");
    Camera c;
    c.m_frame = makeFrame(eye, lookAt - eye, up);
    c.m_lookAt = lookAt;
    c.m_up = up;
    c.m_projection = Projection::Perspective;
    c.m_vfovDegrees = vfovDegrees;
    c.m_tanHalfFov = std::tan(0.5 * vfovDegrees * kPi / 180.0);
    return c;
}

Camera Camera::overridden(const CameraOverrides& o) const {
    const Vec3 eye = o.eye.value_or(m_frame.eye);
    const Vec3 lookAt = o.lookAt.value_or(m_lookAt);
    const Vec3 up = o.up.value_or(m_up);
    if (m_projection == Projection::Perspective)
        return perspective(eye, lookAt, up, o.vfovDegrees.value_or(m_vfovDegrees));
    if (o.vfovDegrees)
        throw std::invalid_argument("camera: a field of view needs a perspective camera (the "
                                    "scene's is orthographic)");
    return orthographic(eye, lookAt - eye, up, m_viewWidth);
}

Camera Camera::orthographic(const Vec3& eye, const Vec3& direction, const Vec3& up,
                            double viewWidth) {
    if (!(viewWidth > 0 && std::isfinite(viewWidth)))
        throw std::invalid_argument("camera: view width must be > 0 (got " +
                                    std::to_string(viewWidth) + ")");
    Camera c;
    c.m_frame = makeFrame(eye, direction, up);
    c.m_lookAt = eye + direction;
    c.m_up = up;
    c.m_projection = Projection::Orthographic;
    c.m_viewWidth = viewWidth;
    return c;
}

Ray Camera::generateRay(double px, double py, int width, int height) const {
    const double aspect = double(width) / double(height);
    // Normalised screen coordinates in [-1, 1], +y up (row 0 is the top).
    const double sx = 2.0 * px / width - 1.0;
    const double sy = 1.0 - 2.0 * py / height;
    const CameraFrame& f = m_frame;
    if (m_projection == Projection::Perspective) {
        const double halfHeight = m_tanHalfFov;
        const double halfWidth = halfHeight * aspect;
        const Vec3 d = f.u * (sx * halfWidth) + f.v * (sy * halfHeight) - f.w;
        return Ray{f.eye, normalize(d)};
    }
    const double halfWidth = 0.5 * m_viewWidth;
    const double halfHeight = halfWidth / aspect;
    return Ray{f.eye + f.u * (sx * halfWidth) + f.v * (sy * halfHeight), -f.w};
}

RayDifferential Camera::differential(const Ray& ray, int width, int height,
                                     double spacing) const {
    return differential(ray, differentialSteps(width, height, spacing));
}

Camera::DifferentialSteps Camera::differentialSteps(int width, int height, double spacing) const {
    const CameraFrame& f = m_frame;
    const double aspect = double(width) / double(height);
    if (m_projection == Projection::Perspective) {
        // The unnormalised direction d' = u sx hw + v sy hh - w changes per
        // pixel by u (2 hw / W) and v (-2 hh / H).
        const double halfHeight = m_tanHalfFov, halfWidth = halfHeight * aspect;
        return {f.u * (2.0 * halfWidth / width * spacing), f.v * (-2.0 * halfHeight / height * spacing)};
    }
    const double halfWidth = 0.5 * m_viewWidth, halfHeight = halfWidth / aspect;
    return {f.u * (2.0 * halfWidth / width * spacing), f.v * (-2.0 * halfHeight / height * spacing)};
}

RayDifferential Camera::differential(const Ray& ray, const DifferentialSteps& steps) const {
    return differential(ray, normalize(ray.d), steps);
}

RayDifferential Camera::differential(const Ray&, const Vec3& d,
                                     const DifferentialSteps& steps) const {
    // Returned as built, member by member: a default RayDifferential would be
    // zeroed first (a `rep stos` per camera ray) and then overwritten.
    const Vec3 zero{0, 0, 0};
    if (m_projection == Projection::Perspective) {
        // d' has w-component -1, so |d'| = 1 / (-d·w); the unit direction
        // d = d'/|d'| changes by (dd' - d (d·dd')) / |d'|, both steps in
        // lockstep (step_pair.h).
        const double along = -dot(d, m_frame.w);
        const double len = 1.0 / along;  // |d'|
        const Vec3Pair dd(steps.dx, steps.dy);
        const Vec3Pair change = (dd - d * dot(dd, d)) / both(len);
        return RayDifferential{zero, zero, change.first(), change.second()};
    }
    return RayDifferential{steps.dx, steps.dy, zero, zero};
}

RayCone Camera::cone(int width, int height, double spacing) const {
    if (m_projection == Projection::Perspective)
        return RayCone{0.0, std::atan(2.0 * m_tanHalfFov * spacing / height)};
    return RayCone{m_viewWidth / width * spacing, 0.0};
}

}  // namespace raylab
