#include "renderer/camera_matrices.h"

#include <cmath>

namespace raylab {

namespace {

constexpr double kPi = 3.14159265358979323846;

Matrix44 multiply(const Matrix44& a, const Matrix44& b) {
    Matrix44 r{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 4; ++k) r[i][j] += a[i][k] * b[k][j];
    return r;
}

}  // namespace

CameraMatrices cameraMatrices(const Camera& camera, int width, int height) {
    const CameraFrame& f = camera.frame();
    const Vec3 x = f.u, y = f.v, z = -f.w;  // right, up, forward
    CameraMatrices m;
    Matrix44& c = m.worldToCamera;
    const Vec3 axes[3] = {x, y, z};
    for (int col = 0; col < 3; ++col) {
        c[0][col] = axes[col].x;
        c[1][col] = axes[col].y;
        c[2][col] = axes[col].z;
        c[3][col] = -dot(f.eye, axes[col]);
    }
    c[3][3] = 1;

    // Camera space -> homogeneous NDC; generateRay's image plane at distance 1
    // spans [-halfWidth, halfWidth] x [-halfHeight, halfHeight].
    const double aspect = double(width) / double(height);
    Matrix44 p{};
    if (camera.projection() == Camera::Projection::Perspective) {
        const double halfHeight = std::tan(0.5 * camera.vfovDegrees() * kPi / 180.0);
        const double halfWidth = halfHeight * aspect;
        // X = x / (2 hw) + z / 2, Y = -y / (2 hh) + z / 2, W = z: after the
        // division, x/z = ±hw maps to 0 and 1, and +y (up) to the top (0).
        p[0][0] = 0.5 / halfWidth;
        p[1][1] = -0.5 / halfHeight;
        p[2][0] = 0.5;
        p[2][1] = 0.5;
        p[2][2] = kNdcFar / (kNdcFar - kNdcNear);
        p[2][3] = 1;
        p[3][2] = -kNdcFar * kNdcNear / (kNdcFar - kNdcNear);
    } else {
        const double halfWidth = 0.5 * camera.viewWidth();
        const double halfHeight = halfWidth / aspect;
        p[0][0] = 0.5 / halfWidth;
        p[1][1] = -0.5 / halfHeight;
        p[2][2] = 1.0 / (kNdcFar - kNdcNear);
        p[3][0] = 0.5;
        p[3][1] = 0.5;
        p[3][2] = -kNdcNear / (kNdcFar - kNdcNear);
        p[3][3] = 1;
    }
    m.worldToNDC = multiply(c, p);
    return m;
}

std::array<double, 3> transformPoint(const Matrix44& m, const std::array<double, 3>& p) {
    double r[4];
    for (int j = 0; j < 4; ++j) r[j] = p[0] * m[0][j] + p[1] * m[1][j] + p[2] * m[2][j] + m[3][j];
    return {r[0] / r[3], r[1] / r[3], r[2] / r[3]};
}

}  // namespace raylab
