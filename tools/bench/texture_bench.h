#pragma once
// Micro-benchmark of texture lookups (raylab bench textures): ns per lookup of
// raylab's own MIP pyramid (shading/mipmap.h) and of OpenImageIO's
// TextureSystem on the same linear float image, for each filter, on the same
// coordinates and footprints; and how far the two disagree. The measurement
// behind the choice of the project's own pyramid (docs/benchmarks.md).

#include <ostream>

namespace raylab {

struct TextureBenchOptions {
    int size = 1024;        ///< image side in texels
    int lookups = 200000;   ///< per filter and run
    int runs = 5;           ///< the fastest run is reported
};

/// Prints the table; one thread, CPU time of the calling thread.
void runTextureBench(const TextureBenchOptions& options, std::ostream& out);

}  // namespace raylab
