#pragma once
// Pinhole perspective and orthographic cameras built on the lecture's eye
// frame (u, v, w): w points from the look-at point back to the eye, u to the
// right, v up. Pixel (x, y) has its centre at (x + 0.5, y + 0.5); row 0 is the
// top of the image.

#include <optional>

#include "geometry/ray.h"
#include "geometry/vec.h"
#include "shading/ray_cone.h"
#include "shading/ray_differential.h"

namespace raylab {

/// Camera settings given on the command line (--eye, --look-at, --camera-up,
/// --fov), each replacing the scene's value; unset ones keep it.
struct CameraOverrides {
    std::optional<Vec3> eye, lookAt, up;
    std::optional<double> vfovDegrees;

    bool any() const { return eye || lookAt || up || vfovDegrees; }
};

struct CameraFrame {
    Vec3 eye;
    Vec3 u, v, w;  ///< orthonormal, right-handed: u × v = w
};

class Camera {
public:
    enum class Projection { Perspective, Orthographic };

    /// Perspective camera; vfovDegrees is the full vertical field of view,
    /// measured between the top and bottom image edges.
    static Camera perspective(const Vec3& eye, const Vec3& lookAt, const Vec3& up,
                              double vfovDegrees);
    /// Orthographic camera looking along `direction`; viewWidth is the width
    /// of the view plane in world units.
    static Camera orthographic(const Vec3& eye, const Vec3& direction, const Vec3& up,
                               double viewWidth);

    /// Ray through the continuous image position (px, py), in pixels from the
    /// top-left corner, for an image of width × height pixels.
    Ray generateRay(double px, double py, int width, int height) const;

    /// This camera with `o` applied: same projection, the given eye, look-at
    /// point, up vector and field of view in place of its own. Throws
    /// std::invalid_argument like the factories, and for a field of view on
    /// an orthographic camera.
    Camera overridden(const CameraOverrides& o) const;
    /// Igehy's camera differential of a ray this camera generated, for a step
    /// of `spacing` pixels right (x) and down (y): derived from the ray
    /// itself, so callers need not know which pixel it came through.
    RayDifferential differential(const Ray& ray, int width, int height, double spacing) const;
    /// What differential() needs of the image, once per image rather than
    /// per ray: the change per step of the unnormalised direction
    /// (perspective) or of the origin (orthographic).
    struct DifferentialSteps {
        Vec3 dx, dy;
    };
    DifferentialSteps differentialSteps(int width, int height, double spacing) const;
    /// differential(ray, width, height, spacing) with the steps computed
    /// before, bit for bit.
    RayDifferential differential(const Ray& ray, const DifferentialSteps& steps) const;
    /// The same with the ray's unit direction normalize(ray.d) known (the
    /// integrator has it), bit for bit.
    RayDifferential differential(const Ray& ray, const Vec3& unitDir,
                                 const DifferentialSteps& steps) const;
    /// The ray cone of a sample `spacing` pixels wide (RTG ch. 20: width 0
    /// and the pixel's spread angle, or an orthographic pixel's width).
    RayCone cone(int width, int height, double spacing) const;

    const CameraFrame& frame() const { return m_frame; }
    /// The point the camera looks at (orthographic: eye + direction) and the
    /// up vector it was built with.
    const Vec3& lookAt() const { return m_lookAt; }
    const Vec3& up() const { return m_up; }
    Projection projection() const { return m_projection; }
    double vfovDegrees() const { return m_vfovDegrees; }
    double viewWidth() const { return m_viewWidth; }

private:
    CameraFrame m_frame;
    Vec3 m_lookAt{0, 0, -1};
    Vec3 m_up{0, 1, 0};
    Projection m_projection = Projection::Perspective;
    double m_vfovDegrees = 45;
    double m_tanHalfFov = 0.41421356237309503;  ///< tan(vfov / 2), once rather than per ray
    double m_viewWidth = 2;
};

}  // namespace raylab
