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

/// The CPU the calling thread runs on right now (sched_getcpu), or -1. A
/// one-thread benchmark samples it between its timed phases: on a VM whose
/// CPUs are not equally fast at a given moment, a process that moved between
/// them compared phases timed at different speeds (docs/benchmarks.md,
/// session 2026-12-06 14:38).
int currentCpu();

}  // namespace raylab
