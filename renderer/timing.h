#pragma once
// The two clocks raylab times things with: wall time since a start, and the
// calling thread's CPU time, which waits for a core on a shared machine do
// not inflate.

#include <time.h>

#include <chrono>
#include <cstdint>

namespace raylab {

/// Wall-clock seconds since t0.
inline double secondsSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// CPU nanoseconds consumed so far by the calling thread (CLOCK_THREAD_CPUTIME_ID).
inline int64_t threadCpuNanoseconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return int64_t(ts.tv_sec) * 1000000000 + ts.tv_nsec;
}

/// The same in seconds.
inline double threadCpuSeconds() { return 1e-9 * double(threadCpuNanoseconds()); }

}  // namespace raylab
