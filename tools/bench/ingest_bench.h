#pragma once
// `raylab bench ingest`: OBJ ingest speed and memory (issue 20 bar 4). A
// generated height-field OBJ (quads, one smoothing group, four materials, no
// vn: the load parses, triangulates, averages normals and assigns materials)
// is loaded with loadObj repeatedly; reported are the median wall time, MB/s
// of OBJ text, and the peak resident memory above the process's baseline per
// triangle, for each thread count asked for.

#include <cstddef>
#include <iosfwd>
#include <string>
#include <vector>

namespace raylab {

/// The OBJ text of a height field of `grid` x `grid` quads ((grid + 1)^2
/// vertices, 2 grid^2 triangles): `mtllib terrain.mtl`, `s 1`, positions with
/// six decimals, faces counter-clockwise seen from +z, and four `usemtl`
/// bands (band0 .. band3) across y.
std::string heightFieldObj(size_t grid);

/// The MTL library heightFieldObj names: materials band0 .. band3.
std::string heightFieldMtl();

struct IngestBenchOptions {
    size_t triangles = 2000000;       ///< about; the grid is round(sqrt(triangles / 2))
    int runs = 5;                     ///< timed loads per thread count; medians reported
    std::vector<int> threads{1, 0};   ///< thread counts to measure (0 = all cores)
    std::string dir;                  ///< where the OBJ is written (empty: a temp dir, removed after)
    bool keep = false;                ///< keep the generated files
};

/// Runs the benchmark and prints a report to `out`. Returns 0.
/// \throws UsageError for invalid options, InputError when the files cannot be written.
int runIngestBench(const IngestBenchOptions& options, std::ostream& out);

}  // namespace raylab
