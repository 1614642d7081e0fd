#pragma once
// Where raylab looks for the shared objects it loads with dlopen only when a
// run needs them (the OpenImageIO module, the MPI module): beside the running
// executable first, where an installed or copied raylab keeps them, then
// where the build put them (compiled in), for executables elsewhere in the tree.

#include <string>
#include <vector>

namespace raylab {

/// The paths to try for the module file `fileName`, in order; `buildPath`
/// (may be null) is the module's path in the build tree.
std::vector<std::string> moduleCandidates(const std::string& fileName, const char* buildPath);

}  // namespace raylab
