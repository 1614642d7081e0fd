#pragma once
// Timing a measured phase and summarising repeated runs of it.

#include <chrono>
#include <vector>

#include "renderer/timing.h"  // secondsSince, threadCpuSeconds

namespace raylab {

/// \brief The clock of a benchmark's timed phases.
/// \details With one thread (TBB then runs the whole loop on the calling
///   thread) it is that thread's CPU time, which a busy shared machine does not
///   inflate; with more threads, wall-clock time.
class PhaseClock {
public:
    explicit PhaseClock(bool cpu) : m_cpu(cpu) {}
    /// Seconds that `phase()` takes on this clock.
    template <class F>
    double time(F&& phase) const {
        if (m_cpu) {
            const double t0 = threadCpuSeconds();
            phase();
            return threadCpuSeconds() - t0;
        }
        const auto t0 = std::chrono::steady_clock::now();
        phase();
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }
    bool cpu() const { return m_cpu; }
    /// "CPU time of the one working thread" or "wall-clock time".
    const char* name() const {
        return m_cpu ? "CPU time of the one working thread" : "wall-clock time";
    }

private:
    bool m_cpu;
};

/// Median of the values (mean of the middle two for an even count); 0 when empty.
double median(std::vector<double> values);

}  // namespace raylab
