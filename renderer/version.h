#pragma once
// raylab's version (CMakeLists.txt's project VERSION): --version and the
// "software" attribute of every image written.

namespace raylab {

constexpr const char* kRaylabVersion = "0.1.0";

/// "raylab 0.1.0": the Software/software tag of the output files.
inline const char* raylabSoftware() { return "raylab 0.1.0"; }

}  // namespace raylab
