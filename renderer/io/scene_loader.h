#pragma once
// Scene readers. loadScene picks the reader by file extension:
// .json (native format), .obj (a mesh alone, auto-framed), .nff (Haines' NFF).
// All of them throw InputError with file and line on bad input.

#include <string>

#include "renderer/scene.h"

namespace raylab {

Scene loadScene(const std::string& path);

/// The native JSON format (docs/scene-format.md); `text` is the file content.
Scene loadJsonScene(const std::string& text, const std::string& path);

/// Eric Haines' Neutral File Format (the SPD scenes); `text` is the file content.
Scene loadNffScene(const std::string& text, const std::string& path);

/// A bare OBJ mesh: camera framed on its bounds, a key light and ambient.
Scene loadObjScene(const std::string& path);

}  // namespace raylab
