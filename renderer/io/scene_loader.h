#pragma once
// Scene readers. loadScene picks the reader by file extension:
// .json (native format), .obj (a mesh alone, auto-framed), .nff (Haines' NFF).
// All of them throw InputError with file and line on bad input.

#include <string>

#include "geometry/vec.h"
#include "renderer/io/obj_loader.h"
#include "renderer/scene.h"

namespace raylab {

/// What only a bare .obj needs to know: how to frame and shade its model.
struct SceneLoadOptions {
    Vec3 up{0, 1, 0};            ///< the model's up axis (--up)
    double aspect = 640.0 / 480; ///< width / height of the image the camera frames
    ObjNormals normals = ObjNormals::File;  ///< --normals
};

Scene loadScene(const std::string& path, const SceneLoadOptions& options = {});

/// The native JSON format (docs/scene-format.md); `text` is the file content.
Scene loadJsonScene(const std::string& text, const std::string& path);

/// Eric Haines' Neutral File Format (the SPD scenes); `text` is the file content.
Scene loadNffScene(const std::string& text, const std::string& path);

/// A bare OBJ mesh: the camera framed on its silhouette, a key, fill and rim
/// light and a low ambient (renderer/first_look.h).
Scene loadObjScene(const std::string& path, const SceneLoadOptions& options = {});

}  // namespace raylab
