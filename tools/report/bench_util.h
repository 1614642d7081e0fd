#pragma once
// Small helpers shared by the benchmarks: machine description, medians,
// output-format choice and number formatting.

#include <chrono>
#include <string>
#include <vector>

#include "renderer/timing.h"  // secondsSince, threadCpuSeconds

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

enum class TableFormat { Csv, Json };

/// \brief The format chosen by a file name's extension (.csv or .json, any case).
/// \throws UsageError for any other extension, naming `what` (e.g. "--output").
TableFormat tableFormatOf(const std::string& path, const std::string& what);

/// A double for CSV/JSON: shortest round-trip form ("%.17g" trimmed); non-finite -> "null".
std::string jsonNumber(double v);

/// `s` as a JSON string literal (quotes and escapes included).
std::string jsonString(const std::string& s);

/// `s` as a CSV field (quoted when it holds a comma, quote or newline).
std::string csvField(const std::string& s);

}  // namespace raylab
