#pragma once
// How a model with no scene around it is shown (a bare `raylab render
// model.obj`): the camera framed on its silhouette, seen from the front-right
// and above in the model's own up axis, and a studio rig of key, fill and rim
// lights that reads its shape (docs/obj.md shows what each part does).

#include <optional>
#include <string>
#include <vector>

#include "geometry/vec.h"
#include "renderer/camera.h"
#include "shading/color.h"
#include "shading/light.h"

namespace raylab {

/// The axis a `--up` name means ("x", "y", "z", "-x", "-y", "-z"), or nothing.
std::optional<Vec3> upAxisNamed(const std::string& name);

/// The vertical field of view of a framed model, in degrees.
constexpr double kFirstLookFovDegrees = 40;
/// The share of the image's limiting dimension the model's silhouette fills.
constexpr double kFirstLookFill = 0.8;

/// A perspective camera (vertical field of view `vfovDegrees`, up = `up`, one
/// of the six axes) looking at `points` from the direction (1, 0.6, 1.5) of
/// the model's (right, up, front) axes, its look-at point and distance chosen
/// so that the projected points are centred and span `fill` of the limiting
/// dimension of an image `aspect` (width / height) wide.
Camera frameModel(const std::vector<Vec3>& points, const Vec3& up, double aspect,
                  double vfovDegrees = kFirstLookFovDegrees, double fill = kFirstLookFill);

/// Three directional lights placed around `camera`: a warm key from the
/// upper left, a cool dimmer fill from the right, a rim from behind above
/// that outlines the silhouette.
std::vector<Light> studioLights(const Camera& camera);

/// The ambient intensity and background that go with studioLights.
constexpr Color kFirstLookAmbient{0.06, 0.06, 0.06};
constexpr Color kFirstLookBackground{0.05, 0.055, 0.065};

}  // namespace raylab
