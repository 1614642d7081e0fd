#pragma once
// raylab bench effects: the specialised kernel (only the effects the scene
// calls for) against the general one (every ray type at every hit), on the
// same scene and rays, interleaved, median of several runs.

#include <iosfwd>
#include <string>
#include <vector>

namespace raylab {

struct EffectsBenchOptions {
    std::vector<std::string> scenes;
    int width = 0, height = 0;  ///< 0: the scene's own resolution
    int runs = 5;
    int threads = 0;
    bool spd = false;
};

/// Prints a table (scene, effects, time and rays for both kernels, speedup);
/// returns the exit code.
int runEffectsBench(const EffectsBenchOptions& options, std::ostream& out);

}  // namespace raylab
