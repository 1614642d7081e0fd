#pragma once
// Finding the files an OBJ or MTL names (material libraries, textures) the
// way their authors meant them: files written on Windows or macOS name
// "Wood.PNG" for "wood.png", which a case-sensitive file system does not find.

#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace raylab {

struct FoundFile {
    std::string path;          ///< the file as it exists
    bool caseDiffers = false;  ///< found only by ignoring letter case
};

/// Looks files up for one load. Folders it had to list are remembered, so
/// 10^5 names that do not exist cost one listing per folder, not one each.
class FileFinder {
public:
    /// `path` when it exists; otherwise the file whose path matches it when
    /// letter case is ignored, component by component (the first in name
    /// order when several match); nothing when there is none.
    std::optional<FoundFile> find(const std::string& path);

private:
    /// Entries of `folder` by lower-case name (the first in name order).
    const std::unordered_map<std::string, std::string>& listing(const std::string& folder);

    std::unordered_map<std::string, std::unordered_map<std::string, std::string>> m_listings;
};

}  // namespace raylab
