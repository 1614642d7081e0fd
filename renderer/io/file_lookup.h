#pragma once
// Finding the files an OBJ or MTL names (material libraries, textures) the
// way their authors meant them: files written on Windows or macOS name
// "Wood.PNG" for "wood.png", which a case-sensitive file system does not find.

#include <optional>
#include <string>

namespace raylab {

struct FoundFile {
    std::string path;          ///< the file as it exists
    bool caseDiffers = false;  ///< found only by ignoring letter case
};

/// `path` when it exists; otherwise the file whose path matches it when
/// letter case is ignored, component by component (the first in name order
/// when several match); nothing when there is none.
std::optional<FoundFile> findFile(const std::string& path);

}  // namespace raylab
