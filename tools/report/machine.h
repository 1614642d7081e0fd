#pragma once
// What every measurement prints about the machine it ran on, so that numbers
// from a shared machine can be judged (CPU, cores, threads, load).

#include <string>

namespace raylab {

/// The CPU model from /proc/cpuinfo ("model name"), or "unknown CPU".
std::string cpuModelName();

/// The 1-minute load average from /proc/loadavg (-1 when unreadable): on a
/// shared machine it says how far wall-clock timings can be trusted.
double loadAverage();

/// Logical cores the process may use (std::thread::hardware_concurrency, >= 1).
int logicalCores();

/// Threads a TBB loop gets for a `threads` setting (0 = all cores).
int effectiveThreads(int threads);

}  // namespace raylab
