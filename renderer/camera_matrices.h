#pragma once
// The camera as the OpenEXR standard attributes worldToCamera and worldToNDC
// describe it (ImfStandardAttributes.h: both spaces "the same as in Pixar's
// RenderMan"): camera space left-handed with +x right, +y up and +z along the
// view direction, origin at the eye; NDC x and y in [0, 1] across the whole
// image with (0, 0) its top-left corner, after the division by w. Matrices
// use Imath's row-vector convention (p' = p · M, translation in row 3), the
// layout Nuke and OpenImageIO read.

#include <array>

#include "renderer/camera.h"

namespace raylab {

using Matrix44 = std::array<std::array<double, 4>, 4>;  ///< [row][column]

/// NDC z of the perspective projection: 0 at kNdcNear, 1 at kNdcFar (the
/// background depth), as RenderMan's screen z between its clipping planes.
constexpr double kNdcNear = 1e-3;
constexpr double kNdcFar = 1e10;

struct CameraMatrices {
    Matrix44 worldToCamera{};
    Matrix44 worldToNDC{};
};

/// The matrices of `camera` rendering a width × height image.
CameraMatrices cameraMatrices(const Camera& camera, int width, int height);

/// p · M with the division by w (what Imath's multVecMatrix does).
std::array<double, 3> transformPoint(const Matrix44& m, const std::array<double, 3>& p);

}  // namespace raylab
