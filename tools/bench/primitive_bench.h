#pragma once
// Micro-benchmark of the analytic primitives' intersect() (raylab bench primitives).

#include <ostream>

namespace raylab {

/// Prints a table of nanoseconds per Shape::intersect() call for every analytic
/// primitive (sphere, plane, disk, cylinder, cone, capped truncated cone,
/// quadric, polygons under both inside tests), each with a hit-heavy and a
/// miss-heavy set of 1024 rays, in double and float precision, followed by the
/// polygon watertightness measurement (rays through the shared edges and the
/// shared vertex of a fan of quads: how many miss every quad). One thread;
/// each timing is the fastest of three runs of `iterations` passes over the
/// rays. iterations = 50 takes well under a second on a 2-core VM.
void runPrimitiveBench(std::ostream& out, int iterations);

}  // namespace raylab
