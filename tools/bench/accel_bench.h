#pragma once
// `raylab bench accel`: the Embree BVH against the naive loop over every
// primitive, on the same rays, for growing procedural scenes and for scene
// files. See docs/benchmarks.md for the method and measured results.

#include <cstddef>
#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

namespace raylab {

struct AccelBenchOptions {
    std::vector<std::string> sceneFiles;  ///< measured after the generators, in order
    int width = 256, height = 256;        ///< one ray per pixel centre (spp 1)
    int runs = 5;                         ///< timed runs per measurement; the median is reported
    int threads = 0;                      ///< 0 = all cores
    double naiveBudgetSeconds = 2.0;      ///< longest naive frame; beyond it, a pixel sample
    std::string outPath;                  ///< results as .csv or .json (empty: none)
    std::string plotPath;                 ///< log-log .svg plot of time per ray (empty: none)
    std::string htmlDir;                  ///< DIR/index.html report (empty: none)
    bool quick = false;                   ///< ~20 s smoke run (small sizes, 128², <= 3 runs)
};

/// \brief Runs the accelerator benchmark and prints a table to `out`.
/// \details For every size of every generator of benchSceneGenerators() (the
///   quick ladder with `quick`) and every scene file: primitive count, build
///   time, frame time and rays/s for Embree (full frame) and the naive loop
///   (full frame, or every k-th pixel when a full frame would exceed
///   naiveBudgetSeconds), the speedup in rays/s, and per family the size below
///   which the naive loop wins. Times are medians of `runs`.
/// \return 0 on success.
/// \throws UsageError for invalid options (checked before anything runs),
///   InputError for an unreadable scene file or output path.
int runAccelBench(const AccelBenchOptions& options, std::ostream& out);

/// \brief The stride of the naive loop's pixel sample: the smallest k >=
///   minStride that shares no factor with `width`, so that every k-th pixel in
///   row-major order (starting at pixel k/2) visits every column, not a few
///   vertical stripes.
size_t pixelSampleStride(size_t minStride, int width);

}  // namespace raylab
