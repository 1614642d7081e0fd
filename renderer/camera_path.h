#pragma once
// A keyframed camera for image sequences: the scene file's "camera_path"
// (docs/distributed.md), interpolated per frame. The JSON reader fills it in
// (io/json_camera_path.h); --frames renders along it.
//
//   "camera_path": {
//       "interpolation": "catmull_rom",          // or "linear" (default catmull_rom)
//       "keyframes": [
//           {"frame": 1,  "eye": [0, 2.4, 8], "look_at": [0, 0.9, 0]},
//           {"frame": 24, "eye": [6, 2.4, 5], "look_at": [0, 0.9, 0], "up": [0, 1, 0], "fov": 35}
//       ]
//   }

#include <vector>

#include "geometry/vec.h"
#include "renderer/camera.h"

namespace raylab {

/// Largest frame number of a keyframe and of --frames.
constexpr int kMaxFrame = 9999999;

/// One keyframe of a perspective camera.
struct CameraKeyframe {
    int frame = 0;
    Vec3 eye;
    Vec3 lookAt;
    Vec3 up{0, 1, 0};
    double fov = 45;  ///< full vertical field of view in degrees
};

class CameraPath {
public:
    enum class Interpolation { Linear, CatmullRom };

    /// `keys` sorted by strictly increasing frame, at least one. Throws
    /// std::invalid_argument otherwise.
    CameraPath(std::vector<CameraKeyframe> keys, Interpolation interpolation);

    /// The keyframes, by increasing frame.
    const std::vector<CameraKeyframe>& keyframes() const { return m_keys; }
    /// How eye and look-at move between keyframes.
    Interpolation interpolation() const { return m_interpolation; }

    /// The camera parameters at `frame`; before the first keyframe and after
    /// the last the camera holds still. Eye and look-at follow the path's
    /// interpolation: linear, or Catmull-Rom as a cubic Hermite curve whose
    /// tangent at a key is the central difference of its neighbours per frame
    /// (one-sided at the ends), so unevenly spaced keys move smoothly. Up and
    /// fov are always linear (a cubic could overshoot the valid fov range).
    CameraKeyframe at(double frame) const;

    /// The perspective camera of `frame`. Throws std::invalid_argument when
    /// it is degenerate there (eye on the look-at point, up along the view).
    Camera cameraAt(int frame) const;

private:
    std::vector<CameraKeyframe> m_keys;
    Interpolation m_interpolation;
};

}  // namespace raylab
