#pragma once
// The "camera_path" of a JSON scene (docs/distributed.md), read by the JSON
// scene loader in the same parse as the rest of the scene.

#include <string>

#include "renderer/camera_path.h"
#include "renderer/io/json.h"

namespace raylab {

/// Reads a "camera_path" value. Keyframes without "fov" get `defaultFov`.
/// Throws InputError(file, line, "camera_path.keyframes[1].frame: ...") on
/// unknown keys, wrong types, frames not strictly increasing, and keyframes
/// whose camera is degenerate.
CameraPath parseCameraPath(const JsonValue& value, const std::string& file, double defaultFov);

}  // namespace raylab
